/* The per-method ledger: p, s, the SO(3) order and the structure of every registered method on
 * the paper's body and on the seeded family of general bodies (tests/ledger/claims_methods.c). */
#ifndef SUSLOV_CLAIMS_METHODS_H
#define SUSLOV_CLAIMS_METHODS_H

void methods_claims(void);

#endif
