/* The tolerance-driven Taylor method (taylor-adaptive) along [0, 50] on the paper's body: (a) the
 * step it takes at each accepted step for a few TOLs, beside the radius its series is proved to
 * converge in (step_taylor.c); (b) the attitude error of its dense-output rows against the
 * long-double reference (refattitude.h), with TOL marked.
 * Usage: figure_adaptive_steps FIGDIR DATADIR */
#include "driver.h"
#include "exact.h"
#include "fig_output.h"
#include "plot.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"
#include "taylor.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#define T_END 50.0
#define DT_ROWS 0.5
#define NROWS 101 /* T_END / DT_ROWS + 1 */
#define NTOL 3
#define MAXSTEPS 400
static const double TOLS[NTOL] = {1e-4, 1e-8, 1e-12};

typedef struct {
    const sus_model *m;
    long n; /* steps so far */
    double t_prev, w_prev[2];
    double t[MAXSTEPS], h[MAXSTEPS], radius[MAXSTEPS];
} steps_ctx;

typedef struct {
    sus_exact ex;
    sus_refatt ref;
    int n;
    double t[NROWS], err[NROWS];
} rows_ctx;

typedef struct {
    steps_ctx s[NTOL];
    rows_ctx r[NTOL];
    int order[NTOL];
} adaptive_fig;

/* Each accepted step's start, length and the proved radius at its start. */
static int take_step(void *vctx, const sus_row *row)
{
    steps_ctx *c = vctx;
    if (row->k > 0 && c->n < MAXSTEPS) {
        c->t[c->n] = c->t_prev;
        c->h[c->n] = row->t - c->t_prev;
        c->radius[c->n++] = sus_step_taylor_radius(c->m, c->w_prev);
    }
    c->t_prev = row->t;
    c->w_prev[0] = row->w[0];
    c->w_prev[1] = row->w[1];
    return 0;
}

static int take_row(void *vctx, const sus_row *row)
{
    rows_ctx *c = vctx;
    double R[3][3];
    sus_refatt_advance(&c->ref, row->t, R);
    if (c->n < NROWS) {
        c->t[c->n] = row->t;
        c->err[c->n++] = sus_so3_dist(R, row->R);
    }
    return 0;
}

static const double *colour(int i) { return SUS_PLOT_PALETTE[i % SUS_PLOT_PALETTE_N]; }

static void draw(cairo_t *cr, void *vctx)
{
    const adaptive_fig *f = vctx;
    const double W = 560, H = 300;
    char lab[NTOL][64];
    sus_plot_style st[NTOL + 1];
    sus_plot_axes ax;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < NTOL; i++) {
        sus_plot_extend(&lo, &hi, f->s[i].h, (size_t)f->s[i].n, 1, 1);
        sus_plot_extend(&lo, &hi, f->s[i].radius, (size_t)f->s[i].n, 1, 1);
    }
    sus_plot_pad(&lo, &hi, 1);
    sus_plot_axes_cell(&ax, cr, W, H, 1, 2, 0, 0, T_END, lo, hi, 0, 1);
    sus_plot_frame(&ax, "t (start of the step)", "step h", "(a)");
    for (int i = 0; i < NTOL; i++) {
        snprintf(lab[i], sizeof lab[i], "TOL %.0e (order %d, %ld steps)", TOLS[i], f->order[i],
                 f->s[i].n);
        st[i] = sus_plot_style_of(colour(i), 1.2, 0, SUS_PLOT_CIRCLE + i, 3.0, lab[i]);
        sus_plot_series(&ax, f->s[i].t, f->s[i].h, (size_t)f->s[i].n, 1, &st[i]);
        sus_plot_markers(&ax, f->s[i].t, f->s[i].h, (size_t)f->s[i].n, 1, &st[i]);
    }
    st[NTOL] =
        sus_plot_style_of(SUS_PLOT_GREY, 1.0, 1, SUS_PLOT_NONE, 0, "proved radius of the series");
    sus_plot_series(&ax, f->s[0].t, f->s[0].radius, (size_t)f->s[0].n, 1, &st[NTOL]);
    sus_plot_legend(&ax, st, NTOL + 1, 2);
    lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < NTOL; i++) {
        sus_plot_extend(&lo, &hi, f->r[i].err + 1, (size_t)f->r[i].n - 1, 1, 1);
        sus_plot_extend(&lo, &hi, &TOLS[i], 1, 1, 1);
    }
    sus_plot_pad(&lo, &hi, 1);
    sus_plot_axes_cell(&ax, cr, W, H, 1, 2, 1, 0, T_END, lo, hi, 0, 1);
    sus_plot_frame(&ax, "t", "attitude error dist(R(t), R\xe2\x82\x96)", "(b)");
    for (int i = 0; i < NTOL; i++) {
        const sus_plot_style e = sus_plot_style_of(colour(i), 1.2, 0, SUS_PLOT_NONE, 0, NULL);
        const sus_plot_style tl = sus_plot_style_of(colour(i), 0.8, 2, SUS_PLOT_NONE, 0, NULL);
        const double tx[2] = {0.0, T_END}, ty[2] = {TOLS[i], TOLS[i]};
        sus_plot_series(&ax, f->r[i].t + 1, f->r[i].err + 1, (size_t)f->r[i].n - 1, 1, &e);
        sus_plot_series(&ax, tx, ty, 2, 1, &tl);
    }
}

/* One TOL's steps and dense rows; 0, or -1 when a run fails. */
static int measure(const sus_model *m, const sus_stepper_type *type, int i, adaptive_fig *f)
{
    static const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_run_report rep;
    f->s[i] = (steps_ctx){.m = m};
    f->order[i] = type->tol->order(TOLS[i]);
    const sus_tol_config every_step = {m, type, TOLS[i], T_END, 0.0, 0};
    if (sus_run_tol(&every_step, SUS_PAPER_OMEGA0, take_step, &f->s[i], &rep) != SUS_RUN_OK)
        return -1;
    rows_ctx *r = &f->r[i];
    r->n = 0;
    sus_exact_init(&r->ex, m, SUS_PAPER_OMEGA0);
    sus_refatt_init(&r->ref, &r->ex, 0.0, I3);
    const sus_tol_config rows = {m, type, TOLS[i], T_END, DT_ROWS, 0};
    return sus_run_tol(&rows, SUS_PAPER_OMEGA0, take_row, r, &rep) == SUS_RUN_OK && r->n == NROWS
               ? 0
               : -1;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: figure_adaptive_steps FIGDIR DATADIR\n");
        return 2;
    }
    gsl_set_error_handler_off();
    char err[256], path[4096], cap[2048];
    static adaptive_fig f;
    sus_model m;
    const sus_step_method *me = sus_step_method_by_name("taylor-adaptive");
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0 || !me) {
        fprintf(stderr, "figure_adaptive_steps: the paper's body or the method: %s\n", err);
        return 1;
    }
    double tol_col[NTOL * MAXSTEPS], t_col[NTOL * MAXSTEPS], h_col[NTOL * MAXSTEPS],
        r_col[NTOL * MAXSTEPS];
    size_t n = 0;
    for (int i = 0; i < NTOL; i++) {
        if (measure(&m, me->type, i, &f) != 0) {
            fprintf(stderr, "figure_adaptive_steps: the run at TOL %g failed\n", TOLS[i]);
            return 1;
        }
        for (long k = 0; k < f.s[i].n; k++, n++) {
            tol_col[n] = TOLS[i];
            t_col[n] = f.s[i].t[k];
            h_col[n] = f.s[i].h[k];
            r_col[n] = f.s[i].radius[k];
        }
    }
    const double *cols[] = {tol_col, t_col, h_col, r_col};
    if (sus_plot_fig_write_csv(
            sus_plot_fig_path(path, sizeof path, argv[2], "adaptive_steps", "csv"),
            "tol,t_start,h,proved_radius", 4, cols, n, 1) != 0)
        return 1;
    snprintf(cap, sizeof cap,
             "The tolerance-driven Taylor method. Regenerate: make "
             "figures (src/prog/figure_adaptive_steps.c).\n"
             "taylor-adaptive (suslov --method taylor-adaptive --tol TOL "
             "--time 50) on the paper's body, w(0) = (0.4, 0.5).\n"
             "(a) the length of each accepted step against its start (the last one ends "
             "at t = 50), for TOL = %.0e, %.0e, %.0e (orders %d, %d, %d), and the\n"
             "radius its series is proved to converge in (dashed grey; no step may exceed it).\n"
             "(b) the attitude error dist(R(t), R_k) of rows R_k every 0.5 "
             "time units (dense output from each step's series)\n"
             "against the long-double reference; dotted: TOL.\n"
             "Data: data/adaptive_steps.csv (the steps).\n",
             TOLS[0], TOLS[1], TOLS[2], f.order[0], f.order[1], f.order[2]);
    return sus_plot_fig_write_figure(argv[1], "adaptive_steps", 560, 300, draw, &f, cap) != 0;
}
