#include "exact_run.h"

#include "mat3.h"
#include "refattitude.h"

int suslov_run_exact(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit,
                     void *ctx, suslov_run_report *report)
{
    suslov_exact ex;
    suslov_refatt ra;
    double I3[3][3];
    suslov_exact_init(&ex, cfg->model, w0);
    mat3_identity(I3);
    *report = (suslov_run_report){.status = SUSLOV_STEP_OK};
    if (suslov_refatt_init(&ra, &ex, 0.0, I3, SUSLOV_REFATT_TOL) != 0)
        return 1;
    int rc = 0;
    for (long k = 0; k <= cfg->steps && rc == 0;) {
        suslov_row row = {.k = k, .t = (double)k * cfg->eps};
        suslov_exact_omega(&ex, row.t, row.w);
        row.w[2] = 0.0;
        row.lambda = suslov_lagmult(cfg->model, row.w);
        const int status = suslov_refatt_advance(&ra, row.t, row.R);
        if (status != 0) {
            report->status = status;
            report->step = k;
            report->t = row.t;
            rc = status;
        } else if (emit(ctx, &row)) {
            rc = -1;
        }
        if (k == cfg->steps)
            break;
        k = k + cfg->every < cfg->steps ? k + cfg->every : cfg->steps;
    }
    suslov_refatt_free(&ra);
    return rc;
}
