/* The attitude along the known w (src/methods/step_exact_attitude.c): a tolerance-driven method
 * that takes w(t) and lambda(t) from the closed form (exact.h) and integrates only R' = R w^(t):
 * by the attitude's Taylor series in t before the inflection of the transient (the step file says
 * why not Magnus6 steps), by one series in e^{-k t} after it (attitude_series.h), and over the
 * steady tail by one step of the steady rotation. */
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
