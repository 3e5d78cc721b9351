/* Fourth-order Magnus integrator for R' = R w^(t) (two Gauss points, exponential map): an
 * independent check of the rk8pd reference attitude. It stays on SO(3) by construction. */
#ifndef SUSLOV_MAGNUS4_H
#define SUSLOV_MAGNUS4_H

#include "exact.h"

/* R <- R Phi(t0, t1) with n equal Magnus steps. */
void suslov_magnus4(const suslov_exact *ex, double t0, double t1, long n, double R[3][3]);

#endif
