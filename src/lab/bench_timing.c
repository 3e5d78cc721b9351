#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"

#include "bench_runs.h"

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <stdio.h>
#include <stdlib.h>

#define T_END SUS_LAB_BENCH_T_END
#define WP_ROUNDS SUS_LAB_BENCH_WP_ROUNDS
#define BATCH_SECONDS SUS_LAB_BENCH_BATCH_SECONDS
#define ROUNDS SUS_LAB_BENCH_ROUNDS
#define COST_STEPS SUS_LAB_BENCH_COST_STEPS

/* ---- the work-precision points ---- */

static void calibrate_batches(sus_lab_bench *b)
{
    for (int p = 0; p < b->npoints; p++) {
        sus_lab_bench_point *pt = &b->points[p];
        const double t0 = sus_lab_bench_now();
        pt->ops->run(pt->ctx);
        const double t1 = sus_lab_bench_now() - t0;
        pt->batch = t1 >= BATCH_SECONDS ? 1 : (int)ceil(BATCH_SECONDS / fmax(t1, 1e-7));
    }
}

static int timed_errors_differ(sus_lab_bench *b)
{
    int bad = 0;
    for (int p = 0; p < b->npoints; p++) {
        sus_lab_bench_series *s = b->points[p].s;
        const int i = b->points[p].i;
        double w[2], R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, ew, eR;
        const int ok = b->points[p].ops->result(b->points[p].ctx, w, R);
        sus_lab_bench_errors(b, s, w, R, &ew, &eR);
        if (ok && ew == s->err_w[i] && (s->w_only || eR == s->err_R[i]))
            continue;
        bad++;
        fprintf(stderr, "bench: %s at %g: timed runs end with errors %g, %g, recorded %g, %g\n",
                s->name, s->param[i], ew, eR, s->err_w[i], s->err_R[i]);
        s->err_w[i] = ok ? fmax(ew, s->err_w[i]) : INFINITY;
        s->err_R[i] = ok ? fmax(eR, s->err_R[i]) : INFINITY;
    }
    return bad;
}

int sus_lab_bench_time_points(sus_lab_bench *b)
{
    calibrate_batches(b);
    for (int r = 0; r < WP_ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "work-precision, round %d of %d (%d points)", r + 1, WP_ROUNDS,
                 b->npoints);
        sus_lab_bench_progress(b, msg);
        for (int p = 0; p < b->npoints; p++) {
            sus_lab_bench_point *pt = &b->points[p];
            const double t0 = sus_lab_bench_now();
            for (int k = 0; k < pt->batch; k++)
                pt->ops->run(pt->ctx);
            pt->t[r] = (sus_lab_bench_now() - t0) / pt->batch;
        }
    }
    const int bad = timed_errors_differ(b);
    for (int p = 0; p < b->npoints; p++) {
        sus_lab_bench_point *pt = &b->points[p];
        sus_lab_bench_series *s = pt->s;
        gsl_sort(pt->t, 1, WP_ROUNDS);
        s->sec[pt->i] = gsl_stats_median_from_sorted_data(pt->t, 1, WP_ROUNDS);
        s->smin[pt->i] = pt->t[0];
        s->smax[pt->i] = pt->t[WP_ROUNDS - 1];
        pt->ops->release(pt->ctx);
    }
    return bad;
}

/* ---- the runs that only the per-step costs time ---- */

/* The whole step (w and attitude) in a bare loop, no driver: what the driver's overhead is
 * measured against. */
static void direct_fn(void *vctx)
{
    sus_lab_bench_dsp_run *r = vctx;
    const sus_lab_bench_problem *pb = r->pb;
    double w[3] = {pb->ex.w0[0], pb->ex.w0[1], 0.0}, x[3], lam = 0.0;
    sus_attitude att;
    sus_stepper_stats stats;
    const double eps = r->T / (double)r->N;
    sus_attitude_identity(&att);
    for (long k = 0; k < r->N; k++) {
        sus_stepper_full(r->st, &pb->model, eps, r->recon, &att, w, x, &lam, &stats);
        w[0] = x[0];
        w[1] = x[1];
    }
    r->sink = w[0] + lam + att.q[0];
}

/* GSL's rk4 on w alone through gsl_odeiv2_driver_apply_fixed_step: the library's cost of a step. */
typedef struct {
    const sus_lab_bench_problem *pb;
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *d;
    long N;
    double h, y[2];
} gsl_fixed_run;

static void gsl_fixed_fn(void *vctx)
{
    gsl_fixed_run *g = vctx;
    double t = 0.0;
    sus_lab_peer_initial(2, g->pb->ex.w0, g->y);
    gsl_odeiv2_driver_reset_hstart(g->d, g->h);
    gsl_odeiv2_driver_apply_fixed_step(g->d, &t, g->h, (unsigned long)g->N, g->y);
}

typedef struct {
    const sus_exact *ex;
    const sus_exact_fast *red;
    long n;
    double acc;
} exact_run;

static void exact_fn(void *vctx)
{
    exact_run *e = vctx;
    double acc = 0.0, w[2];
    for (long i = 0; i < e->n; i++) {
        sus_exact_omega(e->ex, T_END * (double)i / (double)e->n, w);
        acc += w[0];
    }
    e->acc = acc;
}

/* The same with one exponential (exact_fast.h), as the peers on the reduced problem evaluate it. */
static void exact_one_exp_fn(void *vctx)
{
    exact_run *e = vctx;
    double acc = 0.0, w[2];
    for (long i = 0; i < e->n; i++) {
        sus_exact_fast_omega(e->red, T_END * (double)i / (double)e->n, w);
        acc += w[0];
    }
    e->acc = acc;
}

/* A tolerance-driven method's own steps to T_END in a bare loop (its workspace allocated once, as
 * the driver does): no rows, no finiteness checks, no dense output. */
static void tol_bare_fn(void *vctx)
{
    sus_lab_bench_tol_run *r = vctx;
    const sus_lab_bench_problem *pb = r->pb;
    const sus_tol_ops *ops = r->st->tol;
    sus_tol_work *wk = ops->alloc(&pb->model, r->tol, pb->ex.w0);
    double t = 0.0, w[3] = {pb->ex.w0[0], pb->ex.w0[1], 0.0}, lam = 0.0;
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    long k = 0;
    while (wk && t < T_END && ops->step(wk, T_END, &t, w, &lam, &att, &st) == SUS_STEPPER_OK)
        k++;
    if (wk)
        ops->free(wk);
    r->last.k = k;
    r->sink = w[0] + lam + att.q[0];
}

/* ---- per-step costs ---- */

typedef struct {
    void (*fn)(void *);
    void *ctx;
    double t[ROUNDS];
} cost_cfg;

static double min_ns(cost_cfg *c, long steps)
{
    double t = INFINITY;
    for (int r = 0; r < ROUNDS; r++)
        t = fmin(t, c->t[r]);
    return 1e9 * t / (double)steps;
}

static double median_ns(cost_cfg *c, long steps)
{
    gsl_sort(c->t, 1, ROUNDS);
    return 1e9 * gsl_stats_median_from_sorted_data(c->t, 1, ROUNDS) / (double)steps;
}

static void take_costs(const sus_lab_bench *b, cost_cfg *cfg, int n)
{
    for (int r = 0; r < ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "per-step costs, round %d of %d", r + 1, ROUNDS);
        sus_lab_bench_progress(b, msg);
        for (int c = 0; c < n; c++) {
            const double t0 = sus_lab_bench_now();
            cfg[c].fn(cfg[c].ctx);
            cfg[c].t[r] = sus_lab_bench_now() - t0;
        }
    }
}

static void alloc_costs(sus_lab_bench_costs *cost, int nm)
{
    *cost = (sus_lab_bench_costs){.n = nm};
    cost->name = sus_lab_bench_calloc((size_t)nm, sizeof *cost->name);
    for (int m = 0; m < nm; m++)
        snprintf(cost->name[m], sizeof cost->name[m], "%s", sus_step_method_get(m)->type->name);
    cost->ns_raw = sus_lab_bench_calloc((size_t)nm, sizeof(double));
    cost->ns_full = sus_lab_bench_calloc((size_t)nm, sizeof(double));
    cost->ns_direct = sus_lab_bench_calloc((size_t)nm, sizeof(double));
    cost->ns_full_min = sus_lab_bench_calloc((size_t)nm, sizeof(double));
    cost->newton = sus_lab_bench_calloc((size_t)nm, sizeof(double));
}

/* The configurations in cfg (3 nm + 3 of them): the w-steps, the whole steps through the driver,
 * GSL's rk4, the closed form, the whole steps in a bare loop, the closed form with one exp. */
static void cost_configs(const sus_lab_bench *b, cost_cfg *cfg, sus_lab_bench_w_run *raw,
                         sus_lab_bench_dsp_run *rec, gsl_fixed_run *g, exact_run *e)
{
    const int nm = b->cost.n;
    for (int m = 0; m < nm; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        raw[m] = (sus_lab_bench_w_run){&b->pb, me->type, COST_STEPS, T_END, {0}, 0.0, 0};
        rec[m] =
            (sus_lab_bench_dsp_run){&b->pb, me->type, me->recon, COST_STEPS, T_END, {0}, {0}, 0.0};
        cfg[m] = (cost_cfg){sus_lab_bench_w_fn, &raw[m], {0}};
        cfg[nm + m] = (cost_cfg){sus_lab_bench_dsp_fn, &rec[m], {0}};
        cfg[2 * nm + 2 + m] = (cost_cfg){direct_fn, &rec[m], {0}};
    }
    cfg[2 * nm] = (cost_cfg){gsl_fixed_fn, g, {0}};
    cfg[2 * nm + 1] = (cost_cfg){exact_fn, e, {0}};
    cfg[3 * nm + 2] = (cost_cfg){exact_one_exp_fn, e, {0}};
}

void sus_lab_bench_measure_step_costs(sus_lab_bench *b)
{
    const int nm = sus_step_method_count();
    sus_lab_bench_w_run *raw = sus_lab_bench_calloc((size_t)nm, sizeof *raw);
    sus_lab_bench_dsp_run *rec = sus_lab_bench_calloc((size_t)nm, sizeof *rec);
    cost_cfg *cfg = sus_lab_bench_calloc((size_t)(3 * nm + 3), sizeof *cfg);
    sus_lab_bench_costs *cost = &b->cost;
    alloc_costs(cost, nm);
    gsl_fixed_run g = {&b->pb,
                       {sus_lab_peer_rhs_w, NULL, 2, &b->pb.model},
                       NULL,
                       COST_STEPS,
                       T_END / (double)COST_STEPS,
                       {0}};
    if (!(g.d = gsl_odeiv2_driver_alloc_y_new(&g.sys, gsl_odeiv2_step_rk4, g.h, 1e-6, 1e-6)))
        sus_lab_bench_die("GSL allocation failed");
    exact_run e = {&b->pb.ex, &b->pb.red, COST_STEPS, 0.0};
    cost_configs(b, cfg, raw, rec, &g, &e);
    take_costs(b, cfg, 3 * nm + 3);
    gsl_odeiv2_driver_free(g.d);
    for (int m = 0; m < nm; m++) {
        cost->ns_raw[m] = median_ns(&cfg[m], COST_STEPS);
        cost->ns_full[m] = median_ns(&cfg[nm + m], COST_STEPS);
        /* the overhead compares the least-disturbed rounds: under load a median of 11 moves by more
         * than the 10 % it is held to */
        cost->ns_direct[m] = min_ns(&cfg[2 * nm + 2 + m], COST_STEPS);
        cost->ns_full_min[m] = min_ns(&cfg[nm + m], COST_STEPS);
        cost->newton[m] = raw[m].newton;
    }
    cost->ns_gsl_rk4 = median_ns(&cfg[2 * nm], COST_STEPS);
    cost->ns_exact = median_ns(&cfg[2 * nm + 1], COST_STEPS);
    cost->ns_exact_one_exp = median_ns(&cfg[3 * nm + 2], COST_STEPS);
    free(raw);
    free(rec);
    free(cfg);
}

/* ---- per-step cost of a tolerance-driven method: its steps with and without the driver ---- */

/* The fastest of ROUNDS interleaved rounds (each a batch of >= BATCH_SECONDS) of the driver's
 * and the bare loop's runs at point j of series s, per accepted step; the median of the bare
 * rounds goes to the series (the floor), the two minima to the overhead sums. */
static void tol_point_costs(sus_lab_bench *b, sus_lab_bench_series *s, int j)
{
    sus_lab_bench_tol_run r = {.pb = &b->pb, .st = s->me->type, .tol = s->param[j], .T = T_END};
    cost_cfg c[2] = {{sus_lab_bench_tol_fn, &r, {0}}, {tol_bare_fn, &r, {0}}};
    double t0 = sus_lab_bench_now();
    sus_lab_bench_tol_fn(&r);
    const long batch = (long)ceil(BATCH_SECONDS / fmax(sus_lab_bench_now() - t0, 1e-7));
    for (int k = 0; k < ROUNDS; k++)
        for (int q = 0; q < 2; q++) {
            t0 = sus_lab_bench_now();
            for (long i = 0; i < batch; i++)
                c[q].fn(c[q].ctx);
            c[q].t[k] = sus_lab_bench_now() - t0;
        }
    const long steps = batch * r.last.k;
    b->cost.tol_drv_min += min_ns(&c[0], steps);
    b->cost.tol_bare_min += min_ns(&c[1], steps);
    s->step_ns[j] = median_ns(&c[1], steps);
}

void sus_lab_bench_measure_tol_costs(sus_lab_bench *b)
{
    for (int i = 0; i < b->nseries; i++)
        for (int j = 0; b->S[i]->tol_driven && j < b->S[i]->n; j++)
            tol_point_costs(b, b->S[i], j);
}
