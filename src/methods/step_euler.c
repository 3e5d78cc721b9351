/* Explicit Euler as a general DSP (Discretization): l = I_m f(w^k), lambda_{k+1} = lambda(w^{k+1}).
 */
#include "stability_fn.h"
#include "stepper.h"
#include "dsp.h"

/* (Discretization) with l = I_m f(w^k): explicit Euler. */
static int euler_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                       double *lambda_next, sus_stepper_stats *st)
{
    double f[2];
    sus_contdyn(m, w, f);
    w_next[0] = w[0] + eps * f[0];
    w_next[1] = w[1] + eps * f[1];
    w_next[2] = 0.0;
    *lambda_next = sus_lagmult(m, w_next);
    *st = (sus_stepper_stats){0};
    return SUS_STEPPER_OK;
}

static const sus_step_ops EULER_STEP = {.apply = euler_apply};

const sus_stepper_type sus_step_euler_type = {.name = "euler",
                                              .step = &EULER_STEP,
                                              .desc = {.order = 1,
                                                       .lambda_order = 1,
                                                       .follows_recon = 1,
                                                       .substeps = 1,
                                                       .stability = sus_step_stab_euler,
                                                       .source = __FILE__}};
const sus_stepper_type *const sus_step_euler = &sus_step_euler_type;
