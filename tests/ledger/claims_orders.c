#include "claims_orders.h"

#include "bodies.h"
#include "claims_window.h"
#include "orderfit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The least-squares slope over eps[lo .. hi], or NaN. */
static double slope_over(const double *eps, const double *err, int lo, int hi)
{
    sus_lab_order_fit f;
    if (hi - lo < 2 || sus_lab_fit_order(eps + lo, err + lo, hi - lo + 1, INFINITY, 0.0, &f) != 0)
        return NAN;
    return f.slope;
}

/* The last index of the octave of candidates that starts at lo (eps falls with j), or -1 when the
 * candidates stop before an octave: the grids are powers of 2^(1/4) (claims_window.c's rounding).
 */
static int octave_from(const double *eps, const int *cand, int n, int lo)
{
    for (int j = lo; j < n && cand[j]; j++)
        if (eps[lo] >= 2.0 * (1.0 - 1e-9) * eps[j])
            return j;
    return -1;
}

/* The largest eps k at which theory bounds the bend of a local slope below WINDOW_ORDER_TOL: the
 * error is C eps^(p+1) (1 + a eps + ...) with a = 2k / pi, the reciprocal of the radius of
 * analyticity in t of the exact solution (tanh and sech of k t + s0, singular at distance
 * pi / (2k)), whose local slope lies within a eps / (1 - a eps) of p + 1 (claims_fit.c's widened
 * window): below 0.25 for a eps < 0.2, eps k < pi / 10. */
#define EPS_K_BEND (0.1 * 3.14159265358979)

/* Is the window of one slope the asymptotic one? Its guarantee (claims_window.h: the fit within
 * 0.247 of the order) rests on a bend that one term dominates, a eps^m: then the slope moves
 * monotonely toward p as eps falls, and over the octave after a window whose chords span less
 * than WINDOW_SLOPE_SPAN it moves by less than that span. It is not the asymptotic one
 *   - where it lies wholly above EPS_K_BEND, so that nothing bounds its bend (on a stiff body
 *     round-off can cut the curve before the asymptotic range: a pre-asymptotic stretch of one
 *     slope is no evidence of the order), or
 *   - where candidates continue below it and their slope over the next octave differs from the
 *     window's by the span or more (the bend is not of that kind: a near-singular I_m's error
 *     passes through a second regime).
 * Then the slope is only rule 2's lower estimate. */
static int window_settled(const double *eps, double k, const double *err, const int *cand, int n,
                          window_slope w)
{
    if (w.eps_lo * k >= EPS_K_BEND)
        return 0;
    int end = 0;
    while (end < n && eps[end] != w.eps_lo)
        end++;
    const int next = octave_from(eps, cand, n, end);
    return next < 0 || fabs(slope_over(eps, err, end, next) - w.slope) < WINDOW_SLOPE_SPAN;
}

/* Rule 2 of claims_window.h: the smallest-eps candidates, back to an octave. */
static window_slope last_octave(const double *eps, const double *err, const int *cand, int n)
{
    int hi = n - 1, lo;
    while (hi >= 0 && !cand[hi])
        hi--;
    for (lo = hi; lo > 0 && cand[lo - 1] && !(eps[lo] >= 2.0 * (1.0 - 1e-9) * eps[hi]); lo--)
        ;
    const int h = hi < 0 ? 0 : hi, l = lo < 0 ? 0 : lo;
    return (window_slope){slope_over(eps, err, lo, hi), 0, hi - lo + 1, eps[h], eps[l]};
}

curve_order order_of_curve(const double *eps, double k, const double *err, int n, double size,
                           const double *floor)
{
    int *cand = malloc((size_t)n * sizeof *cand), steps = 0, above = 0;
    if (!cand)
        ledger_die("memory for an order fit");
    double eps_ok = NAN;
    for (int j = 0; j < n; j++) {
        cand[j] = isfinite(err[j]) && err[j] > floor[j] && err[j] < size;
        above += cand[j];
        if (isfinite(err[j]) && !steps++)
            eps_ok = eps[j] * k;
    }
    window_slope w = window_measure(eps, err, cand, n);
    if (w.plateau && !window_settled(eps, k, err, cand, n, w))
        w = last_octave(eps, err, cand, n);
    free(cand);
    const int at_roundoff = steps >= 3 && above < 3;
    return (curve_order){w.slope - 1.0, w.plateau, at_roundoff, w.eps_lo * k, w.eps_hi * k, eps_ok};
}

curve_order order_of_pair(curve_order r, curve_order p)
{
    if (r.at_roundoff || p.at_roundoff)
        return r;
    curve_order c = r.order <= p.order || isnan(r.order) ? r : p;
    if (isnan(p.order))
        c.order = NAN;
    return c;
}

order_summary order_summary_new(void)
{
    return (order_summary){.lo = INFINITY, .hi = -INFINITY, .fb_lo = INFINITY, .fb_hi = -INFINITY};
}

void order_summary_add(order_summary *s, curve_order c, double expected, const char *body_name)
{
    if (c.at_roundoff) {
        const size_t len = strlen(s->roundoff_bodies);
        snprintf(s->roundoff_bodies + len, sizeof s->roundoff_bodies - len, "%s%s ($\\le %.3g$)",
                 s->roundoff++ ? ", " : "", body_name, c.eps_ok);
        return;
    }
    if (isnan(c.order)) {
        if (!s->unmeasured++)
            s->unmeasured_body = body_name;
        return;
    }
    if (!c.plateau) {
        s->fallback++;
        if (!s->fb_body || c.order < s->fb_lo)
            s->fb_body = body_name;
        s->fb_lo = fmin(s->fb_lo, c.order);
        s->fb_hi = fmax(s->fb_hi, c.order);
        return;
    }
    s->plateaus++;
    s->lo = fmin(s->lo, c.order);
    s->hi = fmax(s->hi, c.order);
    if (!s->worst_body || fabs(c.order - expected) > fabs(s->worst - expected)) {
        s->worst = c.order;
        s->worst_body = body_name;
        s->eps_lo = c.eps_lo;
        s->eps_hi = c.eps_hi;
    }
}

/* "; no order on ...": the bodies at round-off, or nothing. */
static void roundoff_note(const order_summary *s, char *buf, size_t len)
{
    buf[0] = '\0';
    if (s->roundoff)
        snprintf(buf, len,
                 "; no order on %d (error below the round-off floor at every $\\varepsilon k$ "
                 "stepped, up to): %s",
                 s->roundoff, s->roundoff_bodies);
}

/* "; k with only a lower estimate ...": the fallback bodies beside the windows of one slope. */
static void fallback_note(const order_summary *s, char *buf, size_t len)
{
    buf[0] = '\0';
    if (s->fallback)
        snprintf(buf, len,
                 "; %d reach round-off before one slope (lower estimate over the last octave above "
                 "it, $\\ge p/2$): %.2f to %.2f",
                 s->fallback, s->fb_lo, s->fb_hi);
}

void ledger_order_line_at(const char *file, int line, const char *id, const char *what,
                          const char *name, const order_summary *s, int expected, const char *ref,
                          ledger_assert truth)
{
    char q[640], note[320], fb[200];
    const int measured = BODIES_COUNT - s->roundoff;
    roundoff_note(s, note, sizeof note);
    if (s->unmeasured || !measured) {
        snprintf(q, sizeof q,
                 "%s, %s: no order on %s (%d of %d bodies): fewer than 3 steps taken, or "
                 "fewer than 3 consecutive errors above the round-off floor%s",
                 what, name, s->unmeasured ? s->unmeasured_body : "any",
                 s->unmeasured ? s->unmeasured : measured, BODIES_COUNT, note);
        ledger_add_bound_at(file, line, id, ref, q, -INFINITY, expected - 1.0, 1, truth);
        return;
    }
    if (!s->plateaus || s->fb_lo < 0.5 * expected) {
        snprintf(q, sizeof q,
                 "%s, %s $\\ge p/2$ (lower estimate: not $p$ against $p-1$); lowest of %d of %d "
                 "bodies (seed %u) %s; %d reach round-off before one slope, fit on the last octave "
                 "above it; range %.2f to %.2f%s",
                 what, name, measured, BODIES_COUNT, BODIES_SEED, s->fb_body, s->fallback, s->fb_lo,
                 s->fb_hi, note);
        ledger_add_bound_at(file, line, id, ref, q, s->fb_lo, 0.5 * expected, 1, truth);
        return;
    }
    fallback_note(s, fb, sizeof fb);
    snprintf(
        q, sizeof q,
        "%s, %s; worst of %d of %d bodies (seed %u) with one slope, %s, window $\\varepsilon k "
        "\\in [%.3g, %.3g]$; range %.2f to %.2f%s%s",
        what, name, s->plateaus, BODIES_COUNT, BODIES_SEED, s->worst_body, s->eps_lo, s->eps_hi,
        s->lo, s->hi, fb, note);
    ledger_add_at(file, line, id, ref, q, s->worst, expected, WINDOW_ORDER_TOL, truth);
}
