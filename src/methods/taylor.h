/* High-order Taylor-series methods for (ContDyn) with the attitude as a unit quaternion
 * (src/methods/step_taylor.c). */
#ifndef SUSLOV_TAYLOR_H
#define SUSLOV_TAYLOR_H

#include "stepper.h"

#define SUSLOV_TAYLOR_MAX_ORDER 32

/* The step of (w, R) of order p <= SUSLOV_TAYLOR_MAX_ORDER: the w-step with E restored onto
 * E(w^k), and R_{k+1} = R_k R(q(eps)) from the quaternion series. */
int suslov_taylor_apply_full(int p, const suslov_model *m, double eps, suslov_attitude *att,
                             const double w[3], double w_next[3], double *lambda_next,
                             suslov_step_stats *st);

/* The radius the Taylor series of w and of the attitude increment from w are proved to converge
 * in (a majorant from the series' first coefficient, step_taylor.c); INFINITY at an equilibrium.
 * A Taylor step longer than this refuses to run: SUSLOV_STEP_DIVERGED with the step over the
 * radius in stats.residual and |w|_2 in stats.scale. */
double suslov_taylor_radius(const suslov_model *m, const double w[2]);
/* The proved bound on the w-series' tail past degree p over a step h from w (Cauchy's estimate
 * on the majorant); INFINITY beyond the radius. */
double suslov_taylor_tail_bound(int p, const suslov_model *m, double h, const double w[2]);

double suslov_taylor_stability(int p, double z);
double suslov_stab_taylor8(double z), suslov_stab_taylor10(double z), suslov_stab_taylor12(double z),
    suslov_stab_taylor16(double z);

extern const suslov_stepper_type suslov_taylor8_type, suslov_taylor10_type, suslov_taylor12_type,
    suslov_taylor16_type;

#endif
