/* Figure 2 of the paper: the midpoint DSP and the variational integrator at eps = 1 against the
 * exact solution, plus (f) the distance to the exact steady rotation. Usage: figure_fig2 FIGDIR
 * DATADIR */
#include "experiments.h"
#include "fig_output.h"
#include "fig_setup.h"
#include "plot.h"
#include "series.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#define EPS SUS_LAB_FIG2_EPS
#define T_END SUS_LAB_FIG2_T_END
#define FINE 0.05 /* the reference line is drawn on this finer grid */

typedef struct {
    sus_lab_series mid, var, ex; /* ex on the fine grid */
    double *dist[3];             /* |w - w_inf| for exact (fine), midpoint, variational */
    double *mu[2];
    double winf[2];
} fig2;

static void draw(cairo_t *cr, void *vctx)
{
    const fig2 *f = vctx;
    const double W = 540, H = 660;
    const sus_plot_style ref = sus_plot_style_of(SUS_PLOT_RED, 1.2, 0, SUS_PLOT_NONE, 0, "exact");
    const sus_plot_style mid =
        sus_plot_style_of(SUS_PLOT_GREEN, 0, 0, SUS_PLOT_CIRCLE, 3.2, "midpoint");
    const sus_plot_style var =
        sus_plot_style_of(SUS_PLOT_BLUE, 0, 0, SUS_PLOT_DOT, 2.4, "variational");
    const sus_plot_style leg[3] = {ref, mid, var};
    struct {
        const double *yref, *ym, *yv;
        const char *ylabel;
    } panels[4] = {
        {f->ex.w1, f->mid.w1, f->var.w1, "\xcf\x89\xe2\x82\x81"},
        {f->ex.w2, f->mid.w2, f->var.w2, "\xcf\x89\xe2\x82\x82"},
        {f->ex.lambda, f->mid.lambda, f->var.lambda, "\xce\xbb"},
        {f->ex.energy, f->mid.energy, f->var.energy,
         "E = \xc2\xbd\xe2\x9f\xa8I\xe2\x82\x98\xcf\x89, \xcf\x89\xe2\x9f\xa9"},
    };
    static const char *letters[] = {"(a)", "(b)", "(c)", "(d)", "(e)", "(f)"};
    for (int p = 0; p < 4; p++) {
        sus_plot_axes ax;
        double lo = INFINITY, hi = -INFINITY;
        sus_plot_extend(&lo, &hi, panels[p].yref, f->ex.n, 1, 0);
        sus_plot_extend(&lo, &hi, panels[p].ym, f->mid.n, 1, 0);
        sus_plot_extend(&lo, &hi, panels[p].yv, f->var.n, 1, 0);
        sus_plot_axes_cell(&ax, cr, W, H, 3, 2, p, 0.0, T_END, lo, hi, 0, 0);
        sus_plot_frame(&ax, "t", panels[p].ylabel, letters[p]);
        /* the reference last, on top: where a method is exact (E of the midpoint rule in (d))
         * its markers would hide it */
        sus_plot_markers(&ax, f->mid.t, panels[p].ym, f->mid.n, 1, &mid);
        sus_plot_markers(&ax, f->var.t, panels[p].yv, f->var.n, 1, &var);
        sus_plot_series(&ax, f->ex.t, panels[p].yref, f->ex.n, 1, &ref);
        static const int corner[4] = {1, 1, 3, 5};
        sus_plot_legend(&ax, leg, 3, corner[p]);
    }
    sus_plot_axes ax;
    sus_plot_axes_cell(&ax, cr, W, H, 3, 2, 4, 0.0, T_END, 1e-19, 1e-14, 0, 1);
    sus_plot_frame(&ax, "t",
                   "|\xe2\x9f\xa8"
                   "e\xe2\x82\x83, (R\xe2\x82\x96\xe1\xb5\x80 R\xe2\x82\x96 "
                   "\xcf\x89\xcc\x82\xe2\x82\x96)\xcb\x87\xe2\x9f\xa9|",
                   letters[4]);
    sus_plot_markers(&ax, f->mid.t, f->mu[0], f->mid.n, 1, &mid);
    sus_plot_markers(&ax, f->var.t, f->mu[1], f->var.n, 1, &var);
    sus_plot_legend(&ax, leg + 1, 2, 1);
    double lo = INFINITY, hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->dist[1], f->mid.n, 1, 1);
    sus_plot_extend(&lo, &hi, f->dist[2], f->var.n, 1, 1);
    sus_plot_axes_cell(&ax, cr, W, H, 3, 2, 5, 0.0, T_END, fmax(lo, 1e-17), hi, 0, 1);
    sus_plot_frame(&ax, "t",
                   "|\xcf\x89\xe2\x82\x96 \xe2\x88\x92 \xcf\x89\xe2\x88\x9e| (exact limit)",
                   letters[5]);
    sus_plot_markers(&ax, f->mid.t, f->dist[1], f->mid.n, 1, &mid);
    sus_plot_markers(&ax, f->var.t, f->dist[2], f->var.n, 1, &var);
    sus_plot_series(&ax, f->ex.t, f->dist[0], f->ex.n, 1, &ref);
    sus_plot_legend(&ax, leg, 3, 2);
}

/* |w - w_inf| along the exact solution and both runs, and |mu| of both runs. Returns 0, or -1
 * when out of memory. */
static int distances(fig2 *f)
{
    double *buf = malloc((f->ex.n + 4 * f->mid.n) * sizeof(double));
    if (!buf)
        return -1;
    f->dist[0] = buf;
    f->dist[1] = buf + f->ex.n;
    f->dist[2] = f->dist[1] + f->mid.n;
    f->mu[0] = f->dist[2] + f->mid.n;
    f->mu[1] = f->mu[0] + f->mid.n;
    for (size_t i = 0; i < f->ex.n; i++)
        f->dist[0][i] = hypot(f->ex.w1[i] - f->winf[0], f->ex.w2[i] - f->winf[1]);
    for (size_t i = 0; i < f->mid.n; i++) {
        f->dist[1][i] = hypot(f->mid.w1[i] - f->winf[0], f->mid.w2[i] - f->winf[1]);
        f->dist[2][i] = hypot(f->var.w1[i] - f->winf[0], f->var.w2[i] - f->winf[1]);
        f->mu[0][i] = fabs(f->mid.mu[i]);
        f->mu[1][i] = fabs(f->var.mu[i]);
    }
    return 0;
}

/* DATADIR/fig2.csv: every step of both runs beside the reference at the step times. */
static int write_data(const fig2 *f, const sus_exact *ex, long N, const char *datadir)
{
    char path[4096];
    sus_lab_series exs;
    if (sus_lab_series_init(&exs, N, 1))
        return 1;
    sus_lab_series_exact(&exs, ex, EPS, f->mid.n);
    const double *cols[] = {f->mid.t,      exs.w1,    exs.w2,    exs.lambda,    exs.energy,
                            f->mid.w1,     f->mid.w2, f->mid.w3, f->mid.lambda, f->mid.energy,
                            f->mid.mu,     f->var.w1, f->var.w2, f->var.w3,     f->var.lambda,
                            f->var.energy, f->var.mu};
    return sus_plot_fig_write_csv(sus_plot_fig_path(path, sizeof path, datadir, "fig2", "csv"),
                                  "t,omega1_exact,omega2_exact,lambda_exact,energy_exact,"
                                  "omega1_mid,omega2_mid,omega3_mid,lambda_mid,energy_mid,mu_mid,"
                                  "omega1_var,omega2_var,omega3_var,lambda_var,energy_var,mu_var",
                                  17, cols, f->mid.n, 1) != 0;
}

static void caption(const fig2 *f, long N, char *cap, size_t len)
{
    const size_t last = f->mid.n - 1;
    snprintf(cap, len,
             "Figure 2 (the paper's Figure 2, redrawn; the measurements contradict its caption).\n"
             "Regenerate: make figures (src/prog/figure_fig2.c).\n"
             "Run: midpoint DSP (green circles) and variational "
             "integrator (blue dots), eps = 1, t in [0, %g]\n"
             "(%ld steps; the paper gives no interval), implicit "
             "steps solved by Newton to round-off, inertia by\n"
             "rows as printed, w(0) = (0.4, 0.5). Reference (red line): "
             "the closed-form solution (the paper used RK4).\n"
             "(a) w1, (b) w2, (c) lambda, (d) E = 1/2 <I_m w, w>; "
             "(e) w3 = 0 exactly for both, plotted is the\n"
             "unreduced constraint |<e3, vee(R_k^T R_k w^_k)>| (round-off; "
             "zeros are not drawn); (f) |w_k - w_inf|,\n"
             "the distance to the exact steady rotation w_inf = (%.6f, %.6f).\n"
             "Measured: the midpoint rule conserves E to %.1e "
             "and ends %.1e from w_inf; the variational\n"
             "integrator loses %.3g of E (%.2f%%) and ends %.2e "
             "from w_inf, at a wrong steady rotation.\n"
             "The paper's caption (variational better, mainly in "
             "energy; midpoint decays fast) is not reproduced;\n"
             "see figures/fig2_energy for the readings of the midpoint rule that were tried.\n"
             "Data: data/fig2.csv (every step).\n",
             T_END, N, f->winf[0], f->winf[1],
             sus_lab_series_maxdrift(&f->mid, offsetof(sus_lab_series, energy)), f->dist[1][last],
             f->var.energy[0] - f->var.energy[last],
             100.0 * (f->var.energy[0] - f->var.energy[last]) / f->var.energy[0], f->dist[2][last]);
}

int main(int argc, char **argv)
{
    sus_model m;
    sus_exact ex;
    const int setup = sus_plot_fig_setup_paper(argc, "fig2", &m, &ex);
    if (setup != 0)
        return setup;
    fig2 f;
    sus_exact_limit(&ex, f.winf);
    const long N = sus_lab_experiment_steps(T_END, EPS), NF = (long)llround(T_END / FINE);
    const int run = sus_plot_fig_run_pair("fig2", &m, EPS, N, 1, &f.mid, &f.var);
    if (run != 0)
        return run;
    if (sus_lab_series_init(&f.ex, NF, 1)) {
        fprintf(stderr, "figure_fig2: out of memory\n");
        return 1;
    }
    sus_lab_series_exact(&f.ex, &ex, FINE, (size_t)NF + 1);
    if (distances(&f) != 0 || write_data(&f, &ex, N, argv[2]) != 0)
        return 1;
    char cap[4096];
    caption(&f, N, cap, sizeof cap);
    return sus_plot_fig_write_figure(argv[1], "fig2", 540, 660, draw, &f, cap) != 0;
}
