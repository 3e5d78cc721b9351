/* What the paper, or the theory a method comes from, says its orders are, with the citation.
 * The ledger takes every expected order from here, never from the stepper struct under test:
 * a method missing from this table fails the ledger. */
#ifndef SUSLOV_EXPECTED_ORDERS_H
#define SUSLOV_EXPECTED_ORDERS_H

#include "reconstruct.h"

typedef struct {
    const char *method;
    int p;                       /* local w error O(eps^{p+1}) */
    int s;                       /* multiplier order; -1 where the paper proves it inconsistent */
    int so3[SUS_RECON_COUNT]; /* order on SO(3) (TeoL: min(r, p)) with each reconstruction */
    const char *ref;             /* where p and s are stated */
} expected_order;

const expected_order *expected_order_of(const char *method);

#endif
