/* Figure 1 of the paper: the midpoint DSP and the variational integrator at eps = 1e-3 against
 * the exact solution, the paper's body and w(0). Usage: figure_fig1 FIGDIR DATADIR */
#include "experiments.h"
#include "fig_output.h"
#include "fig_setup.h"
#include "plot.h"
#include "dsp.h"
#include "series.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#define EPS SUS_LAB_FIG1_EPS
#define T_END SUS_LAB_FIG1_T_END
#define EVERY SUS_LAB_FIG1_EVERY
#define MARK_EVERY 50 /* markers: every 50th kept row = every 0.5 time units */
#define ROWS 4        /* (a)-(f) as the paper's Figure 1, then (g), (h): the corrected multiplier */
#define HEIGHT 680.0

typedef struct {
    sus_lab_series ex, mid, var;
    double *dE_mid, *dE_var, *mu_mid, *mu_var;
    /* (taualg) with the (3,3) entry of (cayinver) corrected: + (c(w^{k+1}) - c(w^k)) / eps, and the
     * distances of both multipliers from the exact lambda */
    double *lam_corr, *err_var, *err_corr;
} fig1;

/* Panel (g): the multiplier with the corrected (3,3) entry against the exact one, as (d); panel
 * (h): the distance of both multipliers from the exact lambda, |O_0| for (taualg) as printed,
 * O(eps) with the correction. */
static void draw_corrected(cairo_t *cr, const fig1 *f, double W, double H,
                           const sus_plot_style *ref)
{
    const size_t n = f->ex.n;
    const char *corrected = "corrected (36)";
    const sus_plot_style cor =
        sus_plot_style_of(SUS_PLOT_PURPLE, 0, 0, SUS_PLOT_DOT, 2.6, corrected);
    const sus_plot_style corl =
        sus_plot_style_of(SUS_PLOT_PURPLE, 1.0, 0, SUS_PLOT_NONE, 0, corrected);
    const sus_plot_style varl =
        sus_plot_style_of(SUS_PLOT_GREEN, 1.0, 0, SUS_PLOT_NONE, 0, "as printed");
    sus_plot_axes ax;
    double lo = INFINITY, hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->ex.lambda, n, 1, 0);
    sus_plot_extend(&lo, &hi, f->lam_corr, n, 1, 0);
    sus_plot_axes_cell(&ax, cr, W, H, ROWS, 2, 6, 0.0, T_END, lo, hi, 0, 0);
    sus_plot_frame(&ax, "t", "\xce\xbb, variational, (36) corrected", "(g)");
    sus_plot_markers(&ax, f->var.t, f->lam_corr, n, MARK_EVERY, &cor);
    sus_plot_series(&ax, f->ex.t, f->ex.lambda, n, 1, ref); /* on top: the markers sit on it */
    const sus_plot_style legg[2] = {*ref, cor};
    sus_plot_legend(&ax, legg, 2, 1);
    lo = INFINITY;
    hi = -INFINITY;
    sus_plot_extend(&lo, &hi, f->err_var, n, 1, 1);
    sus_plot_extend(&lo, &hi, f->err_corr, n, 1, 1);
    sus_plot_axes_cell(&ax, cr, W, H, ROWS, 2, 7, 0.0, T_END, lo, hi, 0, 1);
    sus_plot_frame(&ax, "t",
                   "|\xce\xbb\xe2\x82\x96 \xe2\x88\x92 \xce\xbb(t\xe2\x82\x96)|, variational",
                   "(h)");
    sus_plot_series(&ax, f->var.t, f->err_var, n, 1, &varl);
    sus_plot_series(&ax, f->var.t, f->err_corr, n, 1, &corl);
    const sus_plot_style legh[2] = {varl, corl};
    sus_plot_legend(&ax, legh, 2, 3);
}

static void draw(cairo_t *cr, void *vctx)
{
    const fig1 *f = vctx;
    const double W = 540, H = HEIGHT;
    const size_t n = f->ex.n;
    const sus_plot_style ref = sus_plot_style_of(SUS_PLOT_RED, 1.2, 0, SUS_PLOT_NONE, 0, "exact");
    const sus_plot_style mid =
        sus_plot_style_of(SUS_PLOT_BLUE, 0, 0, SUS_PLOT_DOT, 2.6, "midpoint");
    const sus_plot_style var =
        sus_plot_style_of(SUS_PLOT_GREEN, 0, 0, SUS_PLOT_DOT, 2.6, "variational");
    const sus_plot_style midl =
        sus_plot_style_of(SUS_PLOT_BLUE, 1.0, 0, SUS_PLOT_NONE, 0, "midpoint");
    const sus_plot_style varl =
        sus_plot_style_of(SUS_PLOT_GREEN, 1.0, 0, SUS_PLOT_NONE, 0, "variational");
    struct {
        const double *yref, *y;
        const sus_plot_style *st;
        const char *ylabel, *letter;
    } top[4] = {
        {f->ex.w1, f->mid.w1, &mid, "\xcf\x89\xe2\x82\x81 (body angular velocity)", "(a)"},
        {f->ex.w2, f->mid.w2, &mid, "\xcf\x89\xe2\x82\x82", "(b)"},
        {f->ex.lambda, f->mid.lambda, &mid, "\xce\xbb, midpoint", "(c)"},
        {f->ex.lambda, f->var.lambda, &var, "\xce\xbb, variational", "(d)"},
    };
    for (int p = 0; p < 4; p++) {
        sus_plot_axes ax;
        double lo = INFINITY, hi = -INFINITY;
        sus_plot_extend(&lo, &hi, top[p].yref, n, 1, 0);
        sus_plot_extend(&lo, &hi, top[p].y, n, 1, 0);
        sus_plot_axes_cell(&ax, cr, W, H, ROWS, 2, p, 0.0, T_END, lo, hi, 0, 0);
        sus_plot_frame(&ax, "t", top[p].ylabel, top[p].letter);
        sus_plot_markers(&ax, f->mid.t, top[p].y, n, MARK_EVERY, top[p].st);
        sus_plot_series(&ax, f->ex.t, top[p].yref, n, 1, &ref); /* on top: the markers sit on it */
        const sus_plot_style leg[2] = {ref, *top[p].st};
        sus_plot_legend(&ax, leg, 2, p == 1 ? 3 : 1);
    }
    /* (e) the constraint: w3 = 0 exactly, and the unreduced constraint of R_k w^_k */
    sus_plot_axes ax;
    sus_plot_axes_cell(&ax, cr, W, H, ROWS, 2, 4, 0.0, T_END, 1e-19, 1e-14, 0, 1);
    sus_plot_frame(&ax, "t",
                   "|\xe2\x9f\xa8"
                   "e\xe2\x82\x83, (R\xe2\x82\x96\xe1\xb5\x80 R\xe2\x82\x96 "
                   "\xcf\x89\xcc\x82\xe2\x82\x96)\xcb\x87\xe2\x9f\xa9|",
                   "(e)");
    sus_plot_markers(&ax, f->mid.t, f->mu_mid, n, MARK_EVERY / 5, &mid);
    sus_plot_markers(&ax, f->var.t, f->mu_var, n, MARK_EVERY / 5, &var);
    const sus_plot_style lege[2] = {mid, var};
    sus_plot_legend(&ax, lege, 2, 1);
    /* (f) energy */
    sus_plot_axes_cell(&ax, cr, W, H, ROWS, 2, 5, 0.0, T_END, 1e-18, 1e-8, 0, 1);
    sus_plot_frame(&ax, "t", "|E\xe2\x82\x96 \xe2\x88\x92 E\xe2\x82\x80|", "(f)");
    sus_plot_series(&ax, f->mid.t, f->dE_mid, n, 1, &midl);
    sus_plot_series(&ax, f->var.t, f->dE_var, n, 1, &varl);
    const sus_plot_style legf[2] = {midl, varl};
    sus_plot_legend(&ax, legf, 2, 3);
    draw_corrected(cr, f, W, H, &ref);
}

static double max_of(const double *v, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, v[i]);
    return m;
}

/* The variational run again, step by step, for the multiplier with the corrected (3,3) entry of
 * (cayinver): (taualg) + (c(w^{k+1}) - c(w^k)) / eps (the companion's Section on PropoFinal), kept
 * at the rows of the series (row 0: lambda(w0), as every series has it). */
static int corrected_multiplier(const sus_model *m, long N, fig1 *f)
{
    double w[3] = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1], 0.0};
    f->lam_corr[0] = sus_lagmult(m, w);
    for (long k = 0; k < N; k++) {
        double x[3], lam;
        sus_stepper_stats st;
        if (sus_step_variational->step->apply(m, EPS, w, x, &lam, &st) != SUS_STEPPER_OK) {
            fprintf(stderr, "figure_fig1: a variational step failed at step %ld (t = %g)\n", k + 1,
                    (double)(k + 1) * EPS);
            return 3;
        }
        if ((k + 1) % EVERY == 0)
            f->lam_corr[(k + 1) / EVERY] = lam + (sus_c(m, x) - sus_c(m, w)) / EPS;
        w[0] = x[0];
        w[1] = x[1];
    }
    for (size_t i = 0; i < f->ex.n; i++) {
        f->err_var[i] = fabs(f->var.lambda[i] - f->ex.lambda[i]);
        f->err_corr[i] = fabs(f->lam_corr[i] - f->ex.lambda[i]);
    }
    return 0;
}

/* The derived curves: energy changes, constraints, and the corrected multiplier. */
static int derived(const sus_model *m, long N, fig1 *f)
{
    const size_t n = f->mid.n;
    double *buf = malloc(7 * n * sizeof(double));
    if (!buf || n != (size_t)(N / EVERY) + 1) {
        fprintf(stderr, "figure_fig1: out of memory, or %zu rows not one every %d steps\n", n,
                EVERY);
        free(buf);
        return 1;
    }
    double **col[] = {&f->dE_mid,   &f->dE_var,  &f->mu_mid,  &f->mu_var,
                      &f->lam_corr, &f->err_var, &f->err_corr};
    for (size_t c = 0; c < 7; c++)
        *col[c] = buf + c * n;
    for (size_t i = 0; i < n; i++) {
        f->dE_mid[i] = fabs(f->mid.energy[i] - f->mid.energy[0]);
        f->dE_var[i] = fabs(f->var.energy[i] - f->var.energy[0]);
        f->mu_mid[i] = fabs(f->mid.mu[i]);
        f->mu_var[i] = fabs(f->var.mu[i]);
    }
    return corrected_multiplier(m, N, f);
}

static int write_csv(const char *dir, const fig1 *f)
{
    char path[4096];
    const double *cols[] = {f->ex.t,       f->ex.w1,  f->ex.w2,   f->ex.lambda,  f->ex.energy,
                            f->mid.w1,     f->mid.w2, f->mid.w3,  f->mid.lambda, f->mid.energy,
                            f->mid.mu,     f->var.w1, f->var.w2,  f->var.w3,     f->var.lambda,
                            f->var.energy, f->var.mu, f->lam_corr};
    return sus_plot_fig_write_csv(sus_plot_fig_path(path, sizeof path, dir, "fig1", "csv"),
                                  "t,omega1_exact,omega2_exact,lambda_exact,energy_exact,"
                                  "omega1_mid,omega2_mid,omega3_mid,lambda_mid,energy_mid,mu_mid,"
                                  "omega1_var,omega2_var,omega3_var,lambda_var,energy_var,mu_var,"
                                  "lambda_var_corrected",
                                  18, cols, f->mid.n, 1);
}

static void caption(const fig1 *f, const sus_exact *ex, long N, char *cap, size_t len)
{
    const size_t n = f->mid.n;
    snprintf(
        cap, len,
        "Figure 1 (the paper's Figure 1, redrawn). Regenerate: "
        "make figures (src/prog/figure_fig1.c).\n"
        "Run: midpoint DSP ((Discretization) with the midpoint "
        "l1, l2, lambda_{k+1} = lambda(w^{k+1})) and the\n"
        "variational integrator ((taudyn), (taualg)), implicit "
        "steps solved by Newton to round-off;\n"
        "reconstruction R_{k+1} = R_k cay(eps w_k). eps = 1e-3, "
        "t in [0, %g] (%ld steps; the paper gives no\n"
        "interval: %g = 8.7/k covers the whole transient to "
        "the steady rotation, k = %.4f), inertia by rows\n"
        "[[1,0.1,0.2],[0.1,1,0.2],[0.2,0.1,1]] as printed, w(0) = (0.4, 0.5).\n"
        "Reference (red line): the closed-form solution (the paper used RK4).\n"
        "(a), (b) w1, w2 of the midpoint rule (blue dots "
        "every 0.5 time units) against the reference.\n"
        "(c) lambda of the midpoint rule; (d) lambda of the "
        "variational integrator (taualg): offset from the\n"
        "reference by O_0 of (PropoFinal) (at most %.3g here), the inconsistent multiplier.\n"
        "(e) w3 is 0 exactly for both (imposed by (DSP)); "
        "plotted is the unreduced constraint of the\n"
        "reconstructed velocity, |<e3, vee(R_k^T R_k w^_k)>| "
        "<= %.2g (round-off; zeros are not drawn).\n"
        "(f) |E_k - E_0|: midpoint <= %.2g (round-off: the "
        "implicit midpoint rule conserves E), variational\n"
        "<= %.2g (not conserved, O(eps^2), invisible at the scale of (a)-(d)).\n"
        "(g), (h) ours: the variational multiplier with "
        "the (3,3) entry of (cayinver) corrected to 1,\n"
        "(taualg) + (c(w^{k+1}) - c(w^k))/eps: consistent, "
        "within %.2g of the exact lambda, against %.3g\n"
        "for (taualg) as printed.\n"
        "max |w_mid - w_var| = %.2g over the run, against max |lambda_mid - lambda_var| = %.3g.\n"
        "Data: data/fig1.csv (every %dth step).\n",
        T_END, N, T_END, ex->k,
        sus_lab_series_maxdiff(&f->ex, &f->var, offsetof(sus_lab_series, lambda)),
        fmax(sus_lab_series_maxdrift(&f->mid, offsetof(sus_lab_series, mu)),
             sus_lab_series_maxdrift(&f->var, offsetof(sus_lab_series, mu))),
        sus_lab_series_maxdrift(&f->mid, offsetof(sus_lab_series, energy)),
        sus_lab_series_maxdrift(&f->var, offsetof(sus_lab_series, energy)), max_of(f->err_corr, n),
        max_of(f->err_var, n),
        fmax(sus_lab_series_maxdiff(&f->mid, &f->var, offsetof(sus_lab_series, w1)),
             sus_lab_series_maxdiff(&f->mid, &f->var, offsetof(sus_lab_series, w2))),
        sus_lab_series_maxdiff(&f->mid, &f->var, offsetof(sus_lab_series, lambda)), EVERY);
}

int main(int argc, char **argv)
{
    sus_model m;
    sus_exact ex;
    const int setup = sus_plot_fig_setup_paper(argc, "fig1", &m, &ex);
    if (setup != 0)
        return setup;
    fig1 f;
    const long N = sus_lab_experiment_steps(T_END, EPS);
    const int run = sus_plot_fig_run_pair("fig1", &m, EPS, N, EVERY, &f.mid, &f.var);
    if (run != 0)
        return run;
    if (sus_lab_series_init(&f.ex, N, EVERY)) {
        fprintf(stderr, "figure_fig1: out of memory\n");
        return 1;
    }
    sus_lab_series_exact(&f.ex, &ex, EPS * EVERY, f.mid.n);
    const int der = derived(&m, N, &f);
    if (der != 0)
        return der;
    if (write_csv(argv[2], &f) != 0)
        return 1;
    char cap[4096];
    caption(&f, &ex, N, cap, sizeof cap);
    return sus_plot_fig_write_figure(argv[1], "fig1", 540, HEIGHT, draw, &f, cap) != 0;
}
