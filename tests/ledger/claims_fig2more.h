/* Figure 2's remaining statements: "converges much faster", "long-term behaviour much more
 * accurate", the label-swap reading, the trapezoidal reading of the midpoint rule. */
#ifndef SUSLOV_CLAIMS_FIG2MORE_H
#define SUSLOV_CLAIMS_FIG2MORE_H

#include "exact.h"
#include "model.h"

void fig2more_claims(const suslov_model *m, const suslov_exact *ex);

#endif
