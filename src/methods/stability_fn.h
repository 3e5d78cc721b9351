/* Linear stability functions R(z) of the w-steps: the step applied to w' = a w gives
 * w^{k+1} = R(eps a) w^k. A method is linearly stable at the attracting steady rotation, whose
 * transverse eigenvalue is -k, while |R(-eps k)| <= 1. */
#ifndef SUS_STEP_STABILITY_FN_H
#define SUS_STEP_STABILITY_FN_H

#ifdef __cplusplus
extern "C" {
#endif

double sus_step_stab_euler(double z);    /* 1 + z */
double sus_step_stab_rk4(double z);      /* 1 + z + z^2/2 + z^3/6 + z^4/24 */
double sus_step_stab_midpoint(double z); /* (1 + z/2) / (1 - z/2) */

#ifdef __cplusplus
}
#endif

#endif
