/* Ledger rows of the high-order methods (compositions, Taylor series): their orders on
 * w and on SO(3), the structure they keep over 10^6 steps and at T = 1e4, and the accuracy of the
 * long-double reference attitude that judges them. */
#ifndef SUSLOV_CLAIMS_HIGHORDER_H
#define SUSLOV_CLAIMS_HIGHORDER_H

#include "exact.h"

void highorder_claims(const sus_model *m, const sus_exact *ex);

#endif
