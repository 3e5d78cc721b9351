/* The driver of Algorithm (algo) for a tolerance-driven stepper (stepper.h, sus_tol_ops): the
 * method chooses each step; the driver asks it for accepted steps up to t_end and writes rows at
 * the requested times from the method's dense output, so the rows do not shorten the steps. */
#include "driver.h"

#include "api_args.h"
#include "exact_run.h"

#include <math.h>

typedef struct {
    const sus_tol_config *cfg;
    const sus_tol_ops *ops;
    sus_tol_work *wk;
    sus_row row; /* the state at the end of the last accepted step */
    sus_attitude att;
    long next_out; /* the next output time is next_out * every_time */
    double h_last; /* the last accepted step */
} tol_run;

/* Whether the steady rotation turns the body by at most the method's max_angle by t_end, its
 * attitude's promise; from the method's own closed form when its workspace holds one. */
static int within_angle(const tol_run *r, const double w0[2])
{
    const double T = r->cfg->t_end;
    const double angle = r->ops->turn_angle ? r->ops->turn_angle(r->wk, T)
                                            : sus_exact_turn_angle(r->cfg->model, w0, T);
    return angle <= r->ops->max_angle;
}

static int fail(tol_run *r, sus_run_report *report, int rc, long step, double t,
                const sus_stepper_stats *st)
{
    report->step = step;
    report->t = t;
    if (st)
        report->stats = *st;
    r->ops->free(r->wk);
    return rc;
}

/* Emits a finite row (R built from att) or reports the blow-up. */
static int emit_row(tol_run *r, sus_row *row, const sus_attitude *att, sus_emit_fn emit, void *ctx,
                    sus_run_report *report)
{
    sus_attitude_get(att, row->R);
    if (!sus_row_finite(row))
        return fail(r, report, SUS_RUN_BLOWUP, row->k, row->t, NULL);
    if (emit(ctx, row)) {
        r->ops->free(r->wk);
        return SUS_RUN_STOPPED;
    }
    return SUS_RUN_OK;
}

/* The rows every_time apart that fall in the step (t0, t] just taken, by dense output; the row at
 * t_end itself is the step's own end, written by the caller. A time within 4u t_end of t_end
 * (u = SUS_U / 2) is t_end: j every_time carries the roundings of every_time and of t_end as
 * given, of the product, and of j once past 2^53, so 3 x 0.7 = 2.0999999999999996 is the final
 * time 2.1, not a second row beside it. */
static int dense_rows(tol_run *r, sus_emit_fn emit, void *ctx, sus_run_report *report)
{
    const double dt = r->cfg->every_time, last = r->cfg->t_end - 2.0 * SUS_U * r->cfg->t_end;
    for (double tj; (tj = (double)r->next_out * dt) <= r->row.t && tj < last; r->next_out++) {
        sus_row d = {.k = r->row.k, .t = tj};
        sus_attitude a = r->att;
        r->ops->dense(r->wk, tj, d.w, &d.lambda, &a);
        const int rc = emit_row(r, &d, &a, emit, ctx, report);
        if (rc != SUS_RUN_OK)
            return rc;
    }
    return SUS_RUN_OK;
}

int sus_run_tol(const sus_tol_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
                sus_run_report *report)
{
    const char *bad = sus_args_tol(cfg, w0, emit, report);
    if (bad)
        return sus_args_refuse(report, bad);
    tol_run r = {
        .cfg = cfg, .ops = cfg->stepper->tol, .row = {.w = {w0[0], w0[1], 0.0}}, .next_out = 1};
    *report = (sus_run_report){.status = SUS_STEPPER_OK};
    r.row.lambda = sus_lagmult(cfg->model, r.row.w);
    sus_attitude_identity(&r.att);
    if (!(r.wk = r.ops->alloc(cfg->model, cfg->tol, w0))) {
        report->status = SUS_STEPPER_NO_MEMORY;
        return SUS_RUN_STEP_FAILED;
    }
    if (!within_angle(&r, w0)) {
        r.ops->free(r.wk);
        return sus_args_refuse(report, "cfg->t_end: the steady rotation turns the body by more "
                                       "than the method's max_angle by then, beyond which its "
                                       "attitude does not keep its promise");
    }
    int rc = emit_row(&r, &r.row, &r.att, emit, ctx, report);
    while (rc == SUS_RUN_OK && r.row.t < cfg->t_end) {
        const double t0 = r.row.t;
        sus_stepper_stats st = {.det = r.h_last};
        /* the budget is spent short of t_end */
        if (cfg->max_steps > 0 && r.row.k >= cfg->max_steps) {
            report->status = SUS_STEPPER_STEP_LIMIT;
            return fail(&r, report, SUS_RUN_STEP_FAILED, r.row.k + 1, t0, &st);
        }
        const int status =
            r.ops->step(r.wk, cfg->t_end, &r.row.t, r.row.w, &r.row.lambda, &r.att, &st);
        report->sus_newton_iterations += st.iterations; /* here: the rejected tries */
        if (st.iterations > report->max_iterations)
            report->max_iterations = st.iterations;
        if (status != SUS_STEPPER_OK) {
            report->status = status;
            return fail(&r, report, SUS_RUN_STEP_FAILED, r.row.k + 1, t0, &st);
        }
        r.row.k++;
        r.h_last = r.row.t - t0;
        if (cfg->every_time > 0.0 && (rc = dense_rows(&r, emit, ctx, report)) != SUS_RUN_OK)
            return rc;
        if (cfg->every_time <= 0.0 || r.row.t >= cfg->t_end)
            rc = emit_row(&r, &r.row, &r.att, emit, ctx, report);
    }
    if (rc == SUS_RUN_OK)
        r.ops->free(r.wk);
    return rc;
}
