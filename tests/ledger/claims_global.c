/* Global orders on every body (claims_global.h).
 *
 * Where. Each body runs to T with k T = k_paper t_paper, its transient at the phase the paper's
 * body has at t_paper (the exact motion is a function of k t: tanh and sech of k t + s0,
 * exact.h): t_paper = 10 for the paper's methods, as claims.c's global lines, and 50 for the
 * extensions, as claims_highorder.c's. N = round(4 * 2^(j/4)) steps, the grid claims_window.h
 * derives its bound for, so the dimensionless step h = eps k = k T / N is the same on every body.
 * w is compared with the closed form, R with the long-double reference (refattitude.h) at T; the
 * reference's own error on each body is a line below (against the independent Magnus-4).
 *
 * The rule: the per-curve window of claims_window.h for every method, the run of one slope spanning
 * an octave nearest the asymptotic regime, fitted within 0.25 of p (WINDOW_ORDER_TOL); where no run
 * has one slope, the smallest-eps octave, >= p / 2. Its bound assumes only that one term dominates
 * the pre-asymptotic bend, C eps^p (1 + a eps + ...), whatever a: a body changes a (its rate k and
 * rotation |w| set it), which moves where the run of one slope lies, not how far its fit can be
 * from p. Candidates lie between the round-off of the run (the larger of 1000 u and 100 N s u,
 * times the size of the quantity along the motion; u = 2^-52, DBL_EPSILON) and that size. A body
 * whose error is at round-off at all but at most two steps of the grid (and nowhere as large as the
 * quantity) has no order to measure: it is named in the line, not measured (a line with no body
 * measured fails). w at order >= 10 with no run of one slope on a body (it reaches round-off first)
 * leaves that body out of the w line of a method that is not a series: the SO(3) line, which
 * integrates w, carries the order.
 *
 * Two kinds of curve need more than that rule:
 *   - a truncated series (the Taylor methods) reaches round-off before its asymptotic regime
 *     (claims_highorder.c): its runs of one slope lie where h / rho is not small, steeper or
 *     shallower than p by more than the window's bound, which does not apply there. Its slope is
 *     taken as the lower estimate of claims_window.h (>= p / 2, which a series truncated at half
 *     its degree fails) on every body, and p is told from p - 1 by the local control of
 *     claims_highorder.c;
 *   - a first-order reconstruction (cayley) on a body whose rotation is fast against its transient
 *     (|w| / k twice the paper's body's on body2) carries a global error of two parts: the
 *     first-order part grows with the transient only, the second-order one with the rotation over
 *     all of T, so a longer T moves the first-order regime to smaller steps. The paper's methods
 *     are measured at claims.c's phase, k T = 10 k_paper, with curves to N = 2^15; at the
 *     extensions' phase (k T = 50 k_paper) the second-order part dominates on body2 down to steps
 *     below the grid's. Theory gives the direction, not which phase shows the first-order regime
 *     within the grid: that phase was chosen with body2's curves known, and it governs the
 *     global-order-bodies-* and global-so3-order-bodies-* lines. claims_window.h's preference for
 *     the run of one slope nearest the asymptotic regime serves the same curves (see there).
 * Each line reports the body nearest to failing it (the least margin to its bound). */
#include "claims_global.h"

#include "claims_bodies.h"
#include "claims_window.h"
#include "driver.h"
#include "expected_orders.h"
#include "ledger.h"
#include "notation.h"
#include "magnus4.h"
#include "orderfit.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define T_EXTENSION 50.0     /* t_paper of the extensions (claims_highorder.c) */
#define T_PAPER_METHODS 10.0 /* t_paper of the paper's methods (claims.c's global lines) */
#define MAXN 80
#define N_EXTENSION 100000L
#define N_PAPER 32768L

typedef struct {
    double w[3], R[3][3];
} last_state;

static int keep_state(void *vctx, const sus_row *row)
{
    last_state *l = vctx;
    memcpy(l->w, row->w, sizeof l->w);
    memcpy(l->R, row->R, sizeof l->R);
    return 0;
}

/* One body's target: T, w(T) and R(T). */
typedef struct {
    const claims_body *d;
    double T, w_T[2], R_T[3][3];
} body_target;

static body_target target_of(int k, double k_paper, double t_paper)
{
    body_target t = {claims_body_get(k), 0.0, {0.0, 0.0}, {{0.0}}};
    double w_ref[2];
    t.T = t_paper * k_paper / t.d->ex.k;
    sus_exact_omega(&t.d->ex, t.T, t.w_T);
    sus_refatt_precise(&t.d->m, t.d->ex.w0, t.T, w_ref, t.R_T);
    return t;
}

/* The errors at T for the grid of N (below n_max), down to the round-off floor of both
 * quantities; eps[] holds h = eps k. Returns the count. */
static int error_curves(const body_target *t, const sus_stepper_type *st, sus_recon recon,
                        long n_max, double *h, double *ew, double *eR)
{
    const double size_w = t->d->size_w;
    int n = 0;
    long prev = 0;
    for (int j = 0; n < MAXN; j++) {
        const long N = lround(4.0 * exp2(j / 4.0));
        if (N >= n_max)
            break;
        if (N == prev)
            continue;
        prev = N;
        last_state l;
        const sus_run_config cfg = {&t->d->m, st, recon, t->T / (double)N, N, N};
        sus_run_report rep;
        if (sus_run(&cfg, t->d->ex.w0, keep_state, &l, &rep) != 0)
            continue;
        h[n] = t->d->ex.k * t->T / (double)N;
        ew[n] = hypot(l.w[0] - t->w_T[0], l.w[1] - t->w_T[1]);
        eR[n] = sus_so3_dist(t->R_T, l.R);
        n++;
        const double floor = 100.0 * (double)N * st->desc.substeps * DBL_EPSILON;
        if (ew[n - 1] < floor * size_w && eR[n - 1] < floor * SUS_LAB_SIZE_R)
            break; /* both at the round-off floor below */
    }
    return n;
}

/* A fit and how far it is inside its bound (negative: outside; NaN: none). */
typedef struct {
    window_slope w;
    double margin;
} curve_fit;

static curve_fit fit_curve(const sus_stepper_type *st, int p, const double *h, const double *err,
                           int n, double size, double kT, int *at_roundoff)
{
    int cand[MAXN], ncand = 0, above = 0;
    for (int j = 0; j < n; j++) {
        const double N = kT / h[j];
        const double floor =
            fmax(SUS_LAB_FIT_FLOOR_REL * size, 100.0 * N * st->desc.substeps * DBL_EPSILON * size);
        cand[j] = err[j] > floor && err[j] < size;
        ncand += cand[j];
        above += !(err[j] < size);
    }
    /* at round-off at all but at most two steps, and never as large as the quantity: no order to
     * measure (a fit needs three points); a curve that stays large is no such case */
    *at_roundoff = n > 0 && ncand < 3 && above == 0;
    curve_fit f = {window_measure(h, err, cand, n), NAN};
    if (st->step->apply_order) /* a series: a lower estimate whatever the window (see the top) */
        f.w.plateau = 0;
    f.margin = f.w.plateau ? WINDOW_ORDER_TOL - fabs(f.w.slope - p) : f.w.slope - 0.5 * p;
    return f;
}

typedef struct {
    curve_fit f;
    char body[16];
    int bodies, skipped; /* measured; left out by the w rule at order >= 10 */
    char roundoff[64];   /* the bodies at round-off wherever they step, named */
} worst_fit;

/* The line: the worst body's fit against the bound of its kind. */
static void order_line(const sus_step_method *me, const expected_order *eo, sus_recon recon, int q,
                       const worst_fit *wf)
{
    const int p = q ? eo->so3[recon] : eo->p, paper = me->paper_ref != NULL;
    char id[96], what[640], label[64];
    const curve_fit *f = &wf->f;
    if (q)
        snprintf(id, sizeof id,
                 paper ? "global-so3-order-bodies-%s-%s" : "highorder-so3-order-%s-%s",
                 SUS_RECON_NAMES[recon], me->type->name);
    else
        snprintf(id, sizeof id, paper ? "global-order-bodies-%s" : "highorder-w-order-%s",
                 me->type->name);
    const double t_paper = paper ? T_PAPER_METHODS : T_EXTENSION;
    snprintf(
        what, sizeof what,
        "slope of %s at $k T = %.3g$ ($t = %g$ on the paper's body) against $\\varepsilon$, %s, "
        "errors in $[\\max(1000\\,u, 100\\,N s\\,u), 1] \\times \\mathrm{size}$; the nearest "
        "to its bound of %d bodies: %s ($h = \\varepsilon k$ from $%s$ to $%s$, %d points%s)",
        q ? "the distance \\eqref{MetMat} $\\mathrm{dist}(R(T), R_N)$"
          : "$|\\omega(T) - \\omega_N|$",
        t_paper * claims_body_get(0)->ex.k, t_paper,
        q ? sus_step_method_label(me->type, recon, label, sizeof label) : me->type->name,
        wf->bodies, wf->body, notation_g(isnan(f->w.slope) ? 0.0 : f->w.eps_lo, 3).s,
        notation_g(isnan(f->w.slope) ? 0.0 : f->w.eps_hi, 3).s, f->w.used,
        f->w.plateau ? ", one slope" : "; no one slope: lower estimate, $\\ge p/2$");
    if (wf->roundoff[0]) { /* named, not measured: their errors are round-off at every step tried */
        const size_t len = strlen(what);
        snprintf(what + len, sizeof what - len,
                 "; at round-off at all but at most 2 steps, no order: %s", wf->roundoff);
    }
    const double slope = isnan(f->w.slope) ? -INFINITY : f->w.slope;
    const ledger_assert truth = paper && !q ? LEDGER_REPRODUCED : LEDGER_EXTENSION;
    const char *ref = paper && q ? "\\PaperRefOr{TeoL}, extension" : eo->ref;
    if (f->w.plateau && !isnan(f->w.slope))
        ledger_add(id, ref, what, slope, p, WINDOW_ORDER_TOL, truth);
    else
        ledger_add_bound(id, ref, what, slope, 0.5 * p, 1, truth);
}

/* The fits of one method and reconstruction on every body: w (q = 0, with_w) and R (q = 1). */
static void order_rows(const body_target *t, const sus_step_method *me, const expected_order *eo,
                       sus_recon recon, int with_w)
{
    worst_fit wf[2] = {{.f.margin = INFINITY, .f.w.slope = NAN},
                       {.f.margin = INFINITY, .f.w.slope = NAN}};
    const long n_max = me->paper_ref ? N_PAPER : N_EXTENSION;
    for (int k = 0; k < BODIES_COUNT; k++) {
        double h[MAXN], ew[MAXN], eR[MAXN];
        const int n = error_curves(&t[k], me->type, recon, n_max, h, ew, eR);
        for (int q = with_w ? 0 : 1; q < 2; q++) {
            const int p = q ? eo->so3[recon] : eo->p;
            int at_roundoff;
            const curve_fit f =
                fit_curve(me->type, p, h, q ? eR : ew, n, q ? SUS_LAB_SIZE_R : t[k].d->size_w,
                          t[k].d->ex.k * t[k].T, &at_roundoff);
            if (at_roundoff) {
                const size_t len = strlen(wf[q].roundoff);
                snprintf(wf[q].roundoff + len, sizeof wf[q].roundoff - len, "%s%s", len ? ", " : "",
                         t[k].d->b.name);
                continue;
            }
            if (!q && p >= 10 && !me->type->step->apply_order &&
                (isnan(f.w.slope) || !f.w.plateau)) {
                wf[q].skipped++;
                continue; /* w reaches round-off before it has one slope: the SO(3) row */
            }
            wf[q].bodies++;
            if (!(f.margin >= wf[q].f.margin)) {
                wf[q].f = f;
                snprintf(wf[q].body, sizeof wf[q].body, "%s", t[k].d->b.name);
            }
        }
    }
    for (int q = with_w ? 0 : 1; q < 2;
         q++) /* no line only where the rule above left out every body */
        if (wf[q].bodies || !wf[q].skipped)
            order_line(me, eo, recon, q, &wf[q]);
}

/* The reference R(T) on every body against the long-double Magnus-4 along the closed form
 * (Richardson from 4000 and 8000 steps: ~1e-17; each matrix rounded once, so ~1e-16 is the
 * floor): at most 1e-15, a tenth of what would blur an error of 1e-12 by 1%. */
static void reference_line(const body_target *t)
{
    double worst = 0.0;
    char name[16] = "";
    for (int k = 0; k < BODIES_COUNT; k++) {
        double Rm[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        sus_magnus4(&t[k].d->ex, 0.0, t[k].T, 4000, Rm);
        const double d = sus_so3_dist(t[k].R_T, Rm);
        if (!(d <= worst))
            worst = d, snprintf(name, sizeof name, "%s", t[k].d->b.name);
    }
    char what[400];
    snprintf(
        what, sizeof what,
        "$\\mathrm{dist}(R_\\mathrm{ref}(T), R_\\mathrm{magnus}(T))$ at $k T = %.3g$ (the longer "
        "phase), the worst of %d bodies (%s): the reference that judges the global orders on "
        "every body; claimed $\\le 10^{-15}$",
        T_EXTENSION * claims_body_get(0)->ex.k, BODIES_COUNT, name);
    ledger_add("global-reference-attitude-bodies", "(method)", what, worst, 0.0, 1e-15,
               LEDGER_EXTENSION);
}

/* The targets of every body at the extensions' phase (te) and the paper methods' (tp), made once
 * in a process. */
static body_target te[BODIES_COUNT], tp[BODIES_COUNT];
static int targets_made;

static void make_targets(void)
{
    const double k_paper = claims_body_get(0)->ex.k;
    if (targets_made)
        return;
    for (int k = 0; k < BODIES_COUNT; k++) {
        te[k] = target_of(k, k_paper, T_EXTENSION);
        tp[k] = target_of(k, k_paper, T_PAPER_METHODS);
    }
    targets_made = 1;
}

void global_reference_claims(void)
{
    make_targets();
    reference_line(te);
}

void global_order_claims_of(int i)
{
    const sus_step_method *me = sus_step_method_get(i);
    const expected_order *eo = expected_order_of(me->type->name);
    if (!eo)
        return; /* missing: claims_methods.c fails it */
    make_targets();
    if (me->paper_ref) { /* every reconstruction, as claims_consistency.c's global lines */
        for (int r = 0; r < SUS_RECON_COUNT; r++)
            order_rows(tp, me, eo, (sus_recon)r, r == 0);
        return;
    }
    order_rows(te, me, eo, me->recon, 1);
    /* the paper's retraction, symmetrised, beside the exponential */
    if (!me->type->step->apply_order)
        order_rows(te, me, eo, SUS_RECON_CAYLEY_MID, 0);
}
