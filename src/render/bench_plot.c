#include "bench_plot.h"

#include "plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Whether series a and b of ours run the same method: their names start with it ("comp6-kl +
 * cayley-mid", "taylor8 (w only)"), in a live run and in one read back from bench.csv alike. */
static int same_method(const sus_lab_bench_series *a, const sus_lab_bench_series *b)
{
    const size_t n = strcspn(a->name, " ");
    return a->ours && b->ours && n == strcspn(b->name, " ") && strncmp(a->name, b->name, n) == 0;
}

/* Whether series j is the first of ours to run its method. */
static int first_of_method(const sus_lab_bench *b, int j)
{
    if (!b->S[j]->ours)
        return 0;
    for (int k = 0; k < j; k++)
        if (same_method(b->S[k], b->S[j]))
            return 0;
    return 1;
}

/* Series i's method among ours (0, 1, ... in order of first appearance; *nmethods in all) and, in
 * *nth, how many of that method's series come before it: the variants of a method (another
 * reconstruction, w alone) share its hue and marker and differ by dash, so that the legend's
 * series need half as many hues. */
static int method_slot(const sus_lab_bench *b, int i, int *nth, int *nmethods)
{
    int slot = 0, seen = 0;
    *nth = *nmethods = 0;
    for (int j = 0; j < b->nseries; j++) {
        const int same = same_method(b->S[j], b->S[i]);
        *nmethods += first_of_method(b, j);
        if (same && j < i)
            (*nth)++;
        if (same && !seen)
            slot = *nmethods - 1, seen = 1;
    }
    return slot;
}

/* A series' colour: ours take hues around the wheel, the k-th of n methods the k-th hue; peers
 * grey (on the reduced problem a bluer grey). */
static void series_colour(const sus_lab_bench_series *s, int k, int n, double rgb[3])
{
    if (!s->ours) {
        rgb[0] = rgb[1] = rgb[2] = 0.62;
        if (s->reduced)
            rgb[0] = rgb[1] = 0.66, rgb[2] = 0.82;
        return;
    }
    const double h = 6.0 * (double)k / (double)n, x = 1.0 - fabs(fmod(h, 2.0) - 1.0), v = 0.85;
    /* the hue's sector: which of r, g, b is full, which is x */
    static const int full[6] = {0, 1, 1, 2, 2, 0}, part[6] = {1, 0, 2, 1, 0, 2};
    const int sector = (int)h < 5 ? (int)h : 5;
    double c[3] = {0, 0, 0};
    c[full[sector]] = 1;
    c[part[sector]] = x;
    rgb[0] = v * c[0];
    rgb[1] = v * c[1] * 0.85;
    rgb[2] = v * c[2];
}

/* Portrait: at the page's figure scale the text prints at 7 pt and the width fits the text
 * block. */
#define WP_W 530.0
#define WP_PANEL_H 230.0
#define WP_LEGEND_Y (28.0 + WP_PANEL_H + 30.0)

/* The styles of the series: ours with a marker per method in turn, a method's first series solid
 * and its others dashed; peers as grey dots without a label (on the reduced problem, dashed). */
static void wp_styles(const sus_lab_bench *b, sus_plot_style *st, double (*rgb)[3])
{
    static const int mk[6] = {SUS_PLOT_CIRCLE,  SUS_PLOT_SQUARE, SUS_PLOT_TRIANGLE,
                              SUS_PLOT_DIAMOND, SUS_PLOT_CROSS,  SUS_PLOT_DOT};
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        int nth = 0, n = 0;
        const int k = s->ours ? method_slot(b, i, &nth, &n) : 0;
        series_colour(s, k, n, rgb[i]);
        st[i] = sus_plot_style_of(rgb[i], s->ours ? 1.1 : 0.5, s->ours ? nth > 0 : s->reduced,
                                  s->ours ? mk[k % 6] : SUS_PLOT_DOT, s->ours ? 3.5 : 2.0,
                                  s->ours ? s->name : NULL);
    }
}

/* The lower envelopes of the peers: on the full problem solid, on the reduced one dashed. */
static sus_plot_style envelope_style(int reduced)
{
    return sus_plot_style_of(SUS_PLOT_BLACK, reduced ? 1.6 : 2.2, reduced, SUS_PLOT_NONE, 0,
                             reduced ? "peers given w(t): lower envelope"
                                     : "peers, full problem: lower envelope");
}

/* Whether panel p draws series s: (a) the w error, not of the reduced problem (given w); (b) the
 * attitude error, not of w alone. */
static int in_panel(const sus_lab_bench_series *s, int p) { return p ? !s->w_only : !s->reduced; }

/* The dotted lines at the target accuracies. */
static void level_lines(const sus_plot_axes *ax)
{
    const sus_plot_style ls = sus_plot_style_of(SUS_PLOT_GREY, 0.3, 2, SUS_PLOT_NONE, 0, NULL);
    for (int l = 0; l < SUS_LAB_BENCH_NLEVELS; l++) {
        const double yy[2] = {SUS_LAB_BENCH_LEVELS[l], SUS_LAB_BENCH_LEVELS[l]},
                     xx[2] = {ax->x0, ax->x1};
        sus_plot_series(ax, xx, yy, 2, 1, &ls);
    }
}

/* The axes of panel p ((a) the w error, (b) the attitude error) at (x, y), w wide: every point
 * it draws. */
static void wp_axes(cairo_t *cr, const sus_lab_bench *b, int p, double x, double y, double w,
                    sus_plot_axes *ax)
{
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < b->nseries; i++) {
        if (!in_panel(b->S[i], p))
            continue;
        sus_plot_extend(&x0, &x1, b->S[i]->sec, (size_t)b->S[i]->n, 1, 1);
        sus_plot_extend(&y0, &y1, p ? b->S[i]->err_R : b->S[i]->err_w, (size_t)b->S[i]->n, 1, 1);
    }
    sus_plot_axes_init(ax, cr, x, y, w, WP_PANEL_H, x0, x1, fmax(y0, 1e-17), fmin(y1, 1.0), 1, 1);
    sus_plot_pad(&ax->x0, &ax->x1, 1);
    sus_plot_pad(&ax->y0, &ax->y1, 1);
}

#define ATT_LABEL "attitude error dist(R(50), R\xe2\x82\x99)"

/* Panel p: (a) the w error, (b) the attitude error. */
static void wp_panel(cairo_t *cr, const sus_lab_bench *b, int p, const sus_plot_style *st)
{
    sus_plot_axes ax;
    wp_axes(cr, b, p, 58 + p * (WP_W / 2), 28, WP_W / 2 - 75, &ax);
    sus_plot_frame(&ax, "seconds per run",
                   p ? ATT_LABEL : "|\xcf\x89(50) \xe2\x88\x92 \xcf\x89\xe2\x82\x99|",
                   p ? "(b)" : "(a)");
    for (int pass = 0; pass < 2; pass++) /* peers first, underneath */
        for (int i = 0; i < b->nseries; i++) {
            const sus_lab_bench_series *s = b->S[i];
            if (s->ours != pass || !in_panel(s, p))
                continue;
            sus_plot_series(&ax, s->sec, p ? s->err_R : s->err_w, (size_t)s->n, 1, &st[i]);
            sus_plot_markers(&ax, s->sec, p ? s->err_R : s->err_w, (size_t)s->n, 1, &st[i]);
        }
    const sus_plot_style es = envelope_style(0), er = envelope_style(1);
    sus_plot_series(&ax, b->env[p].sec, b->env[p].err, (size_t)b->env[p].n, 1, &es);
    if (p)
        sus_plot_series(&ax, b->env[2].sec, b->env[2].err, (size_t)b->env[2].n, 1, &er);
    level_lines(&ax);
}

/* Whether one of series s's attitude points lies on our lower envelope e. */
static int on_envelope(const sus_lab_bench_series *s, const sus_lab_bench_envelope *e)
{
    for (int j = 0; j < s->n; j++)
        for (int k = 0; k < e->n; k++)
            if (s->sec[j] == e->sec[k] && s->err_R[j] == e->err[k])
                return 1;
    return 0;
}

/* The panel of work_precision_best: wider than (b)'s, its legend (about 190 points) beside it. */
#define BEST_W (WP_W - 58 - 200)

/* work_precision_best: (b) with only our best, the series of ours with a point on our lower
 * envelope (bench_floor.h), over the peers' two envelopes; its legend to the right. */
static void draw_best(cairo_t *cr, void *vctx)
{
    const sus_lab_bench *b = vctx;
    sus_plot_style *st = sus_lab_bench_calloc((size_t)b->nseries, sizeof *st);
    double(*rgb)[3] = sus_lab_bench_calloc((size_t)b->nseries, sizeof *rgb);
    wp_styles(b, st, rgb);
    sus_plot_axes ax;
    wp_axes(cr, b, 1, 58, 14, BEST_W, &ax);
    sus_plot_frame(&ax, "seconds per run", ATT_LABEL, NULL);
    const sus_plot_style es = envelope_style(0), er = envelope_style(1);
    sus_plot_series(&ax, b->env[1].sec, b->env[1].err, (size_t)b->env[1].n, 1, &es);
    sus_plot_series(&ax, b->env[2].sec, b->env[2].err, (size_t)b->env[2].n, 1, &er);
    sus_plot_style *leg = sus_lab_bench_calloc((size_t)b->nseries + 2, sizeof *leg);
    int n = 0;
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        if (!s->ours || s->w_only || !on_envelope(s, &b->env[3]))
            continue;
        leg[n] = st[i];
        leg[n].width = 2.0; /* the few lines of this panel, drawn as the envelopes are */
        sus_plot_series(&ax, s->sec, s->err_R, (size_t)s->n, 1, &leg[n]);
        sus_plot_markers(&ax, s->sec, s->err_R, (size_t)s->n, 1, &leg[n]);
        n++;
    }
    level_lines(&ax);
    leg[n++] = es, leg[n++] = er;
    sus_plot_legend_packed(cr, 58 + BEST_W + 12, 24, leg, n, 1);
    free(leg);
    free(st);
    free(rgb);
}

static void draw_wp(cairo_t *cr, void *vctx)
{
    const sus_lab_bench *b = vctx;
    sus_plot_style *st = sus_lab_bench_calloc((size_t)b->nseries, sizeof *st);
    sus_plot_style *ours = sus_lab_bench_calloc((size_t)b->nseries + 2, sizeof *ours);
    double(*rgb)[3] = sus_lab_bench_calloc((size_t)b->nseries, sizeof *rgb);
    wp_styles(b, st, rgb);
    for (int p = 0; p < 2; p++)
        wp_panel(cr, b, p, st);
    /* legend of (a) and (b): ours and the peers' two envelopes in two columns below the panels;
     * what the peers were given is in the caption (paper/methods.tex), not a box of text */
    int nours = 0;
    for (int i = 0; i < b->nseries; i++)
        if (b->S[i]->ours)
            ours[nours++] = st[i];
    ours[nours++] = envelope_style(0);
    ours[nours++] = envelope_style(1);
    sus_plot_legend_columns(cr, 12, WP_LEGEND_Y, WP_W - 8, ours, nours);
    free(st);
    free(ours);
    free(rgb);
}

/* ---- the cost of one step ---- */

#define COST_H 280.0

static double cost_width(const sus_lab_bench *b) { return 90.0 + 46.0 * (b->cost.n + 2); }

/* Bar i of nb: the w-step (v1, light) and the whole step (v2, dark; ours only), its name below
 * at 45 degrees and its value above. */
static void cost_bar(const sus_lab_bench *b, const sus_plot_axes *ax, int i, double v1, double v2)
{
    cairo_t *cr = ax->cr;
    const int n = b->cost.n;
    const double bw = ax->w / (n + 2), bx = ax->x + i * bw;
    const double ly0 = log10(ax->y0), span = log10(ax->y1) - ly0;
    const double h1 = (log10(v1) - ly0) / span * ax->h, h2 = (log10(v2) - ly0) / span * ax->h;
    cairo_set_source_rgb(cr, 0.55, 0.70, 0.90);
    cairo_rectangle(cr, bx + 0.12 * bw, ax->y + ax->h - h1, 0.36 * bw, h1);
    cairo_fill(cr);
    if (i < n) {
        cairo_set_source_rgb(cr, 0.15, 0.35, 0.75);
        cairo_rectangle(cr, bx + 0.52 * bw, ax->y + ax->h - h2, 0.36 * bw, h2);
        cairo_fill(cr);
    }
    const char *name = i < n ? b->cost.name[i] : i == n ? "GSL rk4" : "exact \xcf\x89(t)";
    cairo_save(cr);
    cairo_translate(cr, bx + 0.5 * bw, ax->y + ax->h + 5);
    cairo_rotate(cr, 0.7853981633974483); /* 45 degrees */
    cairo_set_source_rgb(cr, 0, 0, 0);
    sus_plot_text(cr, 0, 0, name, 8.0, 0.0, 0.5, 0);
    cairo_restore(cr);
    char lab[32];
    snprintf(lab, sizeof lab, "%.0f", i < n ? v2 : v1);
    sus_plot_text(cr, bx + 0.5 * bw, ax->y + ax->h - fmax(h1, h2) - 8, lab, 7.0, 0.5, 0.0, 0);
}

static void draw_cost(cairo_t *cr, void *vctx)
{
    const sus_lab_bench *b = vctx;
    const int nb = b->cost.n + 2;
    const double W = cost_width(b), H = COST_H;
    sus_plot_text(cr, W / 2, 14, "Cost of one step (median ns; lower is better)", 11, 0.5, 0.5, 1);
    double *v1 = sus_lab_bench_calloc((size_t)nb, sizeof *v1),
           *v2 = sus_lab_bench_calloc((size_t)nb, sizeof *v2);
    for (int m = 0; m < b->cost.n; m++) {
        v1[m] = b->cost.ns_raw[m];
        v2[m] = b->cost.ns_full[m];
    }
    v1[b->cost.n] = v2[b->cost.n] = b->cost.ns_gsl_rk4;
    v1[b->cost.n + 1] = v2[b->cost.n + 1] = b->cost.ns_exact;
    double hi = 0.0;
    for (int i = 0; i < nb; i++)
        hi = fmax(hi, fmax(v1[i], v2[i]));
    sus_plot_axes ax;
    sus_plot_axes_init(&ax, cr, 60, 40, W - 80, H - 100, 0.0, nb, 1.0, hi * 1.5, 0, 1);
    sus_plot_pad(&ax.y0, &ax.y1, 1);
    ax.no_xticks = 1;
    sus_plot_frame(&ax, NULL, "ns per step", NULL);
    for (int i = 0; i < nb; i++)
        cost_bar(b, &ax, i, v1[i], v2[i]);
    const sus_plot_style leg[2] = {sus_plot_style_of((const double[3]){0.55, 0.70, 0.90}, 6.0, 0,
                                                     SUS_PLOT_NONE, 0, "w-step only"),
                                   sus_plot_style_of((const double[3]){0.15, 0.35, 0.75}, 6.0, 0,
                                                     SUS_PLOT_NONE, 0,
                                                     "whole step (w, R): default reconstruction, "
                                                     "or own attitude")};
    sus_plot_legend(&ax, leg, 2, 0);
    free(v1);
    free(v2);
}

/* FIGDIR/NAME.{pdf,png}, w x h, drawn by draw from b; 0, or -1 with a message on stderr. */
static int write_fig(const char *figdir, const char *name, double w, double h,
                     void (*draw)(cairo_t *, void *), const sus_lab_bench *b)
{
    char err[256], path[4096];
    snprintf(path, sizeof path, "%s/%s", figdir, name);
    if (sus_plot_write(path, w, h, draw, (void *)b, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    return 0;
}

int sus_plot_bench_figures(const sus_lab_bench *b, const char *figdir)
{
    int nours = 2; /* the two envelopes */
    for (int i = 0; i < b->nseries; i++)
        nours += b->S[i]->ours;
    /* tall enough for the legend's two columns and no more */
    const double wp_h = WP_LEGEND_Y + sus_plot_legend_height((nours + 1) / 2) + 6.0;
    if (write_fig(figdir, "work_precision", WP_W, wp_h, draw_wp, b) != 0 ||
        write_fig(figdir, "work_precision_best", WP_W, 14 + WP_PANEL_H + 34.0, draw_best, b) != 0)
        return -1;
    return write_fig(figdir, "step_cost", cost_width(b), COST_H, draw_cost, b);
}
