#include "exact_run.h"

#include "api_args.h"
#include "refattitude.h"

#include <math.h>

/* Why sus_run_exact refuses its arguments, or NULL. */
static const char *refusal(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit,
                           const sus_run_report *report)
{
    const char *bad = sus_args_run(cfg, w0, emit, report, 0);
    if (bad)
        return bad;
    if (!(sus_exact_turn_angle(cfg->model, w0, (double)cfg->steps * cfg->eps) <=
          SUS_EXACT_MAX_ANGLE))
        return "cfg->steps * cfg->eps: the steady rotation turns the body by more than "
               "SUS_EXACT_MAX_ANGLE = 2^60 radians by then, beyond the reference attitude's stated "
               "accuracy";
    return NULL;
}

double sus_exact_reference_steps(const sus_run_config *cfg, const double w0[2])
{
    const sus_run_report report = {0}; /* only its address is checked */
    if (refusal(cfg, w0, sus_keep_last, &report) != NULL)
        return -1.0;
    const double T = (double)cfg->steps * cfg->eps;
    sus_exact ex;
    sus_refatt ra;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_exact_init(&ex, cfg->model, w0);
    sus_refatt_init(&ra, &ex, 0.0, I3);
    /* the rows k = 0, K, 2K, ... up to the last k with k eps <= min(T, t_s), and the row N */
    const double last = fmin((double)cfg->steps, floor(ra.t_s / cfg->eps));
    const double rows = floor(last / (double)cfg->every) + 1.0 +
                        (last == (double)cfg->steps && cfg->steps % cfg->every != 0);
    return (double)(fminl(T, ra.t_s) / ra.h) + rows;
}

double sus_exact_turn_angle(const sus_model *m, const double w0[2], double T)
{
    if (!sus_model_sealed(m) || !sus_args_finite2(w0) || !(T >= 0.0) || !isfinite(T))
        return -1.0;
    sus_exact ex;
    double w_inf[2];
    sus_exact_init(&ex, m, w0);
    sus_exact_limit(&ex, w_inf);
    return T * hypot(w_inf[0], w_inf[1]);
}

int sus_run_exact(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
                  sus_run_report *report)
{
    const char *bad = refusal(cfg, w0, emit, report);
    if (bad)
        return sus_args_refuse(report, bad);
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_exact ex;
    sus_refatt ra;
    sus_exact_init(&ex, cfg->model, w0);
    sus_refatt_init(&ra, &ex, 0.0, I3);
    *report = (sus_run_report){.status = SUS_STEPPER_OK};
    int rc = SUS_RUN_OK;
    for (long k = 0; rc == SUS_RUN_OK;) {
        sus_row row = {.k = k, .t = (double)k * cfg->eps};
        sus_exact_omega(&ex, row.t, row.w);
        row.w[2] = 0.0;
        row.lambda = sus_lagmult_c(cfg->model, row.w, sus_exact_c(&ex, row.t)); /* exact.h */
        sus_refatt_at(&ra, row.t, row.R);
        if (!sus_row_finite(&row)) {
            report->step = k;
            report->t = row.t;
            rc = SUS_RUN_BLOWUP;
        } else if (emit(ctx, &row)) {
            rc = SUS_RUN_STOPPED;
        }
        if (k == cfg->steps)
            break;
        /* k + every would overflow for N, K near LONG_MAX: compare with what is left. */
        k = cfg->steps - k > cfg->every ? k + cfg->every : cfg->steps;
    }
    return rc;
}
