#include "exact_run.h"

#include "mat3.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>

/* The tail switches on when the rotation angle it neglects is below u = 2^-53, one rounding of
 * R's entries: the reference integration is good to ~1e-17 (refattitude.h), so anything coarser
 * would be the largest error of the exact rows. */
#define EXACT_TAIL_TOL 0x1p-53

/* The time t_s after which replacing w(t) by the steady rotation w* changes R by at most
 * EXACT_TAIL_TOL, and w* itself.
 * With a = sigma s = sigma s0 + k t (exact.h), (cos psi, sin psi) - (0, 1) has norm at most
 * sech a + (1 - tanh a) <= 2 sech a <= 4 e^{-a} for a >= 0, and w = L^{-T} u, |u| = r, so
 * |w(t) - w*| <= 4 |L^{-1}|_F r e^{-a}. Two solutions of R' = R w^ from the same R(t_s)
 * differ by at most the integral of |w - w*| (their propagators are rotations), which is
 * <= 4 |L^{-1}|_F r e^{-a_s} / k. Setting that to the tolerance gives a_s. An equilibrium
 * (ex->fixed) is a steady rotation from t = 0. */
static double steady_time(const suslov_exact *ex, double wstar[3])
{
    suslov_exact_limit(ex, wstar);
    wstar[2] = 0.0;
    if (ex->fixed)
        return 0.0;
    const double linv = sqrt(1.0 / (ex->l11 * ex->l11) + 1.0 / (ex->l22 * ex->l22) +
                             pow(ex->l21 / (ex->l11 * ex->l22), 2));
    const double a_s = log(4.0 * linv * ex->r / (ex->k * EXACT_TAIL_TOL));
    const double t_s = (fmax(a_s, 0.0) - ex->sigma * ex->s0) / ex->k;
    return isfinite(t_s) ? fmax(t_s, 0.0) : INFINITY;
}

int suslov_run_exact(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit,
                     void *ctx, suslov_run_report *report)
{
    suslov_exact ex;
    suslov_refatt ra;
    double I3[3][3], wstar[3], R_s[3][3];
    suslov_exact_init(&ex, cfg->model, w0);
    mat3_identity(I3);
    *report = (suslov_run_report){.status = SUSLOV_STEP_OK};
    const double t_s = steady_time(&ex, wstar);
    int steady = 0; /* R_s = R(t_s) is known */
    suslov_refatt_init(&ra, &ex, 0.0, I3);
    int rc = SUSLOV_RUN_OK;
    for (long k = 0; rc == SUSLOV_RUN_OK;) {
        suslov_row row = {.k = k, .t = (double)k * cfg->eps};
        suslov_exact_omega(&ex, row.t, row.w);
        row.w[2] = 0.0;
        row.lambda = suslov_lagmult(cfg->model, row.w);
        if (row.t <= t_s) {
            suslov_refatt_advance(&ra, row.t, row.R);
        } else { /* R(t) = R(t_s) exp((t - t_s) w*^): closed form, O(1) per row for any t */
            if (!steady)
                suslov_refatt_advance(&ra, t_s, R_s);
            steady = 1;
            double xi[3], E[3][3];
            for (int i = 0; i < 3; i++)
                xi[i] = (row.t - t_s) * wstar[i];
            so3_exp(xi, E);
            mat3_mul(row.R, R_s, E);
        }
        if (!suslov_row_finite(&row)) {
            report->step = k;
            report->t = row.t;
            rc = SUSLOV_RUN_BLOWUP;
        } else if (emit(ctx, &row)) {
            rc = SUSLOV_RUN_STOPPED;
        }
        if (k == cfg->steps)
            break;
        /* k + every would overflow for N, K near LONG_MAX: compare with what is left. */
        k = cfg->steps - k > cfg->every ? k + cfg->every : cfg->steps;
    }
    return rc;
}
