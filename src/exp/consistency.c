#include "consistency.h"

#include "driver.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>

void suslov_local_ref_init(suslov_local_ref *ref, const suslov_exact *ex, double tk, double eps)
{
    ref->tk = tk;
    ref->eps = eps;
    suslov_exact_omega(ex, tk, ref->w_k);
    suslov_exact_omega(ex, tk + eps, ref->w_exact);
    ref->w_k[2] = ref->w_exact[2] = 0.0;
    ref->lambda_exact = suslov_lagmult(ex->model, ref->w_exact);
    suslov_refatt_increment(ex, tk, tk + eps, ref->Phi);
}

int suslov_local_errors(const suslov_model *m, const suslov_stepper_type *stepper,
                        const suslov_local_ref *ref, suslov_local_err *err)
{
    double w_next[3], lambda, R_next[3][3];
    const int status = stepper->apply(m, ref->eps, ref->w_k, w_next, &lambda, &err->stats);
    const double d[3] = {ref->w_exact[0] - w_next[0], ref->w_exact[1] - w_next[1],
                         ref->w_exact[2] - w_next[2]};
    err->w = vec3_norm(d);
    err->lambda_signed = ref->lambda_exact - lambda;
    err->lambda = fabs(err->lambda_signed);
    for (int r = 0; r < SUSLOV_RECON_COUNT && status == SUSLOV_STEP_OK; r++) {
        suslov_attitude att;
        suslov_attitude_identity(&att);
        if (stepper->apply_full) { /* the attitude is advanced inside the step (e.g. after every substep) */
            double w_full[3], lambda_full;
            suslov_step_stats st;
            const int sf =
                stepper->apply_full(m, ref->eps, (suslov_recon)r, &att, ref->w_k, w_full, &lambda_full, &st);
            if (sf != SUSLOV_STEP_OK)
                return sf;
        } else { /* (algo) after the w-step already taken */
            suslov_reconstruct((suslov_recon)r, ref->eps, &att, ref->w_k, w_next);
        }
        suslov_attitude_get(&att, R_next);
        err->so3[r] = so3_dist(ref->Phi, R_next);
    }
    return status;
}

int suslov_global_errors(const suslov_exact *ex, const suslov_stepper_type *stepper,
                         suslov_recon recon, double T, long N, const double R_ref[3][3],
                         suslov_global_err *err)
{
    /* every = N: the driver hands over rows 0 and N only */
    const suslov_run_config cfg = {ex->model, stepper, recon, T / (double)N, N, N};
    suslov_row last;
    suslov_run_report report;
    if (suslov_run(&cfg, ex->w0, suslov_keep_last, &last, &report) != 0)
        return 1;
    double w[2];
    suslov_exact_omega(ex, T, w);
    err->w = hypot(last.w[0] - w[0], last.w[1] - w[1]);
    err->lambda = fabs(last.lambda - suslov_lagmult(ex->model, w));
    err->so3 = so3_dist(R_ref, last.R);
    return 0;
}
