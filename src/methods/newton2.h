/* Newton's method for the 2x2 implicit step equations G(x) = 0 of the midpoint and
 * variational DSPs, with an analytic Jacobian supplied by the caller. */
#ifndef SUSLOV_NEWTON2_H
#define SUSLOV_NEWTON2_H

#include "stepper.h"

/* Iterates from the initial guess in x. Returns SUSLOV_STEP_OK when |G|_inf falls to
 * NEWTON2_RTOL * scale and one more (polishing) correction has been applied, or when a
 * correction falls below the spacing of doubles at x, or when the iteration stagnates at a
 * residual within NEWTON2_STAGNATION * scale (round-off amplified by the Jacobian), SUSLOV_STEP_SINGULAR when the Jacobian (the (REGLOC) block) is
 * singular to working precision, SUSLOV_STEP_NO_CONVERGENCE after NEWTON2_MAXIT steps. */
int newton2_solve(suslov_residual_fn G, const suslov_model *m, double eps, const double w[2],
                  double x[2], suslov_step_stats *st);

/* The common step of the implicit DSPs: w_next = w^{k+1} by Newton on G from the explicit
 * prediction, and (w^{k+1})_3 = 0, the second equation of (DSP). Returns as newton2_solve. */
int suslov_implicit_solve(suslov_residual_fn G, const suslov_model *m, double eps, const double w[3],
                          double w_next[3], suslov_step_stats *st);

/* G is a sum of a handful of products; each carries a relative error of a few units of
 * round-off, so at the root the computed |G| is a few u * scale. 16 u leaves room for that
 * and no more. */
#define NEWTON2_RTOL (16.0 * 2.220446049250313e-16)
#define NEWTON2_MAXIT 50
/* The widest residual accepted as round-off when Newton stagnates: 1000 u times the scale. */
#define NEWTON2_STAGNATION (1000.0 * 2.220446049250313e-16)

#endif
