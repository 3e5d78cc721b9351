#include "composition.h"
#include "dsp.h"
#include "implicit_step.h"

#include "quaternion.h"

#include <math.h>

/* One substep of the base map: the midpoint DSP (Discretization) with step g eps, its step
 * equation solved as the midpoint step solves it; the stats add up the Newton iterations and keep
 * the worst residual, or a failing substep's. No lambda: (LagMult) is read at the substep that ends
 * the step. */
static int substep(const sus_model *m, double h, const double w[3], double x[3],
                   sus_stepper_stats *acc)
{
    sus_stepper_stats st;
    const int status = sus_step_midpoint_solve(m, h, w, x, &st);
    acc->iterations += st.iterations;
    /* the worst residual, or the failing substep's own stats (a failure says where it is) */
    if (status != SUS_STEPPER_OK || !(st.residual <= acc->residual)) { /* also a NaN residual */
        acc->residual = st.residual;
        acc->scale = st.scale;
        acc->det = st.det;
        acc->last_residual = st.last_residual;
    }
    return status;
}

/* The s substeps; with q (the attitude as a quaternion) the reconstruction recon follows every
 * substep, (algo) step 3 over that substep. */
static int run_substeps(const sus_step_composition *c, const sus_model *m, double eps,
                        sus_recon recon, double q[4], const double w[3], double w_next[3],
                        double *lambda_next, sus_stepper_stats *st)
{
    /* Each substep writes its own buffer, the last one w_next, and the next reads it where it lies:
     * no copy of a state just stored (a copy the compiler merges into one wide load of two narrow
     * stores waits for them to retire, most of a substep's time at small steps). */
    double buf[2][3];
    const double *u = w;
    *st = (sus_stepper_stats){0};
    const int s = sus_step_composition_stages(c);
    for (int i = 0; i < s; i++) {
        const double h = sus_step_composition_weight(c, i) * eps;
        double *out = i == s - 1 ? w_next : buf[i % 2];
        const int status = substep(m, h, u, out, st);
        if (status != SUS_STEPPER_OK || i == s - 1) {
            for (int j = 0; out != w_next && j < 3; j++) /* w_next: the failed substep's, as ever */
                w_next[j] = out[j];
            *lambda_next = sus_lagmult(m, w_next); /* (LagMult) at the substep's end */
        }
        if (status != SUS_STEPPER_OK)
            return status;
        if (q)
            sus_reconstruct_quat(recon, h, q, u, out);
        u = out;
    }
    return SUS_STEPPER_OK;
}

int sus_step_composition_apply(const sus_step_composition *c, const sus_model *m, double eps,
                               const double w[3], double w_next[3], double *lambda_next,
                               sus_stepper_stats *st)
{
    return run_substeps(c, m, eps, SUS_RECON_CAYLEY, NULL, w, w_next, lambda_next, st);
}

int sus_step_composition_apply_full(const sus_step_composition *c, const sus_model *m, double eps,
                                    sus_recon recon, sus_attitude *att, const double w[3],
                                    double w_next[3], double *lambda_next, sus_stepper_stats *st)
{
    double q[4];
    /* The attitude goes through the substeps as a quaternion and is written back as R(q/|q|):
     * the 3x3 products would add a rounding to R^T R - I at every substep; this way it is one
     * rounding. */
    sus_quat_of_attitude(att, q);
    const int status = run_substeps(c, m, eps, recon, q, w, w_next, lambda_next, st);
    if (status == SUS_STEPPER_OK)
        sus_quat_to_attitude(q, att);
    return status;
}
