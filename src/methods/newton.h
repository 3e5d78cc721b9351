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
 * |G|_inf falls to SUS_STEP_NEWTON_RTOL * scale and one more (polishing) correction has been
 * applied, or when a correction falls below the spacing of doubles at x, or when the iteration
 * stagnates at a residual within SUS_STEP_NEWTON_STAGNATION * scale (round-off amplified by the
 * Jacobian); SUS_STEPPER_SINGULAR when the Jacobian (for n = 2 the (REGLOC) block) is singular to
 * working precision; SUS_STEPPER_NO_CONVERGENCE after SUS_STEP_NEWTON_MAXIT steps. */
int sus_step_newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                          const double w[2], double *x, sus_stepper_stats *st);

/* The root the step defines: the branch continued in eps from the root at eps = 0 (guess(0)),
 * on which det J > 0 as at eps = 0 ((REGLOC): J is I_m there, or blocks of it). Stages of
 * adaptive length, each a Newton solve from the secant through the last two roots, accepted when
 * it converges quickly, keeps det J > 0 and stays near its prediction (no jump to another root);
 * a failed stage is retried shorter. Regularity: r = |det J|^(2/n) / |J|_F^2 (scale-free, at most
 * 1/n), relative to its value at eps = 0. Returns SUS_STEPPER_OK with the root in x;
 * SUS_STEPPER_SINGULAR when the stages shrink to nothing where r had fallen to BRANCH_FOLD (a
 * fold: the branch turns back, and beyond it the step has no root on the branch);
 * SUS_STEPPER_NO_CONVERGENCE otherwise. *reg_min: the least r over the accepted stages (reg_min
 * NULL: not wanted, and r is computed only where the stages stop short). */
int sus_step_newton_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                           double eps, const double w[2], double *x, sus_stepper_stats *st,
                           double *reg_min);

/* Newton from guess(eps), taken when it holds as a stage of the continuation below would (a quick
 * convergence near the prediction, det J > 0, within FAST_ITS iterations); else the branch by
 * continuation (sus_step_newton_branch). So where the prediction is good (small eps) the step is
 * Newton from it, as it always was, and elsewhere the continued root, not whichever root Newton
 * wandered to. stats.iterations counts every Newton iteration. */
int sus_step_newton_solve_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                                 double eps, const double w[2], double *x, sus_stepper_stats *st);

/* dx = J^{-1} g and det J for n <= SUS_MAX_UNKNOWNS (J row-major, overwritten). Returns -1,
 * leaving dx unset, when J is singular to working precision: |det| at or below 4 n u times the sum
 * of |terms| of its Leibniz expansion (for n = 2 exactly that sum; beyond, the product of the row
 * 1-norms, which bounds it) and, for n > 2, also 4 n u kappa >= 1, kappa the condition number of
 * J with rows scaled to unit 1-norm (the determinant alone calls a J with two small singular
 * values singular long before the solve loses its digits). Both tests are scale-free: the answer
 * and dx are the same for 2^s J and 2^s g. *det is det J where a double holds it; beyond (n > 2,
 * entries far from 1), +-inf above and the least subnormal of its sign below, so its sign reads. */
int sus_step_linear_solve(int n, double *J, const double *g, double *dx, double *det);

/* G is a sum of a handful of products; each carries a relative error of a few units of
 * round-off, so at the root the computed |G| is a few u * scale. 16 u leaves room for that
 * and no more. */
#define SUS_STEP_NEWTON_RTOL (16.0 * SUS_U)
#define SUS_STEP_NEWTON_MAXIT 50
/* The widest residual accepted as round-off when Newton stagnates: 1000 u times the scale. */
#define SUS_STEP_NEWTON_STAGNATION (1000.0 * SUS_U)

/* The continuation (sus_step_newton_branch). The first stage is eps / BRANCH_FIRST, shortened
 * without a solve while the explicit prediction for it moves w by more than BRANCH_JUMP |w|; a
 * stage that holds lets the next grow BRANCH_GROW-fold (BRANCH_GROW_EASY-fold after one that took
 * at most BRANCH_EASY_ITS iterations: the path is nearly straight there); one that fails is
 * retried BRANCH_SHRINK as long. From a secant prediction Newton converges quadratically in a few
 * iterations on the branch: more than BRANCH_STAGE_ITS, or a root BRANCH_JUMP |w| from the
 * prediction (the other roots met lie farther than |w| from the branch's), marks a stage that left
 * it. The stages stop at BRANCH_MIN_STAGE of eps (2^-40: far below any fold's width that double
 * precision resolves) or after BRANCH_MAX_STAGES. Near a fold Newton converges only linearly, so
 * the stages stop where it needs more than BRANCH_STAGE_ITS iterations, with det J near a
 * thousandth of its scale; a regularity below BRANCH_FOLD of its value at eps = 0 where they stop
 * is a fold (a continuation stopped elsewhere leaves det J of its own size). */
#define BRANCH_FIRST 8.0
#define BRANCH_GROW 2.0
#define BRANCH_GROW_EASY 4.0
#define BRANCH_EASY_ITS 4
#define BRANCH_SHRINK 0.25
#define BRANCH_STAGE_ITS 10
#define BRANCH_JUMP 0.5
#define BRANCH_MIN_STAGE 0x1p-40
#define BRANCH_MAX_STAGES 400
#define BRANCH_FOLD 1e-2
/* Newton from the explicit prediction is taken as the step's root only when it converges within
 * FAST_ITS corrections: from a start inside its root's region of quadratic convergence (relative
 * error below 1/2) the error squares at each correction, 2^-1 to 2^-64 in six. More means the
 * start lay outside it, where Newton can wander to another root (it does on a long energy
 * ellipse, a near-singular I_m, where another root lies nearer the prediction than the ellipse's
 * size): the step is then continued from eps = 0 instead. */
#define FAST_ITS 6

#ifdef __cplusplus
}
#endif

#endif
