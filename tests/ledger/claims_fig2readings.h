/* Figure 2 under every reading: of the printed, non-symmetric inertia (third row, third column,
 * symmetric part) and of "converges much faster" / "long-term much more accurate" (to the exact
 * solution, to the exact limit, each trajectory to its own limit). */
#ifndef SUSLOV_CLAIMS_FIG2READINGS_H
#define SUSLOV_CLAIMS_FIG2READINGS_H

#include "model.h"

void fig2readings_claims(const sus_model *m);

#endif
