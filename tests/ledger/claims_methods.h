/* The per-method ledger: p, s, the SO(3) order and the structure of every registered method on
 * the paper's body and on the seeded family of general bodies (tests/ledger/claims_methods.c). */
#ifndef SUSLOV_CLAIMS_METHODS_H
#define SUSLOV_CLAIMS_METHODS_H

#include "stepper.h"

/* The lines of the i-th registered method. */
void methods_claims_of(int i);

/* The round-off bound on |R^T R - I| after `steps` steps of eps with |w| <= size_w, by the method's
 * attitude form (the reasons are at its definition). */
double method_orth_bound(const sus_stepper_type *t, long steps, double eps, double size_w);

#endif
