#include "claims_orders.h"

#include "bodies.h"
#include "claims_window.h"
#include "orderfit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

curve_order order_of_curve(const double *eps, const double *err, int n, double size)
{
    int *cand = malloc((size_t)n * sizeof *cand);
    if (!cand)
        ledger_die("memory for an order fit");
    for (int j = 0; j < n; j++)
        cand[j] = isfinite(err[j]) && err[j] > SUS_EXP_FIT_FLOOR_REL * size && err[j] < size;
    const window_slope w = window_measure(eps, err, cand, n);
    free(cand);
    return (curve_order){w.slope - 1.0, w.plateau, w.eps_lo, w.eps_hi};
}

curve_order order_of_pair(curve_order r, curve_order p)
{
    curve_order c = r.order <= p.order || isnan(r.order) ? r : p;
    if (isnan(p.order))
        c.order = NAN;
    return c;
}

order_summary order_summary_new(void) { return (order_summary){.lo = INFINITY, .hi = -INFINITY}; }

void order_summary_add(order_summary *s, curve_order c, double expected, const char *body_name)
{
    if (isnan(c.order)) {
        if (!s->unmeasured++)
            s->unmeasured_body = body_name;
        return;
    }
    s->fallback += !c.plateau;
    s->lo = fmin(s->lo, c.order);
    s->hi = fmax(s->hi, c.order);
    if (!s->worst_body || fabs(c.order - expected) > fabs(s->worst - expected)) {
        s->worst = c.order;
        s->worst_body = body_name;
        s->eps_lo = c.eps_lo;
        s->eps_hi = c.eps_hi;
    }
}

void ledger_order_line_at(const char *file, int line, const char *id, const char *what, const char *name,
                   const order_summary *s, int expected, const char *ref, ledger_assert truth)
{
    char q[400];
    if (s->unmeasured) {
        snprintf(q, sizeof q, "%s, %s: fewer than 3 errors above 1000 u on %s (%d of %d bodies): no order",
                 what, name, s->unmeasured_body, s->unmeasured, BODIES_COUNT);
        ledger_add_bound_at(file, line, id, ref, q, -INFINITY, expected - 1.0, 1, truth);
        return;
    }
    if (s->fallback) {
        snprintf(q, sizeof q, "%s, %s >= p/2 (lower estimate: not p vs p-1); lowest of %d bodies (seed "
                              "%u); %d reach "
                 "round-off before one slope, fit on the last octave above it; range %.2f .. %.2f",
                 what, name, BODIES_COUNT, BODIES_SEED, s->fallback, s->lo, s->hi);
        ledger_add_bound_at(file, line, id, ref, q, s->lo, 0.5 * expected, 1, truth);
        return;
    }
    snprintf(q, sizeof q, "%s, %s; worst of %d bodies (seed %u) %s, window eps %.3g .. %.3g; range %.2f .. "
                          "%.2f",
             what, name, BODIES_COUNT, BODIES_SEED, s->worst_body, s->eps_lo, s->eps_hi, s->lo, s->hi);
    ledger_add_at(file, line, id, ref, q, s->worst, expected, WINDOW_ORDER_TOL, truth);
}
