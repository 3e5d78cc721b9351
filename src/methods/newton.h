/* Newton's method for the n x n implicit step equations G(x) = 0 of every implicit DSP (the
 * midpoint and variational DSPs, n = 2; the Gauss collocation, n = 4), with the analytic
 * Jacobian supplied by the step. The linear solve keeps everything on the stack. */
#ifndef SUS_STEP_NEWTON_H
#define SUS_STEP_NEWTON_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Iterates from the initial guess in x[n], n <= SUS_MAX_UNKNOWNS. Returns SUS_STEPPER_OK when
 * |G|_inf falls to SUS_STEP_NEWTON_RTOL * scale and one more (polishing) correction has been applied, or
 * when a correction falls below the spacing of doubles at x, or when the iteration stagnates at a
 * residual within SUS_STEP_NEWTON_STAGNATION * scale (round-off amplified by the Jacobian);
 * SUS_STEPPER_SINGULAR when the Jacobian (for n = 2 the (REGLOC) block) is singular to working
 * precision; SUS_STEPPER_NO_CONVERGENCE after SUS_STEP_NEWTON_MAXIT steps. */
int sus_step_newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps, const double w[2],
                        double *x, sus_stepper_stats *st);

/* The common step of the implicit DSPs: Newton on type->residual from type->guess, w^{k+1} from
 * type->result, and (w^{k+1})_3 = 0, the second equation of (DSP). Returns as sus_step_newton_solve. */
int sus_step_implicit_solve(const sus_stepper_type *type, const sus_model *m, double eps,
                          const double w[3], double w_next[3], sus_stepper_stats *st);

/* dx = J^{-1} g and det J for n <= SUS_MAX_UNKNOWNS (J row-major, overwritten). Returns -1,
 * leaving dx unset, when J is singular to working precision: |det| at or below 4 n u times the sum
 * of |terms| of its Leibniz expansion (for n = 2 exactly that sum; beyond, the product of the row
 * 1-norms, which bounds it). */
int sus_step_linear_solve(int n, double *J, const double *g, double *dx, double *det);

/* G is a sum of a handful of products; each carries a relative error of a few units of
 * round-off, so at the root the computed |G| is a few u * scale. 16 u leaves room for that
 * and no more. */
#define SUS_STEP_NEWTON_RTOL (16.0 * SUS_U)
#define SUS_STEP_NEWTON_MAXIT 50
/* The widest residual accepted as round-off when Newton stagnates: 1000 u times the scale. */
#define SUS_STEP_NEWTON_STAGNATION (1000.0 * SUS_U)

#ifdef __cplusplus
}
#endif

#endif
