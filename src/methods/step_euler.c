/* Explicit Euler as a general DSP (Discretization): l = I_m f(w^k), lambda_{k+1} = lambda(w^{k+1}). */
#include "stability_fn.h"
#include "stepper.h"

/* (Discretization) with l = I_m f(w^k): explicit Euler. */
static int euler_apply(const suslov_model *m, double eps, const double w[3], double w_next[3],
                       double *lambda_next, suslov_step_stats *st)
{
    double f[2];
    suslov_contdyn(m, w, f);
    w_next[0] = w[0] + eps * f[0];
    w_next[1] = w[1] + eps * f[1];
    w_next[2] = 0.0;
    *lambda_next = suslov_lagmult(m, w_next);
    *st = (suslov_step_stats){0};
    return SUSLOV_STEP_OK;
}

const suslov_stepper_type suslov_euler_type = {
    .name = "euler", .order = 1, .lambda_order = 1, .apply = euler_apply,
    .stability = suslov_stab_euler, .follows_recon = 1, .substeps = 1, .source = __FILE__};
const suslov_stepper_type *const suslov_step_euler = &suslov_euler_type;
