/* Where each integrator stops working: a map over the dimensionless step h = eps k and the
 * initial angle on the energy ellipse, coloured by the class of the run (stability.h), with
 * the linear stability limits drawn on top. Usage: figure_stability [--quiet] [--jobs N] FIGDIR
 * DATADIR. The runs are split across N processes (SUSLOV_JOBS, else every core, by default): the
 * outputs are the same bytes for any N (stability_maps.h). */
#include "atomic_file.h"
#include "fig_output.h"
#include "fig_setup.h"
#include "plot.h"
#include "progress.h"
#include "stability.h"
#include "stability_maps.h"
#include "workpool.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NH 31               /* h = 10^(-3 + 0.2 i) */
#define NANGLE 36           /* every 10 degrees */
#define CAPTION_COLUMNS 100 /* where the list of limits wraps, near its hand-broken lines */

typedef struct {
    double hs[NH];
    int nm; /* every method of the registry, in its order */
    sus_lab_stab_result (*res)[NH * NANGLE];
    double *limit;
} stab_fig;

/* Panels two to a row, 170 points high, under a legend strip; the caption carries the title. The
 * companion prints the map in two halves cut between panel rows (tools/figsplit.sh), and at this
 * height each half fits a float page at the print scale that keeps its labels legible
 * (SUS_PLOT_PRINT_SCALE). The legend goes above the panels so that the first half carries it. */
#define PANEL_H 170.0
#define STRIP_H 14.0
static double fig_height(int nm) { return STRIP_H + PANEL_H * ((nm + 1) / 2); }

static const double CLASS_RGB[SUS_LAB_STAB_NCLASS][3] = {{0.62, 0.85, 0.60},
                                                         {0.98, 0.75, 0.35},
                                                         {0.85, 0.20, 0.15},
                                                         {0.55, 0.30, 0.75},
                                                         {0.20, 0.20, 0.20}};

static void draw(cairo_t *cr, void *vctx)
{
    const stab_fig *f = vctx;
    const double W = 600, H = fig_height(f->nm), step = pow(10.0, 0.1);
    sus_plot_style leg[SUS_LAB_STAB_NCLASS];
    for (int c = 0; c < SUS_LAB_STAB_NCLASS; c++) { /* a horizontal legend in the strip */
        leg[c] = sus_plot_style_of(CLASS_RGB[c], 0, 0, SUS_PLOT_DOT, 7, SUS_LAB_STAB_NAMES[c]);
        sus_plot_axes la;
        sus_plot_axes_init(&la, cr, 40 + 112 * c, 0, 110, 20, 0, 1, 0, 1, 0, 0);
        sus_plot_legend(&la, &leg[c], 1, 0);
    }
    cairo_translate(cr, 0.0, STRIP_H);
    for (int m = 0; m < f->nm; m++) {
        sus_plot_axes ax;
        char letter[8];
        snprintf(letter, sizeof letter, "(%c)", 'a' + m % 26);
        sus_plot_axes_cell(&ax, cr, W, H - STRIP_H, (f->nm + 1) / 2, 2, m, f->hs[0], f->hs[NH - 1],
                           0.0, 360.0, 1, 0);
        ax.x0 = f->hs[0] / step;
        ax.x1 = f->hs[NH - 1] * step;
        ax.y0 = 0.0;
        ax.y1 = 360.0;
        for (int i = 0; i < NH; i++)
            for (int a = 0; a < NANGLE; a++)
                sus_plot_rect(&ax, f->hs[i] / step, f->hs[i] * step, 10.0 * a, 10.0 * (a + 1),
                              CLASS_RGB[f->res[m][i * NANGLE + a].cls]);
        char title[96];
        snprintf(title, sizeof title, "h = \xce\xb5k   (%s)", sus_step_method_get(m)->type->name);
        sus_plot_frame(&ax, title, "\xce\xb8\xe2\x82\x80 (degrees)", letter);
        if (isfinite(f->limit[m])) {
            const double lx[2] = {f->limit[m], f->limit[m]}, ly[2] = {0.0, 360.0};
            const sus_plot_style ls =
                sus_plot_style_of(SUS_PLOT_BLACK, 1.4, 1, SUS_PLOT_NONE, 0, NULL);
            sus_plot_series(&ax, lx, ly, 2, 1, &ls);
            char lab[64];
            snprintf(lab, sizeof lab, "linear limit h = %.4g", f->limit[m]);
            sus_plot_text(cr, ax.x + 4, ax.y + 10, lab, 8.0, 0.0, 0.5, 0);
        } else { /* inf: |R(-h)| <= 1 up to the last h; NaN: the method states no stability
                  * function R (its desc.stability is NULL), so it has no limit to draw */
            sus_plot_text(cr, ax.x + 4, ax.y + 10,
                          isnan(f->limit[m]) ? "no linear stability function"
                                             : "no linear stability limit",
                          8.0, 0.0, 0.5, 0);
        }
    }
}

/* data/stability.csv: one row per (method, h, starting angle) with its class and error. */
static int write_csv(const stab_fig *f, const char *dir)
{
    char err[256], path[4096];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, sus_plot_fig_path(path, sizeof path, dir, "stability", "csv"),
                                 err, sizeof err) != 0) {
        fprintf(stderr, "figure_stability: %s\n", err);
        return 1;
    }
    fprintf(af.fp, "method,h,theta0_degrees,class,class_name,failed_step,final_relative_error\n");
    for (int m = 0; m < f->nm; m++)
        for (int i = 0; i < NH; i++)
            for (int a = 0; a < NANGLE; a++) {
                const sus_lab_stab_result *r = &f->res[m][i * NANGLE + a];
                fprintf(af.fp, "%s,%.6g,%.4g,%d,%s,%ld,%.6g\n", sus_step_method_get(m)->type->name,
                        f->hs[i],
                        (2.0 * 3.14159265358979323846 * a / NANGLE + SUS_LAB_STAB_ANGLE0) * 180.0 /
                            3.14159265358979323846,
                        r->cls, SUS_LAB_STAB_NAMES[r->cls], r->step, r->final_err);
            }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "figure_stability: %s\n", err);
        return 1;
    }
    return 0;
}

/* The caption under construction; what would not fit is cut and counted in len, which main
 * checks against size. */
typedef struct {
    char *s;
    size_t len, size;
} capbuf;

static void cat(capbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void cat(capbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(b->len < b->size ? b->s + b->len : NULL,
                            b->len < b->size ? b->size - b->len : 0, fmt, ap);
    va_end(ap);
    b->len += n > 0 ? (size_t)n : 0;
}

/* What the map is: the step, the starts, the runs and the classes (stability.h). */
static void cap_setup(const stab_fig *f, const sus_exact *paper, capbuf *b)
{
    cat(b,
        "Stability map. Regenerate: make figures (src/prog/figure_stability.c; classes in "
        "src/lab/stability.h).\n"
        "The field is homogeneous of degree 2, so the step that matters is h = eps k, k = %.4f "
        "the rate of\napproach to the steady rotation for the paper's energy; w0 runs round that "
        "energy ellipse (theta0,\nevery %g degrees, in the Cholesky coordinates of I_m). h = %g "
        ".. %g, %d values; each run lasts\nmax(40/h, 10 h) + 50 steps (at most 40000); implicit "
        "steps are checked against continuation in eps\nfor h >= %g. ",
        paper->k, 360.0 / NANGLE, f->hs[0], f->hs[NH - 1], NH, SUS_LAB_STAB_BRANCH_H);
    cat(b,
        "Classes: good = ends within %g%% of the exact steady rotation; wrong limit = bounded,"
        "\nends elsewhere; blow-up = |w| > %g |w0|; solver failure = the step's solve fails "
        "other than at a\nfold, or a Taylor step lies beyond its series' radius of convergence; "
        "regularity lost = the branch\nof the step equation continued from eps = 0 meets a fold "
        "(no root on it beyond), or the (REGLOC)\nblock is singular or has changed sign. Each "
        "implicit step solves for that branch: Newton from its\nexplicit prediction where that "
        "lands near it, continuation in eps elsewhere.\n",
        100.0 * SUS_LAB_STAB_GOOD_TOL, SUS_LAB_STAB_BLOWUP_FACTOR);
}

/* The width of the caption's last line so far. */
static size_t cap_column(const capbuf *b)
{
    const size_t end = b->len < b->size ? b->len : b->size; /* what was written */
    size_t i = end;
    while (i > 0 && b->s[i - 1] != '\n')
        i--;
    return end - i;
}

/* The linear stability limits (the dashed lines), one per method. */
static void cap_limits(const stab_fig *f, capbuf *b)
{
    cat(b,
        "Boundaries. Linearising psi' = k cos psi at the attracting rotation gives the "
        "eigenvalue -k, so\nan explicit method is linearly stable only below the first h with "
        "|R(-h)| = 1 (dashed lines; checked\nagainst bisection in the claims ledger). These "
        "limits, per method (inf: none up to h = %g; nan: no\nlinear stability function): ",
        f->hs[NH - 1]);
    for (int m = 0; m < f->nm; m++) {
        char item[64];
        const int n =
            snprintf(item, sizeof item, "%s %.6g", sus_step_method_get(m)->type->name, f->limit[m]);
        /* one column kept for the ',' or '.' that ends the line */
        const int wrap = m > 0 && cap_column(b) + 2 + (size_t)n + 1 > CAPTION_COLUMNS;
        cat(b, "%s%s", m == 0 ? "" : wrap ? ",\n" : ", ", item);
    }
    cat(b, ".\n");
}

/* Where each class first appears in each method's map, read from the map just drawn. */
static void cap_onsets(const stab_fig *f, capbuf *b)
{
    cat(b,
        "Where each class first appears, per method: the smallest h at which a run on any start "
        "is of that\nclass, and on how many of the %d starts a run is of it at some h.\n",
        NANGLE);
    for (int m = 0; m < f->nm; m++) {
        sus_lab_stab_onsets o;
        sus_lab_stability_onsets(f->res[m], f->hs, NH, NANGLE, &o);
        cat(b, "  %s:", sus_step_method_get(m)->type->name);
        int failed = 0;
        for (int c = SUS_LAB_STAB_GOOD + 1; c < SUS_LAB_STAB_NCLASS; c++)
            if (o.starts[c] > 0)
                cat(b, "%s %s from h = %.6g (%d of %d starts)", failed++ ? "," : "",
                    SUS_LAB_STAB_NAMES[c], o.first_h[c], o.starts[c], NANGLE);
        if (!failed)
            cat(b, " every run good, up to h = %g", f->hs[NH - 1]);
        cat(b, "\n");
    }
}

/* Why the classes fall where they do: theory and the ledger's checks, no measured number. */
static void cap_reading(capbuf *b)
{
    cat(b,
        "Reading. A blow-up below a method's linear limit is the nonlinear transient far from "
        "the rotation,\n"
        "which the linearisation there does not see. Euler's wrong limits are its O(h) energy "
        "drift. The\n"
        "midpoint rule is A-stable and conserves E: it has no linear limit and its runs stay "
        "bounded. The\n"
        "variational step has no linear stability function, but a start 1e-6 off the rotation "
        "returns to it\n"
        "at every h tested (claims ledger, stability-boundary-variational): its wrong limits are "
        "its energy\n"
        "loss moving its limit by more than %g%%. Each midpoint substep of a composition "
        "conserves E, so a\n"
        "composition's runs stay bounded: they cannot blow up. The Taylor methods solve no "
        "equation: their\n"
        "solver failures are steps refused beyond their series' radius of convergence. Where "
        "gauss4 loses\n"
        "regularity, its step equation's branch meets a fold: two roots meet and vanish (claims "
        "ledger,\n"
        "stability-fold-gauss4).\n"
        "Data: data/stability.csv.\n",
        100.0 * SUS_LAB_STAB_GOOD_TOL);
}

/* The caption: the map's setup, the linear limits, where each class first appears, and why;
 * every number in it computed here. Returns its length (>= caplen: cut short). */
static size_t caption(const stab_fig *f, const sus_exact *paper, char *cap, size_t caplen)
{
    capbuf b = {cap, 0, caplen};
    cap_setup(f, paper, &b);
    cap_limits(f, &b);
    cap_onsets(f, &b);
    cap_reading(&b);
    return b.len;
}

typedef struct {
    const stab_fig *f;
    long done;
} progress_ctx;

/* A row came back (from whichever process ran it): its runs' steps counted done. */
static void row_done(int m, int i, void *vctx)
{
    progress_ctx *c = vctx;
    c->done += NANGLE * sus_lab_stability_steps(c->f->hs[i]);
    suslov_progress_tick(c->done, "%s at h = %.3g", sus_step_method_get(m)->type->name,
                         c->f->hs[i]);
}

/* Every method's map over NH steps and NANGLE starts, its rows split across `jobs` processes, and
 * its linear limit at the largest h, with the progress (the work counted in steps: a run's cost
 * follows its step count, from 40000 at the smallest h to 50 in the middle). Returns the number of
 * runs that ended with a non-finite error but no failure class, or -1 when the processes failed. */
static int run_maps(stab_fig *f, const sus_exact *paper, int modes, int jobs)
{
    long per_method = 0;
    for (int i = 0; i < NH; i++) {
        f->hs[i] = pow(10.0, -3.0 + 0.2 * i);
        per_method += NANGLE * sus_lab_stability_steps(f->hs[i]);
    }
    progress_ctx pc = {f, 0};
    const sus_lab_stab_maps maps = {paper, f->hs, NH, NANGLE, jobs, row_done, &pc};
    char err[256];
    suslov_progress_start("figure_stability", NULL, per_method * f->nm, modes);
    const int rc = sus_lab_stability_maps(&maps, &f->res[0][0], err, sizeof err);
    suslov_progress_end();
    if (rc != 0) {
        fprintf(stderr, "figure_stability: %s\n", err);
        return -1;
    }
    int unclassified = 0;
    for (int m = 0; m < f->nm; m++) {
        f->limit[m] = sus_lab_linear_limit(sus_step_method_get(m), f->hs[NH - 1]);
        for (int j = 0; j < NH * NANGLE; j++) {
            const sus_lab_stab_result *r = &f->res[m][j];
            unclassified += r->cls < SUS_LAB_STAB_WRONG_LIMIT + 1 && !isfinite(r->final_err);
        }
    }
    return unclassified;
}

/* A number of processes, 1 to 256, read from text; -1 when it is none. */
static int jobs_of(const char *text)
{
    char *end = NULL;
    const long n = text ? strtol(text, &end, 10) : 0;
    return end && end != text && !*end && n >= 1 && n <= 256 ? (int)n : -1;
}

/* The processes the runs are split across: --jobs N (taken out of argv), else SUSLOV_JOBS, else
 * every core. Returns 0, or 2 after one line on stderr for a value that is not 1 to 256. */
static int jobs_option(int *argc, char **argv, int *jobs)
{
    const char *env = getenv("SUSLOV_JOBS");
    *jobs = env ? jobs_of(env) : sus_sys_pool_cores();
    for (int i = 1; i < *argc; i++) {
        if (strcmp(argv[i], "--jobs") != 0)
            continue;
        *jobs = jobs_of(i + 1 < *argc ? argv[i + 1] : NULL);
        for (int j = i; j + 2 <= *argc; j++)
            argv[j] = argv[j + 2];
        *argc -= i + 1 < *argc ? 2 : 1;
        break;
    }
    if (*jobs < 1) {
        fprintf(stderr, "figure_stability: --jobs and SUSLOV_JOBS want a whole number of "
                        "processes, 1 to 256\n");
        return 2;
    }
    return 0;
}

/* --quiet: no progress line; --jobs N: N processes (default SUSLOV_JOBS, else every core) */
int main(int argc, char **argv)
{
    const int modes = suslov_progress_modes(&argc, argv);
    int jobs;
    if (jobs_option(&argc, argv, &jobs) != 0)
        return 2;
    if (argc != 3) { /* the setup's usage line would leave out the options */
        fprintf(stderr, "usage: figure_stability [--quiet] [--jobs N] FIGDIR DATADIR\n");
        return 2;
    }
    sus_model model;
    sus_exact paper;
    const int setup = sus_plot_fig_setup_paper(argc, "stability", &model, &paper);
    if (setup != 0)
        return setup;
    stab_fig *f = malloc(sizeof *f);
    if (!f)
        return 1;
    f->nm = sus_step_method_count();
    f->res = calloc((size_t)f->nm, sizeof *f->res);
    f->limit = calloc((size_t)f->nm, sizeof *f->limit);
    if (!f->res || !f->limit)
        return 1;
    const int unclassified = run_maps(f, &paper, modes, jobs);
    if (unclassified < 0)
        return 1;
    if (unclassified) {
        fprintf(stderr,
                "figure_stability: %d runs ended with a non-finite error but no failure class\n",
                unclassified);
        return 1;
    }
    if (write_csv(f, argv[2]) != 0)
        return 1;
    char cap[8192];
    if (caption(f, &paper, cap, sizeof cap) >= sizeof cap) {
        fprintf(stderr, "figure_stability: the caption is longer than its %zu bytes\n", sizeof cap);
        return 1;
    }
    return sus_plot_fig_write_figure(argv[1], "stability", 600, fig_height(f->nm), draw, f, cap) !=
           0;
}
