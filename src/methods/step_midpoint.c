/* The midpoint DSP of the paper's Figures 1-2: (Discretization) with
 *   l1 = -((w2^{k+1} + w2^k)/2) I_3i (w_i^{k+1} + w_i^k)/2,
 *   l2 =  ((w1^{k+1} + w1^k)/2) I_3i (w_i^{k+1} + w_i^k)/2,
 * and lambda_{k+1} = lambda(w^{k+1}) from (LagMult). The implicit equation
 *   G(x) = I_m (x - w^k) - eps (l1, l2) = 0
 * is solved by Newton from an explicit prediction. */
#include "implicit_step.h"
#include "newton_core.h"
#include "stability_fn.h"
#include "dsp.h"

#include <math.h>

/* (Discretization) residual with the midpoint l1, l2, and its Jacobian in x = w^{k+1}. */
NEWTON_INLINE void mid_residual(const sus_model *m, double eps, const double w[2], const double *x,
                                double *g, double *J, double *scale)
{
    const double(*I)[3] = m->I;
    const double mid[2] = {0.5 * (x[0] + w[0]), 0.5 * (x[1] + w[1])};
    const double c = sus_c(m, mid);
    const double l1 = -mid[1] * c, l2 = mid[0] * c;
    const double d0 = x[0] - w[0], d1 = x[1] - w[1];
    g[0] = I[0][0] * d0 + I[0][1] * d1 - eps * l1;
    g[1] = I[1][0] * d0 + I[1][1] * d1 - eps * l2;
    const double *b = m->b;
    J[0] = I[0][0] + 0.5 * eps * mid[1] * b[0];
    J[1] = I[0][1] + 0.5 * eps * (c + mid[1] * b[1]);
    J[2] = I[1][0] - 0.5 * eps * (c + mid[0] * b[0]);
    J[3] = I[1][1] - 0.5 * eps * mid[0] * b[1];
    const double sx = fabs(x[0]) + fabs(x[1]) + fabs(w[0]) + fabs(w[1]);
    *scale = (fabs(I[0][0]) + fabs(I[0][1]) + fabs(I[1][0]) + fabs(I[1][1])) * sx +
             eps * (fabs(l1) + fabs(l2));
}

static const sus_step_equation MID_EQUATION = {.unknowns = 2,
                                               .residual = mid_residual,
                                               .guess = sus_step_predict,
                                               .result = sus_step_result_is_x};

int sus_step_midpoint_solve(const sus_model *m, double eps, const double w[3], double w_next[3],
                            sus_stepper_stats *st)
{
    return newton_w_step(mid_residual, newton_predict, m, eps, w, w_next, st);
}

static int midpoint_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                          double *lambda_next, sus_stepper_stats *st)
{
    const int status = sus_step_midpoint_solve(m, eps, w, w_next, st);
    *lambda_next = sus_lagmult(m, w_next);
    return status;
}

/* The midpoint rule conserves the quadratic invariant E of (ContDyn). */
static const sus_step_ops MID_STEP = {.apply = midpoint_apply};

const sus_stepper_type sus_step_midpoint_type = {.name = "midpoint",
                                                 .step = &MID_STEP,
                                                 .equation = &MID_EQUATION,
                                                 .desc = {.order = 2,
                                                          .lambda_order = 2,
                                                          .implicit = 1,
                                                          .conserves_energy = 1,
                                                          .follows_recon = 1,
                                                          .substeps = 1,
                                                          .stability = sus_step_stab_midpoint,
                                                          .source = __FILE__}};
const sus_stepper_type *const sus_step_midpoint = &sus_step_midpoint_type;
