#include "stepper.h"

#include "api_args.h"

#include <math.h>

int sus_stepper_full(const sus_stepper_type *st, const sus_model *m, double eps, sus_recon recon,
                     sus_attitude *att, const double w[3], double w_next[3], double *lambda_next,
                     sus_stepper_stats *stats)
{
    if (!stats)
        return SUS_STEPPER_BAD_ARGUMENT;
    /* Cheap checks only: the driver calls this every step (and checked the model once). */
    if (!st || st->tol || !(st->apply || st->apply_full) || !m || !isfinite(eps) || (int)recon < 0
        || (int)recon >= SUS_RECON_COUNT || !att || !w_next || !lambda_next
        || !sus_args_finite2(w)) {
        *stats = (sus_stepper_stats){.last_residual = NAN};
        return SUS_STEPPER_BAD_ARGUMENT;
    }
    if (st->apply_full)
        return st->apply_full(m, eps, recon, att, w, w_next, lambda_next, stats);
    const int status = st->apply(m, eps, w, w_next, lambda_next, stats);
    if (status == SUS_STEPPER_OK)
        sus_reconstruct(recon, eps, att, w, w_next);
    return status;
}

void sus_predict(const sus_model *m, double eps, const double w[2], double x[2])
{
    double f[2], mid[2];
    if (!x)
        return;
    if (!m || !w) {
        x[0] = x[1] = NAN;
        return;
    }
    sus_contdyn(m, w, f);
    mid[0] = w[0] + 0.5 * eps * f[0];
    mid[1] = w[1] + 0.5 * eps * f[1];
    sus_contdyn(m, mid, f);
    x[0] = w[0] + eps * f[0];
    x[1] = w[1] + eps * f[1];
}

void sus_result_is_x(const sus_model *m, double eps, const double w[2], const double *x,
                        double w_next[2])
{
    (void)m;
    (void)eps;
    (void)w;
    if (!w_next)
        return;
    if (!x) {
        w_next[0] = w_next[1] = NAN;
        return;
    }
    w_next[0] = x[0];
    w_next[1] = x[1];
}
