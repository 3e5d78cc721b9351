/* Section 6 drawn: a method's steps are the period map of an eps-periodic perturbation of
 * (ContDyn) (TheoPer). (a)-(b) the solution of x' = h(x) + eps^p d (rk8pd through the Newton
 * inversion of the blend, src/lab/perturbation.h) passes through explicit Euler's points at eps =
 * 4; (c) sup |eps^p d| against eps for every method of the registry; (d) the attitude part of the
 * perturbation on SO(3) (Per11) for the midpoint DSP with each reconstruction.
 * Usage: figure_perturbation FIGDIR DATADIR */
#include "exact.h"
#include "fig_output.h"
#include "fig_setup.h"
#include "paper_ref.h"
#include "perturbation.h"
#include "plot.h"
#include "registry.h"
#include "dsp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The width of the text block at the page's figure scale; the caption carries the title. */
#define FIG_W 560.0 /* panel (c) as wide as its two-column legend */
#define FIG_H 480.0
#define LEGEND_COLS 2 /* panel (c)'s legend, above its lines */
#define EPS_A                                                                                      \
    4.0 /* explicit Euler at h = eps k = 0.58: its steps visibly leave the exact curve             \
         */
#define NSTEP_A 10
#define NSUB 40 /* samples per period */
#define NPA (NSTEP_A * NSUB + 1)
#define NE 12     /* eps = 2 .. 2^-10 */
#define NE_SO3 10 /* eps = 2 .. 2^-8 (claims_section6.c) */
#define TOL 1e-14
/* points below the ledger's round-off floors (perturbation.h) are not drawn */
#define FLOOR_G SUS_LAB_PERTURB_FLOOR_G
#define FLOOR_ATT SUS_LAB_PERTURB_FLOOR_ATT
/* panel (c)'s reference slopes, a decade of eps long, in the lower left, which no curve reaches:
 * below the low-order curves and left of the high-order ones (the axis is extended down to them) */
#define SLOPE_XA 2e-3
#define SLOPE_XB 2e-2
#define SLOPE_Y1 1e-10
#define SLOPE_Y2 1e-11

typedef struct {
    double t[NPA], w[NPA][2], ex[NPA][2];
    double tk[NSTEP_A + 1], wk[NSTEP_A + 1][2];
    int nm;             /* every registered method, */
    const char **names; /* their names */
    double (*g)[NE];    /* and their sizes, allocated once */
    double eps[NE];
    double att[SUS_RECON_COUNT][NE];
} pert_fig;

static void die(const char *what, int status)
{
    fprintf(stderr, "figure_perturbation: %s\n", what);
    exit(status);
}

/* Panel c, the size of the perturbation against eps for every method; the legend in a strip above
 * the lines, where a curve that a later one covers says so. */
static void panel_sizes(cairo_t *cr, const pert_fig *f, double W, double H)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int m = 0; m < f->nm; m++)
        sus_plot_extend(&lo, &hi, f->g[m], NE, 1, 1);
    sus_plot_axes ax;
    lo = fmin(lo, SLOPE_Y2 * pow(SLOPE_XA / SLOPE_XB, 2.0) / 10.0); /* room for the slopes */
    sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 2, f->eps[NE - 1], f->eps[0], lo, hi, 1, 1);
    /* a strip above the lines for the legend, in LEGEND_COLS columns */
    const double strip = sus_plot_legend_height((f->nm + LEGEND_COLS - 1) / LEGEND_COLS) + 6.0;
    const double decades = log10(ax.y1 / ax.y0);
    sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 2, f->eps[NE - 1], f->eps[0], lo,
                       ax.y1 * pow(10.0, decades * strip / (ax.h - strip)), 1, 1);
    sus_plot_frame(&ax, "\xce\xb5", "sup |\xce\xb5\xe1\xb5\x96 d|", "(c)");
    sus_plot_style leg[f->nm];
    char under[f->nm][48];
    static const int mk[] = {SUS_PLOT_SQUARE,  SUS_PLOT_CIRCLE, SUS_PLOT_TRIANGLE,
                             SUS_PLOT_DIAMOND, SUS_PLOT_CROSS,  SUS_PLOT_DOT};
    int nl = 0, shown[f->nm];
    for (int m = 0; m < f->nm; m++) {
        int drawn = 0;
        for (int j = 0; j < NE; j++)
            drawn += isfinite(f->g[m][j]);
        if (drawn < 2) /* at round-off for every eps: said in the caption */
            continue;
        /* method m's colour in every per-method figure (convergence_plot.c): one each, so no two
         * curves here share a colour, and none is dashed like the grey reference slopes */
        leg[nl] = sus_plot_style_of(SUS_PLOT_PALETTE[m % SUS_PLOT_PALETTE_N], 1.0, 0, mk[m % 6],
                                    3.5, f->names[m]);
        sus_plot_series(&ax, f->eps, f->g[m], NE, 1, &leg[nl]);
        sus_plot_markers(&ax, f->eps, f->g[m], NE, 1, &leg[nl]);
        shown[nl++] = m;
    }
    /* a curve that a later one covers to within half a marker (1.5 of 3.5 pt) has its markers drawn
     * again on top, inside the other's open ones, and says so in the legend */
    for (int a = 0; a < nl; a++)
        for (int b = nl - 1; b > a; b--)
            if (sus_plot_hidden_under(&ax, f->eps, f->g[shown[a]], f->g[shown[b]], NE, 1.5)) {
                snprintf(under[a], sizeof under[a], "%s (on %s)", f->names[shown[a]],
                         f->names[shown[b]]);
                leg[a].label = under[a];
                sus_plot_markers(&ax, f->eps, f->g[shown[a]], NE, 1, &leg[a]);
                break;
            }
    sus_plot_legend_packed(cr, ax.x + 4.0, ax.y + 4.0, leg, nl, LEGEND_COLS);
    sus_plot_slope(&ax, SLOPE_XA, SLOPE_XB, SLOPE_Y1, 1.0, "1");
    sus_plot_slope(&ax, SLOPE_XA, SLOPE_XB, SLOPE_Y2, 2.0, "2");
}

static void draw(cairo_t *cr, void *vctx)
{
    const pert_fig *f = vctx;
    const double W = FIG_W, H = FIG_H;
    const sus_plot_style sp = sus_plot_style_of(SUS_PLOT_BLUE, 1.2, 0, SUS_PLOT_NONE, 0,
                                                "x' = h(x) + \xce\xb5\xe1\xb5\x96 d, rk8pd");
    const sus_plot_style se =
        sus_plot_style_of(SUS_PLOT_GREY, 1.0, 1, SUS_PLOT_NONE, 0, "exact flow from \xcf\x89(0)");
    const sus_plot_style sk =
        sus_plot_style_of(SUS_PLOT_RED, 0, 0, SUS_PLOT_CIRCLE, 5.0, "euler steps, \xce\xb5 = 4");
    for (int c = 0; c < 2; c++) {
        double x[NPA], e[NPA], xk[NSTEP_A + 1], lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < NPA; i++) {
            x[i] = f->w[i][c];
            e[i] = f->ex[i][c];
        }
        for (int k = 0; k <= NSTEP_A; k++)
            xk[k] = f->wk[k][c];
        sus_plot_extend(&lo, &hi, x, NPA, 1, 0);
        sus_plot_extend(&lo, &hi, e, NPA, 1, 0);
        sus_plot_axes ax;
        sus_plot_axes_cell(&ax, cr, W, H, 2, 2, c, 0, f->t[NPA - 1], lo, hi, 0, 0);
        sus_plot_frame(&ax, "t", c ? "\xcf\x89\xe2\x82\x82" : "\xcf\x89\xe2\x82\x81",
                       c ? "(b)" : "(a)");
        sus_plot_series(&ax, f->t, e, NPA, 1, &se);
        sus_plot_series(&ax, f->t, x, NPA, 1, &sp);
        sus_plot_markers(&ax, f->tk, xk, NSTEP_A + 1, 1, &sk);
        if (c == 0) {
            const sus_plot_style leg[3] = {sp, se, sk};
            sus_plot_legend(&ax, leg, 3, 1);
        }
    }
    panel_sizes(cr, f, W, H);
    /* (d) the attitude perturbation, midpoint DSP */
    {
        double lo = INFINITY, hi = -INFINITY;
        for (int r = 0; r < SUS_RECON_COUNT; r++)
            sus_plot_extend(&lo, &hi, f->att[r], NE_SO3, 1, 1);
        sus_plot_axes ax;
        sus_plot_axes_cell(&ax, cr, W, H, 2, 2, 3, f->eps[NE_SO3 - 1], f->eps[0], lo, hi, 1, 1);
        sus_plot_frame(&ax, "\xce\xb5",
                       "sup |(R\xe1\xb5\x80R\xe2\x80\xb2)\xcb\x87 \xe2\x88\x92 \xcf\x89|", "(d)");
        const double *const colour[SUS_RECON_COUNT] = {SUS_PLOT_BLUE, SUS_PLOT_RED, SUS_PLOT_BLACK};
        sus_plot_style leg[SUS_RECON_COUNT];
        for (int r = 0; r < SUS_RECON_COUNT; r++) {
            leg[r] = sus_plot_style_of(colour[r], 1.0, r == 2, SUS_PLOT_CIRCLE + r, 4.0,
                                       SUS_RECON_NAMES[r]);
            sus_plot_series(&ax, f->eps, f->att[r], NE_SO3, 1, &leg[r]);
            sus_plot_markers(&ax, f->eps, f->att[r], NE_SO3, 1, &leg[r]);
        }
        sus_plot_legend(&ax, leg, SUS_RECON_COUNT, 3);
    }
}

/* Panels (a)-(b): NSTEP_A periods of (Eq2), each from the method's previous point; the largest gap
 * between the period map and the Euler step in *gap. Returns 0, or 3 when a solve fails. */
static int trajectory(pert_fig *f, const sus_model *m, const sus_exact *ex, double *gap)
{
    sus_lab_perturb P;
    if (sus_lab_perturb_init(&P, m, sus_step_euler, EPS_A) != 0)
        die("singular inertia", 1);
    double x[2] = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]}, seg[NSUB + 1][2];
    *gap = 0.0;
    f->tk[0] = 0.0;
    f->wk[0][0] = x[0];
    f->wk[0][1] = x[1];
    for (int k = 0; k < NSTEP_A; k++) {
        if (sus_lab_perturb_trajectory(&P, x, TOL, NSUB, seg) != SUS_LAB_PERTURB_OK) {
            char eq2[32];
            fprintf(stderr,
                    "figure_perturbation: %s failed on period "
                    "%d, t in [%g, %g], Newton residual %.3g\n",
                    sus_paper_name("Eq2", eq2, sizeof eq2), k, EPS_A * k, EPS_A * (k + 1),
                    P.sus_lab_newton_res);
            return 3;
        }
        for (int i = (k ? 1 : 0); i <= NSUB; i++) {
            const int n = k * NSUB + i;
            f->t[n] = EPS_A * (k + (double)i / NSUB);
            f->w[n][0] = seg[i][0];
            f->w[n][1] = seg[i][1];
            sus_exact_omega(ex, f->t[n], f->ex[n]);
        }
        double w3[3] = {x[0], x[1], 0.0}, wn[3], lam;
        sus_stepper_stats st;
        if (P.st->step->apply(m, EPS_A, w3, wn, &lam, &st) != SUS_STEPPER_OK) {
            fprintf(stderr, "figure_perturbation: euler step %d failed at t = %g\n", k, EPS_A * k);
            return 3;
        }
        *gap = fmax(*gap, hypot(wn[0] - seg[NSUB][0], wn[1] - seg[NSUB][1]));
        x[0] = wn[0];
        x[1] = wn[1];
        f->tk[k + 1] = EPS_A * (k + 1);
        f->wk[k + 1][0] = x[0];
        f->wk[k + 1][1] = x[1];
    }
    return 0;
}

static const double TK[] = {0.0, 3.0, 7.0};

/* Panel (c): sizes along one period from w(0), w(3), w(7), every method */
static void sizes(pert_fig *f, const sus_model *m, const sus_exact *ex)
{
    for (int j = 0; j < NE; j++)
        f->eps[j] = ldexp(1.0, 1 - j);
    for (int i = 0; i < f->nm; i++) {
        f->names[i] = sus_step_method_get(i)->type->name;
        for (int j = 0; j < NE; j++) {
            sus_lab_perturb Q;
            double s = 0.0;
            if (sus_lab_perturb_init(&Q, m, sus_step_method_get(i)->type, f->eps[j]) != 0)
                die("singular inertia", 1);
            for (int t = 0; t < 3; t++) {
                double x0[2], v;
                sus_exact_omega(ex, TK[t], x0);
                if (sus_lab_perturb_sup_reduced(&Q, x0, 64, &v) != SUS_LAB_PERTURB_OK)
                    die("a perturbation size failed", 3);
                s = fmax(s, v);
            }
            f->g[i][j] = s > FLOOR_G / f->eps[j] ? s : NAN;
        }
    }
}

/* Panel (d): the attitude part for the midpoint DSP */
static void attitude_sizes(pert_fig *f, const sus_model *m, const sus_exact *ex)
{
    for (int r = 0; r < SUS_RECON_COUNT; r++)
        for (int j = 0; j < NE; j++) {
            f->att[r][j] = NAN;
            if (j >= NE_SO3)
                continue;
            sus_lab_perturb Q;
            double s = 0.0;
            if (sus_lab_perturb_init(&Q, m, sus_step_midpoint, f->eps[j]) != 0)
                die("singular inertia", 1);
            for (int t = 0; t < 2; t++) {
                double x0[2], a, g;
                sus_exact_omega(ex, TK[t], x0);
                if (sus_lab_perturb_sup_so3(&Q, (sus_recon)r, x0, 32, SUS_LAB_PERTURB_ATT_TOL, &a,
                                            &g) != SUS_LAB_PERTURB_OK)
                    die("an attitude blend failed", 3);
                s = fmax(s, a);
            }
            f->att[r][j] = s > FLOOR_ATT / f->eps[j] ? s : NAN;
        }
}

/* data: the trajectory, then the sizes (one column per method and reconstruction) */
static int write_data(const pert_fig *f, const char *datadir)
{
    char path[4096];
    static double tcol[NPA], c1[NPA], c2[NPA], e1[NPA], e2[NPA];
    for (int i = 0; i < NPA; i++) {
        tcol[i] = f->t[i];
        c1[i] = f->w[i][0];
        c2[i] = f->w[i][1];
        e1[i] = f->ex[i][0];
        e2[i] = f->ex[i][1];
    }
    const double *cols[] = {tcol, c1, c2, e1, e2};
    if (sus_plot_fig_write_csv(sus_plot_fig_path(path, sizeof path, datadir, "perturbation", "csv"),
                               "t,omega1_perturbed,omega2_perturbed,omega1_exact,omega2_exact", 5,
                               cols, NPA, 1) != 0)
        return 1;
    char header[8192];
    const double *scols[1 + f->nm + SUS_RECON_COUNT];
    int nc = 0, used = snprintf(header, sizeof header, "eps");
    scols[nc++] = f->eps;
    for (int i = 0; i < f->nm; i++) {
        used += snprintf(header + used, sizeof header - (size_t)used, ",sup_g_%s", f->names[i]);
        scols[nc++] = f->g[i];
    }
    for (int r = 0; r < SUS_RECON_COUNT; r++) {
        used += snprintf(header + used, sizeof header - (size_t)used, ",attitude_midpoint_%s",
                         SUS_RECON_NAMES[r]);
        scols[nc++] = f->att[r];
    }
    sus_plot_fig_path(path, sizeof path, datadir, "perturbation_sizes", "csv");
    return sus_plot_fig_write_csv(path, header, nc, scols, NE, 1) != 0;
}

int main(int argc, char **argv)
{
    sus_model m;
    sus_exact ex;
    const int setup = sus_plot_fig_setup_paper(argc, "perturbation", &m, &ex);
    if (setup != 0)
        return setup;
    static pert_fig f;
    f.nm = sus_step_method_count();
    f.names = calloc((size_t)f.nm, sizeof *f.names);
    f.g = calloc((size_t)f.nm, sizeof *f.g);
    if (!f.names || !f.g)
        die("out of memory", 1);
    double gap;
    const int traj = trajectory(&f, &m, &ex, &gap);
    if (traj != 0)
        return traj;
    sizes(&f, &m, &ex);
    attitude_sizes(&f, &m, &ex);
    if (write_data(&f, argv[2]) != 0)
        return 1;
    char cap[2048];
    snprintf(
        cap, sizeof cap,
        "Section 6 made constructive. Regenerate: make figures (src/prog/figure_perturbation.c, "
        "src/lab/perturbation.c).\n"
        "On each period [k eps, (k+1) eps] the curve blends the "
        "exact flow forward from w_k and backward from the\n"
        "method's w_{k+1} with a C-infinity weight flat on the first "
        "and last tenth; d is its defect against (ContDyn),\n"
        "evaluated at any point by Newton on the blend. (a)-(b): "
        "x' = h(x) + eps^p d integrated by rk8pd (tol 1e-14)\n"
        "over %d periods of explicit Euler at eps = %g passes "
        "through Euler's points (largest gap %.1e); dashed:\n"
        "the exact flow. (c): sup over a period of |eps^p d| from "
        "w(0), w(3), w(7), every method of the registry;\n"
        "slopes p (claims sec6-size-order-*); points below 1000x "
        "round-off (%.1e/eps) omitted, and methods with fewer\n"
        "than two points left (their perturbation is at round-off "
        "for every eps <= 2). (d): the attitude\n"
        "part of the perturbation on SO(3) (geodesic blend, "
        "Per11): sup |vee(R^T R') - w|, the body angular\n"
        "velocity of the blended attitude R(t) against the curve's "
        "w, midpoint DSP: order 1 with cayley, 2 with\n"
        "the symmetric reconstructions. Data: data/perturbation.csv, "
        "data/perturbation_sizes.csv.\n",
        NSTEP_A, EPS_A, gap, FLOOR_G);
    return sus_plot_fig_write_figure(argv[1], "perturbation", FIG_W, FIG_H, draw, &f, cap) != 0;
}
