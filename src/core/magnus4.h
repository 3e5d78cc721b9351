/* Fourth-order Magnus integrator for R' = R w^(t) (two Gauss points, exponential map) along the
 * closed-form w(t), in long double: an independent check of the reference attitude
 * (refattitude.h), which integrates (ContDyn) itself by a Taylor series. */
#ifndef SUS_MAGNUS4_H
#define SUS_MAGNUS4_H

#include "exact.h"
#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* R <- R Phi(t0, t1) from n and 2n equal steps with Richardson extrapolation (the closed form
 * and the scheme in long double; the result rounded once to double). */
void sus_magnus4(const sus_exact *ex, double t0, double t1, long n, double R[3][3]);

#ifdef __cplusplus
}
#endif

#endif
