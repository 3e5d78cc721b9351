/* One order over every body, as one ledger line: each curve's order by the window rule of
 * claims_window.h, kept where the window is the asymptotic one; the worst body kept; the line
 * two-sided over the bodies with a window of one slope and one-sided (the lower estimate) over
 * the others; bodies at round-off named. Used by claims_methods.c and claims_propocons1.c. */
#ifndef SUSLOV_CLAIMS_ORDERS_H
#define SUSLOV_CLAIMS_ORDERS_H

#include "ledger.h"

typedef struct {
    double order;          /* NaN: fewer than 3 points above round-off */
    int plateau;           /* 1: a window of one slope, 0: the lower estimate */
    int at_roundoff;       /* 1: 3 or more steps taken, but fewer than 3 errors above the floor */
    double eps_lo, eps_hi; /* the window, in eps k */
    double eps_ok;         /* the largest eps k at which the step was taken */
} curve_order;

/* The local order of one error curve over eps (largest first) on a body of rate k: the slope minus
 * 1 (local error O(eps^{q+1})), over the points that are finite, above the round-off floor
 * floor[j] and below the size itself. */
curve_order order_of_curve(const double *eps, double k, const double *err, int n, double size,
                           const double *floor);

/* TeoL: the pair (w, R) has order min(r, p). An order without one slope is a lower estimate (the
 * slope still rises), so the smaller of the two decides the kind of line too. Where w's error is
 * at round-off (p beyond what double precision shows) the pair's is r's; where R's is, the
 * pair's is at round-off too. */
curve_order order_of_pair(curve_order r, curve_order p);

typedef struct {
    double worst, lo, hi; /* over bodies with a window of one slope: the order farthest from
                           * expected, and the range */
    const char *worst_body;
    double eps_lo, eps_hi; /* the worst body's window, in eps k */
    int plateaus;          /* bodies with a window of one slope */
    int fallback;          /* bodies with only the lower estimate */
    double fb_lo, fb_hi;   /* the range of the lower estimates */
    const char *fb_body;   /* the body of the lowest */
    int unmeasured;        /* bodies with fewer than 3 steps taken */
    const char *unmeasured_body;
    int roundoff;              /* bodies whose error is at round-off wherever a step is taken */
    char roundoff_bodies[160]; /* their names, each with the largest eps k stepped */
} order_summary;

order_summary order_summary_new(void);
void order_summary_add(order_summary *s, curve_order c, double expected, const char *body_name);

/* The line: "what, name" measured over every body against expected; its source column names the
 * caller (a macro, as ledger_add). The bodies with a window of one slope are held to the order
 * within WINDOW_ORDER_TOL, those with only the lower estimate to at least half of it (the line
 * then shows the lowest of these if it falls short, else the worst of those); bodies at
 * round-off are named and carry no order. The line fails when a body took fewer than 3 steps or
 * no body has an order. */
#define ledger_order_line(...) ledger_order_line_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_order_line_at(const char *file, int line, const char *id, const char *what,
                          const char *name, const order_summary *s, int expected, const char *ref,
                          ledger_assert truth);

#endif
