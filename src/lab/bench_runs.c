#include "bench_runs.h"

#include "magnus6.h"

#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

void sus_lab_bench_dsp_fn(void *vctx)
{
    sus_lab_bench_dsp_run *r = vctx;
    const sus_run_config cfg = {&r->pb->model, r->st, r->recon, r->T / (double)r->N, r->N, r->N};
    sus_run(&cfg, r->pb->ex.w0, sus_keep_last, &r->last, &r->rep);
}

/* w and R of a run's last row; 1 when the run succeeded. */
static int last_row_result(const sus_row *last, int ok, double w[2], double R[3][3])
{
    memcpy(w, last->w, 2 * sizeof(double));
    memcpy(R, last->R, 9 * sizeof(double));
    return ok;
}

static int dsp_result(const void *vctx, double w[2], double R[3][3])
{
    const sus_lab_bench_dsp_run *r = vctx;
    return last_row_result(&r->last, r->rep.status == SUS_STEPPER_OK, w, R);
}

void sus_lab_bench_w_fn(void *vctx)
{
    sus_lab_bench_w_run *r = vctx;
    const sus_lab_bench_problem *pb = r->pb;
    double w[3] = {pb->ex.w0[0], pb->ex.w0[1], 0.0}, x[3], lam = 0.0;
    long it = 0;
    sus_stepper_stats stats;
    const double eps = r->T / (double)r->N;
    r->status = SUS_STEPPER_OK;
    for (long k = 0; k < r->N && r->status == SUS_STEPPER_OK; k++) {
        r->status = r->st->step->apply(&pb->model, eps, w, x, &lam, &stats);
        it += stats.iterations;
        w[0] = x[0];
        w[1] = x[1];
    }
    memcpy(r->w, w, sizeof w);
    r->newton = (double)it / (double)r->N;
}

static int w_result(const void *vctx, double w[2], double R[3][3])
{
    const sus_lab_bench_w_run *r = vctx;
    (void)R;
    memcpy(w, r->w, 2 * sizeof(double));
    return r->status == SUS_STEPPER_OK;
}

void sus_lab_bench_tol_fn(void *vctx)
{
    sus_lab_bench_tol_run *r = vctx;
    const sus_tol_config cfg = {&r->pb->model, r->st, r->tol, r->T, r->T, 0}; /* one row: the end */
    r->rc = sus_run_tol(&cfg, r->pb->ex.w0, sus_keep_last, &r->last, &r->rep);
}

static int tol_result(const void *vctx, double w[2], double R[3][3])
{
    const sus_lab_bench_tol_run *r = vctx;
    return last_row_result(&r->last, r->rc == SUS_RUN_OK, w, R);
}

void sus_lab_bench_peer_fn(void *vctx)
{
    sus_lab_bench_peer_run *g = vctx;
    g->status = sus_lab_peer_run(&g->p, g->pb->ex.w0, g->T, g->y, &g->steps);
}

static int peer_result(const void *vctx, double w[2], double R[3][3])
{
    const sus_lab_bench_peer_run *g = vctx;
    /* the reduced problem is given w(t): its w is the closed form's */
    memcpy(w, g->p.dim == 4 ? g->pb->w_T : g->y, 2 * sizeof(double));
    if (g->p.dim != 2)
        sus_lab_peer_attitude(g->p.dim, g->y, R);
    return g->status == GSL_SUCCESS;
}

void sus_lab_bench_magnus6_fn(void *vctx)
{
    sus_lab_bench_magnus6_run *r = vctx;
    sus_lab_magnus6(&r->pb->red, r->T, r->N, r->q);
}

/* w is the closed form's, as for the other peers on the reduced problem. */
static int magnus6_result(const void *vctx, double w[2], double R[3][3])
{
    const sus_lab_bench_magnus6_run *r = vctx;
    memcpy(w, r->pb->w_T, 2 * sizeof(double));
    sus_lab_peer_attitude(4, r->q, R);
    return 1;
}

static void peer_release(void *vctx)
{
    sus_lab_bench_peer_run *g = vctx;
    sus_lab_peer_close(&g->p);
    free(g);
}

const sus_lab_bench_run_ops SUS_LAB_BENCH_DSP_OPS = {sus_lab_bench_dsp_fn, dsp_result, free},
                            SUS_LAB_BENCH_W_OPS = {sus_lab_bench_w_fn, w_result, free},
                            SUS_LAB_BENCH_TOL_OPS = {sus_lab_bench_tol_fn, tol_result, free},
                            SUS_LAB_BENCH_PEER_OPS = {sus_lab_bench_peer_fn, peer_result,
                                                      peer_release},
                            SUS_LAB_BENCH_MAGNUS6_OPS = {sus_lab_bench_magnus6_fn, magnus6_result,
                                                         free};
