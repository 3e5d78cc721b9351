/* The reduced problem: w(t) is known in closed form (exact.h), so only the attitude is left to
 * integrate, the linear equation q' = 1/2 q (x) (0, w(t)) for a quaternion q (R = R(q/|q|)). make
 * bench gives it to the library integrators, so that they meet our methods that use the closed
 * form on the same structure (y = q, 4 unknowns). w(t) is the one the method exact-attitude
 * evaluates: exact_fast.h, one exponential, within a few roundings of sus_exact_omega
 * (tests/unit/test_peers.c holds it to that). */
#ifndef SUS_LAB_REDUCED_H
#define SUS_LAB_REDUCED_H

#include "exact_fast.h"

#ifdef __cplusplus
extern "C" {
#endif

/* q' = 1/2 q (x) (0, w(t)) as a GSL odeiv2 right-hand side: y = q; params is the sus_exact_fast. */
int sus_lab_reduced_rhs(double t, const double y[], double f[], void *params);

#ifdef __cplusplus
}
#endif

#endif
