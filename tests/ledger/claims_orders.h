/* One order over every body, as one ledger line: each curve's order by the window rule of
 * claims_window.h, the worst body kept, and the line two-sided when every body has a window of one
 * slope, else one-sided (the lower estimate). Used by claims_methods.c and claims_propocons1.c. */
#ifndef SUSLOV_CLAIMS_ORDERS_H
#define SUSLOV_CLAIMS_ORDERS_H

#include "ledger.h"

typedef struct {
    double order;             /* NaN: fewer than 3 points above round-off */
    int plateau;              /* 1: a window of one slope, 0: the lower estimate */
    double eps_lo, eps_hi;
} curve_order;

/* The local order of one error curve over eps (largest first): the slope minus 1 (local error
 * O(eps^{q+1})), over the points that are finite, above the round-off floor 1000 u size and below
 * the size itself. */
curve_order order_of_curve(const double *eps, const double *err, int n, double size);

/* TeoL: the pair (w, R) has order min(r, p). An order without one slope is a lower estimate (the
 * slope still rises), so the smaller of the two decides the kind of line too. */
curve_order order_of_pair(curve_order r, curve_order p);

typedef struct {
    double worst, lo, hi;     /* the order farthest from expected, and the range over bodies */
    const char *worst_body;
    int fallback;             /* bodies with only the lower estimate */
    int unmeasured;           /* bodies with fewer than 3 points above round-off */
    const char *unmeasured_body;
    double eps_lo, eps_hi;    /* the worst body's window */
} order_summary;

order_summary order_summary_new(void);
void order_summary_add(order_summary *s, curve_order c, double expected, const char *body_name);

/* The line: "what, name" measured over every body against expected; its source column names the
 * caller (a macro, as ledger_add). */
#define ledger_order_line(...) ledger_order_line_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_order_line_at(const char *file, int line, const char *id, const char *what, const char *name,
                   const order_summary *s, int expected, const char *ref, ledger_assert truth);

#endif
