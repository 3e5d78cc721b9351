/* Newton's method for the n x n implicit step equations G(x) = 0 of every implicit DSP (the
 * midpoint and variational DSPs, n = 2; the Gauss collocation, n = 4), with the analytic
 * Jacobian supplied by the step. The linear solve keeps everything on the stack. */
#ifndef SUSLOV_NEWTON_H
#define SUSLOV_NEWTON_H

#include "stepper.h"

/* Iterates from the initial guess in x[n], n <= SUSLOV_MAX_UNKNOWNS. Returns SUSLOV_STEP_OK when
 * |G|_inf falls to NEWTON_RTOL * scale and one more (polishing) correction has been applied, or
 * when a correction falls below the spacing of doubles at x, or when the iteration stagnates at a
 * residual within NEWTON_STAGNATION * scale (round-off amplified by the Jacobian);
 * SUSLOV_STEP_SINGULAR when the Jacobian (for n = 2 the (REGLOC) block) is singular to working
 * precision; SUSLOV_STEP_NO_CONVERGENCE after NEWTON_MAXIT steps. */
int suslov_newton_solve(suslov_residual_fn G, int n, const suslov_model *m, double eps, const double w[2],
                        double *x, suslov_step_stats *st);

/* The common step of the implicit DSPs: Newton on type->residual from type->guess, w^{k+1} from
 * type->result, and (w^{k+1})_3 = 0, the second equation of (DSP). Returns as suslov_newton_solve. */
int suslov_implicit_solve(const suslov_stepper_type *type, const suslov_model *m, double eps,
                          const double w[3], double w_next[3], suslov_step_stats *st);

/* dx = J^{-1} g and det J for n <= SUSLOV_MAX_UNKNOWNS (J row-major, overwritten). Returns -1,
 * leaving dx unset, when J is singular to working precision: |det| at or below 4 n u times the sum
 * of |terms| of its Leibniz expansion (for n = 2 exactly that sum; beyond, the product of the row
 * 1-norms, which bounds it). */
int suslov_linear_solve(int n, double *J, const double *g, double *dx, double *det);

/* G is a sum of a handful of products; each carries a relative error of a few units of
 * round-off, so at the root the computed |G| is a few u * scale. 16 u leaves room for that
 * and no more. */
#define NEWTON_RTOL (16.0 * SUSLOV_U)
#define NEWTON_MAXIT 50
/* The widest residual accepted as round-off when Newton stagnates: 1000 u times the scale. */
#define NEWTON_STAGNATION (1000.0 * SUSLOV_U)

#endif
