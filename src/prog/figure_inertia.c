/* The inertia ambiguity: the printed I has I23 = 0.2 but I32 = 0.1. (RGB2)/(ContDyn) use the third
 * row; a symmetric body would have (I31, I32) = (I13, I23). Exact solutions for both.
 * Usage: figure_inertia FIGDIR DATADIR */
#include "experiments.h"
#include "fig_output.h"
#include "plot.h"
#include "series.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#define T_END SUS_LAB_INERTIA_T_END
#define DT SUS_LAB_INERTIA_DT
#define NPTS 1201 /* T_END / DT + 1, checked in main */
#define FIG_W 530.0
#define FIG_H 340.0

typedef struct {
    sus_lab_series row, col;
    double dist[NPTS];
    double k_row, k_col;
} inertia_fig;

static void draw(cairo_t *cr, void *vctx)
{
    const inertia_fig *f = vctx;
    const double W = FIG_W, H = FIG_H;
    const sus_plot_style r1 =
        sus_plot_style_of(SUS_PLOT_RED, 1.4, 0, SUS_PLOT_NONE, 0,
                          "\xcf\x89\xe2\x82\x81, third row (0.2, 0.1) as printed");
    const sus_plot_style r2 = sus_plot_style_of(SUS_PLOT_RED, 1.4, 1, SUS_PLOT_NONE, 0,
                                                "\xcf\x89\xe2\x82\x82, third row");
    const sus_plot_style c1 = sus_plot_style_of(SUS_PLOT_BLUE, 1.4, 0, SUS_PLOT_NONE, 0,
                                                "\xcf\x89\xe2\x82\x81, third column (0.2, 0.2)");
    const sus_plot_style c2 = sus_plot_style_of(SUS_PLOT_BLUE, 1.4, 1, SUS_PLOT_NONE, 0,
                                                "\xcf\x89\xe2\x82\x82, third column");
    sus_plot_axes ax;
    double lo = INFINITY, hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->row.w1, f->row.n, 1, 0);
    sus_plot_extend(&lo, &hi, f->row.w2, f->row.n, 1, 0);
    sus_plot_extend(&lo, &hi, f->col.w1, f->col.n, 1, 0);
    sus_plot_extend(&lo, &hi, f->col.w2, f->col.n, 1, 0);
    sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 0, 0, T_END, lo, hi, 0, 0);
    sus_plot_frame(&ax, "t", "\xcf\x89 (exact)", "(a)");
    sus_plot_series(&ax, f->row.t, f->row.w1, f->row.n, 1, &r1);
    sus_plot_series(&ax, f->row.t, f->row.w2, f->row.n, 1, &r2);
    sus_plot_series(&ax, f->col.t, f->col.w1, f->col.n, 1, &c1);
    sus_plot_series(&ax, f->col.t, f->col.w2, f->col.n, 1, &c2);
    lo = INFINITY;
    hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->row.lambda, f->row.n, 1, 0);
    sus_plot_extend(&lo, &hi, f->col.lambda, f->col.n, 1, 0);
    sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 1, 0, T_END, lo, hi, 0, 0);
    sus_plot_frame(&ax, "t", "\xce\xbb (exact)", "(b)");
    const sus_plot_style lr =
        sus_plot_style_of(SUS_PLOT_RED, 1.4, 0, SUS_PLOT_NONE, 0, "third row");
    const sus_plot_style lc =
        sus_plot_style_of(SUS_PLOT_BLUE, 1.4, 0, SUS_PLOT_NONE, 0, "third column");
    sus_plot_series(&ax, f->row.t, f->row.lambda, f->row.n, 1, &lr);
    sus_plot_series(&ax, f->col.t, f->col.lambda, f->col.n, 1, &lc);
    const sus_plot_style legb[2] = {lr, lc};
    sus_plot_legend(&ax, legb, 2, 3);
    lo = INFINITY;
    hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->dist, f->row.n, 1, 0);
    sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 2, 0, T_END, 0.0, hi, 0, 0);
    sus_plot_frame(&ax, "t", "|\xcf\x89(row) \xe2\x88\x92 \xcf\x89(column)|", "(c)");
    const sus_plot_style d = sus_plot_style_of(SUS_PLOT_BLACK, 1.4, 0, SUS_PLOT_NONE, 0, NULL);
    sus_plot_series(&ax, f->row.t, f->dist, f->row.n, 1, &d);
    /* (d): the key of (a); the rates and limits are in the caption */
    double x, y, w, h;
    sus_plot_cell(W, H, 2, 2, 3, &x, &y, &w, &h);
    sus_plot_axes_init(&ax, cr, x - 40, y, w + 40, h, 0, 1, 0, 1, 0, 0);
    const sus_plot_style lega[4] = {r1, r2, c1, c2};
    sus_plot_legend(&ax, lega, 4, 4);
}

/* The exact solutions for the printed third row and for the third column, their distance, and
 * their limits (the steady rotations): 0, or 1 (said). */
static int solve(inertia_fig *f, double lr[2], double lc[2])
{
    char err[256];
    double Icol[9];
    sus_model mr, mc;
    sus_exact er, ec;
    sus_lab_inertia_column_swap(SUS_PAPER_INERTIA, Icol); /* (I31, I32) := (I13, I23) */
    if (sus_model_init(&mr, SUS_PAPER_INERTIA, err, sizeof err) ||
        sus_model_init(&mc, Icol, err, sizeof err)) {
        fprintf(stderr, "figure_inertia: an inertia tensor is rejected: %s\n", err);
        return 1;
    }
    sus_exact_init(&er, &mr, SUS_PAPER_OMEGA0);
    sus_exact_init(&ec, &mc, SUS_PAPER_OMEGA0);
    f->k_row = er.k;
    f->k_col = ec.k;
    if (sus_lab_series_init(&f->row, NPTS - 1, 1) || sus_lab_series_init(&f->col, NPTS - 1, 1))
        return 1;
    sus_lab_series_exact(&f->row, &er, DT, NPTS);
    sus_lab_series_exact(&f->col, &ec, DT, NPTS);
    for (size_t i = 0; i < f->row.n; i++)
        f->dist[i] = hypot(f->row.w1[i] - f->col.w1[i], f->row.w2[i] - f->col.w2[i]);
    sus_exact_limit(&er, lr);
    sus_exact_limit(&ec, lc);
    return 0;
}

static int write_data(const inertia_fig *f, const char *datadir)
{
    char path[4096];
    const double *cols[] = {f->row.t,  f->row.w1, f->row.w2,    f->row.lambda,
                            f->col.w1, f->col.w2, f->col.lambda};
    return sus_plot_fig_write_csv(
        sus_plot_fig_path(path, sizeof path, datadir, "inertia", "csv"),
        "t,omega1_row,omega2_row,lambda_row,omega1_col,omega2_col,lambda_col", 7, cols, f->row.n,
        1);
}

static void caption(char *cap, size_t len, const inertia_fig *f, const double lr[2],
                    const double lc[2])
{
    double maxd = 0.0;
    for (size_t i = 0; i < f->row.n; i++)
        maxd = fmax(maxd, f->dist[i]);
    snprintf(cap, len,
             "The inertia ambiguity. Regenerate: make figures (src/prog/figure_inertia.c).\n"
             "The paper prints I = [[1,0.1,0.2],[0.1,1,0.2],[0.2,0.1,1]], "
             "which is not symmetric. (RGB2), (ContDyn)\n"
             "and (LagMult) use I_m and the third row (I31, I32) = (0.2, "
             "0.1) (red; all other figures); a symmetric body with the\n"
             "printed third column would have (0.2, 0.2) (blue). "
             "Exact solutions, w(0) = (0.4, 0.5), t in [0, %g].\n"
             "(a) w1 (solid), w2 (dashed); (b) lambda; (c) |w_row "
             "- w_col|, at most %.3f. Steady rotations:\n"
             "row (%.4f, %.4f), column (%.4f, %.4f); rates k = %.4f and %.4f.\n"
             "Data: data/inertia.csv.\n",
             T_END, maxd, lr[0], lr[1], lc[0], lc[1], f->k_row, f->k_col);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: figure_inertia FIGDIR DATADIR\n");
        return 2;
    }
    gsl_set_error_handler_off();
    static inertia_fig f;
    if (sus_lab_experiment_steps(T_END, DT) + 1 != NPTS) {
        fprintf(stderr, "figure_inertia: NPTS does not match src/lab/experiments.h\n");
        return 1;
    }
    double lr[2], lc[2];
    if (solve(&f, lr, lc) != 0 || write_data(&f, argv[2]) != 0)
        return 1;
    char cap[2048];
    caption(cap, sizeof cap, &f, lr, lc);
    return sus_plot_fig_write_figure(argv[1], "inertia", FIG_W, FIG_H, draw, &f, cap) != 0;
}
