/* The attitude along the known w (src/methods/step_exact_attitude.c): a tolerance-driven method
 * that takes w(t) and lambda(t) from the closed form (exact.h) and integrates only R' = R w^(t),
 * by the attitude's Taylor series at every tolerance (the step file says why not Magnus6 steps),
 * and jumps the steady tail in one step. */
#ifndef SUS_EXACT_ATTITUDE_H
#define SUS_EXACT_ATTITUDE_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

extern const sus_stepper_type sus_step_exact_attitude_type;

/* The order it uses at tol: the degree of its Taylor sums. */
int sus_step_exact_attitude_order(double tol);

#ifdef __cplusplus
}
#endif

#endif
