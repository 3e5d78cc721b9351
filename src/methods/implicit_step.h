/* The common step of the implicit DSPs (the midpoint and variational DSPs, the Gauss
 * collocation): their step equation (stepper.h, sus_step_equation) solved by Newton on the
 * branch continued from eps = 0 (newton.h), and the two hooks most of them share. */
#ifndef SUS_STEP_IMPLICIT_H
#define SUS_STEP_IMPLICIT_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The root of eq->residual by sus_step_newton_solve_branch from eq->guess, w^{k+1} from
 * eq->result, and (w^{k+1})_3 = 0, the second equation of (DSP). */
int sus_step_implicit_solve(const sus_step_equation *eq, const sus_model *m, double eps,
                            const double w[3], double w_next[3], sus_stepper_stats *st);

/* w^{k+1} of the root on eq's branch continued from eps = 0 alone (sus_step_newton_branch, no
 * Newton from the prediction first): what a check of a step's root compares it with. Returns the
 * continuation's status (SUS_STEPPER_SINGULAR at a fold); w_next is written only on
 * SUS_STEPPER_OK. */
int sus_step_branch_root(const sus_step_equation *eq, const sus_model *m, double eps,
                         const double w[2], double w_next[2]);

/* The midpoint DSP's step (step_midpoint.c): sus_step_implicit_solve of its equation, with its
 * residual inlined into Newton's loop (newton_core.h); the compositions call it for every substep.
 */
int sus_step_midpoint_solve(const sus_model *m, double eps, const double w[3], double w_next[3],
                            sus_stepper_stats *st);

/* Explicit midpoint (second order) prediction, the starting point of the Newton solves (a guess
 * hook). These two write NaN where an input is NULL, and nothing where the output is. */
void sus_step_predict(const sus_model *m, double eps, const double w[2], double x[2]);
/* The result hook of a step whose unknowns are x = w^{k+1} itself. */
void sus_step_result_is_x(const sus_model *m, double eps, const double w[2], const double *x,
                          double w_next[2]);

#ifdef __cplusplus
}
#endif

#endif
