#include "composition.h"

#include "quaternion.h"

#include <math.h>

/* One substep of the base map: the midpoint DSP (Discretization) with step g eps; the stats add
 * up the Newton iterations and keep the worst residual. */
static int substep(const suslov_model *m, double h, const double w[3], double x[3], double *lambda,
                   suslov_step_stats *acc)
{
    suslov_step_stats st;
    const int status = suslov_step_midpoint->apply(m, h, w, x, lambda, &st);
    acc->iterations += st.iterations;
    if (!(st.residual <= acc->residual)) { /* also takes a NaN residual */
        acc->residual = st.residual;
        acc->scale = st.scale;
        acc->det = st.det;
    }
    return status;
}

/* The s substeps; with q (the attitude as a quaternion) the reconstruction recon follows every
 * substep, (algo) step 3 over that substep. */
static int run_substeps(const suslov_composition *c, const suslov_model *m, double eps, suslov_recon recon,
                        double q[4], const double w[3], double w_next[3], double *lambda_next,
                        suslov_step_stats *st)
{
    double u[3] = {w[0], w[1], w[2]};
    *st = (suslov_step_stats){0};
    const int s = suslov_composition_stages(c);
    for (int i = 0; i < s; i++) {
        const double h = suslov_composition_weight(c, i) * eps;
        const int status = substep(m, h, u, w_next, lambda_next, st);
        if (status != SUSLOV_STEP_OK)
            return status;
        if (q)
            suslov_reconstruct_quat(recon, h, q, u, w_next);
        u[0] = w_next[0];
        u[1] = w_next[1];
        u[2] = w_next[2];
    }
    return SUSLOV_STEP_OK;
}

int suslov_composition_apply(const suslov_composition *c, const suslov_model *m, double eps,
                             const double w[3], double w_next[3], double *lambda_next,
                             suslov_step_stats *st)
{
    return run_substeps(c, m, eps, SUSLOV_RECON_CAYLEY, NULL, w, w_next, lambda_next, st);
}

int suslov_composition_apply_full(const suslov_composition *c, const suslov_model *m, double eps,
                                  suslov_recon recon, suslov_attitude *att, const double w[3],
                                  double w_next[3], double *lambda_next, suslov_step_stats *st)
{
    double q[4];
    /* The attitude goes through the substeps as a quaternion and is written back as R(q/|q|):
     * the 3x3 products would add a rounding to R^T R - I at every substep; this way it is one
     * rounding. */
    quat_of_attitude(att, q);
    const int status = run_substeps(c, m, eps, recon, q, w, w_next, lambda_next, st);
    if (status == SUSLOV_STEP_OK)
        quat_to_attitude(q, att);
    return status;
}
