/* make bench: work-precision of every registered method against library integrators, the cost of
 * one step, the long-run structure errors, and the speed targets of the benchmark issues, printed
 * as PASS/MISS lines (never a failing test: the machine is shared and noisy).
 * Usage: bench FIGDIR DATADIR
 *
 * Peers, each given the same problem (the paper's body, w(0) = (0.4, 0.5), t in [0, 50]), at
 * abs = rel tolerance 1e-3 ... 1e-15 (four a decade): GSL odeiv2 rk8pd and rkck through
 * gsl_odeiv2_driver_apply and through a gsl_odeiv2_evolve_apply loop, each from initial step
 * 1e-3, 1e-2, 0.1 and 1; rkf45 and msadams (driver, 1e-3); Boost.Odeint runge_kutta_fehlberg78
 * (make_controlled) and bulirsch_stoer (integrate_adaptive) when built with SUSLOV_WITH_ODEINT
 * (make bench does). Each on three formulations: (w1, w2, R) with R' = R w^ (11 unknowns),
 * (w1, w2, q) with q' = 1/2 q (x) (0, w) and R = R(q/|q|) at the end (6 unknowns), and, for the
 * w accuracies only, (w1, w2) alone (2 unknowns; our Taylor methods get the same choice,
 * "(w only)"). Every run of a configuration starts from the same state, its step size included
 * (src/exp/peers.c), and the error credited to a point is the one its timed runs end with. The
 * "best peer" at an accuracy is the fastest configuration whose timed runs reach it.
 * Errors: |w(50) - w_n| against the closed form, dist(R(50), R_n) (MetMat) against the precise
 * long-double reference sus_refatt_precise (good to ~1e-17, see refattitude.h). */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include "driver.h"
#include "exact.h"
#include "fig_output.h"
#include "mat3.h"
#include "monoclock.h"
#include "peers.h"
#include "plot.h"
#include "quaternion.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"
#include "dsp.h"
#ifdef SUSLOV_WITH_ODEINT
#include "bench_odeint.h"
#endif

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define T_END 50.0
#define T_LONG 1e4
#define MAX_STEPS 2000000L /* caps euler's sweep: 2e6 steps of T/N is ~0.1 s a point */
/* The grids: a user of a fixed-step method picks N, a user of an adaptive peer picks tol. The
 * Taylor methods are swept at every N up to FINE_N (their cost per step is large and their error
 * falls like N^-p, so a factor sqrt 2 in N would skip up to two decades of error), and the peers
 * at four tolerances a decade, 10^(-3 - j/4): both grids are finer than one point per decade of
 * error, and the peers' is never coarser than before (each decade point is still in it). */
#define FINE_N 40
#define TOLS_PER_DECADE 4
#define NLEVELS 6
static const double LEVELS[NLEVELS] = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};

static volatile double sink; /* results are added here so that no run can be optimized away */
static int progress_tty;

static void progress(const char *what)
{
    if (progress_tty) {
        fprintf(stderr, "\rbench: %-60s", what);
        fflush(stderr);
    }
}

/* The bench's tables are sized from the counts (methods, series, points); running out of memory
 * ends the bench. */
static void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (!p) {
        fprintf(stderr, "bench: out of memory\n");
        exit(1);
    }
    return p;
}

static void *xrealloc(void *p, size_t n, size_t size)
{
    p = realloc(p, n * size);
    if (!p) {
        fprintf(stderr, "bench: out of memory\n");
        exit(1);
    }
    return p;
}

/* ---- the problem ---- */

static sus_model model;
static sus_exact ex;
static double w_T[2], R_T[3][3];

/* ---- what a method is, for the bench: one predicate each, so no consumer compares names ---- */

/* The Taylor methods carry their own quaternion attitude (no reconstruction to choose) and have
 * a w-step that does not depend on the attitude series. */
static int own_attitude(const sus_step_method *me) { return !me->type->follows_recon; }

/* Keeps E, w3 = 0 and R in SO(3) by construction, as the method's type says of itself. */
static int keeps_structure(const sus_step_method *me) { return me->type->conserves_energy; }

/* A step made of several implicit substeps: the compositions. */
static int composed(const sus_step_method *me) { return me->type->implicit && me->type->substeps > 1; }

/* ---- our methods through the driver (reconstruction included), as `suslov` runs them ---- */

typedef struct {
    const sus_stepper_type *st;
    sus_recon recon;
    long N;
    double T;
    sus_row last;
    sus_run_report rep;
} dsp_run;

static void dsp_fn(void *vctx)
{
    dsp_run *r = vctx;
    const sus_run_config cfg = {&model, r->st, r->recon, r->T / (double)r->N, r->N, r->N};
    sus_run(&cfg, ex.w0, sus_keep_last, &r->last, &r->rep);
    sink += r->last.w[0];
}

/* w and R of a run's last row; 1 when the run succeeded. */
static int last_row_result(const sus_row *last, int ok, double w[2], double R[3][3])
{
    memcpy(w, last->w, 2 * sizeof(double));
    memcpy(R, last->R, 9 * sizeof(double));
    return ok;
}

static int dsp_result(void *vctx, double w[2], double R[3][3])
{
    const dsp_run *r = vctx;
    return last_row_result(&r->last, r->rep.status == SUS_STEPPER_OK, w, R);
}

/* ---- w alone (no attitude): the driver's w-steps without the reconstruction, for a user who
 * needs only w (the peers get the same choice, 2 unknowns), and the per-step cost ---- */

typedef struct {
    const sus_stepper_type *st;
    long N;
    double T, w[3], newton;
    int status;
} w_run;

static void w_fn(void *vctx)
{
    w_run *r = vctx;
    double w[3] = {ex.w0[0], ex.w0[1], 0.0}, x[3], lam = 0.0;
    long it = 0;
    sus_stepper_stats stats;
    const double eps = r->T / (double)r->N;
    r->status = SUS_STEPPER_OK;
    for (long k = 0; k < r->N && r->status == SUS_STEPPER_OK; k++) {
        r->status = r->st->apply(&model, eps, w, x, &lam, &stats);
        it += stats.iterations;
        w[0] = x[0];
        w[1] = x[1];
    }
    memcpy(r->w, w, sizeof w);
    r->newton = (double)it / (double)r->N;
    sink += w[0] + lam;
}

static int w_result(void *vctx, double w[2], double R[3][3])
{
    const w_run *r = vctx;
    (void)R;
    memcpy(w, r->w, 2 * sizeof(double));
    return r->status == SUS_STEPPER_OK;
}

/* ---- a tolerance-driven method through sus_run_tol, as `suslov --tol` runs it ---- */

typedef struct {
    const sus_stepper_type *st;
    double tol, T;
    sus_row last;
    sus_run_report rep;
    int rc;
} tol_run;

static void tol_fn(void *vctx)
{
    tol_run *r = vctx;
    const sus_tol_config cfg = {&model, r->st, r->tol, r->T, r->T, 0}; /* one row: the end */
    r->rc = sus_run_tol(&cfg, ex.w0, sus_keep_last, &r->last, &r->rep);
    sink += r->last.w[0];
}

static int tol_result(void *vctx, double w[2], double R[3][3])
{
    const tol_run *r = vctx;
    return last_row_result(&r->last, r->rc == SUS_RUN_OK, w, R);
}

/* ---- GSL odeiv2 peers (src/exp/peers.c): (w, R) 11 unknowns, (w, q) 6, w alone 2 ---- */

typedef struct {
    sus_exp_peer p;
    double y[11];
    long steps;
    int status;
} peer_run;

static void peer_fn(void *vctx)
{
    peer_run *g = vctx;
    g->status = sus_exp_peer_run(&g->p, ex.w0, T_END, g->y, &g->steps);
    sink += g->y[0];
}

static void peer_long_fn(void *vctx)
{
    peer_run *g = vctx;
    g->status = sus_exp_peer_run(&g->p, ex.w0, T_LONG, g->y, &g->steps);
    sink += g->y[0];
}

static int peer_result(void *vctx, double w[2], double R[3][3])
{
    const peer_run *g = vctx;
    memcpy(w, g->y, 2 * sizeof(double));
    if (g->p.dim != 2)
        sus_exp_peer_attitude(g->p.dim, g->y, R);
    return g->status == GSL_SUCCESS;
}

#ifdef SUSLOV_WITH_ODEINT
typedef struct {
    suslov_odeint *o;
    size_t dim;
    double T;
    double y[11];
    long steps;
} odeint_run;

static void odeint_fn(void *vctx)
{
    odeint_run *r = vctx;
    sus_exp_peer_initial(r->dim, ex.w0, r->y);
    r->steps = suslov_odeint_run(r->o, r->T, r->y);
    sink += r->y[0];
}

static int odeint_result(void *vctx, double w[2], double R[3][3])
{
    const odeint_run *r = vctx;
    memcpy(w, r->y, 2 * sizeof(double));
    if (r->dim != 2)
        sus_exp_peer_attitude(r->dim, r->y, R);
    return 1;
}
#endif

/* ---- work-precision series ---- */

#define MAXPTS 64 /* per series: the grids below stop well before (about 50 N or tolerances) */

typedef struct {
    char name[96];
    int ours; /* 1: a registered method; 0: a peer */
    int preserves; /* keeps E, w3 = 0 and R in SO(3) by construction */
    int w_only; /* w alone, no attitude: counts for the w accuracies only (err_R = inf) */
    int tol_driven; /* ours, tolerance-driven: param is TOL, steps the accepted steps */
    const char *method;
    sus_recon recon;
    const gsl_odeiv2_step_type *type; /* a GSL peer's stepper and configuration, else NULL */
    size_t dim;
    sus_exp_peer_api api;
    double hstart;
    int n;
    double param[MAXPTS], err_w[MAXPTS], err_R[MAXPTS], sec[MAXPTS], smin[MAXPTS], smax[MAXPTS];
    long steps[MAXPTS];
    double step_ns[MAXPTS]; /* tolerance-driven: the cost of one accepted step in a bare loop */
    double last_run; /* seconds of the last point's first run (untimed rounds: one clock reading) */
} wp_series;

static wp_series **S; /* grown one series at a time: as many as the registry and peers give */
static int nseries;

/* What a series' parameter is: a tolerance (peers, tolerance-driven methods) or a step. */
static const char *param_name(const wp_series *s) { return s->ours && !s->tol_driven ? "eps" : "tol"; }

static wp_series *new_series(void)
{
    S = xrealloc(S, (size_t)(nseries + 1), sizeof *S);
    S[nseries] = xcalloc(1, sizeof **S);
    return S[nseries++];
}

/* Every point of every series is timed in interleaved rounds: a batch of repeats lasting at
 * least BATCH_SECONDS per round, WP_ROUNDS rounds, the median over rounds (with min and max). A
 * burst of load from elsewhere then slows one round of every point alike. */
#define WP_ROUNDS 7
#define BATCH_SECONDS 1e-3

typedef struct {
    void (*fn)(void *);
    int (*result)(void *, double w[2], double R[3][3]); /* the state the last run ended in */
    void *ctx; /* malloc'd by the sweep; owned by the point */
    wp_series *s;
    int i, batch;
    double t[WP_ROUNDS];
} wp_point;

static wp_point *points;
static int npoints;

static void add_point(void (*fn)(void *), int (*result)(void *, double[2], double[3][3]), void *ctx,
                      wp_series *s, int i)
{
    points = xrealloc(points, (size_t)(npoints + 1), sizeof *points);
    points[npoints++] = (wp_point){fn, result, ctx, s, i, 1, {0}};
}

static void errors_of(const wp_series *s, const double w[2], const double R[3][3], double *ew, double *eR)
{
    *ew = hypot(w[0] - w_T[0], w[1] - w_T[1]);
    *eR = s->w_only ? INFINITY : sus_so3_dist(R_T, R);
}

/* Runs ctx once and keeps the point unless the run failed or diverged (an error above 1 says
 * nothing about speed at any accuracy the targets ask for). Returns 1 when kept; otherwise the
 * caller frees ctx. */
static int record(wp_series *s, double param, void (*fn)(void *),
                  int (*result)(void *, double[2], double[3][3]), void *ctx)
{
    double w[2], R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, ew, eR;
    const double t0 = sus_sys_now();
    fn(ctx);
    s->last_run = sus_sys_now() - t0;
    if (s->n >= MAXPTS || !result(ctx, w, R))
        return 0;
    errors_of(s, w, R, &ew, &eR);
    if (!(ew < 1.0 && (s->w_only || eR < 1.0)))
        return 0;
    const int i = s->n++;
    s->param[i] = param;
    s->err_w[i] = ew;
    s->err_R[i] = eR;
    add_point(fn, result, ctx, s, i);
    return 1;
}

/* The N grid of our methods: the Taylor methods at every N from 2 to FINE_N, then by factors
 * ~sqrt 2; the other high-order ones from N = 4 by factors ~sqrt 2, the paper's low-order DSPs
 * from N = 50 by factors of 4. */
static double next_N(double Nd, int fine, int high)
{
    return fine && Nd < FINE_N ? Nd + 1.0 : Nd * (high ? 1.4142135623730951 : 4.0);
}

/* A sweep stops once the errors are below SWEEP_FLOOR, ten times below the finest target level,
 * or once they are below ROUNDOFF_ZONE and 1.4 times as many steps no longer halve them (which
 * any method of order >= 2 does while truncation dominates): more steps then only add round-off
 * (the compositions' floor is above 1e-15). */
#define SWEEP_FLOOR 1e-15
#define ROUNDOFF_ZONE 1e-12

static double worst_err(const wp_series *s, int i)
{
    return fmax(s->err_w[i], s->w_only ? 0.0 : s->err_R[i]);
}

/* One of our runs that takes longer than this is far slower than our fastest and the best peer's
 * runs at every level, so it can be the fastest at no level: our sweep stops there (the slow
 * implicit methods' finest steps cost more bench time than everything else they do). A peer's
 * sweep is never cut this way: a burst of load in that one run could cut away a peer's fastest
 * point. */
#define OURS_SLOW_RUN 1e-2

static int sweep_done(const wp_series *s)
{
    const int i = s->n - 1;
    if (s->ours && s->last_run > OURS_SLOW_RUN)
        return 1;
    const double e = worst_err(s, i);
    if (e < SWEEP_FLOOR)
        return 1;
    if (e > ROUNDOFF_ZONE)
        return 0;
    for (int j = i - 1; j >= 0; j--)
        if ((double)s->steps[j] * 1.4 <= (double)s->steps[i])
            return e > 0.5 * worst_err(s, j);
    return 0;
}

static void sweep_ours(const sus_step_method *me, sus_recon recon)
{
    wp_series *s = new_series();
    snprintf(s->name, sizeof s->name, "%s + %s", me->type->name, SUS_RECON_NAMES[recon]);
    const int fine = own_attitude(me), high = me->type->order > 4;
    if (fine) /* the attitude is its own: no reconstruction */
        snprintf(s->name, sizeof s->name, "%s (quaternion)", me->type->name);
    s->ours = 1;
    s->method = me->type->name;
    s->recon = recon;
    s->preserves = keeps_structure(me);
    long prevN = 0;
    const double N0 = fine ? 2.0 : high ? 4.0 : 50.0;
    for (double Nd = N0; Nd <= (double)MAX_STEPS && s->n < MAXPTS; Nd = next_N(Nd, fine, high)) {
        const long N = lround(Nd);
        if (N == prevN)
            continue;
        prevN = N;
        dsp_run *r = xcalloc(1, sizeof *r);
        *r = (dsp_run){me->type, recon, N, T_END, {0}, {0}};
        if (!record(s, T_END / (double)N, dsp_fn, dsp_result, r)) {
            free(r);
            continue;
        }
        s->steps[s->n - 1] = N;
        if (sweep_done(s))
            break;
    }
}

/* A Taylor method's w alone (its w-step does not depend on the attitude series, so the row's
 * suslov_args reproduce its w error), on the same N grid as sweep_ours. */
static void sweep_ours_w(const sus_step_method *me)
{
    wp_series *s = new_series();
    snprintf(s->name, sizeof s->name, "%s (w only)", me->type->name);
    s->ours = 1;
    s->preserves = 1; /* E and w3 = 0, all there is without an attitude */
    s->w_only = 1;
    s->method = me->type->name;
    s->recon = me->recon;
    long prevN = 0;
    for (double Nd = 2.0; Nd <= (double)MAX_STEPS && s->n < MAXPTS; Nd = next_N(Nd, 1, 1)) {
        const long N = lround(Nd);
        if (N == prevN)
            continue;
        prevN = N;
        w_run *r = xcalloc(1, sizeof *r);
        *r = (w_run){me->type, N, T_END, {0}, 0.0, 0};
        if (!record(s, T_END / (double)N, w_fn, w_result, r)) {
            free(r);
            continue;
        }
        s->steps[s->n - 1] = N;
        if (sweep_done(s))
            break;
    }
}

static const char *dim_name(size_t dim) { return dim == 11 ? "(w,R)" : dim == 6 ? "(w,q)" : "(w)"; }

/* The peers' tolerances: four a decade, 10^(-3 - j/4), down to 1e-15. */
#define PEER_TOL(j) pow(10.0, -3.0 - (double)(j) / TOLS_PER_DECADE)
#define PEER_TOL_MIN 0.99e-15

/* A tolerance-driven method of ours on the peers' TOL grid (each run to T_END through the driver). */
static void sweep_ours_tol(const sus_step_method *me)
{
    wp_series *s = new_series();
    snprintf(s->name, sizeof s->name, "%s (quaternion)", me->type->name);
    s->ours = 1;
    s->tol_driven = 1;
    s->method = me->type->name;
    s->recon = me->recon;
    s->preserves = keeps_structure(me);
    for (int j = 0; s->n < MAXPTS && PEER_TOL(j) >= PEER_TOL_MIN; j++) {
        tol_run *r = xcalloc(1, sizeof *r);
        *r = (tol_run){.st = me->type, .tol = PEER_TOL(j), .T = T_END};
        if (!record(s, PEER_TOL(j), tol_fn, tol_result, r)) {
            free(r);
            continue;
        }
        s->steps[s->n - 1] = r->last.k;
        if (sweep_done(s))
            break;
    }
}

static void sweep_gsl(const gsl_odeiv2_step_type *type, size_t dim, sus_exp_peer_api api, double hstart)
{
    wp_series *s = new_series();
    snprintf(s->name, sizeof s->name, "GSL %s %s %s h0 %g", type->name, dim_name(dim),
             api == SUS_EXP_PEER_DRIVER ? "driver" : "evolve", hstart);
    s->w_only = dim == 2;
    s->type = type;
    s->dim = dim;
    s->api = api;
    s->hstart = hstart;
    for (int j = 0; j < MAXPTS && PEER_TOL(j) >= PEER_TOL_MIN; j++) {
        peer_run *g = xcalloc(1, sizeof *g);
        if (sus_exp_peer_open(&g->p, &model, type, dim, api, PEER_TOL(j), hstart) != 0) {
            fprintf(stderr, "bench: GSL allocation failed\n");
            exit(1);
        }
        if (!record(s, PEER_TOL(j), peer_fn, peer_result, g)) {
            sus_exp_peer_close(&g->p);
            free(g);
            continue;
        }
        s->steps[s->n - 1] = g->steps;
    }
}

#ifdef SUSLOV_WITH_ODEINT
static void sweep_odeint(int stepper, size_t dim)
{
    wp_series *s = new_series();
    snprintf(s->name, sizeof s->name, "Boost %s %s",
             stepper == SUSLOV_ODEINT_RKF78 ? "rkf78" : "bulirsch-stoer", dim_name(dim));
    s->w_only = dim == 2;
    for (int j = 0; j < MAXPTS && PEER_TOL(j) >= PEER_TOL_MIN; j++) {
        odeint_run *r = xcalloc(1, sizeof *r);
        *r = (odeint_run){suslov_odeint_open(stepper, (int)dim, PEER_TOL(j), &model), dim, T_END, {0}, 0};
        if (!r->o) {
            fprintf(stderr, "bench: Boost.Odeint allocation failed\n");
            exit(1);
        }
        if (!record(s, PEER_TOL(j), odeint_fn, odeint_result, r)) {
            suslov_odeint_close(r->o);
            free(r);
            continue;
        }
        s->steps[s->n - 1] = r->steps;
    }
}
#endif

static void calibrate_batches(void)
{
    for (int p = 0; p < npoints; p++) {
        const double t0 = sus_sys_now();
        points[p].fn(points[p].ctx);
        const double t1 = sus_sys_now() - t0;
        points[p].batch = t1 >= BATCH_SECONDS ? 1 : (int)ceil(BATCH_SECONDS / fmax(t1, 1e-7));
    }
}

/* The errors the timed runs ended with, against the ones recorded: the same runs, so equal bit
 * for bit. A point whose timed error differs is counted (the CHECK line) and keeps the larger
 * error, so no configuration is credited with an accuracy its timed runs did not reach. */
static int timed_errors_differ(void)
{
    int bad = 0;
    for (int p = 0; p < npoints; p++) {
        wp_series *s = points[p].s;
        const int i = points[p].i;
        double w[2], R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, ew, eR;
        const int ok = points[p].result(points[p].ctx, w, R);
        errors_of(s, w, R, &ew, &eR);
        if (ok && ew == s->err_w[i] && (s->w_only || eR == s->err_R[i]))
            continue;
        bad++;
        fprintf(stderr, "bench: %s at %g: timed runs end with errors %g, %g, recorded %g, %g\n", s->name,
                s->param[i], ew, eR, s->err_w[i], s->err_R[i]);
        s->err_w[i] = ok ? fmax(ew, s->err_w[i]) : INFINITY;
        s->err_R[i] = ok ? fmax(eR, s->err_R[i]) : INFINITY;
    }
    return bad;
}

static void free_point(wp_point *pt)
{
    if (pt->fn == peer_fn)
        sus_exp_peer_close(&((peer_run *)pt->ctx)->p);
#ifdef SUSLOV_WITH_ODEINT
    if (pt->fn == odeint_fn)
        suslov_odeint_close(((odeint_run *)pt->ctx)->o);
#endif
    free(pt->ctx);
}

/* Returns the number of points whose timed runs' errors differ from the recorded ones. */
static int time_points(void)
{
    calibrate_batches();
    for (int r = 0; r < WP_ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "work-precision, round %d of %d (%d points)", r + 1, WP_ROUNDS, npoints);
        progress(msg);
        for (int p = 0; p < npoints; p++) {
            const double t0 = sus_sys_now();
            for (int b = 0; b < points[p].batch; b++)
                points[p].fn(points[p].ctx);
            points[p].t[r] = (sus_sys_now() - t0) / points[p].batch;
        }
    }
    const int bad = timed_errors_differ();
    for (int p = 0; p < npoints; p++) {
        wp_series *s = points[p].s;
        const int i = points[p].i;
        gsl_sort(points[p].t, 1, WP_ROUNDS);
        s->sec[i] = gsl_stats_median_from_sorted_data(points[p].t, 1, WP_ROUNDS);
        s->smin[i] = points[p].t[0];
        s->smax[i] = points[p].t[WP_ROUNDS - 1];
        free_point(&points[p]);
    }
    return bad;
}

/* The fastest point reaching error <= level among the series selected by want (INFINITY if
 * none); which = 0 for w, 1 for R. */
typedef struct {
    double sec;
    int series, point;
} best_point;

static best_point fastest(double level, int which, int (*want)(const wp_series *))
{
    best_point b = {INFINITY, -1, -1};
    for (int i = 0; i < nseries; i++) {
        if (!want(S[i]))
            continue;
        for (int j = 0; j < S[i]->n; j++) {
            const double e = which ? S[i]->err_R[j] : S[i]->err_w[j];
            if (e <= level && S[i]->sec[j] < b.sec)
                b = (best_point){S[i]->sec[j], i, j};
        }
    }
    return b;
}

static int is_peer(const wp_series *s) { return !s->ours; }
static int is_ours_preserving(const wp_series *s) { return s->ours && s->preserves; }

/* The peers' lower envelope: every peer point that no other peer point beats in both time and
 * error, by increasing time (the staircase drawn as one line). */
typedef struct {
    int n;
    double *sec, *err; /* npoints each at most */
} envelope;

static envelope env[2];

static void build_envelope(int which, envelope *e)
{
    double *sec = xcalloc((size_t)npoints, sizeof *sec), *err = xcalloc((size_t)npoints, sizeof *err);
    size_t *idx = xcalloc((size_t)npoints, sizeof *idx);
    e->sec = xcalloc((size_t)npoints, sizeof *e->sec);
    e->err = xcalloc((size_t)npoints, sizeof *e->err);
    int n = 0;
    for (int i = 0; i < nseries; i++)
        if (!S[i]->ours)
            for (int j = 0; j < S[i]->n; j++) {
                sec[n] = S[i]->sec[j];
                err[n] = which ? S[i]->err_R[j] : S[i]->err_w[j];
                n++;
            }
    gsl_sort_index(idx, sec, 1, (size_t)n);
    e->n = 0;
    double best = INFINITY;
    for (int k = 0; k < n; k++) {
        const size_t p = idx[k];
        if (err[p] < best) {
            best = err[p];
            e->sec[e->n] = sec[p];
            e->err[e->n] = err[p];
            e->n++;
        }
    }
    free(sec);
    free(err);
    free(idx);
}

/* ---- per-step cost, for every registered method ---- */

/* The whole step (w and attitude) in a bare loop, no driver: what the driver's overhead is
 * measured against. */
static void direct_fn(void *vctx)
{
    dsp_run *r = vctx;
    double w[3] = {ex.w0[0], ex.w0[1], 0.0}, x[3], lam = 0.0;
    sus_attitude att;
    sus_stepper_stats stats;
    const double eps = r->T / (double)r->N;
    sus_attitude_identity(&att);
    for (long k = 0; k < r->N; k++) {
        sus_stepper_full(r->st, &model, eps, r->recon, &att, w, x, &lam, &stats);
        w[0] = x[0];
        w[1] = x[1];
    }
    sink += w[0] + lam + att.q[0];
}

/* GSL's rk4 on w alone through gsl_odeiv2_driver_apply_fixed_step: the library's cost of a step. */
typedef struct {
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *d;
    long N;
    double h, y[2];
} gsl_fixed_run;

static void gsl_fixed_fn(void *vctx)
{
    gsl_fixed_run *g = vctx;
    double t = 0.0;
    sus_exp_peer_initial(2, ex.w0, g->y);
    gsl_odeiv2_driver_reset_hstart(g->d, g->h);
    gsl_odeiv2_driver_apply_fixed_step(g->d, &t, g->h, (unsigned long)g->N, g->y);
    sink += g->y[0];
}

typedef struct {
    long n;
} exact_run;

static void exact_fn(void *vctx)
{
    const exact_run *e = vctx;
    double acc = 0.0, w[2];
    for (long i = 0; i < e->n; i++) {
        sus_exact_omega(&ex, T_END * (double)i / (double)e->n, w);
        acc += w[0];
    }
    sink += acc;
}

typedef struct {
    int n;
    /* n each, one per registered method: the w-step, the whole step through the driver and in a
     * bare loop, Newton iterations per step */
    double *ns_raw, *ns_full, *ns_direct, *ns_full_min, *newton, ns_gsl_rk4, ns_exact;
} step_costs;

static step_costs cost;

#define ROUNDS 11
#define COST_STEPS 20000L /* eps = 2.5e-3 */

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

static void take_costs(cost_cfg *cfg, int n)
{
    for (int r = 0; r < ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "per-step costs, round %d of %d", r + 1, ROUNDS);
        progress(msg);
        for (int c = 0; c < n; c++) {
            const double t0 = sus_sys_now();
            cfg[c].fn(cfg[c].ctx);
            cfg[c].t[r] = sus_sys_now() - t0;
        }
    }
}

static void measure_step_costs(void)
{
    const int nm = sus_step_method_count();
    w_run *raw = xcalloc((size_t)nm, sizeof *raw);
    dsp_run *rec = xcalloc((size_t)nm, sizeof *rec);
    cost_cfg *cfg = xcalloc((size_t)(3 * nm + 2), sizeof *cfg); /* raw, driver, GSL, exact, direct */
    cost = (step_costs){.n = nm};
    cost.ns_raw = xcalloc((size_t)nm, sizeof(double));
    cost.ns_full = xcalloc((size_t)nm, sizeof(double));
    cost.ns_direct = xcalloc((size_t)nm, sizeof(double));
    cost.ns_full_min = xcalloc((size_t)nm, sizeof(double));
    cost.newton = xcalloc((size_t)nm, sizeof(double));
    for (int m = 0; m < nm; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        raw[m] = (w_run){me->type, COST_STEPS, T_END, {0}, 0.0, 0};
        rec[m] = (dsp_run){me->type, me->recon, COST_STEPS, T_END, {0}, {0}};
        cfg[m] = (cost_cfg){w_fn, &raw[m], {0}};
        cfg[nm + m] = (cost_cfg){dsp_fn, &rec[m], {0}};
        cfg[2 * nm + 2 + m] = (cost_cfg){direct_fn, &rec[m], {0}};
    }
    gsl_fixed_run g = {
        {sus_exp_peer_rhs_w, NULL, 2, &model}, NULL, COST_STEPS, T_END / (double)COST_STEPS, {0}};
    if (!(g.d = gsl_odeiv2_driver_alloc_y_new(&g.sys, gsl_odeiv2_step_rk4, g.h, 1e-6, 1e-6))) {
        fprintf(stderr, "bench: GSL allocation failed\n");
        exit(1);
    }
    exact_run e = {COST_STEPS};
    cfg[2 * nm] = (cost_cfg){gsl_fixed_fn, &g, {0}};
    cfg[2 * nm + 1] = (cost_cfg){exact_fn, &e, {0}};
    take_costs(cfg, 3 * nm + 2);
    gsl_odeiv2_driver_free(g.d);
    for (int m = 0; m < nm; m++) {
        cost.ns_raw[m] = median_ns(&cfg[m], COST_STEPS);
        cost.ns_full[m] = median_ns(&cfg[nm + m], COST_STEPS);
        /* the overhead compares the least-disturbed rounds: under load a median of 11 moves by more
         * than the 10 % it is held to */
        cost.ns_direct[m] = min_ns(&cfg[2 * nm + 2 + m], COST_STEPS);
        cost.ns_full_min[m] = min_ns(&cfg[nm + m], COST_STEPS);
        cost.newton[m] = raw[m].newton;
    }
    cost.ns_gsl_rk4 = median_ns(&cfg[2 * nm], COST_STEPS);
    cost.ns_exact = median_ns(&cfg[2 * nm + 1], COST_STEPS);
    free(raw);
    free(rec);
    free(cfg);
}

/* ---- per-step cost of a tolerance-driven method: its steps with and without the driver ---- */

/* The method's own steps to T_END in a bare loop (its workspace allocated once, as the driver
 * does): no rows, no finiteness checks, no dense output. */
static void tol_bare_fn(void *vctx)
{
    tol_run *r = vctx;
    const sus_tol_ops *ops = r->st->tol;
    sus_tol_work *wk = ops->alloc(&model, r->tol, ex.w0);
    double t = 0.0, w[3] = {ex.w0[0], ex.w0[1], 0.0}, lam = 0.0;
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    long k = 0;
    while (wk && t < T_END && ops->step(wk, T_END, &t, w, &lam, &att, &st) == SUS_STEPPER_OK)
        k++;
    if (wk)
        ops->free(wk);
    r->last.k = k;
    sink += w[0] + lam + att.q[0];
}

/* The fastest of ROUNDS interleaved rounds (each a batch of >= BATCH_SECONDS) of the driver's
 * and the bare loop's runs at every point of the tolerance-driven series, per accepted step;
 * the median of the bare rounds goes to the series (the floor), the two sums of minima to the
 * overhead line. */
static double tol_drv_min, tol_bare_min;

static void measure_tol_costs(void)
{
    for (int i = 0; i < nseries; i++) {
        wp_series *s = S[i];
        if (!s->tol_driven)
            continue;
        for (int j = 0; j < s->n; j++) {
            tol_run r = {.st = sus_step_method_by_name(s->method)->type, .tol = s->param[j], .T = T_END};
            cost_cfg c[2] = {{tol_fn, &r, {0}}, {tol_bare_fn, &r, {0}}};
            double t0 = sus_sys_now();
            tol_fn(&r);
            const long batch = (long)ceil(BATCH_SECONDS / fmax(sus_sys_now() - t0, 1e-7));
            for (int k = 0; k < ROUNDS; k++)
                for (int q = 0; q < 2; q++) {
                    t0 = sus_sys_now();
                    for (long b = 0; b < batch; b++)
                        c[q].fn(c[q].ctx);
                    c[q].t[k] = sus_sys_now() - t0;
                }
            const long steps = batch * r.last.k;
            tol_drv_min += min_ns(&c[0], steps);
            tol_bare_min += min_ns(&c[1], steps);
            s->step_ns[j] = median_ns(&c[1], steps);
        }
    }
}

/* ---- the long run: structure errors at T = 1e4 ---- */

typedef struct {
    char name[64];
    double orth, energy, w3; /* max over the run of |R^T R - I|, |E - E0|, |w3| */
    int ours;
} longrun_result;

static longrun_result *LR; /* nseries at most */
static int nlr;

typedef struct {
    double e0, orth, energy, w3;
} lr_acc;

static int lr_emit(void *vctx, const sus_row *row)
{
    lr_acc *a = vctx;
    a->orth = fmax(a->orth, sus_so3_orth_defect(row->R));
    a->energy = fmax(a->energy, fabs(sus_energy(&model, row->w) - a->e0));
    a->w3 = fmax(a->w3, fabs(row->w[2]));
    return 0;
}

static void long_run_ours(const wp_series *s, int j, lr_acc *a)
{
    const sus_step_method *me = sus_step_method_by_name(s->method);
    if (s->tol_driven) {
        const sus_tol_config tc = {&model, me->type, s->param[j], T_LONG, T_LONG / 1000.0, 0};
        sus_run_report rep;
        sus_run_tol(&tc, ex.w0, lr_emit, a, &rep);
        return;
    }
    const double eps = s->param[j];
    const long N = lround(T_LONG / eps);
    const sus_run_config cfg = {&model, me->type, s->recon, eps, N, N / 1000 > 0 ? N / 1000 : 1};
    sus_run_report rep;
    sus_run(&cfg, ex.w0, lr_emit, a, &rep);
}

/* For (w, q) the attitude is R(q/|q|), orthogonal by construction; ||q| - 1| is its drift,
 * reported in place of |R^T R - I|. */
static void long_run_peer(const wp_series *s, int j, lr_acc *a)
{
    gsl_odeiv2_system sys = {s->dim == 11 ? sus_exp_peer_rhs_wR : sus_exp_peer_rhs_wq, NULL, s->dim, &model};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, s->type, s->hstart, s->param[j], s->param[j]);
    double y[11], t = 0.0;
    sus_exp_peer_initial(s->dim, ex.w0, y);
    for (int k = 1; d && k <= 1000; k++) {
        if (gsl_odeiv2_driver_apply(d, &t, T_LONG * k / 1000.0, y) != GSL_SUCCESS)
            break;
        double R[3][3];
        sus_exp_peer_attitude(s->dim, y, R);
        const double nq = sqrt(y[2] * y[2] + y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
        const double w[3] = {y[0], y[1], 0.0};
        a->orth = fmax(a->orth, s->dim == 11 ? sus_so3_orth_defect(R) : fabs(nq - 1.0));
        a->energy = fmax(a->energy, fabs(sus_energy(&model, w) - a->e0));
    }
    if (d)
        gsl_odeiv2_driver_free(d);
}

/* The long-run peer: the one the issue measured, rk8pd through the driver from hstart 1e-3, on
 * both attitude formulations. */
static int long_run_wanted(const wp_series *s)
{
    if (s->ours)
        return s->preserves && !s->w_only;
    return s->type == gsl_odeiv2_step_rk8pd && s->api == SUS_EXP_PEER_DRIVER && s->hstart == 1e-3
        && s->dim != 2;
}

/* Our preserving methods at the step that reached attitude 1e-10 at t = 50 (matched accuracy),
 * the peers at the tolerance that did, sampled 1000 times over [0, T_LONG]. */
static void long_runs(void)
{
    const double E0 = sus_energy(&model, ex.w0);
    LR = xcalloc((size_t)nseries, sizeof *LR);
    for (int i = 0; i < nseries; i++) {
        int j = -1;
        for (int k = 0; k < S[i]->n && j < 0; k++)
            if (S[i]->err_R[k] <= 1e-10)
                j = k;
        if (j < 0 || !long_run_wanted(S[i]))
            continue;
        longrun_result *L = &LR[nlr++];
        snprintf(L->name, sizeof L->name, "%.63s", S[i]->name);
        lr_acc a = {E0, 0.0, 0.0, 0.0};
        (S[i]->ours ? long_run_ours : long_run_peer)(S[i], j, &a);
        L->orth = a.orth;
        L->energy = a.energy;
        L->w3 = a.w3;
        L->ours = S[i]->ours;
    }
}

/* ---- at T = 1e4 and equal error: our Taylor methods against rk8pd on (w, q) ---- */

#define EQ_REPEATS 3 /* the minimum over a few runs: each is milliseconds long */

static double min_seconds(void (*fn)(void *), void *ctx)
{
    double best = INFINITY;
    for (int r = 0; r < EQ_REPEATS; r++) {
        const double t0 = sus_sys_now();
        fn(ctx);
        best = fmin(best, sus_sys_now() - t0);
    }
    return best;
}

typedef struct {
    double sec, err, tol;
} long_point;

/* rk8pd (w, q) through the driver from hstart 1e-3: the loosest of four tolerances a decade whose
 * attitude error at T_LONG is at most err (sec = INFINITY when none down to 1e-15 is). */
static long_point rk8pd_matching(double err, const double R_ref[3][3])
{
    for (int j = 0; PEER_TOL(j) >= PEER_TOL_MIN; j++) {
        peer_run g = {0};
        const double tol = PEER_TOL(j);
        if (sus_exp_peer_open(&g.p, &model, gsl_odeiv2_step_rk8pd, 6, SUS_EXP_PEER_DRIVER, tol, 1e-3) != 0)
            break;
        g.status = sus_exp_peer_run(&g.p, ex.w0, T_LONG, g.y, &g.steps);
        double R[3][3];
        sus_exp_peer_attitude(6, g.y, R);
        const double e = sus_so3_dist(R_ref, R);
        long_point lp = {INFINITY, e, PEER_TOL(j)};
        if (g.status == GSL_SUCCESS && e <= err)
            lp.sec = min_seconds(peer_long_fn, &g);
        sus_exp_peer_close(&g.p);
        if (isfinite(lp.sec))
            return lp;
    }
    return (long_point){INFINITY, INFINITY, 0.0};
}

/* Each Taylor method at the step that reached attitude 1e-10 at t = 50, run to T_LONG; the peer
 * at the loosest tolerance that reaches the same error there. */
static void print_equal_error_long(void)
{
    double w_ref[2], R_ref[3][3];
    sus_refatt_precise(&model, ex.w0, T_LONG, w_ref, R_ref);
    for (int i = 0; i < nseries; i++) {
        const wp_series *s = S[i];
        /* explicit methods only: the target is the series methods', and an implicit one needs so
         * many steps to reach 1e-10 that its T = 1e4 runs would take most of this phase */
        const sus_step_method *me = s->ours && !s->w_only ? sus_step_method_by_name(s->method) : NULL;
        if (me && me->type->implicit)
            continue;
        int j = -1;
        for (int k = 0; me && own_attitude(me) && k < s->n && j < 0; k++)
            if (s->err_R[k] <= 1e-10)
                j = k;
        if (j < 0)
            continue;
        double sec, err;
        if (s->tol_driven) {
            tol_run r = {.st = me->type, .tol = s->param[j], .T = T_LONG};
            sec = min_seconds(tol_fn, &r);
            err = sus_so3_dist(R_ref, r.last.R);
        } else {
            dsp_run r = {me->type, s->recon, lround(T_LONG / s->param[j]), T_LONG, {0}, {0}};
            sec = min_seconds(dsp_fn, &r);
            err = sus_so3_dist(R_ref, r.last.R);
        }
        const long_point p = rk8pd_matching(err, R_ref);
        const double ratio = p.sec / sec;
        printf("  %s T = 1e4 at equal error: %s (%s %.4g) %.3g s, error %.2g, vs GSL rk8pd (w,q) tol %.2g "
               "%.3g s, error %.2g: %.2fx (target 3x)\n",
               ratio >= 3.0 ? "PASS" : "MISS", s->name, param_name(s), s->param[j], sec, err, p.tol, p.sec,
               p.err, ratio);
    }
}

/* ---- re-running "ours" rows with build/suslov ---- */

static void args_of(const wp_series *s, int j, char *buf, size_t len)
{
    if (s->tol_driven) {
        snprintf(buf, len, "--method %s --tol %.17g --time %.17g --every-time %.17g", s->method, s->param[j],
                 T_END, T_END);
        return;
    }
    const int n = snprintf(buf, len, "--method %s", s->method);
    if (n < 0 || (size_t)n >= len)
        return;
    if (!own_attitude(sus_step_method_by_name(s->method))) /* else suslov warns that it ignores it */
        snprintf(buf + n, len - (size_t)n, " --reconstruct %s", SUS_RECON_NAMES[s->recon]);
    snprintf(buf + strlen(buf), len - strlen(buf), " --eps %.17g --steps %ld", s->param[j], s->steps[j]);
}

/* Runs `suslov ARGS --every N` and compares the last row's errors with the bench's: the same
 * code path, so they must agree to the digits the CSV carries (%.17g: exactly). */
static int reproduce(const char *suslov, const wp_series *s, int j, double *dw, double *dR)
{
    char args[256], cmd[4096], line[4096], last[4096] = "";
    args_of(s, j, args, sizeof args);
    snprintf(cmd, sizeof cmd, "%.3000s %.255s", suslov, args);
    if (!s->tol_driven) /* one row: the last (a --tol run's comes from --every-time T) */
        snprintf(cmd + strlen(cmd), sizeof cmd - strlen(cmd), " --every %ld", s->steps[j]);
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    while (fgets(line, sizeof line, p))
        memcpy(last, line, sizeof last);
    if (pclose(p) != 0)
        return -1;
    double v[16];
    char *q = last;
    for (int i = 0; i < 16; i++) {
        char *end;
        v[i] = strtod(q, &end);
        if (end == q)
            return -1;
        q = end + (*end == ',');
    }
    const double R[3][3] = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, {v[13], v[14], v[15]}};
    *dw = fabs(hypot(v[2] - w_T[0], v[3] - w_T[1]) - s->err_w[j]);
    *dR = s->w_only ? 0.0 : fabs(sus_so3_dist(R_T, R) - s->err_R[j]);
    return 0;
}

/* ---- figures ---- */

static void series_colour(int i, double rgb[3])
{
    /* ours: hues around the wheel; peers: greys */
    if (!S[i]->ours) {
        rgb[0] = rgb[1] = rgb[2] = 0.62;
        return;
    }
    int k = 0, n = 0;
    for (int j = 0; j < nseries; j++)
        if (S[j]->ours) {
            if (j == i)
                k = n;
            n++;
        }
    const double h = 6.0 * (double)k / (double)n, x = 1.0 - fabs(fmod(h, 2.0) - 1.0), v = 0.85;
    const int sector = (int)h;
    double r = 0, g = 0, b = 0;
    switch (sector) {
    case 0:
        r = 1;
        g = x;
        break;
    case 1:
        r = x;
        g = 1;
        break;
    case 2:
        g = 1;
        b = x;
        break;
    case 3:
        g = x;
        b = 1;
        break;
    case 4:
        r = x;
        b = 1;
        break;
    default:
        r = 1;
        b = x;
        break;
    }
    rgb[0] = v * r;
    rgb[1] = v * g * 0.85;
    rgb[2] = v * b;
}

/* Portrait: at the page's figure scale the text prints at 7 pt and the width fits the text block. */
#define WP_W 530.0
#define WP_PANEL_H 230.0
#define WP_LEGEND_Y (28.0 + WP_PANEL_H + 30.0)

static void draw_wp(cairo_t *cr, void *vctx)
{
    (void)vctx;
    static const int mk[6] = {SUS_PLOT_CIRCLE,  SUS_PLOT_SQUARE, SUS_PLOT_TRIANGLE,
                              SUS_PLOT_DIAMOND, SUS_PLOT_CROSS,  SUS_PLOT_DOT};
    sus_plot_style *st = xcalloc((size_t)nseries, sizeof *st), *ours = xcalloc((size_t)nseries, sizeof *ours);
    double(*rgb)[3] = xcalloc((size_t)nseries, sizeof *rgb);
    for (int p = 0; p < 2; p++) {
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (int i = 0; i < nseries; i++) {
            if (p && S[i]->w_only)
                continue; /* no attitude */
            sus_plot_extend(&x0, &x1, S[i]->sec, (size_t)S[i]->n, 1, 1);
            sus_plot_extend(&y0, &y1, p ? S[i]->err_R : S[i]->err_w, (size_t)S[i]->n, 1, 1);
        }
        sus_plot_axes ax;
        sus_plot_axes_init(&ax, cr, 58 + p * (WP_W / 2), 28, WP_W / 2 - 75, WP_PANEL_H, x0, x1,
                           fmax(y0, 1e-17), fmin(y1, 1.0), 1, 1);
        sus_plot_pad(&ax.x0, &ax.x1, 1);
        sus_plot_pad(&ax.y0, &ax.y1, 1);
        sus_plot_frame(&ax, "seconds per run",
                   p ? "attitude error dist(R(50), R\xe2\x82\x99)"
                     : "|\xcf\x89(50) \xe2\x88\x92 \xcf\x89\xe2\x82\x99|",
                   p ? "(b)" : "(a)");
        int k = 0;
        for (int i = 0; i < nseries; i++) { /* peers first, underneath */
            series_colour(i, rgb[i]);
            st[i] =
                sus_plot_style_of(rgb[i], S[i]->ours ? 1.1 : 0.5, 0, S[i]->ours ? mk[k++ % 6] : SUS_PLOT_DOT,
                                  S[i]->ours ? 3.5 : 2.0, S[i]->ours ? S[i]->name : NULL);
        }
        for (int pass = 0; pass < 2; pass++)
            for (int i = 0; i < nseries; i++)
                if (S[i]->ours == pass && !(p && S[i]->w_only)) {
                    sus_plot_series(&ax, S[i]->sec, p ? S[i]->err_R : S[i]->err_w, (size_t)S[i]->n, 1,
                                    &st[i]);
                    sus_plot_markers(&ax, S[i]->sec, p ? S[i]->err_R : S[i]->err_w, (size_t)S[i]->n, 1,
                                     &st[i]);
                }
        const sus_plot_style es = sus_plot_style_of(SUS_PLOT_BLACK, 2.2, 0, SUS_PLOT_NONE, 0, NULL);
        sus_plot_series(&ax, env[p].sec, env[p].err, (size_t)env[p].n, 1, &es);
        for (int l = 0; l < NLEVELS; l++) { /* the target accuracies */
            const double yy[2] = {LEVELS[l], LEVELS[l]}, xx[2] = {ax.x0, ax.x1};
            const sus_plot_style ls = sus_plot_style_of(SUS_PLOT_GREY, 0.3, 2, SUS_PLOT_NONE, 0, NULL);
            sus_plot_series(&ax, xx, yy, 2, 1, &ls);
        }
    }
    /* legend: ours in two columns below the panels; what the peers were given is in the caption
     * (paper/methods.tex), not a box of text in the figure */
    int nours = 0;
    for (int i = 0; i < nseries; i++)
        if (S[i]->ours)
            ours[nours++] = st[i];
    sus_plot_legend_columns(cr, 12, WP_LEGEND_Y, WP_W - 8, ours, nours);
    free(st);
    free(ours);
    free(rgb);
}

static void draw_cost(cairo_t *cr, void *vctx)
{
    (void)vctx;
    const int nb = cost.n + 2;
    const double W = 90.0 + 46.0 * nb, H = 280;
    sus_plot_text(cr, W / 2, 14, "Cost of one step (median ns; lower is better)", 11, 0.5, 0.5, 1);
    double *v1 = xcalloc((size_t)nb, sizeof *v1), *v2 = xcalloc((size_t)nb, sizeof *v2);
    for (int m = 0; m < cost.n; m++) {
        v1[m] = cost.ns_raw[m];
        v2[m] = cost.ns_full[m];
    }
    v1[cost.n] = v2[cost.n] = cost.ns_gsl_rk4;
    v1[cost.n + 1] = v2[cost.n + 1] = cost.ns_exact;
    double hi = 0.0;
    for (int i = 0; i < nb; i++)
        hi = fmax(hi, fmax(v1[i], v2[i]));
    sus_plot_axes ax;
    sus_plot_axes_init(&ax, cr, 60, 40, W - 80, H - 100, 0.0, nb, 1.0, hi * 1.5, 0, 1);
    sus_plot_pad(&ax.y0, &ax.y1, 1);
    ax.no_xticks = 1;
    sus_plot_frame(&ax, NULL, "ns per step", NULL);
    const double bw = ax.w / nb;
    for (int i = 0; i < nb; i++) {
        const double bx = ax.x + i * bw;
        const double ly0 = log10(ax.y0), span = log10(ax.y1) - ly0;
        const double h1 = (log10(v1[i]) - ly0) / span * ax.h, h2 = (log10(v2[i]) - ly0) / span * ax.h;
        cairo_set_source_rgb(cr, 0.55, 0.70, 0.90);
        cairo_rectangle(cr, bx + 0.12 * bw, ax.y + ax.h - h1, 0.36 * bw, h1);
        cairo_fill(cr);
        if (i < cost.n) {
            cairo_set_source_rgb(cr, 0.15, 0.35, 0.75);
            cairo_rectangle(cr, bx + 0.52 * bw, ax.y + ax.h - h2, 0.36 * bw, h2);
            cairo_fill(cr);
        }
        const char *name = i < cost.n ? sus_step_method_get(i)->type->name
            : i == cost.n             ? "GSL rk4"
                                      : "exact \xcf\x89(t)";
        cairo_save(cr);
        cairo_translate(cr, bx + 0.5 * bw, ax.y + ax.h + 5);
        cairo_rotate(cr, 0.7853981633974483); /* 45 degrees */
        cairo_set_source_rgb(cr, 0, 0, 0);
        sus_plot_text(cr, 0, 0, name, 8.0, 0.0, 0.5, 0);
        cairo_restore(cr);
        char lab[32];
        snprintf(lab, sizeof lab, "%.0f", i < cost.n ? v2[i] : v1[i]);
        sus_plot_text(cr, bx + 0.5 * bw, ax.y + ax.h - fmax(h1, h2) - 8, lab, 7.0, 0.5, 0.0, 0);
    }
    const sus_plot_style leg[2] = {
        sus_plot_style_of((const double[3]){0.55, 0.70, 0.90}, 6.0, 0, SUS_PLOT_NONE, 0, "w-step only"),
        sus_plot_style_of((const double[3]){0.15, 0.35, 0.75}, 6.0, 0, SUS_PLOT_NONE, 0,
                      "whole step (w, R), default reconstruction")};
    sus_plot_legend(&ax, leg, 2, 0);
    free(v1);
    free(v2);
}

/* ---- output ---- */

static int write_csv(const char *path)
{
    char err[256], args[256];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    /* the method field is quoted: peer names such as "GSL rk8pd (w,q)" hold a comma */
    fprintf(
        af.fp,
        "section,method,kind,preserves,parameter,steps,omega_error,attitude_error,seconds_median,seconds_min,"
        "seconds_max,ns_per_step,newton_per_step,suslov_args\n");
    for (int i = 0; i < nseries; i++)
        for (int j = 0; j < S[i]->n; j++) {
            args[0] = '\0';
            if (S[i]->ours)
                args_of(S[i], j, args, sizeof args);
            char eR[32] = ""; /* empty for a w-only row: no attitude */
            if (!S[i]->w_only)
                snprintf(eR, sizeof eR, "%.6g", S[i]->err_R[j]);
            fprintf(af.fp, "work,\"%s\",%s,%s,%.17g,%ld,%.6g,%s,%.6g,%.6g,%.6g,,,%s\n", S[i]->name,
                    S[i]->ours ? "ours" : "peer", S[i]->preserves ? "yes" : "no", S[i]->param[j],
                    S[i]->steps[j], S[i]->err_w[j], eR, S[i]->sec[j], S[i]->smin[j], S[i]->smax[j], args);
        }
    for (int m = 0; m < cost.n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        fprintf(af.fp, "step,%s,ours,,,,,,,,,%.4g,%.3g,\n", me->type->name, cost.ns_raw[m], cost.newton[m]);
        fprintf(af.fp, "step,%s+%s,ours,,,,,,,,,%.4g,%.3g,\n", me->type->name, SUS_RECON_NAMES[me->recon],
                cost.ns_full[m], cost.newton[m]);
    }
    fprintf(af.fp, "step,gsl-rk4-driver,peer,,,,,,,,,%.4g,,\n", cost.ns_gsl_rk4);
    fprintf(af.fp, "step,exact-omega,,,,,,,,,,%.4g,,\n", cost.ns_exact);
    for (int i = 0; i < nlr; i++)
        fprintf(af.fp, "longrun,\"%s\",%s,,%g,,%.3g,%.3g,,,,,,\n", LR[i].name,
                strncmp(LR[i].name, "GSL", 3) ? "ours" : "peer", T_LONG, LR[i].energy, LR[i].orth);
    return sus_sys_atomic_file_commit(&af, err, sizeof err);
}

/* ---- the steps of main ---- */

static int set_up_problem(void)
{
    char err[256];
    if (sus_model_init(&model, SUS_PAPER_INERTIA, err, sizeof err) != 0) {
        fprintf(stderr, "bench: the paper's inertia is rejected: %s\n", err);
        return -1;
    }
    sus_exact_init(&ex, &model, SUS_PAPER_OMEGA0);
    sus_exact_omega(&ex, T_END, w_T);
    double w_ref[2];
    sus_refatt_precise(&model, ex.w0, T_END, w_ref, R_T);
    return 0;
}

static void sweep_all(void)
{
    progress("sweeping");
    for (int m = 0; m < sus_step_method_count(); m++) {
        const sus_step_method *me = sus_step_method_get(m);
        sweep_ours(me, me->recon);
        if (own_attitude(me))
            sweep_ours_w(me);
        /* the symmetric Cayley reconstruction beside the default one, where it differs */
        else if (me->type->order >= 2 && me->recon != SUS_RECON_CAYLEY_MID)
            sweep_ours(me, SUS_RECON_CAYLEY_MID);
    }
    for (int m = sus_step_method_count(); m < sus_step_method_count_all(); m++)
        sweep_ours_tol(sus_step_method_get(m));
    /* the two the issue found fastest, in every configuration a user might pick */
    const gsl_odeiv2_step_type *tuned[2] = {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkck};
    const double hstarts[4] = {1e-3, 1e-2, 0.1, 1.0};
    const size_t dims[3] = {11, 6, 2};
    for (int d = 0; d < 3; d++) {
        for (int k = 0; k < 2; k++)
            for (int api = 0; api < 2; api++)
                for (int h = 0; h < 4; h++)
                    sweep_gsl(tuned[k], dims[d], (sus_exp_peer_api)api, hstarts[h]);
        sweep_gsl(gsl_odeiv2_step_rkf45, dims[d], SUS_EXP_PEER_DRIVER, 1e-3);
        sweep_gsl(gsl_odeiv2_step_msadams, dims[d], SUS_EXP_PEER_DRIVER, 1e-3);
#ifdef SUSLOV_WITH_ODEINT
        for (int k = 0; k < 2; k++)
            sweep_odeint(k, dims[d]);
#endif
    }
}

static void print_costs(void)
{
    printf("Per-step cost (ns, median of %d interleaved rounds of %ld steps; eps = %g):\n", ROUNDS,
           COST_STEPS, T_END / (double)COST_STEPS);
    const int irk4 = sus_step_method_index_of(sus_step_rk4);
    printf("  %-12s %10s %18s %12s %12s\n", "method", "w-step", "whole step (recon)", "Newton/step",
           "x our rk4");
    for (int m = 0; m < cost.n; m++)
        printf("  %-12s %10.1f %10.1f %-7s %12.2f %12.2f\n", sus_step_method_get(m)->type->name,
               cost.ns_raw[m], cost.ns_full[m], SUS_RECON_NAMES[sus_step_method_get(m)->recon],
               cost.newton[m], cost.ns_raw[m] / cost.ns_raw[irk4]);
    printf("  %-12s %10.1f\n", "GSL rk4", cost.ns_gsl_rk4);
    printf("  %-12s %10.1f   (one closed-form w(t): the floor)\n\n", "exact w(t)", cost.ns_exact);
}

/* The per-step targets; returns 1 when every implicit step passes. */
static int print_step_targets(double *speedup)
{
    const int irk4 = sus_step_method_index_of(sus_step_rk4);
    *speedup = cost.ns_gsl_rk4 / cost.ns_raw[irk4];
    printf(
        "  %s our rk4 step is >= 5x faster than GSL rk4 through gsl_odeiv2_driver_apply_fixed_step: %.1fx\n",
        *speedup >= 5 ? "PASS" : "MISS", *speedup);
    int implicit_pass = 1;
    for (int m = 0; m < cost.n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        if (!me->type->implicit || composed(me))
            continue;
        const double r = cost.ns_raw[m] / cost.ns_raw[irk4];
        implicit_pass &= r <= 3;
        printf("  %s an implicit %s step costs <= 3x our rk4 step: %.2fx (%.2f Newton iterations per step)\n",
               r <= 3 ? "PASS" : "MISS", me->type->name, r, cost.newton[m]);
    }
    for (int m = 0; m < cost.n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        if (!own_attitude(me))
            continue;
        const double over = cost.ns_full_min[m] / cost.ns_direct[m] - 1.0;
        printf("  %s the driver adds <= 10 %% to a %s step (%.1f ns in a bare loop, fastest rounds): "
               "%+.1f %%\n",
               over <= 0.10 ? "PASS" : "MISS", me->type->name, cost.ns_direct[m], 100.0 * over);
    }
    if (tol_bare_min > 0.0) {
        const double over = tol_drv_min / tol_bare_min - 1.0;
        printf("  %s the driver (sus_run_tol, one row) adds <= 10 %% to a tolerance-driven run to t = 50, "
               "summed over its TOL grid (fastest rounds): %+.1f %%\n",
               over <= 0.10 ? "PASS" : "MISS", 100.0 * over);
    }
    return implicit_pass;
}

/* The speed-up each level asks for over the best honest peer (issue 21): the 1e-4 target sits
 * below the measured floor of any Taylor design there (fewest steps x cost per step). */
static const double LEVEL_TARGET[NLEVELS] = {1.3, 2.2, 2.2, 3.0, 3.7, 4.5};

/* The floor at a level: the fewest steps any of our explicit structure-preserving methods needs to
 * reach it, times that method's measured cost per step (implicit steps are left out: their Newton
 * iterations, hence their cost, depend on the step); a tolerance-driven method's steps at a TOL
 * cost what its bare loop measured at that TOL. INFINITY when none reaches it. */
static double floor_seconds(double level, int which)
{
    double best = INFINITY;
    for (int i = 0; i < nseries; i++) {
        const wp_series *s = S[i];
        const sus_step_method *me = s->ours && s->preserves ? sus_step_method_by_name(s->method) : NULL;
        if (!me || me->type->implicit || (which && s->w_only))
            continue;
        const int m = s->tol_driven ? -1 : sus_step_method_index(s->method);
        for (int j = 0; j < s->n; j++) {
            const double ns = m < 0 ? s->step_ns[j] : s->w_only ? cost.ns_raw[m] : cost.ns_full[m];
            if ((which ? s->err_R[j] : s->err_w[j]) <= level)
                best = fmin(best, (double)s->steps[j] * 1e-9 * ns);
        }
    }
    return best;
}

static void print_level(int which, int l, int *pass, double *ratio)
{
    const best_point o = fastest(LEVELS[l], which, is_ours_preserving),
                     p = fastest(LEVELS[l], which, is_peer);
    const char *what = which ? "attitude" : "w";
    *pass = 0;
    *ratio = 0.0;
    if (o.series < 0) {
        printf("  MISS %s accuracy %.0e at t = 50: none of our structure-preserving methods reaches it\n",
               what, LEVELS[l]);
        return;
    }
    const wp_series *os = S[o.series];
    const double fl = floor_seconds(LEVELS[l], which);
    if (isinf(fl))
        printf("  MISS %s accuracy %.0e: no floor (none of our explicit methods reaches it)\n", what,
               LEVELS[l]);
    else
        printf("  %s %s accuracy %.0e: our best %.3g s is within 1.15x of the floor %.3g s (fewest steps x "
               "cost per step): %.2fx\n",
               o.sec <= 1.15 * fl ? "PASS" : "MISS", what, LEVELS[l], o.sec, fl, o.sec / fl);
    if (p.series < 0) {
        printf("  PASS %s accuracy %.0e at t = 50: ours %.3g s (%s, %s %.4g); no peer configuration reaches "
               "it\n",
               what, LEVELS[l], o.sec, os->name, param_name(os), os->param[o.point]);
        *pass = 1;
        *ratio = INFINITY;
        return;
    }
    *ratio = p.sec / o.sec;
    *pass = *ratio >= LEVEL_TARGET[l];
    printf(
        "  %s %s accuracy %.0e at t = 50: ours %.3g s (%s, %s %.4g) vs best peer %.3g s (%s, tol %.2g, its "
        "timed runs' error %.2g): %.2fx (target %gx)\n",
        *pass ? "PASS" : "MISS", what, LEVELS[l], o.sec, os->name, param_name(os), os->param[o.point], p.sec,
        S[p.series]->name, S[p.series]->param[p.point],
        which ? S[p.series]->err_R[p.point] : S[p.series]->err_w[p.point], *ratio, LEVEL_TARGET[l]);
}

static void print_long_runs(void)
{
    for (int i = 0; i < nlr; i++) {
        if (LR[i].ours) {
            const int ok = LR[i].orth <= 1e-13 && LR[i].energy <= 1e-13 && LR[i].w3 == 0.0;
            printf("  %s T = 1e4, %s: |R^T R - I| = %.2g, |E - E0| = %.2g, |w3| = %.2g (targets 1e-13, "
                   "1e-13, 0)\n",
                   ok ? "PASS" : "MISS", LR[i].name, LR[i].orth, LR[i].energy, LR[i].w3);
        } else {
            printf("  (peer) T = 1e4, %s at the tolerance reaching 1e-10 at t = 50: %s = %.2g, |E - E0| = "
                   "%.2g\n",
                   LR[i].name, strstr(LR[i].name, "(w,q)") ? "||q| - 1|" : "|R^T R - I|", LR[i].orth,
                   LR[i].energy);
        }
    }
}

/* Every "ours" row reproduces with the suslov command: re-run the fastest preserving row at each
 * attitude and each w level and compare its errors (the w error only for a w-only row). */
static int check_reproduce(const char *argv0)
{
    char suslov[4096];
    const char *slash = strrchr(argv0, '/');
    snprintf(suslov, sizeof suslov, "%.*ssuslov", slash ? (int)(slash - argv0 + 1) : 0, argv0);
    int tried = 0, ok = 0;
    for (int l = 0; l < 2 * NLEVELS; l++) {
        const best_point o = fastest(LEVELS[l % NLEVELS], l < NLEVELS, is_ours_preserving);
        if (o.series < 0)
            continue;
        const wp_series *s = S[o.series];
        double dw, dR;
        tried++;
        if (reproduce(suslov, s, o.point, &dw, &dR) == 0 &&
            dw <= 1e-15 * fmax(1.0, s->err_w[o.point] * 1e6) &&
            dR <= 1e-15 * fmax(1.0, s->err_R[o.point] * 1e6))
            ok++;
        else
            printf("  row not reproduced by suslov: %s %s %.17g\n", s->name, param_name(s),
                   s->param[o.point]);
    }
    printf(
        "  %s %d of %d \"ours\" rows re-run with %s give the same errors (suslov_args in data/bench.csv)\n",
        ok == tried ? "CHECK ok:" : "CHECK FAILED:", ok, tried, suslov);
    return ok != tried;
}

/* The numbers the companion text quotes. */
static int write_tex(const char *path, double speedup, int implicit_pass, int pass[2][NLEVELS],
                     double ratio[2][NLEVELS])
{
    char err[256];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    const int irk4 = sus_step_method_index_of(sus_step_rk4),
              imid = sus_step_method_index_of(sus_step_midpoint),
              ivar = sus_step_method_index_of(sus_step_variational);
    fprintf(af.fp,
            "%% Generated by make bench (src/prog/bench.c): do not edit.\n"
            "\\newcommand{\\BenchRkNs}{%.3g}\n\\newcommand{\\BenchGslRkNs}{%.3g}\n"
            "\\newcommand{\\BenchRkSpeedup}{%.3g}\n\\newcommand{\\BenchMidpointRatio}{%.3g}\n"
            "\\newcommand{\\BenchVariationalRatio}{%.3g}\n\\newcommand{\\BenchExactNs}{%.3g}\n"
            "\\newcommand{\\BenchMidpointNewton}{%.2g}\n\\newcommand{\\BenchVariationalNewton}{%.2g}\n",
            cost.ns_raw[irk4], cost.ns_gsl_rk4, speedup, cost.ns_raw[imid] / cost.ns_raw[irk4],
            cost.ns_raw[ivar] / cost.ns_raw[irk4], cost.ns_exact, cost.newton[imid], cost.newton[ivar]);
    fprintf(af.fp, "\\newcommand{\\BenchPassRkSpeedup}{%s}\n\\newcommand{\\BenchPassImplicit}{%s}\n",
            speedup >= 5 ? "PASS" : "MISS", implicit_pass ? "PASS" : "MISS");
    static const char *lvl[NLEVELS] = {"Four", "Six", "Eight", "Ten", "Twelve", "Fourteen"};
    for (int l = 0; l < NLEVELS; l++) {
        /* two decimals: a ratio of 1.96 must not print as "2", nor 1.30 as "1.3", beside its verdict */
        fprintf(af.fp, "\\newcommand{\\BenchRatioR%s}{%.2f}\n\\newcommand{\\BenchRatioW%s}{%.2f}\n", lvl[l],
                ratio[1][l], lvl[l], ratio[0][l]);
        fprintf(af.fp, "\\newcommand{\\BenchPassR%s}{%s}\n\\newcommand{\\BenchPassW%s}{%s}\n", lvl[l],
                pass[1][l] ? "PASS" : "MISS", lvl[l], pass[0][l] ? "PASS" : "MISS");
        fprintf(af.fp, "\\newcommand{\\BenchTarget%s}{%.2g}\n", lvl[l], LEVEL_TARGET[l]);
    }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    return 0;
}

/* The "what to use when" data: at each level the fastest of ours and of the peers, from their
 * timed runs, with the suslov arguments that reproduce ours (README, the companion). */
static int write_what_to_use(const char *path)
{
    char err[256], args[256];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    fprintf(af.fp,
            "quantity\tlevel\tours\tours_seconds\tpeer\tpeer_tol\tpeer_seconds\tratio\ttarget\t"
            "verdict\tsuslov_args\n");
    for (int which = 1; which >= 0; which--)
        for (int l = 0; l < NLEVELS; l++) {
            const best_point o = fastest(LEVELS[l], which, is_ours_preserving),
                             p = fastest(LEVELS[l], which, is_peer);
            if (o.series < 0)
                continue;
            args_of(S[o.series], o.point, args, sizeof args);
            const double ratio = p.series < 0 ? INFINITY : p.sec / o.sec;
            fprintf(af.fp, "%s\t%.0e\t%s\t%.4g\t%s\t%.2g\t%.4g\t%.3g\t%g\t%s\t%s\n",
                    which ? "attitude" : "omega", LEVELS[l], S[o.series]->name, o.sec,
                    p.series < 0 ? "none reaches it" : S[p.series]->name,
                    p.series < 0 ? NAN : S[p.series]->param[p.point], p.series < 0 ? NAN : p.sec, ratio,
                    LEVEL_TARGET[l], ratio >= LEVEL_TARGET[l] ? "PASS" : "MISS", args);
        }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    return 0;
}

static int write_figures(const char *figdir)
{
    char err[256], path[4096];
    snprintf(path, sizeof path, "%s/work_precision", figdir);
    int nours = 0;
    for (int i = 0; i < nseries; i++)
        nours += S[i]->ours;
    /* tall enough for the legend's two columns and no more */
    const double wp_h = WP_LEGEND_Y + sus_plot_legend_height((nours + 1) / 2) + 6.0;
    if (sus_plot_write(path, WP_W, wp_h, draw_wp, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    snprintf(path, sizeof path, "%s/step_cost", figdir);
    if (sus_plot_write(path, 90.0 + 46.0 * (cost.n + 2), 280, draw_cost, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    return 0;
}

static void print_header(int differ)
{
    printf("Benchmark (T = %g, w(0) = (0.4, 0.5), the paper's body). Work-precision times: median over %d\n"
           "interleaved rounds, each a batch of >= %g s, min and max in data/bench.csv. The machine is "
           "shared and\n"
           "noisy: compare the ratios measured in this same run rather than absolute times.\n"
#ifndef SUSLOV_WITH_ODEINT
           "(built without Boost.Odeint: `make bench` builds the bench with it)\n"
#endif
           "  %s %d of %d timed points end their timed runs with the error recorded for them\n\n",
           T_END, WP_ROUNDS, BATCH_SECONDS, differ ? "CHECK FAILED:" : "CHECK ok:", npoints - differ,
           npoints);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench FIGDIR DATADIR\n");
        return 2;
    }
    gsl_set_error_handler_off();
    progress_tty = isatty(2);
    if (set_up_problem() != 0)
        return 1;
    double t_phase[6];
    t_phase[0] = sus_sys_now();
    sweep_all();
    t_phase[1] = sus_sys_now();
    const int differ = time_points();
    t_phase[2] = sus_sys_now();
    build_envelope(0, &env[0]);
    build_envelope(1, &env[1]);
    measure_step_costs();
    measure_tol_costs();
    t_phase[3] = sus_sys_now();
    progress("long runs");
    long_runs();
    t_phase[4] = sus_sys_now();
    if (progress_tty)
        fprintf(stderr, "\r%70s\r", "");
    print_header(differ);
    print_costs();
    printf("Targets:\n");
    double speedup;
    const int implicit_pass = print_step_targets(&speedup);
    int pass[2][NLEVELS];
    double ratio[2][NLEVELS];
    for (int which = 1; which >= 0; which--)
        for (int l = 0; l < NLEVELS; l++)
            print_level(which, l, &pass[which][l], &ratio[which][l]);
    print_long_runs();
    print_equal_error_long();
    const int unreproduced = check_reproduce(argv[0]);
    t_phase[5] = sus_sys_now();
    printf("\nbench ran for %.1f s (sweeps %.1f, work-precision timing %.1f, step costs %.1f, long runs "
           "%.1f, equal-error runs and reproducing %.1f)\n",
           t_phase[5] - t_phase[0], t_phase[1] - t_phase[0], t_phase[2] - t_phase[1], t_phase[3] - t_phase[2],
           t_phase[4] - t_phase[3], t_phase[5] - t_phase[4]);
    if (differ || unreproduced) { /* data the companion would quote as checked: none rather than wrong */
        fprintf(stderr, "bench: a CHECK FAILED (see its line in the output above); nothing written\n");
        return 1;
    }
    char path[4096];
    if (write_csv(sus_plot_fig_path(path, sizeof path, argv[2], "bench", "csv")) != 0 ||
        write_tex(sus_plot_fig_path(path, sizeof path, argv[2], "bench", "tex"), speedup, implicit_pass, pass,
                  ratio) != 0 ||
        write_what_to_use(sus_plot_fig_path(path, sizeof path, argv[2], "what_to_use", "tsv")) != 0 ||
        write_figures(argv[1]) != 0)
        return 1;
    return 0;
}
