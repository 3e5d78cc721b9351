/* Remark 5.5 (RemarkLambda): the shifted multiplier lambda(w^{k+1}) + l_lambda, for euler,
 * midpoint, rk4 and the variational integrator; and the small statements about the multiplier
 * (the "(2,1)" label, the sign of (VSO3) against (PartCase), the corrected (cayinver)). */
#ifndef SUSLOV_CLAIMS_REMARK55_H
#define SUSLOV_CLAIMS_REMARK55_H

#include "exact.h"
#include "model.h"

void remark55_claims(const sus_model *m, const sus_exact *ex);

#endif
