/* What the paper, or the theory a method comes from, says its orders are, with the citation.
 * The ledger takes every expected order from here, never from the stepper struct under test:
 * a method missing from this table fails the ledger. */
#ifndef SUSLOV_EXPECTED_ORDERS_H
#define SUSLOV_EXPECTED_ORDERS_H

#include "reconstruct.h"

typedef struct {
    const char *method;
    int p;                    /* local w error O(eps^{p+1}) */
    int s;                    /* multiplier order; -1 where the paper proves it inconsistent */
    int so3[SUS_RECON_COUNT]; /* order on SO(3) (TeoL: min(r, p)) with each reconstruction */
    const char *ref;          /* where p and s are stated, in the notation (notation.h) */
    /* Linear stability: 1 when theory gives R(z) = sum_{n<=p} z^n/n! (an explicit Runge-Kutta
     * method with p = stages <= 4, or a Taylor series of degree p), so that the real stability
     * limit follows from p alone; the first step h at which a run's step equation loses its
     * branch, as docs/explanation/where-methods-fail.md states it from the stability map (0: none
     * stated; INFINITY: none up to the largest h tested); and 1 where that document states that
     * the map meets a fold of the step equation's branch. */
    int stab_truncated_exp;
    double solvable_h;
    int fold_on_map;
} expected_order;

const expected_order *expected_order_of(const char *method);

/* What a tolerance-driven method's TOL bounds (stepper.h, sus_tol_ops; it has no fixed step to take
 * an order in): TOL_LOCAL, each step's own error estimate, so that the global error is up to N of
 * them; TOL_GLOBAL, the global error of R at every time, up to round-off. key starts the ids of its
 * ledger lines (tests/ledger/claims_adaptive.c). */
typedef struct {
    const char *method;
    const char *key;
    enum { TOL_LOCAL = 1, TOL_GLOBAL } bounds;
    const char *ref; /* where that is stated */
} expected_tol;

const expected_tol *expected_tol_of(const char *method);

#endif
