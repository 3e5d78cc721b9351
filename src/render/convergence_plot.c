/* The convergence figures: local and global errors against eps, in w, on SO(3) and in lambda,
 * for the registered methods a figure selects (src/figure_convergence*.c). One program per
 * figure; this file holds what they share: the sweep, the six panels and the data file. */
#include "convergence_plot.h"

#include "fig_output.h"
#include "fig_setup.h"
#include "orderfit.h"
#include "plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NJ SUS_LAB_CONV_NJ
static const double TK[] = {0.0, 3.0, 7.0, 12.0, 20.0};
#define T_GLOBAL 10.0
/* Three rows of panels at the page's figure scale; the caption says what is local and global. */
#define CONV_W 560.0
#define CONV_H 620.0

/* Method m's colour and marker: colours cycle through a colour-blind-safe set, markers through
 * the five shapes, so neighbours in the registry never share both. */
static sus_plot_style method_style(int m, int dashed, int with_label)
{
    static const int mk[] = {SUS_PLOT_SQUARE, SUS_PLOT_CIRCLE, SUS_PLOT_TRIANGLE, SUS_PLOT_DIAMOND,
                             SUS_PLOT_CROSS};
    const int nmk = (int)(sizeof mk / sizeof mk[0]);
    return sus_plot_style_of(SUS_PLOT_PALETTE[m % SUS_PLOT_PALETTE_N], 1.0, dashed, mk[m % nmk],
                             4.2, with_label ? sus_step_method_get(m)->type->name : NULL);
}

/* The error curve `what` of method m; so3 curves pick reconstruction r. */
enum { LOC_W, GLOB_W, LOC_SO3, GLOB_SO3, LOC_LAMBDA, GLOB_LAMBDA };
static const double *curve(const sus_plot_conv_fig *f, int m, int what, int r)
{
    const sus_lab_conv_method *c = &f->c.m[m];
    switch (what) {
        case LOC_W: return c->loc_w;
        case GLOB_W: return c->glob_w;
        case LOC_SO3: return c->loc_so3[r];
        case GLOB_SO3: return c->glob_so3[r];
        case LOC_LAMBDA: return c->loc_lambda;
        default: return c->glob_lambda;
    }
}

/* The least-squares slope of one curve over the ledger's window, as the legend prints it. */
static void slope_text(const double *eps, const double *err, int nj, double size, char *out,
                       size_t len)
{
    sus_lab_order_fit fit;
    if (sus_lab_fit_order(eps, err, nj, SUS_LAB_FIT_EPS_MAX, SUS_LAB_FIT_FLOOR_REL * size, &fit) !=
        0)
        snprintf(out, len, "none");
    else
        snprintf(out, len, "%.2f", fabs(fit.slope) < 0.005 ? 0.0 : fit.slope);
}

/* How many of the registry's methods the figure draws: one legend line each. */
static int drawn_methods(const sus_plot_conv_fig *f)
{
    int n = 0;
    for (int m = 0; m < f->c.nmethod; m++)
        n += f->spec->select(sus_step_method_get(m)) != 0;
    return n;
}

/* The strip above the panels: a figure's one legend (SUS_PLOT_CONV_LEGEND_ABOVE), in STRIP_COLS
 * columns, the curves' names and the reconstructions' line styles; or, when each panel has its own
 * legend, the line styles alone. The strip's height. */
#define STRIP_COLS 6
static double strip_height(const sus_plot_conv_fig *f)
{
    if (f->spec->legend == SUS_PLOT_CONV_LEGEND_PANELS)
        return sus_plot_legend_height(1) + 8.0;
    const int n = drawn_methods(f) + 2; /* and the two line styles */
    return sus_plot_legend_height((n + STRIP_COLS - 1) / STRIP_COLS) + 10.0;
}

/* Each panel's legend (SUS_PLOT_CONV_LEGEND_PANELS) sits above its plot area, beside its letter,
 * in the room the panel's top margin leaves and a strip this much taller: one line per method. */
static double panel_strip(const sus_plot_conv_fig *f)
{
    if (f->spec->legend != SUS_PLOT_CONV_LEGEND_PANELS)
        return 0.0;
    return fmax(0.0, sus_plot_legend_height(drawn_methods(f)) - 30.0);
}

/* The axes of panel idx. Its y-range is its data's, widened by a factor Y_MARGIN each way so that
 * no marker is cut by the frame, and no more: no legend is drawn inside a panel, so none needs
 * room. */
#define Y_MARGIN 2.0
static void panel_axes(sus_plot_axes *ax, cairo_t *cr, const sus_plot_conv_fig *f, int idx,
                       double lo, double hi)
{
    const double x0 = f->c.eps[NJ - 1], x1 = f->c.eps[f->j0], strip = panel_strip(f);
    if (strip <= 0.0) {
        sus_plot_axes_cell(ax, cr, CONV_W, CONV_H, 3, 2, idx, x0, x1, lo, hi, 1, 1);
    } else { /* each row of two panels under its legends' strip, the figure no taller than CONV_H */
        const double row_h = (CONV_H - strip_height(f)) / 3.0;
        sus_plot_axes_cell(ax, cr, CONV_W, row_h - strip, 1, 2, idx % 2, x0, x1, lo, hi, 1, 1);
        ax->y += (idx / 2) * row_h + strip;
    }
    if (lo > 0.0 && lo <= hi && isfinite(hi)) { /* else the cell's default range */
        ax->y0 = lo / Y_MARGIN;
        ax->y1 = hi * Y_MARGIN;
    }
}

/* The legend of panel `what`: one entry per curve (with its fitted slopes when the figure says so),
 * then, with keys, on SO(3) the two reconstructions' line styles. labels holds the texts (nmethod +
 * 2 of them). Returns the number of entries. */
static int panel_legend(const sus_plot_conv_fig *f, int what, const double *eps, int nj,
                        double size, int keys, char (*labels)[96], sus_plot_style *leg)
{
    const int nm = f->c.nmethod, so3 = what == LOC_SO3 || what == GLOB_SO3, j0 = f->j0;
    int nleg = 0;
    for (int m = 0; m < nm; m++) {
        if (!f->spec->select(sus_step_method_get(m)))
            continue;
        /* the legend carries the least-squares slope over the ledger's window: of the solid
         * curve, and on SO(3) of the dashed one after it */
        char sl[32], sd[48] = "";
        slope_text(eps, curve(f, m, what, f->spec->solid) + j0, nj, size, sl, sizeof sl);
        if (so3) {
            char t[32];
            slope_text(eps, curve(f, m, what, f->spec->dashed) + j0, nj, size, t, sizeof t);
            snprintf(sd, sizeof sd, ", dashed %s", t);
        }
        const char *name = sus_step_method_get(m)->type->name;
        if (!f->spec->legend_slopes)
            snprintf(labels[m], sizeof labels[m], "%s", name);
        else
            snprintf(labels[m], sizeof labels[m], "%s, slope %s%s", name, sl, sd);
        leg[nleg] = method_style(m, 0, 1);
        leg[nleg++].label = labels[m];
    }
    if (so3 && keys) {
        snprintf(labels[nm], sizeof labels[nm], "solid: %s", SUS_RECON_NAMES[f->spec->solid]);
        snprintf(labels[nm + 1], sizeof labels[nm + 1], "dashed: %s",
                 SUS_RECON_NAMES[f->spec->dashed]);
        leg[nleg++] = sus_plot_style_of(SUS_PLOT_GREY, 1.0, 0, SUS_PLOT_NONE, 0, labels[nm]);
        leg[nleg++] = sus_plot_style_of(SUS_PLOT_GREY, 1.0, 1, SUS_PLOT_NONE, 0, labels[nm + 1]);
    }
    return nleg;
}

/* One log-log panel of curve `what` (and, for SO(3), the spec's dashed reconstruction), with its
 * legend above it when the figure has one per panel. */
static void panel(cairo_t *cr, int idx, const sus_plot_conv_fig *f, int what, const char *ylabel,
                  const char *letter, double size)
{
    const int nm = f->c.nmethod, so3 = what == LOC_SO3 || what == GLOB_SO3, j0 = f->j0,
              nj = NJ - f->j0;
    const int global = what == GLOB_W || what == GLOB_SO3 || what == GLOB_LAMBDA;
    const double *eps = (global ? f->c.glob_eps : f->c.eps) + j0;
    char(*labels)[96] = calloc((size_t)nm + 2, sizeof *labels);
    sus_plot_style *leg = calloc((size_t)nm + 3, sizeof *leg);
    if (!labels || !leg) {
        free(labels);
        free(leg);
        return;
    }
    double lo = INFINITY, hi = -INFINITY;
    for (int m = 0; m < nm; m++) {
        if (!f->spec->select(sus_step_method_get(m)))
            continue;
        sus_plot_extend(&lo, &hi, curve(f, m, what, f->spec->solid) + j0, (size_t)nj, 1, 1);
        if (so3)
            sus_plot_extend(&lo, &hi, curve(f, m, what, f->spec->dashed) + j0, (size_t)nj, 1, 1);
    }
    lo = fmax(lo, 1e-17);
    const int nleg = panel_legend(f, what, eps, nj, size, 0, labels, leg);
    sus_plot_axes ax;
    panel_axes(&ax, cr, f, idx, lo, hi);
    sus_plot_frame(&ax, "\xce\xb5", ylabel, letter);
    for (int m = 0, k = 0; m < nm; m++) {
        if (!f->spec->select(sus_step_method_get(m)))
            continue;
        const double *err = curve(f, m, what, f->spec->solid) + j0;
        sus_plot_series(&ax, eps, err, (size_t)nj, 1, &leg[k]);
        sus_plot_markers(&ax, eps, err, (size_t)nj, 1, &leg[k++]);
        if (so3) {
            const sus_plot_style d = method_style(m, 1, 0);
            sus_plot_series(&ax, eps, curve(f, m, what, f->spec->dashed) + j0, (size_t)nj, 1, &d);
        }
    }
    if (f->spec->legend == SUS_PLOT_CONV_LEGEND_PANELS) { /* its bottom 4 points over the frame */
        sus_plot_axes la;
        sus_plot_axes_init(&la, cr, ax.x, ax.y - sus_plot_legend_height(nleg) - 8.0, 1, 1, 0, 1, 0,
                           1, 0, 0);
        sus_plot_legend(&la, leg, nleg, 0);
    }
    free(labels);
    free(leg);
}

static void draw_strip(cairo_t *cr, const sus_plot_conv_fig *f)
{
    const int nm = f->c.nmethod;
    char(*labels)[96] = calloc((size_t)nm + 2, sizeof *labels);
    sus_plot_style *leg = calloc((size_t)nm + 3, sizeof *leg);
    if (labels && leg) {
        const int n =
            panel_legend(f, LOC_SO3, f->c.eps + f->j0, NJ - f->j0, SUS_LAB_SIZE_R, 1, labels, leg);
        if (f->spec->legend == SUS_PLOT_CONV_LEGEND_PANELS)
            sus_plot_legend_packed(cr, 64.0, 0.0, leg + n - 2, 2, 2);
        else
            sus_plot_legend_packed(cr, 64.0, 6.0, leg, n, STRIP_COLS);
    }
    free(labels);
    free(leg);
}

static void draw(cairo_t *cr, void *vctx)
{
    const sus_plot_conv_fig *f = vctx;
    draw_strip(cr, f);
    cairo_translate(cr, 0.0, strip_height(f));
    panel(cr, 0, f, LOC_W,
          "local |\xcf\x89(t\xe2\x82\x96+\xce\xb5) \xe2\x88\x92 "
          "\xcf\x89\xe2\x82\x96\xe2\x82\x8a\xe2\x82\x81|",
          "(a)", SUS_LAB_SIZE_W);
    panel(cr, 1, f, GLOB_W, "global |\xcf\x89(10) \xe2\x88\x92 \xcf\x89\xe2\x82\x99|", "(b)",
          SUS_LAB_SIZE_W);
    panel(cr, 2, f, LOC_SO3,
          "local dist(R(t\xe2\x82\x96+\xce\xb5), R\xe2\x82\x96\xe2\x82\x8a\xe2\x82\x81)", "(c)",
          SUS_LAB_SIZE_R);
    panel(cr, 3, f, GLOB_SO3, "global dist(R(10), R\xe2\x82\x99)", "(d)", SUS_LAB_SIZE_R);
    panel(cr, 4, f, LOC_LAMBDA,
          "local |\xce\xbb(t\xe2\x82\x96+\xce\xb5) \xe2\x88\x92 "
          "\xce\xbb\xe2\x82\x96\xe2\x82\x8a\xe2\x82\x81|",
          "(e)", SUS_LAB_SIZE_LAMBDA);
    panel(cr, 5, f, GLOB_LAMBDA, "global |\xce\xbb(10) \xe2\x88\x92 \xce\xbb\xe2\x82\x99|", "(f)",
          SUS_LAB_SIZE_LAMBDA);
}

/* DATADIR/NAME.csv: eps and, per selected method, its error curves (w, lambda, and SO(3) per
 * reconstruction, local then global). Returns 0, or 1. */
static int write_data(const sus_plot_conv_fig *f, const char *datadir)
{
    char path[4096];
    enum { NQ = 4 + 2 * SUS_RECON_COUNT };
    const int nm = f->c.nmethod;
    const double **cols = calloc(2 + (size_t)NQ * (size_t)nm, sizeof *cols);
    char *header = calloc(64 * (2 + (size_t)NQ * (size_t)nm), 1);
    if (!cols || !header)
        return 1;
    size_t len = (size_t)sprintf(header, "eps,global_eps");
    int nc = 0;
    cols[nc++] = f->c.eps;
    cols[nc++] = f->c.glob_eps;
    for (int k = 0; k < nm; k++) {
        if (!f->spec->select(sus_step_method_get(k)))
            continue;
        const char *name = sus_step_method_get(k)->type->name;
        const sus_lab_conv_method *c = &f->c.m[k];
        cols[nc++] = c->loc_w;
        cols[nc++] = c->loc_lambda;
        len += (size_t)sprintf(header + len, ",local_w_%s,local_lambda_%s", name, name);
        for (int r = 0; r < SUS_RECON_COUNT; r++) {
            cols[nc++] = c->loc_so3[r];
            len += (size_t)sprintf(header + len, ",local_so3_%s_%s", SUS_RECON_NAMES[r], name);
        }
        cols[nc++] = c->glob_w;
        cols[nc++] = c->glob_lambda;
        len += (size_t)sprintf(header + len, ",global_w_%s,global_lambda_%s", name, name);
        for (int r = 0; r < SUS_RECON_COUNT; r++) {
            cols[nc++] = c->glob_so3[r];
            len += (size_t)sprintf(header + len, ",global_so3_%s_%s", SUS_RECON_NAMES[r], name);
        }
    }
    sus_plot_fig_path(path, sizeof path, datadir, f->spec->name, "csv");
    const int rc = sus_plot_fig_write_csv(path, header, nc, cols, NJ, 1) != 0;
    free(cols);
    free(header);
    return rc;
}

int sus_plot_conv_figure_main(int argc, char **argv, const sus_plot_conv_figure_spec *spec)
{
    sus_model m;
    sus_exact ex;
    const int setup = sus_plot_fig_setup_paper(argc, spec->name, &m, &ex);
    if (setup != 0)
        return setup;
    sus_plot_conv_fig *f = malloc(sizeof *f);
    if (!f ||
        sus_lab_convergence_run(&f->c, &ex, TK, (int)(sizeof TK / sizeof TK[0]), T_GLOBAL) != 0)
        return 1;
    f->spec = spec;
    for (f->j0 = 0; f->j0 < NJ && f->c.eps[f->j0] > spec->eps_plot_max; f->j0++)
        ;
    f->o0max = 0.0;
    for (size_t t = 0; t < sizeof TK / sizeof TK[0]; t++) {
        double w[2];
        sus_exact_omega(&ex, TK[t], w);
        f->o0max = fmax(f->o0max, fabs(sus_lagmult_o0(&m, w)));
    }
    if (write_data(f, argv[2]) != 0)
        return 1;
    char cap[4096];
    spec->caption(cap, sizeof cap, f);
    const double height =
        f->spec->legend == SUS_PLOT_CONV_LEGEND_PANELS ? CONV_H : CONV_H + strip_height(f);
    return sus_plot_fig_write_figure(argv[1], spec->name, CONV_W, height, draw, f, cap) != 0;
}
