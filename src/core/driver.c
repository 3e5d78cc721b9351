#include "driver.h"

#include <math.h>

int suslov_row_finite(const suslov_row *r)
{
    int ok = isfinite(r->t) && isfinite(r->w[0]) && isfinite(r->w[1]) && isfinite(r->w[2])
          && isfinite(r->lambda);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ok = ok && isfinite(r->R[i][j]);
    return ok;
}

int suslov_keep_last(void *ctx, const suslov_row *row)
{
    *(suslov_row *)ctx = *row;
    return 0;
}

/* Every step's blow-up check, without building R: w, lambda and the attitude as stored (a unit
 * quaternion, or the matrix; R(q) of a finite unit q is finite, and lo is finite with hi). */
static int state_finite(const double w[3], double lambda, const suslov_attitude *a)
{
    int ok = isfinite(w[0]) && isfinite(w[1]) && isfinite(w[2]) && isfinite(lambda);
    if (a->r_stale)
        return ok && isfinite(a->q[0]) && isfinite(a->q[1]) && isfinite(a->q[2]) && isfinite(a->q[3]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ok = ok && isfinite(a->hi[i][j]);
    return ok;
}

int suslov_run(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit, void *ctx,
               suslov_run_report *report)
{
    suslov_row row = {.k = 0, .t = 0.0, .w = {w0[0], w0[1], 0.0}};
    suslov_attitude att;
    row.lambda = suslov_lagmult(cfg->model, row.w);
    suslov_attitude_identity(&att);
    suslov_attitude_get(&att, row.R);
    *report = (suslov_run_report){.status = SUSLOV_STEP_OK};
    if (!suslov_row_finite(&row))
        return SUSLOV_RUN_BLOWUP; /* report->step = 0, t = 0 */
    if (emit(ctx, &row))
        return SUSLOV_RUN_STOPPED;
    for (long k = 0; k < cfg->steps; k++) {
        double w_next[3], lambda;
        suslov_step_stats st;
        const int status = suslov_step_full(cfg->stepper, cfg->model, cfg->eps, cfg->recon, &att, row.w,
                                            w_next, &lambda, &st);
        report->newton_iterations += st.iterations;
        if (st.iterations > report->max_iterations)
            report->max_iterations = st.iterations;
        if (status != SUSLOV_STEP_OK) {
            report->status = status;
            report->step = k + 1;
            report->t = (double)(k + 1) * cfg->eps;
            report->stats = st;
            return SUSLOV_RUN_STEP_FAILED;
        }
        row.k = k + 1;
        row.t = (double)(k + 1) * cfg->eps;
        row.w[0] = w_next[0];
        row.w[1] = w_next[1];
        row.w[2] = w_next[2];
        row.lambda = lambda;
        const int emitted = row.k % cfg->every == 0 || row.k == cfg->steps;
        if (emitted) /* R only for the rows written */
            suslov_attitude_get(&att, row.R);
        if (!state_finite(row.w, row.lambda, &att) || (emitted && !suslov_row_finite(&row))) {
            report->step = row.k;
            report->t = row.t;
            report->stats = st;
            return SUSLOV_RUN_BLOWUP;
        }
        if (emitted && emit(ctx, &row))
            return SUSLOV_RUN_STOPPED;
    }
    return SUSLOV_RUN_OK;
}
