#include "driver.h"

#include "api_args.h"

#include <math.h>

int sus_row_finite(const sus_row *r)
{
    if (!r)
        return 0;
    int ok = isfinite(r->t) && isfinite(r->w[0]) && isfinite(r->w[1]) && isfinite(r->w[2]) &&
             isfinite(r->lambda);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ok = ok && isfinite(r->R[i][j]);
    return ok;
}

int sus_keep_last(void *ctx, const sus_row *row)
{
    if (!ctx || !row)
        return -1;
    *(sus_row *)ctx = *row;
    return 0;
}

/* Every step's blow-up check, without building R: w, lambda and the attitude as stored (a unit
 * quaternion, or the matrix; R(q) of a finite unit q is finite, and lo is finite with hi). */
static int state_finite(const double w[3], double lambda, const sus_attitude *a)
{
    int ok = isfinite(w[0]) && isfinite(w[1]) && isfinite(w[2]) && isfinite(lambda);
    if (a->r_stale)
        return ok && isfinite(a->q[0]) && isfinite(a->q[1]) && isfinite(a->q[2]) &&
               isfinite(a->q[3]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ok = ok && isfinite(a->hi[i][j]);
    return ok;
}

int sus_run(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
            sus_run_report *report)
{
    const char *bad = sus_args_run(cfg, w0, emit, report, 1);
    if (bad)
        return sus_args_refuse(report, bad);
    sus_row row = {.k = 0, .t = 0.0, .w = {w0[0], w0[1], 0.0}};
    sus_attitude att;
    row.lambda = sus_lagmult(cfg->model, row.w);
    sus_attitude_identity(&att);
    sus_attitude_get(&att, row.R);
    *report = (sus_run_report){.status = SUS_STEPPER_OK};
    if (!sus_row_finite(&row))
        return SUS_RUN_BLOWUP; /* report->step = 0, t = 0 */
    if (emit(ctx, &row))
        return SUS_RUN_STOPPED;
    for (long k = 0; k < cfg->steps; k++) {
        double w_next[3], lambda;
        sus_stepper_stats st;
        const int status = sus_stepper_full(cfg->stepper, cfg->model, cfg->eps, cfg->recon, &att,
                                            row.w, w_next, &lambda, &st);
        report->sus_newton_iterations += st.iterations;
        if (st.iterations > report->max_iterations)
            report->max_iterations = st.iterations;
        if (status != SUS_STEPPER_OK) {
            report->status = status;
            report->step = k + 1;
            report->t = (double)(k + 1) * cfg->eps;
            report->stats = st;
            return SUS_RUN_STEP_FAILED;
        }
        row.k = k + 1;
        row.t = (double)(k + 1) * cfg->eps;
        row.w[0] = w_next[0];
        row.w[1] = w_next[1];
        row.w[2] = w_next[2];
        row.lambda = lambda;
        const int emitted = row.k % cfg->every == 0 || row.k == cfg->steps;
        if (emitted) /* R only for the rows written */
            sus_attitude_get(&att, row.R);
        if (!state_finite(row.w, row.lambda, &att) || (emitted && !sus_row_finite(&row))) {
            report->step = row.k;
            report->t = row.t;
            report->stats = st;
            return SUS_RUN_BLOWUP;
        }
        if (emitted && emit(ctx, &row))
            return SUS_RUN_STOPPED;
    }
    return SUS_RUN_OK;
}
