#include "driver.h"


int suslov_run(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit, void *ctx,
               suslov_run_report *report)
{
    suslov_row row = {.k = 0, .t = 0.0, .w = {w0[0], w0[1], 0.0}};
    suslov_attitude att;
    row.lambda = suslov_lagmult(cfg->model, row.w);
    suslov_attitude_identity(&att);
    suslov_attitude_get(&att, row.R);
    *report = (suslov_run_report){.status = SUSLOV_STEP_OK};
    if (emit(ctx, &row))
        return -1;
    for (long k = 0; k < cfg->steps; k++) {
        double w_next[3], lambda;
        suslov_step_stats st;
        const int status = cfg->stepper->apply(cfg->model, cfg->eps, row.w, w_next, &lambda, &st);
        report->newton_iterations += st.iterations;
        if (st.iterations > report->max_iterations)
            report->max_iterations = st.iterations;
        if (status != SUSLOV_STEP_OK) {
            report->status = status;
            report->step = k + 1;
            report->t = (double)(k + 1) * cfg->eps;
            report->stats = st;
            return 1;
        }
        suslov_reconstruct(cfg->recon, cfg->eps, &att, row.w, w_next);
        row.k = k + 1;
        row.t = (double)(k + 1) * cfg->eps;
        row.w[0] = w_next[0];
        row.w[1] = w_next[1];
        row.w[2] = w_next[2];
        row.lambda = lambda;
        suslov_attitude_get(&att, row.R);
        if ((row.k % cfg->every == 0 || row.k == cfg->steps) && emit(ctx, &row))
            return -1;
    }
    return 0;
}
