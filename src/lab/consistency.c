#include "consistency.h"

#include "driver.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>

void sus_lab_local_ref_init(sus_lab_local_ref *ref, const sus_exact *ex, double tk, double eps)
{
    ref->tk = tk;
    ref->eps = eps;
    sus_exact_omega(ex, tk, ref->w_k);
    sus_exact_omega(ex, tk + eps, ref->w_exact);
    ref->w_k[2] = ref->w_exact[2] = 0.0;
    ref->lambda_exact = sus_lagmult_c(ex->model, ref->w_exact, sus_exact_c(ex, tk + eps));
    sus_refatt_increment(ex, tk, tk + eps, ref->Phi);
}

int sus_lab_local_errors(const sus_model *m, const sus_stepper_type *stepper,
                         const sus_lab_local_ref *ref, sus_lab_local_err *err)
{
    double w_next[3], lambda, R_next[3][3];
    const int status = stepper->step->apply(m, ref->eps, ref->w_k, w_next, &lambda, &err->stats);
    const double d[3] = {ref->w_exact[0] - w_next[0], ref->w_exact[1] - w_next[1],
                         ref->w_exact[2] - w_next[2]};
    err->w = sus_vec3_norm(d);
    err->lambda_signed = ref->lambda_exact - lambda;
    err->lambda = fabs(err->lambda_signed);
    for (int r = 0; r < SUS_RECON_COUNT && status == SUS_STEPPER_OK; r++) {
        sus_attitude att;
        sus_attitude_identity(&att);
        /* apply_full: the attitude is advanced inside the step (e.g. after every substep) */
        if (stepper->step->apply_full) {
            double w_full[3], lambda_full;
            sus_stepper_stats st;
            const int sf = stepper->step->apply_full(m, ref->eps, (sus_recon)r, &att, ref->w_k,
                                                     w_full, &lambda_full, &st);
            if (sf != SUS_STEPPER_OK)
                return sf;
        } else { /* (algo) after the w-step already taken */
            sus_reconstruct((sus_recon)r, ref->eps, &att, ref->w_k, w_next);
        }
        sus_attitude_get(&att, R_next);
        err->so3[r] = sus_so3_dist(ref->Phi, R_next);
    }
    return status;
}

int sus_lab_global_errors(const sus_exact *ex, const sus_stepper_type *stepper, sus_recon recon,
                          double T, long N, const double R_ref[3][3], sus_lab_global_err *err)
{
    /* every = N: the driver hands over rows 0 and N only */
    const sus_run_config cfg = {ex->model, stepper, recon, T / (double)N, N, N};
    sus_row last;
    sus_run_report report;
    if (sus_run(&cfg, ex->w0, sus_keep_last, &last, &report) != 0)
        return 1;
    double w[2];
    sus_exact_omega(ex, T, w);
    err->w = hypot(last.w[0] - w[0], last.w[1] - w[1]);
    err->lambda = fabs(last.lambda - sus_lagmult_c(ex->model, w, sus_exact_c(ex, T)));
    err->so3 = sus_so3_dist(R_ref, last.R);
    return 0;
}
