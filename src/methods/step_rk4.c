/* Classical Runge-Kutta 4 as a general DSP (Discretization), lambda_{k+1} = lambda(w^{k+1}). */
#include "stability_fn.h"
#include "stepper.h"
#include "dsp.h"

/* (Discretization) with l = I_m times the RK4 increment: classical Runge-Kutta. */
static int rk4_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                     double *lambda_next, sus_stepper_stats *st)
{
    double k1[2], k2[2], k3[2], k4[2], y[2];
    sus_contdyn(m, w, k1);
    y[0] = w[0] + 0.5 * eps * k1[0];
    y[1] = w[1] + 0.5 * eps * k1[1];
    sus_contdyn(m, y, k2);
    y[0] = w[0] + 0.5 * eps * k2[0];
    y[1] = w[1] + 0.5 * eps * k2[1];
    sus_contdyn(m, y, k3);
    y[0] = w[0] + eps * k3[0];
    y[1] = w[1] + eps * k3[1];
    sus_contdyn(m, y, k4);
    const double e6 = eps / 6.0;
    w_next[0] = w[0] + e6 * (k1[0] + 2.0 * (k2[0] + k3[0]) + k4[0]);
    w_next[1] = w[1] + e6 * (k1[1] + 2.0 * (k2[1] + k3[1]) + k4[1]);
    w_next[2] = 0.0;
    *lambda_next = sus_lagmult(m, w_next);
    *st = (sus_stepper_stats){0};
    return SUS_STEPPER_OK;
}

static const sus_step_ops RK4_STEP = {.apply = rk4_apply};

const sus_stepper_type sus_step_rk4_type = {.name = "rk4",
                                            .step = &RK4_STEP,
                                            .desc = {.order = 4,
                                                     .lambda_order = 4,
                                                     .follows_recon = 1,
                                                     .substeps = 1,
                                                     .stability = sus_step_stab_rk4,
                                                     .source = __FILE__}};
const sus_stepper_type *const sus_step_rk4 = &sus_step_rk4_type;
