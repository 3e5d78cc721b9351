/* The claims the captions of Figures 1 and 2 make, measured on the same runs the figures draw
 * (src/prog/figure_fig1.c, src/prog/figure_fig2.c, src/prog/figure_fig2_energy.c,
 * src/prog/figure_inertia.c).
 */
#include "claims_figures.h"
#include "dsp.h"

#include "experiments.h"
#include "claims_refs.h"
#include "ledger.h"
#include "mat3.h"
#include "midpoint_sweeps.h"
#include "notation.h"
#include "series.h"
#include "so3.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#define FIELD(f) offsetof(sus_lab_series, f)

static void run(sus_lab_series *s, const sus_model *m, const sus_stepper_type *st, double eps,
                long N, long every)
{
    sus_run_report rep;
    const sus_run_config cfg = {m, st, SUS_RECON_CAYLEY, eps, N, every};
    if (sus_lab_series_init(s, N, every) != 0 ||
        sus_lab_series_run(s, &cfg, SUS_PAPER_OMEGA0, &rep) != 0) {
        fprintf(stderr, "claims: %s run at eps = %g failed\n", st->name, eps);
        exit(2);
    }
}

/* Is the series the run it claims to be? N/every + 1 rows (the last one at t = N eps), row 0 at
 * w(0), the energy column E(w_k) of its own w, and w_k nowhere zero (the solution tends to a
 * steady rotation of the initial energy, |w| ~ 0.64). A zeroed or truncated series fails. */
static int series_is_run(const sus_lab_series *s, const sus_model *m, double eps, long N,
                         long every)
{
    if (s->n != (size_t)(N / every + 1) || s->t[0] != 0.0 ||
        fabs(s->t[s->n - 1] - (double)N * eps) > 1e-9 * N * eps ||
        s->w1[0] != SUS_PAPER_OMEGA0[0] || s->w2[0] != SUS_PAPER_OMEGA0[1])
        return 0;
    for (size_t i = 0; i < s->n; i++) {
        const double w[2] = {s->w1[i], s->w2[i]};
        if (!(hypot(w[0], w[1]) > 0.1) || s->energy[i] != sus_energy(m, w) || !isfinite(s->mu[i]))
            return 0;
    }
    return 1;
}

/* The unreduced constraint of step 6 of (algo), computed here from the row: <e3, vee(R^T R w^)>,
 * with w^ the hat of all three components of w_k (a w3 != 0 shows as itself). */
static double row_constraint(const sus_row *row)
{
    double W[3][3], V[3][3], P[3][3], xi[3];
    sus_so3_hat(row->w, W);
    sus_mat3_mul(V, row->R, W);
    sus_mat3_mul_at(P, row->R, V);
    sus_so3_vee(P, xi);
    return xi[2];
}

/* A midpoint step that then breaks the constraint by setting w3 = VIOLATION: the positive
 * control, showing that the measurement of the figure claims sees a violation. */
#define VIOLATION 1e-9
static int violating_step(const sus_model *m, double eps, const double w[3], double w_next[3],
                          double *lambda_next, sus_stepper_stats *st)
{
    const double w_in[3] = {w[0], w[1], 0.0};
    const int status = sus_step_midpoint->step->apply(m, eps, w_in, w_next, lambda_next, st);
    w_next[2] = VIOLATION;
    return status;
}
static const sus_step_ops violating_ops = {.apply = violating_step};
static const sus_stepper_type violating_type = {
    .name = "midpoint+violation", .step = &violating_ops, .desc = {.order = 2, .lambda_order = 2}};

/* max over the recorded rows of |w3| and |mu|, when the series is the run it claims to be,
 * and its mu column agrees with the constraint recomputed here from R_k and w_k (to 1e-15: the
 * same products, which another FMA contraction could change by a few u |w| ~ 1e-16); NaN
 * otherwise, so the claim fails. */
typedef struct {
    const sus_lab_series *s;
    size_t i;
    double worst, mismatch;
} recheck_ctx;

static int recheck(void *vctx, const sus_row *row)
{
    recheck_ctx *c = vctx;
    if (c->i < c->s->n) {
        const double mu = row_constraint(row);
        c->mismatch =
            fmax(c->mismatch, fabs(mu - c->s->mu[c->i]) + fabs(row->w[2] - c->s->w3[c->i]));
        c->worst = fmax(c->worst, fmax(fabs(mu), fabs(row->w[2])));
    }
    c->i++;
    return 0;
}

static double constraint_of(const sus_lab_series *s, const sus_model *m, const sus_stepper_type *st,
                            double eps, long N, long every)
{
    if (!series_is_run(s, m, eps, N, every))
        return NAN;
    recheck_ctx c = {s, 0, 0.0, 0.0};
    sus_run_report rep;
    const sus_run_config cfg = {m, st, SUS_RECON_CAYLEY, eps, N, every};
    if (sus_run(&cfg, SUS_PAPER_OMEGA0, recheck, &c, &rep) != 0 || c.i != s->n ||
        !(c.mismatch <= 1e-15))
        return NAN;
    return fmax(c.worst, fmax(sus_lab_series_maxdrift(s, FIELD(w3)) + fabs(s->w3[0]),
                              sus_lab_series_maxdrift(s, FIELD(mu)) + fabs(s->mu[0])));
}

/* The constraint claim of a figure panel (e): both runs, each checked as above, plus the
 * positive control on the same eps and steps: w3 = 1e-9 injected each step must be measured
 * as 1e-9 (vee(R^T R w^)_3 = w3 (1 + O(|R^T R - I|)), so within 10%). */
static void constraint_claims(const char *fig, const char *ref, const sus_model *m,
                              const sus_lab_series *mid, const sus_lab_series *var, double eps,
                              long N, long every)
{
    char id[64], what[400];
    const double cm = constraint_of(mid, m, sus_step_midpoint, eps, N, every);
    const double cv = constraint_of(var, m, sus_step_variational, eps, N, every);
    const double c = isnan(cm) || isnan(cv) ? NAN : fmax(cm, cv); /* fmax would drop a NaN */
    snprintf(id, sizeof id, "%s-constraint", fig);
    snprintf(what, sizeof what,
             "max over both methods of $\\max(|\\omega_3|, |\\langle e_3, (R_k^\\top R_k "
             "\\hat{\\omega}_k)^\\vee \\rangle|)$, $\\varepsilon = %g$, %ld steps (series checked "
             "complete and recomputed from $R_k$)",
             eps, N);
    /* w3 is imposed; the unreduced constraint costs a few u |w| (see constraint-preserved-*) */
    ledger_add(id, ref, what, c, 0.0, 1e-14, LEDGER_REPRODUCED);
    sus_lab_series v;
    sus_run_report rep;
    const sus_run_config cfg = {m, &violating_type, SUS_RECON_CAYLEY, eps, N, every};
    double seen = NAN;
    if (sus_lab_series_init(&v, N, every) == 0 &&
        sus_lab_series_run(&v, &cfg, SUS_PAPER_OMEGA0, &rep) == 0) {
        seen = constraint_of(&v, m, &violating_type, eps, N, every);
        sus_lab_series_free(&v);
    }
    snprintf(id, sizeof id, "%s-constraint-positive-control", fig);
    snprintf(what, sizeof what,
             "the same measurement on a midpoint run with $\\omega_3 "
             "= %s$ injected every step: it sees it",
             notation_g(VIOLATION, 6).s);
    ledger_add(id, "(test of the test)", what, seen, VIOLATION, 0.1 * VIOLATION, LEDGER_EXTENSION);
}

static void figure1(const sus_model *m, const sus_exact *ex)
{
    sus_lab_series mid, var;
    const double eps = SUS_LAB_FIG1_EPS;
    const long N = sus_lab_experiment_steps(SUS_LAB_FIG1_T_END, eps), every = SUS_LAB_FIG1_EVERY;
    run(&mid, m, sus_step_midpoint, eps, N, every);
    run(&var, m, sus_step_variational, eps, N, every);
    const double dw = fmax(sus_lab_series_maxdiff(&mid, &var, FIELD(w1)),
                           sus_lab_series_maxdiff(&mid, &var, FIELD(w2)));
    /* A difference invisible in panels (a)-(b): the smallest plotted range (w2: 0.50 .. 0.68)
     * spans ~400 pixels at 150 dpi, so 1e-4 is a fraction of a pixel. */
    ledger_add(
        "fig1-indistinguishable", REF_SEC56 "; \\PaperRefOr{Fig1}",
        "$\\max_k |\\omega_\\mathrm{mid} - \\omega_\\mathrm{var}|$ at $\\varepsilon = 10^{-3}$ "
        "over $[0, 60]$: below a pixel ($10^{-4}$) of panels (a) and (b)",
        dw, 0.0, 1e-4, LEDGER_REPRODUCED);
    /* "...except with respect to the multipliers": the multipliers differ by O_0 of PropoFinal,
     * up to O(eps) = O(1e-3 |lambda'|) ~ 1e-5. */
    double o0 = 0.0; /* max over the run of |O_0(w(t))| */
    for (size_t i = 0; i < mid.n; i++) {
        double w[2];
        sus_exact_omega(ex, mid.t[i], w);
        o0 = fmax(o0, fabs(sus_lagmult_o0(m, w)));
    }
    /* Row by row, not maxima against maxima: lambda_mid - lambda_var must follow O_0(w(t_k)) at
     * every k >= 1 (row 0 carries lambda(w0) for both methods, driver.h). */
    double off = 0.0;
    for (size_t i = 1; i < mid.n; i++) {
        double w[2];
        sus_exact_omega(ex, mid.t[i], w);
        off = fmax(off, fabs(mid.lambda[i] - var.lambda[i] - sus_lagmult_o0(m, w)));
    }
    if (mid.n < 2)
        off = NAN;
    char q[400];
    snprintf(q, sizeof q,
             "$\\max_{k \\ge 1} |(\\lambda_\\mathrm{mid} - \\lambda_\\mathrm{var})_k - "
             "O_0(\\omega(t_k))|$ at $\\varepsilon = 10^{-3}$: the multipliers differ by $O_0$ "
             "(\\PaperRefOr{PropoFinal}), up to $\\max |O_0| = %.4g$",
             o0);
    ledger_number("FigOneMaxOZero", o0);
    ledger_add("fig1-multipliers-differ", REF_SEC56 "; \\PaperRefOr{Fig1}, panels (c) and (d)", q,
               off, 0.0, 1e-4, LEDGER_REPRODUCED);
    constraint_claims("fig1", "\\PaperRefOr{Fig1}, panel (e)", m, &mid, &var, eps, N, every);
    /* Round-off in E over 6e4 steps walks like sqrt(N) u E ~ 1e-14; 1e-13 leaves a factor 10. */
    ledger_add("fig1-energy-midpoint", "\\PaperRefOr{Fig1}, panel (f)",
               "$\\max_k |E_k - E_0|$ of the midpoint rule, $\\varepsilon = 10^{-3}$: conserved to "
               "round-off (it conserves $E$ exactly)",
               sus_lab_series_maxdrift(&mid, FIELD(energy)), 0.0, 1e-13, LEDGER_REPRODUCED);
    ledger_add_bound(
        "fig1-energy-variational", "\\PaperRefOr{Fig1}, panel (f); extension",
        "$\\max_k |E_k - E_0|$ of the variational integrator, $\\varepsilon = 10^{-3}$: at "
        "least $10^{-12}$, i.e. not round-off ($O(\\varepsilon^2)$ drift)",
        sus_lab_series_maxdrift(&var, FIELD(energy)), 1e-12, 1, LEDGER_EXTENSION);
    sus_lab_series_free(&mid);
    sus_lab_series_free(&var);
}

/* The readings of Figure 2(d) say what they are: one fixed-point sweep of the midpoint rule's
 * equation from x = w^k is explicit Euler, w + eps f(w); two sweeps are the explicit midpoint
 * rule, w + eps f(w + eps f(w)/2). Both written out here, step by step on (ContDyn), and
 * compared over the N steps of the figure: the same operations, so equal to round-off (1e-15
 * on E ~ 0.2 allows a different FMA contraction). */
static void sweeps_are_explicit_methods(const sus_model *m, double eps, long N, double *E)
{
    for (int n = 1; E && n <= 2; n++) {
        double w[2] = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]}, wN[2], d = 0.0;
        sus_lab_midpoint_sweeps_run(m, eps, n, SUS_PAPER_OMEGA0, N, E, wN);
        for (long k = 0; k <= N; k++) {
            d = fmax(d, fabs(E[k] - sus_energy(m, w)));
            double f[2], y[2] = {w[0], w[1]};
            sus_contdyn(m, w, f);
            if (n == 2) {
                y[0] = w[0] + 0.5 * eps * f[0];
                y[1] = w[1] + 0.5 * eps * f[1];
                sus_contdyn(m, y, f);
            }
            w[0] += eps * f[0];
            w[1] += eps * f[1];
        }
        char id[64], what[320];
        snprintf(id, sizeof id, "fig2-reading-%d-sweep%s", n,
                 n == 1 ? "-is-euler" : "s-are-explicit-midpoint");
        snprintf(
            what, sizeof what,
            "$\\max_k$ of the difference in $E_k$, %d fixed-point sweep%s against %s written out, "
            "$\\varepsilon = %g$, %ld steps",
            n, n == 1 ? "" : "s", n == 1 ? "explicit Euler" : "the explicit midpoint rule", eps, N);
        ledger_add(id, REF_FIG2D "; evidence", what, d, 0.0, 1e-15, LEDGER_EXTENSION);
    }
}

/* "works quite well if the step size is relatively big": the variational error relative to
 * |w0|, against the midpoint rule's, over the Figure 2 run. */
static void fig2_accuracy_claims(const sus_exact *ex, const sus_lab_series *mid,
                                 const sus_lab_series *var)
{
    double err_var = 0.0, err_mid = 0.0;
    for (size_t i = 0; i < mid->n; i++) {
        double w[2];
        sus_exact_omega(ex, mid->t[i], w);
        err_var = fmax(err_var, hypot(var->w1[i] - w[0], var->w2[i] - w[1]));
        err_mid = fmax(err_mid, hypot(mid->w1[i] - w[0], mid->w2[i] - w[1]));
    }
    const double r0 = hypot(SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]);
    /* The paper gives no tolerance for "quite well" and its figure image is missing, so no
     * verdict on the paper can follow from a threshold we would choose; what is measured is the
     * comparison, recorded as ours. */
    ledger_add_bound(
        "fig2-accuracy", "(extension)",
        "$\\max_k |\\omega_\\mathrm{var} - \\omega(t_k)| / |\\omega_0|$ at $\\varepsilon "
        "= 1$ over $[0, 200]$, above the midpoint rule's (expected); the paper's ``quite "
        "well'' gives no tolerance to test",
        err_var / r0, err_mid / r0, 1, LEDGER_EXTENSION);
    ledger_number("FigTwoMidAccuracyPercent", 100.0 * err_mid / r0);
    ledger_number("FigTwoVarAccuracyPercent", 100.0 * err_var / r0);
}

/* The caption: midpoint shows a fast decay of energy, the variational integrator is better. */
static void fig2_energy_claims(const sus_lab_series *mid, double loss_mid, double loss_var)
{
    ledger_add_bound(
        "fig2-energy-midpoint", REF_FIG2D "; " REF_SEC56,
        "energy lost by the midpoint rule over $[0, 200]$, $\\varepsilon = 1$; the paper's "
        "``fast decay'' needs it to exceed the variational loss (expected)",
        loss_mid, loss_var, 1, LEDGER_NOT_REPRODUCED);
    ledger_add_bound(
        "fig2-energy-variational", REF_FIG2D "; " REF_SEC56,
        "$|E_N - E_0|$ of the variational integrator, $\\varepsilon = 1$; ``much better'' "
        "needs it below the midpoint's $|E_N - E_0|$ (expected)",
        fabs(loss_var), fabs(loss_mid), 0, LEDGER_NOT_REPRODUCED);
    /* 200 steps, each changing E by at most a few roundings u E ~ 1e-16 (Newton solves to 16 u
     * of its scale): a walk of sqrt(200) u E ~ 1e-15; 1e-14 leaves a factor 10. */
    ledger_add("fig2-energy-midpoint-conserved", "(extension)",
               "$\\max_k |E_k - E_0|$ of the midpoint rule at $\\varepsilon = 1$ over 200 steps: "
               "round-off, the implicit midpoint rule conserves $E$",
               sus_lab_series_maxdrift(mid, FIELD(energy)), 0.0, 1e-14, LEDGER_EXTENSION);
}

/* Every reading of the midpoint rule's implicit equation tried (figures/fig2_energy). */
static void fig2_readings_claims(const sus_model *m, double eps, long N, double loss_mid,
                                 double loss_var)
{
    double worst_loss = loss_mid, *E = malloc((size_t)(N + 1) * sizeof *E), wN[2];
    int gaining = 0;
    for (int n = 1; E && n <= SUS_LAB_FIG2_NSWEEP; n++) {
        sus_lab_midpoint_sweeps_run(m, eps, n, SUS_PAPER_OMEGA0, N, E, wN);
        worst_loss = fmax(worst_loss, E[0] - E[N]);
        gaining += E[N] > E[0];
    }
    ledger_number("FigTwoSweepsTried", SUS_LAB_FIG2_NSWEEP);
    ledger_number("FigTwoSweepsGaining",
                  gaining); /* readings that end with more energy than they began */
    sweeps_are_explicit_methods(m, eps, N, E);
    free(E);
    ledger_number("FigTwoReadingsWorstLoss", worst_loss);
    ledger_add_bound(
        "fig2-energy-readings", REF_FIG2D "; evidence",
        "largest energy loss at $t = 200$ over the readings of the midpoint rule (Newton; 1 "
        "to 8 fixed-point sweeps, explicit Euler and explicit midpoint among them); the "
        "caption needs it above the variational loss (expected)",
        worst_loss, loss_var, 1, LEDGER_NOT_REPRODUCED);
}

/* Where each run ends: the midpoint rule at the exact steady rotation, the variational integrator
 * at a steady rotation of the energy it has lost. */
static void fig2_limit_claims(const sus_exact *ex, const sus_lab_series *mid,
                              const sus_lab_series *var)
{
    const size_t last = mid->n - 1;
    const double E0 = mid->energy[0];
    double winf[2];
    sus_exact_limit(ex, winf);
    const double lim_var = hypot(var->w1[last] - winf[0], var->w2[last] - winf[1]);
    const double lim_mid = hypot(mid->w1[last] - winf[0], mid->w2[last] - winf[1]);
    ledger_add_bound(
        "fig2-longterm", REF_FIG2_CAPTION,
        "$|\\omega_\\mathrm{var}(200) - \\omega_\\infty|$, $\\varepsilon = 1$: ``long-term "
        "behaviour much more accurate'' needs it below the midpoint's "
        "$|\\omega_\\mathrm{mid}(200) - \\omega_\\infty|$ (expected)",
        lim_var, lim_mid, 0, LEDGER_NOT_REPRODUCED);
    /* The midpoint rule conserves E, and its fixed points are the zeros of f on the energy
     * ellipse: it tends to the exact steady rotation. At t = 200 the exact distance is
     * e^{-200 k} ~ 1e-13; 1e-10 bounds the midpoint's. */
    ledger_add(
        "fig2-limit-midpoint", "(extension)",
        "$|\\omega_\\mathrm{mid}(200) - \\omega_\\infty|$ at $\\varepsilon = 1$: the midpoint "
        "rule reaches the exact steady rotation",
        lim_mid, 0.0, 1e-10, LEDGER_EXTENSION);
    /* A fixed point of (taudyn) has c(w) = 0: the variational integrator also ends on a steady
     * rotation, but at the energy it has lost, so |w_var - w_inf| = |w_inf| (1 - sqrt(E_N/E_0)).
     * The identity holds once the run sits on that rotation: at t = 200 the exact motion is
     * e^{-200 k} ~ 3e-13 from it, and 1e-9 allows the variational run to settle a thousand
     * times more slowly than the exact one. */
    const double predicted = hypot(winf[0], winf[1]) * (1.0 - sqrt(var->energy[last] / E0));
    ledger_add("fig2-limit-variational", "(extension)",
               "$|\\omega_\\mathrm{var}(200) - \\omega_\\infty|$ against $|\\omega_\\infty| (1 - "
               "\\sqrt{E_N / E_0})$: a steady rotation at the wrong energy",
               lim_var, predicted, 1e-9, LEDGER_EXTENSION);
}

static void figure2(const sus_model *m, const sus_exact *ex)
{
    sus_lab_series mid, var;
    const double eps = SUS_LAB_FIG2_EPS;
    const long N = sus_lab_experiment_steps(SUS_LAB_FIG2_T_END, eps);
    run(&mid, m, sus_step_midpoint, eps, N, 1);
    run(&var, m, sus_step_variational, eps, N, 1);
    const size_t last = mid.n - 1;
    const double E0 = mid.energy[0];
    const double loss_mid = E0 - mid.energy[last], loss_var = E0 - var.energy[last];
    constraint_claims("fig2", "\\PaperRefOr{Fig2}, panel (e)", m, &mid, &var, eps, N, 1);
    fig2_energy_claims(&mid, loss_mid, loss_var);
    fig2_readings_claims(m, eps, N, loss_mid, loss_var);
    fig2_accuracy_claims(ex, &mid, &var);
    ledger_number("FigTwoVarEnergyLossPercent", 100.0 * loss_var / E0);
    fig2_limit_claims(ex, &mid, &var);
    sus_lab_series_free(&mid);
    sus_lab_series_free(&var);
}

/* The printed I has I23 = 0.2 but I32 = 0.1. The dynamics use the third row; a symmetric
 * body would have (I31, I32) = (I13, I23) = (0.2, 0.2). How much does the choice matter? */
static void inertia_ambiguity(const sus_model *m)
{
    double Irow[9], Icol[9];
    for (int i = 0; i < 9; i++)
        Irow[i] = m->I[i / 3][i % 3];
    sus_lab_inertia_column_swap(Irow, Icol);
    sus_model mc;
    sus_exact er, ec;
    char err[128];
    if (sus_model_init(&mc, Icol, err, sizeof err) != 0)
        exit(2);
    sus_exact_init(&er, m, SUS_PAPER_OMEGA0);
    sus_exact_init(&ec, &mc, SUS_PAPER_OMEGA0);
    double d = 0.0;
    const long n = sus_lab_experiment_steps(SUS_LAB_INERTIA_T_END, SUS_LAB_INERTIA_DT);
    for (long i = 0; i <= n; i++) { /* the grid src/prog/figure_inertia.c draws */
        double a[2], b[2];
        sus_exact_omega(&er, SUS_LAB_INERTIA_DT * (double)i, a);
        sus_exact_omega(&ec, SUS_LAB_INERTIA_DT * (double)i, b);
        d = fmax(d, hypot(a[0] - b[0], a[1] - b[1]));
    }
    ledger_add_bound(
        "inertia-row-vs-column", "\\eqref{RGB2} with $I$ as printed; extension",
        "$\\max_t |\\omega_\\mathrm{row}(t) - \\omega_\\mathrm{col}(t)|$ on $[0, 60]$, exact "
        "solutions with $(I_{31}, I_{32}) = (0.2, 0.1)$ against $(0.2, 0.2)$: the choice is "
        "visible ($> 10^{-3}$)",
        d, 1e-3, 1, LEDGER_EXTENSION);
}

void figure_claims(const sus_model *m, const sus_exact *ex)
{
    figure1(m, ex);
    figure2(m, ex);
    inertia_ambiguity(m);
}
