/* Ledger rows of the high-order methods (compositions, Taylor series): the Taylor methods'
 * control of p against p - 1, the structure they keep at T = 1e4, and the accuracy of the
 * long-double reference attitude that judges them and the recorded bench's settings
 * (claims_recommended.h; their global orders on every body: claims_global.h). */
#ifndef SUSLOV_CLAIMS_HIGHORDER_H
#define SUSLOV_CLAIMS_HIGHORDER_H

#include "exact.h"

/* The reference attitude at t = 50 and the recorded bench's settings checked against it. */
void highorder_reference_claims(const sus_model *m, const sus_exact *ex);
/* The control and the long run of the i-th registered method, if it is one of ours. */
void highorder_method_claims(const sus_model *m, const sus_exact *ex, int i);

#endif
