#define _POSIX_C_SOURCE 200809L
#include "bench_longrun.h"

#include "bench_runs.h"
#include "refattitude.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define T_LONG SUS_LAB_BENCH_T_LONG

/* ---- the long run: structure errors at T = 1e4 ---- */

typedef struct {
    const sus_model *m;
    double e0, orth, energy, w3, energy_half;
} lr_acc;

static int lr_emit(void *vctx, const sus_row *row)
{
    lr_acc *a = vctx;
    const double de = fabs(sus_energy(a->m, row->w) - a->e0);
    a->orth = fmax(a->orth, sus_so3_orth_defect(row->R));
    a->energy = fmax(a->energy, de);
    if (row->t <= 0.5 * T_LONG)
        a->energy_half = fmax(a->energy_half, de);
    a->w3 = fmax(a->w3, fabs(row->w[2]));
    return 0;
}

static void long_run_ours(const sus_lab_bench *b, const sus_lab_bench_series *s, int j, lr_acc *a)
{
    const sus_step_method *me = s->me;
    sus_run_report rep;
    if (s->tol_driven) {
        const sus_tol_config tc = {&b->pb.model, me->type, s->param[j], T_LONG, T_LONG / 1000.0, 0};
        sus_run_tol(&tc, b->pb.ex.w0, lr_emit, a, &rep);
        return;
    }
    const double eps = s->param[j];
    const long N = lround(T_LONG / eps);
    const sus_run_config cfg = {&b->pb.model, me->type, s->recon,
                                eps,          N,        N / 1000 > 0 ? N / 1000 : 1};
    sus_run(&cfg, b->pb.ex.w0, lr_emit, a, &rep);
}

/* For (w, q) the attitude is R(q/|q|), orthogonal by construction; ||q| - 1| is its drift,
 * reported in place of |R^T R - I|. */
static void long_run_peer(const sus_lab_bench *b, const sus_lab_bench_series *s, int j, lr_acc *a)
{
    gsl_odeiv2_system sys = {s->dim == 11 ? sus_lab_peer_rhs_wR : sus_lab_peer_rhs_wq, NULL, s->dim,
                             (void *)&b->pb.model};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, s->type, s->hstart, s->param[j], s->param[j]);
    double y[11], t = 0.0;
    sus_lab_peer_initial(s->dim, b->pb.ex.w0, y);
    for (int k = 1; d && k <= 1000; k++) {
        if (gsl_odeiv2_driver_apply(d, &t, T_LONG * k / 1000.0, y) != GSL_SUCCESS)
            break;
        double R[3][3];
        sus_lab_peer_attitude(s->dim, y, R);
        const double nq = sqrt(y[2] * y[2] + y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
        const double w[3] = {y[0], y[1], 0.0};
        a->orth = fmax(a->orth, s->dim == 11 ? sus_so3_orth_defect(R) : fabs(nq - 1.0));
        a->energy = fmax(a->energy, fabs(sus_energy(a->m, w) - a->e0));
    }
    if (d)
        gsl_odeiv2_driver_free(d);
}

static int long_run_wanted(const sus_lab_bench_series *s)
{
    if (s->ours)
        return s->preserves && !s->w_only;
    return s->type == gsl_odeiv2_step_rk8pd && s->api == SUS_LAB_PEER_DRIVER && s->hstart == 1e-3 &&
           s->dim != 2;
}

/* The first point of s whose attitude error is at most 1e-10 (-1 if none). */
static int point_at_1e10(const sus_lab_bench_series *s)
{
    for (int k = 0; k < s->n; k++)
        if (s->err_R[k] <= 1e-10)
            return k;
    return -1;
}

void sus_lab_bench_long_runs(sus_lab_bench *b)
{
    const double E0 = sus_energy(&b->pb.model, b->pb.ex.w0);
    b->LR = sus_lab_bench_calloc((size_t)b->nseries, sizeof *b->LR);
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        const int j = point_at_1e10(s);
        if (j < 0 || !long_run_wanted(s))
            continue;
        sus_lab_bench_longrun *L = &b->LR[b->nlr++];
        snprintf(L->name, sizeof L->name, "%.63s", s->name);
        lr_acc a = {&b->pb.model, E0, 0.0, 0.0, 0.0, 0.0};
        (s->ours ? long_run_ours : long_run_peer)(b, s, j, &a);
        L->orth = a.orth;
        L->energy = a.energy;
        L->w3 = a.w3;
        L->energy_half = a.energy_half;
        L->ours = s->ours;
        L->dim = s->dim;
    }
}

/* ---- at T = 1e4 and equal error: our methods against rk8pd, and the cost to T = 1e6 ---- */

/* ROUNDS interleaved rounds of ours and the peer's (or of the two lengths of one run), the median
 * of each. A run shorter than EQ_BATCH seconds is repeated within its round (the batch's time over
 * its calls), as the work-precision points are: timed alone, a run of microseconds right after a
 * peer's milliseconds starts with the caches and predictors the peer left, and takes several times
 * as long as the same run timed warm. */
#define EQ_ROUNDS 5
#define EQ_BATCH 1e-3

typedef struct {
    void (*fn)(void *);
    void *ctx;
    double t[EQ_ROUNDS];
} timed_run;

/* The median seconds of each of n runs, timed in interleaved rounds of batches, into sec; one
 * untimed call of each first sets its batch. */
static void time_interleaved(timed_run *r, int n, double *sec)
{
    long reps[n];
    for (int i = 0; i < n; i++) {
        const double t0 = sus_lab_bench_now();
        r[i].fn(r[i].ctx);
        const double once = sus_lab_bench_now() - t0;
        reps[i] = once >= EQ_BATCH ? 1 : (long)ceil(EQ_BATCH / fmax(once, 1e-9));
    }
    for (int k = 0; k < EQ_ROUNDS; k++)
        for (int i = 0; i < n; i++) {
            const double t0 = sus_lab_bench_now();
            for (long c = 0; c < reps[i]; c++)
                r[i].fn(r[i].ctx);
            r[i].t[k] = (sus_lab_bench_now() - t0) / (double)reps[i];
        }
    for (int i = 0; i < n; i++) {
        gsl_sort(r[i].t, 1, EQ_ROUNDS);
        sec[i] = gsl_stats_median_from_sorted_data(r[i].t, 1, EQ_ROUNDS);
    }
}

/* The loosest of four tolerances a decade at which rk8pd, on (w, q) through the driver from
 * hstart 1e-3 (reduced 0: the full problem) or on the reduced problem (reduced 1: driver,
 * abs = rel, hstart 1e-2), ends within LONG_LEVEL of R_ref at T_LONG; opened in g, its tolerance
 * and error into *tol and *perr. Returns 0, or -1 (g closed) when none down to 1e-15 does. */
static int rk8pd_matching(const sus_lab_bench *b, int reduced, sus_lab_bench_peer_run *g,
                          double *tol, double *perr)
{
    for (int j = 0; SUS_LAB_BENCH_PEER_TOL(j) >= SUS_LAB_BENCH_PEER_TOL_MIN; j++) {
        *g = (sus_lab_bench_peer_run){.pb = &b->pb, .T = T_LONG};
        *tol = SUS_LAB_BENCH_PEER_TOL(j);
        const int rc = reduced ? sus_lab_peer_open_reduced(&g->p, &b->pb.red, gsl_odeiv2_step_rk8pd,
                                                           SUS_LAB_PEER_DRIVER, *tol, *tol, 1e-2)
                               : sus_lab_peer_open(&g->p, &b->pb.model, gsl_odeiv2_step_rk8pd, 6,
                                                   SUS_LAB_PEER_DRIVER, *tol, *tol, 1e-3);
        if (rc != 0)
            sus_lab_bench_die("GSL allocation failed");
        sus_lab_bench_peer_fn(g);
        double R[3][3];
        sus_lab_peer_attitude(g->p.dim, g->y, R);
        *perr = sus_so3_dist(b->R_long, R);
        if (g->status == GSL_SUCCESS && *perr <= SUS_LAB_BENCH_LONG_LEVEL)
            return 0;
        sus_lab_peer_close(&g->p);
    }
    return -1;
}

/* Explicit methods only: the target is the series methods', and an implicit one needs so many
 * steps to reach the level that its T = 1e4 runs would take most of this phase. */
static int equal_error_wanted(const sus_lab_bench_series *s)
{
    return s->ours && !s->w_only && !s->me->type->desc.implicit &&
           sus_lab_bench_own_attitude(s->me);
}

/* Series s at point j as a run to T (a fixed-step run keeps s's step as nearly as N = T / eps
 * steps allow: eps = T / N, the step the reproduce check gives suslov). */
static void ours_run(const sus_lab_bench *b, const sus_lab_bench_series *s, int j, double T,
                     sus_lab_bench_tol_run *tr, sus_lab_bench_dsp_run *dr, timed_run *r)
{
    if (s->tol_driven) {
        *tr = (sus_lab_bench_tol_run){.pb = &b->pb, .st = s->me->type, .tol = s->param[j], .T = T};
        *r = (timed_run){sus_lab_bench_tol_fn, tr, {0}};
    } else {
        *dr = (sus_lab_bench_dsp_run){&b->pb, s->me->type, s->recon, lround(T / s->param[j]),
                                      T,      {0},         {0},      0.0};
        *r = (timed_run){sus_lab_bench_dsp_fn, dr, {0}};
    }
}

static const double (*ours_R(const sus_lab_bench_series *s, const sus_lab_bench_tol_run *tr,
                             const sus_lab_bench_dsp_run *dr))[3]
{
    return (const double(*)[3])(s->tol_driven ? tr->last.R : dr->last.R);
}

/* The first point of s, in the order of its sweep (towards accuracy), whose run to T_LONG ends
 * within LONG_LEVEL, trying at most MAX_TRIES from the first that reached it at t = 50; its
 * index (-1 when none) and the run's end into e. */
#define MAX_TRIES 12
static int point_at_level(const sus_lab_bench *b, const sus_lab_bench_series *s,
                          sus_lab_bench_equal_error *e)
{
    sus_lab_bench_tol_run tr;
    sus_lab_bench_dsp_run dr;
    timed_run r;
    for (int j = 0, tries = 0; j < s->n && tries < MAX_TRIES; j++) {
        if (!(s->err_R[j] <= SUS_LAB_BENCH_LONG_LEVEL))
            continue;
        tries++;
        ours_run(b, s, j, T_LONG, &tr, &dr, &r);
        r.fn(r.ctx);
        memcpy(e->R_end, ours_R(s, &tr, &dr), sizeof e->R_end);
        e->err = sus_so3_dist(b->R_long, e->R_end);
        if (e->err <= SUS_LAB_BENCH_LONG_LEVEL)
            return j;
    }
    return -1;
}

/* Row e: series i at the point that reaches the level at T_LONG, timed interleaved with the
 * peers (g[k] when have[k]). Returns 0, or -1 when no point of i reaches the level. */
static int equal_error_row(const sus_lab_bench *b, int i, sus_lab_bench_peer_run g[2],
                           const int have[2], sus_lab_bench_equal_error *e)
{
    const sus_lab_bench_series *s = b->S[i];
    const double peer_tol = e->peer_tol, peer_err = e->peer_err, red_tol = e->red_tol,
                 red_err = e->red_err;
    *e = (sus_lab_bench_equal_error){.series = i,
                                     .peer_sec = INFINITY,
                                     .red_sec = INFINITY,
                                     .peer_tol = peer_tol,
                                     .peer_err = peer_err,
                                     .red_tol = red_tol,
                                     .red_err = red_err};
    if ((e->point = point_at_level(b, s, e)) < 0)
        return -1;
    sus_lab_bench_tol_run tr;
    sus_lab_bench_dsp_run dr;
    timed_run r[3];
    double sec[3];
    ours_run(b, s, e->point, T_LONG, &tr, &dr, &r[0]);
    int n = 1;
    for (int k = 0; k < 2; k++)
        if (have[k])
            r[n++] = (timed_run){sus_lab_bench_peer_fn, &g[k], {0}};
    time_interleaved(r, n, sec);
    e->sec = sec[0];
    n = 1;
    for (int k = 0; k < 2; k++)
        if (have[k])
            *(k ? &e->red_sec : &e->peer_sec) = sec[n++];
    return 0;
}

int sus_lab_bench_best_equal_error(const sus_lab_bench *b)
{
    int best = -1;
    for (int k = 0; k < b->neq; k++)
        if (best < 0 || b->EQ[k].peer_sec / b->EQ[k].sec > b->EQ[best].peer_sec / b->EQ[best].sec)
            best = k;
    return best;
}

/* The best row's run to T_GROWTH, timed interleaved with the same run to T_LONG. */
static void growth_run(sus_lab_bench *b)
{
    const int k = sus_lab_bench_best_equal_error(b);
    b->growth = (sus_lab_bench_growth){.series = -1, .point = -1, .eq = k, .sec = NAN};
    if (k < 0)
        return;
    const sus_lab_bench_series *s = b->S[b->EQ[k].series];
    const int j = b->EQ[k].point;
    sus_lab_bench_tol_run tr[2];
    sus_lab_bench_dsp_run dr[2];
    timed_run r[2];
    double sec[2];
    ours_run(b, s, j, T_LONG, &tr[0], &dr[0], &r[0]);
    ours_run(b, s, j, SUS_LAB_BENCH_T_GROWTH, &tr[1], &dr[1], &r[1]);
    time_interleaved(r, 2, sec);
    b->growth.series = b->EQ[k].series;
    b->growth.point = j;
    b->growth.sec = sec[1];
    b->growth.sec_long = sec[0];
    memcpy(b->growth.R_end, ours_R(s, &tr[1], &dr[1]), sizeof b->growth.R_end);
}

double sus_lab_bench_growth_ratio(const sus_lab_bench *b)
{
    return b->growth.series < 0 ? NAN : b->growth.sec / b->growth.sec_long;
}

void sus_lab_bench_equal_error_runs(sus_lab_bench *b)
{
    double w_ref[2];
    sus_refatt_precise(&b->pb.model, b->pb.ex.w0, T_LONG, w_ref, b->R_long);
    b->EQ = sus_lab_bench_calloc((size_t)b->nseries, sizeof *b->EQ);
    b->neq = 0;
    sus_lab_bench_peer_run g[2];
    sus_lab_bench_equal_error peers = {.peer_sec = INFINITY, .red_sec = INFINITY};
    const int have[2] = {rk8pd_matching(b, 0, &g[0], &peers.peer_tol, &peers.peer_err) == 0,
                         rk8pd_matching(b, 1, &g[1], &peers.red_tol, &peers.red_err) == 0};
    for (int i = 0; i < b->nseries; i++) {
        b->EQ[b->neq] = peers;
        if (equal_error_wanted(b->S[i]) && equal_error_row(b, i, g, have, &b->EQ[b->neq]) == 0)
            b->neq++;
    }
    for (int k = 0; k < 2; k++)
        if (have[k])
            sus_lab_peer_close(&g[k].p);
    growth_run(b);
}
