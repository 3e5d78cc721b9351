/* Stability boundaries (src/lab/stability.h, figures/stability): the measured linear stability
 * limit of each method at the attracting steady rotation against the one derived from
 * psi' = k cos psi, and where the implicit steps stop being solvable. */
#include "claims_stability.h"

#include "claims_bodies.h"
#include "expected_orders.h"
#include "ledger.h"
#include "stability.h"
#include "stepper.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define H_MAX 1000.0

/* The expected linear limit from theory, independent of src/: for psi' = -k psi an explicit
 * Runge-Kutta method of p = s <= 4 stages (euler, rk4) and a Taylor method of order p both have
 * R(z) = sum_{n <= p} z^n / n!, and the limit is the first h > 0 with |R(-h)| = 1 (bisection on a
 * scan of 1e-3 steps from h = 0.5, where |R(-h)| < 1 for every p >= 1). NAN for other methods. */
static double truncexp(int p, double z)
{
    double r = 1.0, t = 1.0;
    for (int n = 1; n <= p; n++) {
        t *= z / n;
        r += t;
    }
    return r;
}

static double theory_limit(const sus_step_method *me)
{
    const expected_order *eo = expected_order_of(me->type->name);
    if (!eo || !eo->stab_truncated_exp)
        return NAN;
    double lo = 0.5, hi = lo;
    while (fabs(truncexp(eo->p, -hi)) <= 1.0 && hi < H_MAX)
        lo = hi, hi += 1e-3;
    for (int it = 0; it < 60; it++) {
        const double mid = 0.5 * (lo + hi);
        if (fabs(truncexp(eo->p, -mid)) <= 1.0)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* How far a measured limit h is from expect; with no expected limit (none up to H_MAX), the smaller
 * h the worse. A NaN (no return even at the smallest h) is the worst of all. */
static double miss(double h, double expect)
{
    return isnan(h) ? INFINITY : isfinite(expect) ? fabs(h - expect) : -h;
}

/* The measured limit farthest from expect over the paper's body and the general ones: in h = eps k
 * the linearisation is psi' = -k psi on every body, so theory gives one limit for all of them. A
 * body where the returns end because a step is refused beyond its series' proved radius (a Taylor
 * step: step_taylor.c) before expect cannot show the linear limit: it is named in *bound (with the
 * h where its steps stop), not measured. */
static double limit_over_bodies(const sus_stepper_type *st, double expect, char *worst, size_t len,
                                char *bound, size_t blen)
{
    double far = NAN;
    int measured = 0;
    bound[0] = '\0';
    for (int k = 0; k < BODIES_COUNT; k++) {
        const claims_body *d = claims_body_get(k);
        int radius_bound;
        const double h = sus_lab_stability_limit(&d->ex, st, 0.1, H_MAX, &radius_bound);
        if (radius_bound && h < expect) { /* named: its steps stop at the radius before the limit */
            const size_t n = strlen(bound);
            snprintf(bound + n, blen - n, "%s%s ($h \\le %.3g$)", n ? ", " : "", d->b.name, h);
            continue;
        }
        if (!measured++ || miss(h, expect) > miss(far, expect)) {
            far = h;
            snprintf(worst, len, "%s", d->b.name);
        }
    }
    return far;
}

/* The line of a method with a linear limit below H_MAX: the farthest body's against theory
 * (or src/'s R(z) where theory has none), and src/'s R(z) against theory. */
static void limit_lines(const sus_step_method *me, double predicted, double theory)
{
    const sus_stepper_type *st = me->type;
    const double expect = isfinite(theory) ? theory : predicted; /* theory where it is known */
    char id[64], q[640], worst[16], bound[160], named[240] = "";
    const double measured = limit_over_bodies(st, expect, worst, sizeof worst, bound, sizeof bound);
    if (bound[0])
        snprintf(named, sizeof named,
                 "; its steps are refused beyond their proved radius first on %s", bound);
    snprintf(id, sizeof id, "stability-boundary-%s", st->name);
    /* The bisection stops at 1e-4 relative and 4000 steps resolve |R(-h)| - 1 to ~1e-4; the start
     * 1e-6 off the rotation keeps nonlinear terms at 1e-6: 1e-3 h is ample. */
    snprintf(q, sizeof q,
             "largest $h = \\varepsilon k$ at which a start $10^{-6}$ off the steady rotation "
             "returns (bisection), against the linear limit $|R(-h)| = 1$ of %s (%s); the farthest "
             "of %d bodies (%s)%s",
             st->name,
             isfinite(theory) ? "$R = \\sum_{n \\le p} z^n/n!$, theory"
                              : "$R(z)$ of \\texttt{src/methods/stability\\_fn.c}",
             BODIES_COUNT, worst, named);
    ledger_add(id, "(extension)", q, measured, expect, 1e-3 * expect, LEDGER_EXTENSION);
    /* and R(z) in src/ against the truncated exponential of theory (both root-found to 1e-14;
     * 1e-10 leaves room) */
    if (isfinite(theory)) {
        snprintf(id, sizeof id, "stability-boundary-theory-%s", st->name);
        snprintf(q, sizeof q,
                 "linear limit of %s from the $R(z)$ of \\texttt{src/} against the first $h$ with "
                 "$|\\sum_{n \\le p} (-h)^n/n!| = 1$ (theory, $p = %d$)",
                 st->name, expected_order_of(st->name)->p);
        ledger_add(id, "(extension)", q, predicted, theory, 1e-10 * theory, LEDGER_EXTENSION);
    }
}

/* The linear stability boundary of the m-th registered method, if it has a stability function,
 * against bisection, on every body. */
void stability_boundary_claims(int m)
{
    const sus_step_method *me = sus_step_method_get(m);
    const sus_stepper_type *st = me->type;
    /* Compositions have no single linear limit: prod (1 + g_i z/2)/(1 - g_i z/2) is unstable only
     * in narrow bands around the poles z = 2/g_i of the negative weights, so the bisection below
     * and a first crossing measure different things; no claim is made (the map in
     * figures/stability shows where they work). */
    if (!me->type->desc.stability && me->type->desc.substeps > 1)
        return;
    const double predicted = sus_lab_linear_limit(me, H_MAX), theory = theory_limit(me);
    if (isfinite(predicted)) {
        limit_lines(me, predicted, theory);
        return;
    }
    /* No linear limit up to H_MAX (|R(-h)| <= 1 there, or no linear stability function): the
     * start near the rotation must still return at h = H_MAX, where the measurement gives
     * INFINITY; a NaN (no return even at h = 0.1) fails. */
    char id[64], q[640], worst[16], bound[160];
    const double expect = isfinite(theory) ? theory : predicted;
    const double measured = limit_over_bodies(st, expect, worst, sizeof worst, bound, sizeof bound);
    snprintf(id, sizeof id, "stability-boundary-%s", st->name);
    snprintf(q, sizeof q,
             "%s has no linear stability limit (%s): the start $10^{-6}$ off the rotation still "
             "returns at $h = %g$ (the largest $h$ tested), on each of %d bodies (the least: %s)",
             st->name,
             me->type->desc.stability ? "$|R(-h)| \\le 1$ for all $h$ tested"
                                      : "no stability function",
             H_MAX, BODIES_COUNT, worst);
    ledger_add_none_found(id, "(extension)", q, measured, H_MAX, H_MAX, LEDGER_EXTENSION);
}

/* Where the implicit steps stop being solvable: the smallest h of a grid (h = 10^-2 .. 10^3 by 0.2
 * decades, nangle starts round the paper's energy ellipse) at which a run's step equation has no
 * root on its branch (a fold) or its solve fails (stability.h), INFINITY when none; the failed
 * run's result in *failed. */
static double first_failure(const sus_exact *paper, const sus_stepper_type *st, int nangle,
                            double h_from, sus_lab_stab_result *failed)
{
    enum { NHS = 26, NA_MAX = 36 };
    for (int i = 0; i < NHS; i++) {
        const double h = pow(10.0, -2.0 + 0.2 * i);
        sus_lab_stab_result res[NA_MAX];
        if (h < h_from * (1.0 - 1e-9))
            continue;
        sus_lab_stability_map(paper, st, &h, 1, nangle, res);
        for (int a = 0; a < nangle; a++)
            if (res[a].cls == SUS_LAB_STAB_SOLVER || res[a].cls == SUS_LAB_STAB_REGULARITY) {
                *failed = res[a];
                return h;
            }
    }
    return INFINITY;
}

/* Solvability on the ledger's map (12 angles; the figure's 36 for a method whose fold that document
 * places on the figure's map, so that this line sees the fold the figure shows): every implicit
 * step is asserted solvable on its branch far beyond the paper's eps = 1 (h = 0.145): from h = 1,
 * 7x the paper's step, at least.
 * Where docs/explanation/where-methods-fail.md states that no run fails up to the largest h tested
 * (expected_orders.c: solvable_h = INFINITY), the line asserts exactly that (a failure at h = 1000
 * itself fails it). The steps solve for the branch themselves (newton.h), so a failure here is the
 * step equation's: a fold, or a continuation that cannot follow it. */
void stability_solvable_claims(const sus_exact *paper, int m)
{
    char id[64], q[640];
    const sus_step_method *me = sus_step_method_get(m);
    if (!me->type->desc.implicit)
        return;
    sus_lab_stab_result failed;
    const expected_order *eo = expected_order_of(me->type->name);
    const int nangle = eo && eo->fold_on_map ? 36 : 12;
    const double first = first_failure(paper, me->type, nangle, 0.0, &failed);
    const int none_stated = eo && isinf(eo->solvable_h);
    snprintf(id, sizeof id, "stability-solvable-%s", me->type->name);
    snprintf(
        q, sizeof q,
        "smallest $h$ at which a %s run (%d angles, $h$ from 0.01 to 1000) meets a fold of its "
        "step equation's branch continued from $\\varepsilon = 0$, or fails to solve it: %s",
        me->type->name, nangle,
        none_stated ? "none up to $h = 1000$, as where-methods-fail.md states"
                    : "at least 1 ($7\\times$ the paper's $\\varepsilon = 1$)");
    ledger_add_none_found(id, "(extension)", q, first, none_stated ? H_MAX * (1.0 + 1e-12) : 1.0,
                          H_MAX, LEDGER_EXTENSION);
}

/* A fold is what the solvable lines would see: where that document states one on the figure's map
 * (36 angles; expected_orders.c: fold_on_map), the first run that meets it (searched from h = 1),
 * the step there located by bisection on the continuation, and det J's decay towards it. Theory:
 * at a quadratic fold det J ~ (e* - e)^(1/2); the next term, of relative size (e* - e)^(1/2) in
 * the natural scaling, moves the log-log slope fitted over e* - e = 10^-3 .. 10^-7 e* by at most
 * sqrt(1e-3) / 2 = 0.016: the tolerance is 0.05. A fold not found fails the line (NaN). */
void stability_fold_claims(const sus_exact *paper, int m)
{
    char id[64], q[640];
    const sus_step_method *me = sus_step_method_get(m);
    const expected_order *eo = expected_order_of(me->type->name);
    if (!me->type->desc.implicit || !eo || !eo->fold_on_map)
        return;
    sus_lab_stab_result failed = {0};
    double e_star = NAN, exponent = NAN;
    const double h = first_failure(paper, me->type, 36, 1.0, &failed);
    if (isfinite(h) && failed.cls == SUS_LAB_STAB_REGULARITY)
        sus_lab_fold(paper->model, me->type, failed.w_fail, h / paper->k, &e_star, &exponent);
    snprintf(id, sizeof id, "stability-fold-%s", me->type->name);
    snprintf(q, sizeof q,
             "exponent of $|\\det J|$ of the %s step equation against the distance "
             "$\\varepsilon^* - \\varepsilon$ to the fold its branch meets (first on the map of 36 "
             "angles from $h = 1$: $h = %.3g$, step %ld, fold at $\\varepsilon^* k = %.4g$), fit "
             "over $\\varepsilon^* - \\varepsilon$ from $10^{-7}$ to $10^{-3}\\,\\varepsilon^*$: "
             "1/2 (a quadratic fold)",
             me->type->name, h, failed.step, e_star * paper->k);
    ledger_add(id, "(extension)", q, exponent, 0.5, 0.05, LEDGER_EXTENSION);
}
