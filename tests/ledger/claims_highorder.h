/* Ledger rows of the high-order methods (compositions, Taylor series): their global orders on
 * every body (claims_global.c, called from here), the Taylor methods' control of p against p - 1,
 * the structure they keep at T = 1e4, the bench's recommended settings, and the accuracy of the
 * long-double reference attitude that judges them. */
#ifndef SUSLOV_CLAIMS_HIGHORDER_H
#define SUSLOV_CLAIMS_HIGHORDER_H

#include "exact.h"

void highorder_claims(const sus_model *m, const sus_exact *ex);

#endif
