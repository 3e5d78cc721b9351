/* figures/longrun: the structure over a long run, T = 1e4. Our high-order methods and
 * GSL's rk8pd, each run at the step or tolerance that reaches attitude error 1e-10 at t = 50
 * (matched accuracy), sampled 500 times: (a) |R^T R - I| (for rk8pd on (w, q), where R = R(q/|q|)
 * is orthogonal by construction, the drift ||q| - 1| instead; ours as one band), (b) |E - E0|.
 * w3 is exactly 0 for every curve (ours never compute it; the peers integrate w1, w2 only),
 * stated in the caption. Usage: figure_longrun FIGDIR DATADIR */
#include "driver.h"
#include "exact.h"
#include "fig_output.h"
#include "fig_setup.h"
#include "peers.h"
#include "plot.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define T_LONG 1e4
#define T_MATCH 50.0
#define LEVEL 1e-10
#define NS 500
/* Portrait: at the page's figure scale the text prints at 7 pt and the width fits the text block.
 */
#define LR_W 530.0
#define LR_PANEL_H 220.0
#define LR_LEGEND_Y (22.0 + LR_PANEL_H + 40.0)
#define FLOOR 1e-17 /* exact zeros are drawn here on the log axes */

typedef struct {
    char name[80];
    int ours;
    double param;
    double t[NS + 1], orth[NS + 1], energy[NS + 1], w3max;
} curve;

static curve *C; /* one per selected method and peer, allocated once */
static int nc;
static sus_model model;
static sus_exact ex;
static double R50[3][3];

typedef struct {
    curve *c;
    double e0;
    int k;
} sampler;

static int sample(void *vctx, const sus_row *row)
{
    sampler *s = vctx;
    if (s->k > NS)
        return 0;
    curve *c = s->c;
    c->t[s->k] = row->t;
    c->orth[s->k] = fmax(sus_so3_orth_defect(row->R), FLOOR);
    c->energy[s->k] = fmax(fabs(sus_energy(&model, row->w) - s->e0), FLOOR);
    c->w3max = fmax(c->w3max, fabs(row->w[2]));
    s->k++;
    return 0;
}

/* attitude error at t = 50 of a method with N steps */
static double error_at_50(const sus_step_method *me, long N)
{
    sus_row last = {0};
    sus_run_report rep;
    const sus_run_config cfg = {&model, me->type, me->recon, T_MATCH / (double)N, N, N};
    if (sus_run(&cfg, ex.w0, sus_keep_last, &last, &rep) != 0)
        return INFINITY;
    return sus_so3_dist(R50, last.R);
}

static void ours(const sus_step_method *me)
{
    long N = 4;
    while (N < 100000 && !(error_at_50(me, N) <= LEVEL))
        N = (long)ceil(N * 1.189207115002721); /* 2^(1/4) */
    curve *c = &C[nc++];
    const double eps = T_MATCH / (double)N;
    char label[64];
    snprintf(c->name, sizeof c->name, "%s, eps %.3g",
             sus_step_method_label(me->type, me->recon, label, sizeof label), eps);
    c->ours = 1;
    c->param = eps;
    const long steps = lround(T_LONG / eps);
    sampler s = {c, sus_energy(&model, ex.w0), 0};
    const sus_run_config cfg = {&model, me->type,  me->recon, T_LONG / (double)steps,
                                steps,  steps / NS};
    sus_run_report rep;
    sus_run(&cfg, ex.w0, sample, &s, &rep);
}

static void peer(size_t dim)
{
    gsl_odeiv2_system sys = {dim == 11 ? sus_lab_peer_rhs_wR : sus_lab_peer_rhs_wq, NULL, dim,
                             &model};
    double y[11], R[3][3], tol = 1e-3;
    for (; tol >= 1e-14; tol /= 10.0) { /* the loosest tolerance reaching LEVEL at t = 50 */
        gsl_odeiv2_driver *d =
            gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
        double t = 0.0;
        sus_lab_peer_initial(dim, ex.w0, y);
        const int st = gsl_odeiv2_driver_apply(d, &t, T_MATCH, y);
        gsl_odeiv2_driver_free(d);
        sus_lab_peer_attitude(dim, y, R);
        if (st == GSL_SUCCESS && sus_so3_dist(R50, R) <= LEVEL)
            break;
    }
    curve *c = &C[nc++];
    snprintf(c->name, sizeof c->name, "GSL rk8pd on %s, tol %.0e%s",
             dim == 11 ? "(w, R)" : "(w, q)", tol, dim == 11 ? "" : " (||q| - 1|)");
    c->param = tol;
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
    double t = 0.0;
    const double e0 = sus_energy(&model, ex.w0);
    sus_lab_peer_initial(dim, ex.w0, y);
    for (int k = 0; k <= NS; k++) {
        if (k > 0 && gsl_odeiv2_driver_apply(d, &t, T_LONG * k / NS, y) != GSL_SUCCESS)
            break;
        sus_lab_peer_attitude(dim, y, R);
        const double q2 = y[2] * y[2] + y[3] * y[3] + y[4] * y[4] + y[5] * y[5];
        const double nq = dim == 6 ? fabs(sqrt(q2) - 1.0) : 0.0;
        c->t[k] = t;
        c->orth[k] = fmax(dim == 11 ? sus_so3_orth_defect(R) : nq, FLOOR);
        c->energy[k] = fmax(fabs(sus_energy(&model, y) - e0), FLOOR);
    }
    gsl_odeiv2_driver_free(d);
}

/* Panel (a)'s band: at each sample, the least and the largest over our methods of the largest
 * |R^T R - I| each has reached so far. Our curves are round-off, a tangle of lines at one level;
 * what (a) asks is whether they stay there. */
static void ours_band(double lo[NS + 1], double hi[NS + 1], double t[NS + 1])
{
    double so_far[nc > 0 ? nc : 1];
    for (int i = 0; i < nc; i++)
        so_far[i] = 0.0;
    for (int k = 0; k <= NS; k++) {
        lo[k] = INFINITY, hi[k] = 0.0;
        for (int i = 0; i < nc; i++) {
            if (!C[i].ours)
                continue;
            so_far[i] = fmax(so_far[i], C[i].orth[k]);
            lo[k] = fmin(lo[k], so_far[i]);
            hi[k] = fmax(hi[k], so_far[i]);
            t[k] = C[i].t[k];
        }
    }
}

#define BAND_LABEL "ours, in (a): range of max |R\xe1\xb5\x80R \xe2\x88\x92 I| up to t"

static void draw(cairo_t *cr, void *vctx)
{
    (void)vctx;
    const double W = LR_W, band_rgb[3] = {0.55, 0.75, 0.95};
    double lo[NS + 1], hi[NS + 1], t[NS + 1];
    ours_band(lo, hi, t);
    sus_plot_style st[nc + 1];
    int k = 0;
    for (int i = 0; i < nc; i++)
        st[i] = C[i].ours ? sus_plot_style_of(SUS_PLOT_PALETTE[k++ % SUS_PLOT_PALETTE_N], 1.1, 0,
                                              SUS_PLOT_NONE, 0, C[i].name)
                          : sus_plot_style_of(SUS_PLOT_GREY, 1.6, i % 2 ? 2 : 1, SUS_PLOT_NONE, 0,
                                              C[i].name);
    for (int p = 0; p < 2; p++) {
        sus_plot_axes ax;
        sus_plot_axes_init(&ax, cr, 58 + p * (W / 2), 22, W / 2 - 75, LR_PANEL_H, 1.0, T_LONG,
                           1e-17, 1e-4, 1, 1);
        const char *ylabel = p ? "|E \xe2\x88\x92 E\xe2\x82\x80|"
                               : "|R\xe1\xb5\x80R \xe2\x88\x92 I|  "
                                 "(peer on (\xcf\x89, q): ||q| \xe2\x88\x92 1|)";
        sus_plot_frame(&ax, "t", ylabel, p ? "(b)" : "(a)");
        if (!p)
            sus_plot_band(&ax, t + 1, lo + 1, hi + 1, NS, band_rgb);
        for (int i = 0; i < nc; i++)
            if (p || !C[i].ours)
                sus_plot_series(&ax, C[i].t + 1, (p ? C[i].energy : C[i].orth) + 1, NS, 1, &st[i]);
    }
    st[nc] = sus_plot_style_of(band_rgb, 4.0, 0, SUS_PLOT_NONE, 0, BAND_LABEL);
    sus_plot_legend_columns(cr, 12, LR_LEGEND_Y, W - 8, st, nc + 1);
}

/* One row per curve and sample. */
static int write_data(const char *datadir)
{
    const size_t rows = (size_t)nc * (NS + 1);
    double *buf = malloc(4 * rows * sizeof *buf);
    if (!buf)
        return 1;
    double *idx = buf, *t = buf + rows, *o = buf + 2 * rows, *e = buf + 3 * rows;
    size_t n = 0;
    for (int i = 0; i < nc; i++)
        for (int k = 0; k <= NS; k++, n++) {
            idx[n] = i;
            t[n] = C[i].t[k];
            o[n] = C[i].orth[k];
            e[n] = C[i].energy[k];
        }
    const double *cols[] = {idx, t, o, e};
    char path[4096];
    const int rc =
        sus_plot_fig_write_csv(sus_plot_fig_path(path, sizeof path, datadir, "longrun", "csv"),
                               "curve,t,orth_defect,energy_error", 4, cols, n, 1);
    free(buf);
    return rc != 0;
}

static void caption(char *cap, size_t size)
{
    int len = snprintf(
        cap, size,
        "Structure over a long run, T = 1e4. Regenerate: make figures "
        "(src/prog/figure_longrun.c).\n"
        "Each method runs at the step (ours) or tolerance (GSL rk8pd, abs = rel) that reaches "
        "attitude error 1e-10\n"
        "at t = 50 against the long-double reference; 500 samples. (a) |R^T R - I| (for rk8pd "
        "on (w, q) the\n"
        "attitude R(q/|q|) is orthogonal by construction; its drift ||q| - 1| is drawn "
        "instead); ours as one band,\n"
        "from the least to the largest over the methods of each one's max |R^T R - I| up to t "
        "(the curves\n"
        "themselves are round-off, in data/longrun.csv); (b) |E - E0|.\n"
        "Exact zeros are drawn at 1e-17. w3 is exactly 0 for every curve: ours never compute "
        "it, the peers\n"
        "integrate w1, w2 only. Curves (data/longrun.csv, column curve):\n");
    for (int i = 0; i < nc && len < (int)size; i++) {
        double mo = 0.0, me = 0.0;
        for (int k = 0; k <= NS; k++) {
            mo = fmax(mo, C[i].orth[k]);
            me = fmax(me, C[i].energy[k]);
        }
        len += snprintf(cap + len, size - (size_t)len,
                        "  %d: %s: max |R^T R - I| %.2g, max |E - E0| %.2g%s\n", i, C[i].name, mo,
                        me, C[i].ours ? (C[i].w3max == 0.0 ? ", w3 = 0" : ", w3 NOT 0") : "");
    }
}

int main(int argc, char **argv)
{
    const int setup = sus_plot_fig_setup_paper(argc, "longrun", &model, &ex);
    if (setup != 0)
        return setup;
    double w50[2];
    sus_refatt_precise(&model, ex.w0, T_MATCH, w50, R50);
    C = calloc((size_t)sus_step_method_count() + 2, sizeof *C);
    if (!C)
        return 1;
    for (int i = 0; i < sus_step_method_count(); i++) {
        const sus_step_method *me = sus_step_method_get(i);
        /* high order, structure-preserving */
        if (me->type->desc.conserves_energy && me->type->desc.order > 2)
            ours(me);
    }
    peer(11);
    peer(6);
    if (write_data(argv[2]) != 0)
        return 1;
    char cap[8192];
    caption(cap, sizeof cap);
    const double h =
        LR_LEGEND_Y + 11.0 * ((nc + 2) / 2) + 20.0; /* two legend columns of 11-unit rows */
    const int rc = sus_plot_fig_write_figure(argv[1], "longrun", LR_W, h, draw, NULL, cap) != 0;
    free(C);
    return rc;
}
