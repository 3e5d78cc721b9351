/* The nonholonomic variational integrator of Section 5.5: (taudyn) for w^{k+1}, solved by
 * Newton from an explicit prediction, and (taualg) for lambda_{k+1}, both as printed. */
#include "implicit_step.h"
#include "newton_core.h"
#include "dsp.h"

#include <math.h>

/* y y^T I_m y = y <y, I_m y>, the eps^2/4 terms of (taudyn). */
static void quartic_term(const double (*I)[3], const double y[2], double q[2])
{
    const double p0 = I[0][0] * y[0] + I[0][1] * y[1], p1 = I[1][0] * y[0] + I[1][1] * y[1];
    const double s = y[0] * p0 + y[1] * p1;
    q[0] = y[0] * s;
    q[1] = y[1] * s;
}

/* (taudyn): G(x) with x = w^{k+1}, and its Jacobian (the (REGLOC)/(RegCond) block). */
NEWTON_INLINE void taudyn_residual(const sus_model *m, double eps, const double w[2],
                                   const double *x, double *g, double *J, double *scale)
{
    const double(*I)[3] = m->I;
    const double *b = m->b;
    const double cx = sus_c(m, x), cw = sus_c(m, w);
    double qx[2], qw[2];
    quartic_term(I, x, qx);
    quartic_term(I, w, qw);
    const double d0 = x[0] - w[0], d1 = x[1] - w[1];
    const double h = 0.5 * eps, h2 = 0.25 * eps * eps;
    const double t0 = x[1] * cx + w[1] * cw, t1 = -x[0] * cx - w[0] * cw;
    g[0] = I[0][0] * d0 + I[0][1] * d1 + h * t0 + h2 * (qx[0] - qw[0]);
    g[1] = I[1][0] * d0 + I[1][1] * d1 + h * t1 + h2 * (qx[1] - qw[1]);

    /* d/dx [x <x, I_m x>] = <x, I_m x> Id + x ((I_m + I_m^T) x)^T */
    const double p0 = I[0][0] * x[0] + I[0][1] * x[1], p1 = I[1][0] * x[0] + I[1][1] * x[1];
    const double s = x[0] * p0 + x[1] * p1;
    const double a0 = p0 + I[0][0] * x[0] + I[1][0] * x[1];
    const double a1 = p1 + I[0][1] * x[0] + I[1][1] * x[1];
    J[0] = I[0][0] + h * x[1] * b[0] + h2 * (s + x[0] * a0);
    J[1] = I[0][1] + h * (cx + x[1] * b[1]) + h2 * x[0] * a1;
    J[2] = I[1][0] - h * (cx + x[0] * b[0]) + h2 * x[1] * a0;
    J[3] = I[1][1] - h * x[0] * b[1] + h2 * (s + x[1] * a1);

    const double sx = fabs(x[0]) + fabs(x[1]) + fabs(w[0]) + fabs(w[1]);
    *scale = (fabs(I[0][0]) + fabs(I[0][1]) + fabs(I[1][0]) + fabs(I[1][1])) * sx +
             h * (fabs(x[1] * cx) + fabs(w[1] * cw) + fabs(x[0] * cx) + fabs(w[0] * cw)) +
             h2 * (fabs(qx[0]) + fabs(qw[0]) + fabs(qx[1]) + fabs(qw[1]));
}

/* (taualg): the multiplier after the rescaling lambda -> -lambda / eps^2. */
static double taualg(const sus_model *m, const double x[2], const double w[2])
{
    const double(*I)[3] = m->I;
    return 0.5 * (x[0] * (I[1][0] * x[0] + I[1][1] * x[1]) +
                  w[0] * (I[1][0] * w[0] + I[1][1] * w[1])) -
           0.5 * (x[1] * (I[0][0] * x[0] + I[0][1] * x[1]) +
                  w[1] * (I[0][0] * w[0] + I[0][1] * w[1]));
}

static const sus_step_equation TAUDYN = {.unknowns = 2,
                                         .residual = taudyn_residual,
                                         .guess = sus_step_predict,
                                         .result = sus_step_result_is_x};

/* Newton inlined with (taudyn) (newton_core.h), as the midpoint step has it: the same operations
 * as sus_step_implicit_solve's, without a call through a pointer for each residual. */
static int variational_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                             double *lambda_next, sus_stepper_stats *st)
{
    const int status = newton_w_step(taudyn_residual, newton_predict, m, eps, w, w_next, st);
    *lambda_next = taualg(m, w_next, w);
    return status;
}

static const sus_step_ops VARIATIONAL_STEP = {.apply = variational_apply};

/* (taudyn) is not a linear one-step map of f: no stability function. */
const sus_stepper_type sus_step_variational_type = {.name = "variational",
                                                    .step = &VARIATIONAL_STEP,
                                                    .equation = &TAUDYN,
                                                    .desc = {.order = 2,
                                                             .lambda_order = -1,
                                                             .implicit = 1,
                                                             .follows_recon = 1,
                                                             .substeps = 1,
                                                             .source = __FILE__}};
const sus_stepper_type *const sus_step_variational = &sus_step_variational_type;
