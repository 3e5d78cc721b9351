/* make bench: work-precision of our DSPs against GSL's odeiv2 steppers, the cost of one step,
 * and the speed targets of the benchmark issue, printed as PASS/MISS lines (never a failing
 * test: the machine is shared and noisy). Usage: bench FIGDIR DATADIR */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include "driver.h"
#include "exact.h"
#include "fig_output.h"
#include "mat3.h"
#include "monoclock.h"
#include "plot.h"
#include "refattitude.h"
#include "so3.h"
#include "stepper.h"

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
#define MAX_STEPS 2000000L  /* caps euler's sweep: 2e6 steps of T/N is ~2 s a point */
#define NSERIES 9
#define MAXPTS 16

static volatile double sink; /* results are added here so that no run can be optimized away */
static int progress_tty;

static void progress(const char *what)
{
    if (progress_tty) {
        fprintf(stderr, "\rbench: %-60s", what);
        fflush(stderr);
    }
}

/* ---- the problem ---- */

static suslov_model model;
static suslov_exact ex;
static double w_T[2], R_T[3][3];

/* ---- our DSPs through the driver (reconstruction included) ---- */

typedef struct {
    const suslov_stepper_type *st;
    suslov_recon recon;
    long N;
    suslov_row last;
    suslov_run_report rep;
} dsp_run;

static int keep(void *vctx, const suslov_row *row)
{
    ((dsp_run *)vctx)->last = *row;
    return 0;
}

static void dsp_fn(void *vctx)
{
    dsp_run *r = vctx;
    const suslov_run_config cfg = {&model, r->st, r->recon, T_END / (double)r->N, r->N, r->N};
    suslov_run(&cfg, ex.w0, keep, r, &r->rep);
    sink += r->last.w[0];
}

/* ---- the peer: GSL odeiv2 on (w, R), 11 unknowns ---- */

static int gsl_rhs(double t, const double y[], double f[], void *p)
{
    (void)t;
    (void)p;
    double W[3][3];
    const double w[3] = {y[0], y[1], 0.0};
    suslov_contdyn(&model, y, f);
    so3_hat(w, W);
    mat3_mul(*(double(*)[3][3])(f + 2), *(const double(*)[3][3])(y + 2), W);
    return GSL_SUCCESS;
}

static int gsl_rhs_w(double t, const double y[], double f[], void *p)
{
    (void)t;
    (void)p;
    suslov_contdyn(&model, y, f);
    return GSL_SUCCESS;
}

typedef struct {
    const gsl_odeiv2_step_type *type;
    int fixed;       /* fixed step (apply_fixed_step) or adaptive (apply) */
    double param;    /* h or tolerance */
    size_t dim;      /* 11: (w, R); 2: w alone (per-step cost) */
    long N;
    gsl_odeiv2_driver *d;
    double y[11];
    int status;
} gsl_run;

static void gsl_fn(void *vctx)
{
    gsl_run *g = vctx;
    double t = 0.0;
    memset(g->y, 0, sizeof g->y);
    g->y[0] = ex.w0[0];
    g->y[1] = ex.w0[1];
    g->y[2] = g->y[6] = g->y[10] = 1.0;
    gsl_odeiv2_driver_reset(g->d);
    if (g->fixed) {
        gsl_odeiv2_driver_reset_hstart(g->d, g->param);
        g->status = gsl_odeiv2_driver_apply_fixed_step(g->d, &t, g->param, (unsigned long)g->N, g->y);
    } else {
        g->status = gsl_odeiv2_driver_apply(g->d, &t, T_END, g->y);
    }
    sink += g->y[0];
}

static void gsl_open(gsl_run *g, gsl_odeiv2_system *sys)
{
    *sys = (gsl_odeiv2_system){g->dim == 11 ? gsl_rhs : gsl_rhs_w, NULL, g->dim, NULL};
    const double tol = g->fixed ? 1e-6 : g->param;
    g->d = gsl_odeiv2_driver_alloc_y_new(sys, g->type, g->fixed ? g->param : 1e-3, tol, tol);
    if (!g->d) {
        fprintf(stderr, "bench: GSL driver allocation failed\n");
        exit(1);
    }
}

/* ---- work-precision series ---- */

typedef struct {
    const char *name;
    int ours;
    int n;
    double param[MAXPTS], err_w[MAXPTS], err_R[MAXPTS], sec[MAXPTS], smin[MAXPTS], smax[MAXPTS];
    long steps[MAXPTS];
} wp_series;

static wp_series S[NSERIES];
static int nseries;

static double attitude_error_of(const double *R9)
{
    return so3_dist(R_T, *(const double(*)[3][3])R9);
}

/* Every point of every series is timed in interleaved rounds, like the per-step costs: a
 * batch of repeats lasting at least BATCH_SECONDS per round, WP_ROUNDS rounds, the median
 * over rounds (with min and max). */
#define WP_ROUNDS 7
#define BATCH_SECONDS 1e-3
#define MAXPOINTS (NSERIES * MAXPTS)

typedef struct {
    void (*fn)(void *);
    void *ctx;
    int batch;
    double t[WP_ROUNDS];
    double *sec, *smin, *smax; /* where the result goes */
} wp_point;

static wp_point points[MAXPOINTS];
static int npoints;
static dsp_run dsp_runs[MAXPOINTS];
static gsl_run gsl_runs[MAXPOINTS];
static gsl_odeiv2_system gsl_systems[MAXPOINTS];

static void add_point(void (*fn)(void *), void *ctx, wp_series *s, int i)
{
    points[npoints++] = (wp_point){fn, ctx, 1, {0}, &s->sec[i], &s->smin[i], &s->smax[i]};
}

static void sweep_ours(const suslov_stepper_type *st, suslov_recon recon, const char *name)
{
    wp_series *s = &S[nseries++];
    s->name = name;
    s->ours = 1;
    for (long N = 50; N <= MAX_STEPS && s->n < MAXPTS; N *= 4) {
        dsp_run *r = &dsp_runs[npoints];
        *r = (dsp_run){st, recon, N, {0}, {0}};
        dsp_fn(r);
        const int i = s->n++;
        s->param[i] = T_END / (double)N;
        s->steps[i] = N;
        s->err_w[i] = hypot(r->last.w[0] - w_T[0], r->last.w[1] - w_T[1]);
        s->err_R[i] = so3_dist(R_T, r->last.R);
        add_point(dsp_fn, r, s, i);
        if (s->err_w[i] < 1e-13) /* at round-off: more steps buy nothing */
            break;
    }
}

static void sweep_gsl(const gsl_odeiv2_step_type *type, int fixed, const char *name)
{
    wp_series *s = &S[nseries++];
    s->name = name;
    s->ours = 0;
    for (int j = 0; j < MAXPTS; j++) {
        gsl_run *g = &gsl_runs[npoints];
        *g = (gsl_run){type, fixed, 0.0, 11, 0, NULL, {0}, 0};
        if (fixed) {
            g->N = 50L << (2 * j);
            if (g->N > MAX_STEPS)
                break;
            g->param = T_END / (double)g->N;
        } else {
            g->param = pow(10.0, -3.0 - j);
            if (g->param < 1e-14)
                break;
        }
        gsl_open(g, &gsl_systems[npoints]);
        gsl_fn(g);
        if (g->status != GSL_SUCCESS) {
            gsl_odeiv2_driver_free(g->d);
            continue;
        }
        const int i = s->n++;
        s->param[i] = g->param;
        s->steps[i] = g->N;
        s->err_w[i] = hypot(g->y[0] - w_T[0], g->y[1] - w_T[1]);
        s->err_R[i] = attitude_error_of(g->y + 2);
        add_point(gsl_fn, g, s, i);
        if (s->err_w[i] < 1e-13)
            break;
    }
}

static void time_points(void)
{
    for (int p = 0; p < npoints; p++) { /* calibrate the batches */
        const double t0 = suslov_now();
        points[p].fn(points[p].ctx);
        const double t1 = suslov_now() - t0;
        points[p].batch = t1 >= BATCH_SECONDS ? 1 : (int)ceil(BATCH_SECONDS / fmax(t1, 1e-7));
    }
    for (int r = 0; r < WP_ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "work-precision, round %d of %d (%d points)", r + 1, WP_ROUNDS, npoints);
        progress(msg);
        for (int p = 0; p < npoints; p++) {
            const double t0 = suslov_now();
            for (int b = 0; b < points[p].batch; b++)
                points[p].fn(points[p].ctx);
            points[p].t[r] = (suslov_now() - t0) / points[p].batch;
        }
    }
    for (int p = 0; p < npoints; p++) {
        gsl_sort(points[p].t, 1, WP_ROUNDS);
        *points[p].sec = gsl_stats_median_from_sorted_data(points[p].t, 1, WP_ROUNDS);
        *points[p].smin = points[p].t[0];
        *points[p].smax = points[p].t[WP_ROUNDS - 1];
    }
    for (int p = 0; p < npoints; p++)
        if (points[p].fn == gsl_fn)
            gsl_odeiv2_driver_free(((gsl_run *)points[p].ctx)->d);
}

/* Fastest time at which the series reaches an error <= level (INFINITY if never). */
static double time_to(const wp_series *s, double level, int *at)
{
    double best = INFINITY;
    for (int i = 0; i < s->n; i++)
        if (s->err_w[i] <= level && s->sec[i] < best) {
            best = s->sec[i];
            *at = i;
        }
    return best;
}

/* ---- per-step cost ---- */

typedef struct {
    const suslov_stepper_type *st;
    long N;
    double newton;
} raw_run;

static void raw_fn(void *vctx)
{
    raw_run *r = vctx;
    double w[3] = {ex.w0[0], ex.w0[1], 0.0}, x[3], lam;
    long it = 0;
    suslov_step_stats stats;
    const double eps = T_END / (double)r->N;
    for (long k = 0; k < r->N; k++) {
        r->st->apply(&model, eps, w, x, &lam, &stats);
        it += stats.iterations;
        w[0] = x[0];
        w[1] = x[1];
    }
    r->newton = (double)it / (double)r->N;
    sink += w[0] + lam;
}

typedef struct {
    long n;
} exact_run;

static void exact_fn(void *vctx)
{
    const exact_run *e = vctx;
    double acc = 0.0, w[2];
    for (long i = 0; i < e->n; i++) {
        suslov_exact_omega(&ex, T_END * (double)i / (double)e->n, w);
        acc += w[0];
    }
    sink += acc;
}

typedef struct {
    double ns_raw[4], ns_recon[4], newton[4], ns_gsl_rk4, ns_exact;
} step_costs;

static step_costs cost;

/* Per-step costs are timed in interleaved rounds: every configuration once per round, the
 * median over rounds. A burst of load from elsewhere on a shared machine then slows one
 * round of every configuration alike instead of all the repeats of one of them. */
#define ROUNDS 21
#define COST_STEPS 100000L /* eps = 5e-4 */

typedef struct {
    void (*fn)(void *);
    void *ctx;
    double t[ROUNDS];
} cost_cfg;

static double median_ns(cost_cfg *c, long steps)
{
    gsl_sort(c->t, 1, ROUNDS);
    return 1e9 * gsl_stats_median_from_sorted_data(c->t, 1, ROUNDS) / (double)steps;
}

static void measure_step_costs(void)
{
    raw_run raw[4];
    dsp_run rec[4];
    cost_cfg cfg[10];
    for (int m = 0; m < 4; m++) {
        raw[m] = (raw_run){suslov_stepper_get(m), COST_STEPS, 0.0};
        rec[m] = (dsp_run){suslov_stepper_get(m), SUSLOV_RECON_CAYLEY, COST_STEPS, {0}, {0}};
        cfg[m] = (cost_cfg){raw_fn, &raw[m], {0}};
        cfg[4 + m] = (cost_cfg){dsp_fn, &rec[m], {0}};
    }
    gsl_odeiv2_system sys;
    gsl_run g = {gsl_odeiv2_step_rk4, 1, T_END / (double)COST_STEPS, 2, COST_STEPS, NULL, {0}, 0};
    gsl_open(&g, &sys);
    exact_run e = {COST_STEPS};
    cfg[8] = (cost_cfg){gsl_fn, &g, {0}};
    cfg[9] = (cost_cfg){exact_fn, &e, {0}};
    for (int r = 0; r < ROUNDS; r++) {
        char msg[64];
        snprintf(msg, sizeof msg, "per-step costs, round %d of %d", r + 1, ROUNDS);
        progress(msg);
        for (int c = 0; c < 10; c++) {
            const double t0 = suslov_now();
            cfg[c].fn(cfg[c].ctx);
            cfg[c].t[r] = suslov_now() - t0;
        }
    }
    gsl_odeiv2_driver_free(g.d);
    for (int m = 0; m < 4; m++) {
        cost.ns_raw[m] = median_ns(&cfg[m], COST_STEPS);
        cost.ns_recon[m] = median_ns(&cfg[4 + m], COST_STEPS);
        cost.newton[m] = raw[m].newton;
    }
    cost.ns_gsl_rk4 = median_ns(&cfg[8], COST_STEPS);
    cost.ns_exact = median_ns(&cfg[9], COST_STEPS);
}

/* ---- figures ---- */

static const double *series_colour(int i)
{
    static const double brown[3] = {0.55, 0.33, 0.12};
    const double *c[NSERIES] = {PLOT_ORANGE, PLOT_GREEN, PLOT_PURPLE, PLOT_BLUE, brown, PLOT_RED, PLOT_GREY, PLOT_BLACK, PLOT_GREEN};
    return c[i];
}

static void draw_wp(cairo_t *cr, void *vctx)
{
    (void)vctx;
    const double W = 600, H = 380;
    static const int mk[NSERIES] = {PLOT_SQUARE, PLOT_CIRCLE, PLOT_TRIANGLE, PLOT_DIAMOND, PLOT_TRIANGLE, PLOT_CROSS, PLOT_SQUARE, PLOT_CIRCLE, PLOT_CIRCLE};
    plot_text(cr, W / 2, 14, "Work-precision at t = 50: error against CPU time per run (median)", 11, 0.5, 0.5, 1);
    for (int p = 0; p < 2; p++) {
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (int i = 0; i < nseries; i++) {
            plot_extend(&x0, &x1, S[i].sec, (size_t)S[i].n, 1, 1);
            plot_extend(&y0, &y1, p ? S[i].err_R : S[i].err_w, (size_t)S[i].n, 1, 1);
        }
        plot_axes ax;
        plot_axes_cell(&ax, cr, W, H - 90, 1, 2, p, x0, x1, fmax(y0, 1e-16), y1, 1, 1);
        plot_frame(&ax, "seconds per run", p ? "attitude error dist(R(50), R\xe2\x82\x99)" : "|\xcf\x89(50) \xe2\x88\x92 \xcf\x89\xe2\x82\x99|", p ? "(b)" : "(a)");
        plot_style st[NSERIES];
        for (int i = 0; i < nseries; i++) {
            st[i] = plot_style_of(series_colour(i), 1.0, S[i].ours ? 0 : 1, mk[i], 4.0, S[i].name);
            plot_series(&ax, S[i].sec, p ? S[i].err_R : S[i].err_w, (size_t)S[i].n, 1, &st[i]);
            plot_markers(&ax, S[i].sec, p ? S[i].err_R : S[i].err_w, (size_t)S[i].n, 1, &st[i]);
        }
        if (p == 1) { /* below the panels: ours on the left, GSL on the right */
            int nours = 0;
            while (nours < nseries && S[nours].ours)
                nours++;
            plot_axes la;
            plot_axes_init(&la, cr, 60, H - 80, 250, 76, 0, 1, 0, 1, 0, 0);
            plot_legend(&la, st, nours, 0);
            plot_axes_init(&la, cr, 340, H - 80, 250, 76, 0, 1, 0, 1, 0, 0);
            plot_legend(&la, st + nours, nseries - nours, 0);
        }
    }
}

static void draw_cost(cairo_t *cr, void *vctx)
{
    (void)vctx;
    const double W = 600, H = 260;
    plot_text(cr, W / 2, 14, "Cost of one step (median ns; lower is better)", 11, 0.5, 0.5, 1);
    const char *names[6] = {"euler", "midpoint", "rk4", "variational", "GSL rk4 (driver)", "exact \xcf\x89(t)"};
    double v1[6], v2[6];
    for (int m = 0; m < 4; m++) {
        v1[m] = cost.ns_raw[m];
        v2[m] = cost.ns_recon[m];
    }
    v1[4] = v2[4] = cost.ns_gsl_rk4;
    v1[5] = v2[5] = cost.ns_exact;
    double hi = 0.0;
    for (int i = 0; i < 6; i++)
        hi = fmax(hi, fmax(v1[i], v2[i]));
    plot_axes ax;
    plot_axes_cell(&ax, cr, W, H, 1, 1, 0, 0.0, 6.0, 0.0, hi, 0, 0);
    ax.y0 = 0.0;
    ax.no_xticks = 1;
    plot_frame(&ax, NULL, "ns per step", NULL);
    const double bw = ax.w / 6.0;
    for (int i = 0; i < 6; i++) {
        const double bx = ax.x + i * bw;
        const double h1 = v1[i] / ax.y1 * ax.h, h2 = v2[i] / ax.y1 * ax.h;
        cairo_set_source_rgb(cr, 0.55, 0.70, 0.90);
        cairo_rectangle(cr, bx + 0.15 * bw, ax.y + ax.h - h1, 0.33 * bw, h1);
        cairo_fill(cr);
        if (i < 4) {
            cairo_set_source_rgb(cr, 0.15, 0.35, 0.75);
            cairo_rectangle(cr, bx + 0.52 * bw, ax.y + ax.h - h2, 0.33 * bw, h2);
            cairo_fill(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        plot_text(cr, bx + 0.5 * bw, ax.y + ax.h + 5, names[i], 8.0, 0.5, 0.0, 0);
        char lab[32];
        snprintf(lab, sizeof lab, "%.0f", v1[i]);
        plot_text(cr, bx + 0.315 * bw, ax.y + ax.h - h1 - 9, lab, 7.5, 0.5, 0.0, 0);
        if (i < 4) {
            snprintf(lab, sizeof lab, "%.0f", v2[i]);
            plot_text(cr, bx + 0.685 * bw, ax.y + ax.h - h2 - 9, lab, 7.5, 0.5, 0.0, 0);
        }
    }
    const plot_style leg[2] = {plot_style_of((const double[3]){0.55, 0.70, 0.90}, 6.0, 0, PLOT_NONE, 0, "step only (w)"),
                               plot_style_of((const double[3]){0.15, 0.35, 0.75}, 6.0, 0, PLOT_NONE, 0, "with R\xe2\x82\x96\xe2\x82\x8a\xe2\x82\x81 = R\xe2\x82\x96 cay(\xce\xb5 \xcf\x89\xcc\x82\xe2\x82\x96)")};
    plot_legend(&ax, leg, 2, 0);
}

/* ---- output ---- */

static int write_csv(const char *path)
{
    char err[256];
    atomic_file af;
    if (atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    fprintf(af.fp, "section,method,parameter,steps,omega_error,attitude_error,seconds_median,seconds_min,seconds_max,ns_per_step,newton_per_step\n");
    for (int i = 0; i < nseries; i++)
        for (int j = 0; j < S[i].n; j++)
            fprintf(af.fp, "work,%s,%.6g,%ld,%.6g,%.6g,%.6g,%.6g,%.6g,,\n", S[i].name, S[i].param[j], S[i].steps[j],
                    S[i].err_w[j], S[i].err_R[j], S[i].sec[j], S[i].smin[j], S[i].smax[j]);
    for (int m = 0; m < 4; m++) {
        fprintf(af.fp, "step,%s,,,,,,,,%.4g,%.3g\n", suslov_stepper_get(m)->name, cost.ns_raw[m], cost.newton[m]);
        fprintf(af.fp, "step,%s+cayley,,,,,,,,%.4g,%.3g\n", suslov_stepper_get(m)->name, cost.ns_recon[m], cost.newton[m]);
    }
    fprintf(af.fp, "step,gsl-rk4-driver,,,,,,,,%.4g,\n", cost.ns_gsl_rk4);
    fprintf(af.fp, "step,exact-omega,,,,,,,,%.4g,\n", cost.ns_exact);
    return atomic_file_commit(&af, err, sizeof err);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench FIGDIR DATADIR\n");
        return 2;
    }
    gsl_set_error_handler_off();
    progress_tty = isatty(2);
    char err[256], path[4096];
    suslov_model_init(&model, SUSLOV_PAPER_INERTIA, err, sizeof err);
    suslov_exact_init(&ex, &model, SUSLOV_PAPER_OMEGA0);
    suslov_exact_omega(&ex, T_END, w_T);
    {
        double I3[3][3];
        suslov_refatt ra;
        mat3_identity(I3);
        if (suslov_refatt_init(&ra, &ex, 0.0, I3, SUSLOV_REFATT_TOL) || suslov_refatt_advance(&ra, T_END, R_T))
            return 1;
        suslov_refatt_free(&ra);
    }
    const double t_start = suslov_now();
    sweep_ours(suslov_step_euler, SUSLOV_RECON_CAYLEY, "euler");
    sweep_ours(suslov_step_midpoint, SUSLOV_RECON_CAYLEY_MID, "midpoint + cayley-mid");
    sweep_ours(suslov_step_rk4, SUSLOV_RECON_CAYLEY_MID, "rk4 + cayley-mid");
    sweep_ours(suslov_step_variational, SUSLOV_RECON_CAYLEY, "variational (paper: algo)");
    sweep_ours(suslov_step_rk4, SUSLOV_RECON_CAYLEY, "rk4 + cayley (algo)");
    sweep_gsl(gsl_odeiv2_step_rk4, 1, "GSL rk4 fixed step");
    sweep_gsl(gsl_odeiv2_step_rk8pd, 0, "GSL rk8pd adaptive");
    sweep_gsl(gsl_odeiv2_step_rkf45, 0, "GSL rkf45 adaptive");
    time_points();
    measure_step_costs();
    if (progress_tty)
        fprintf(stderr, "\r%70s\r", "");

    printf("Benchmark (T = %g, w(0) = (0.4, 0.5), the paper's body). Work-precision times: median over %d\n"
           "interleaved rounds, each a batch of >= %g s, min and max in data/bench.csv. The machine is shared and\n"
           "noisy: compare the ratios measured in this same run rather than absolute times.\n\n",
           T_END, WP_ROUNDS, BATCH_SECONDS);
    printf("Per-step cost (ns, median of %d interleaved rounds of %ld steps; eps = %g):\n", ROUNDS, COST_STEPS, T_END / (double)COST_STEPS);
    printf("  %-12s %10s %14s %12s %14s %14s\n", "method", "step only", "with cayley", "Newton/step", "x our rk4", "x GSL rk4");
    for (int m = 0; m < 4; m++)
        printf("  %-12s %10.1f %14.1f %12.2f %14.2f %14.3f\n", suslov_stepper_get(m)->name, cost.ns_raw[m], cost.ns_recon[m],
               cost.newton[m], cost.ns_raw[m] / cost.ns_raw[2], cost.ns_raw[m] / cost.ns_gsl_rk4);
    printf("  %-12s %10.1f %14s %12s %14.2f %14.3f\n", "GSL rk4", cost.ns_gsl_rk4, "-", "-", cost.ns_gsl_rk4 / cost.ns_raw[2], 1.0);
    printf("  %-12s %10.1f %14s %12s %14.2f %14.3f   (one closed-form w(t): the floor)\n\n", "exact w(t)", cost.ns_exact, "-", "-",
           cost.ns_exact / cost.ns_raw[2], cost.ns_exact / cost.ns_gsl_rk4);

    printf("Targets:\n");
    const double speedup = cost.ns_gsl_rk4 / cost.ns_raw[2];
    printf("  %s our rk4 step is >= 5x faster than GSL rk4 through gsl_odeiv2_driver_apply_fixed_step: %.1fx\n",
           speedup >= 5 ? "PASS" : "MISS", speedup);
    for (int m = 1; m < 4; m += 2) {
        const double r = cost.ns_raw[m] / cost.ns_raw[2];
        printf("  %s an implicit %s step costs <= 3x our rk4 step: %.2fx (%.2f Newton iterations per step)\n",
               r <= 3 ? "PASS" : "MISS", suslov_stepper_get(m)->name, r, cost.newton[m]);
    }
    for (int e = 4; e <= 12; e++) {
        const double level = pow(10.0, -e);
        double best_ours = INFINITY, best_gsl = INFINITY;
        int io = -1, ig = -1, ao = 0, ag = 0;
        for (int i = 0; i < nseries; i++) {
            int at = 0;
            const double tt = time_to(&S[i], level, &at);
            if (S[i].ours && tt < best_ours) {
                best_ours = tt;
                io = i;
                ao = at;
            } else if (!S[i].ours && tt < best_gsl) {
                best_gsl = tt;
                ig = i;
                ag = at;
            }
        }
        if (io < 0 || ig < 0) {
            printf("  MISS accuracy 1e-%d: %s reaches it\n", e, io < 0 ? "none of our methods" : "no GSL configuration");
            continue;
        }
        const double ratio = best_gsl / best_ours;
        printf("  %s accuracy 1e-%02d in w at t = 50: ours %.3g s (%s, param %.3g) vs GSL %.3g s (%s, param %.3g): %.1fx%s\n",
               ratio >= 2 ? "PASS" : "MISS", e, best_ours, S[io].name, S[io].param[ao], best_gsl, S[ig].name, S[ig].param[ag], ratio,
               ratio >= 2 ? "" : " (target 2x)");
    }
    printf("  (the exact solution gives w(50) to round-off in %.0f ns: no integration needed for w at all)\n", cost.ns_exact);
    printf("\nbench ran for %.1f s\n", suslov_now() - t_start);

    if (write_csv(fig_path(path, sizeof path, argv[2], "bench", "csv")) != 0)
        return 1;
    /* the numbers the companion text quotes */
    atomic_file af;
    if (atomic_file_open(&af, fig_path(path, sizeof path, argv[2], "bench", "tex"), err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return 1;
    }
    fprintf(af.fp, "%% Generated by make bench (src/bench.c): do not edit.\n"
                   "\\newcommand{\\BenchRkNs}{%.3g}\n\\newcommand{\\BenchGslRkNs}{%.3g}\n"
                   "\\newcommand{\\BenchRkSpeedup}{%.2g}\n\\newcommand{\\BenchMidpointRatio}{%.2g}\n"
                   "\\newcommand{\\BenchVariationalRatio}{%.2g}\n\\newcommand{\\BenchExactNs}{%.3g}\n"
                   "\\newcommand{\\BenchMidpointNewton}{%.2g}\n\\newcommand{\\BenchVariationalNewton}{%.2g}\n",
            cost.ns_raw[2], cost.ns_gsl_rk4, speedup, cost.ns_raw[1] / cost.ns_raw[2], cost.ns_raw[3] / cost.ns_raw[2],
            cost.ns_exact, cost.newton[1], cost.newton[3]);
    if (atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return 1;
    }
    snprintf(path, sizeof path, "%s/work_precision", argv[1]);
    if (plot_write(path, 600, 380, draw_wp, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return 1;
    }
    snprintf(path, sizeof path, "%s/step_cost", argv[1]);
    if (plot_write(path, 600, 260, draw_cost, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return 1;
    }
    return 0;
}
