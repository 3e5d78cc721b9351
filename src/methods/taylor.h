/* High-order Taylor-series methods for (ContDyn) with the attitude as a unit quaternion
 * (src/methods/step_taylor.c). */
#ifndef SUS_STEP_TAYLOR_H
#define SUS_STEP_TAYLOR_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_STEP_TAYLOR_MAX_ORDER 32

/* The step of (w, R) of order p <= SUS_STEP_TAYLOR_MAX_ORDER: the w-step with E restored onto
 * E(w^k), and R_{k+1} = R_k R(q(eps)) from the quaternion series. */
int sus_step_taylor_apply_full(int p, const sus_model *m, double eps, sus_attitude *att,
                               const double w[3], double w_next[3], double *lambda_next,
                               sus_stepper_stats *st);

/* The radius the Taylor series of w and of the attitude increment from w are proved to converge
 * in (a majorant from the series' first coefficient, step_taylor.c); INFINITY at an equilibrium.
 * A Taylor step longer than this refuses to run: SUS_STEPPER_DIVERGED with the step over the
 * radius in stats.residual and |w|_2 in stats.scale. */
double sus_step_taylor_radius(const sus_model *m, const double w[2]);
/* The proved bound on the w-series' tail past degree p over a step h from w (Cauchy's estimate
 * on the majorant); INFINITY beyond the radius. */
double sus_step_taylor_tail_bound(int p, const sus_model *m, double h, const double w[2]);

double sus_step_taylor_stability(int p, double z);
double sus_step_stab_taylor8(double z), sus_step_stab_taylor10(double z),
    sus_step_stab_taylor12(double z), sus_step_stab_taylor16(double z);

/* The tolerance-driven Taylor method (step_taylor_adaptive.c; stepper.h, sus_tol_ops) and the
 * order it uses at a tolerance. */
extern const sus_stepper_type sus_step_taylor_adaptive_type;
int sus_step_taylor_adaptive_order(double tol);

extern const sus_stepper_type sus_step_taylor8_type, sus_step_taylor10_type, sus_step_taylor12_type,
    sus_step_taylor16_type;

#ifdef __cplusplus
}
#endif

#endif
