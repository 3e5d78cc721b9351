/* The claims behind the paper's Figures 1 and 2 and the inertia ambiguity, for the ledger. */
#ifndef SUSLOV_CLAIMS_FIGURES_H
#define SUSLOV_CLAIMS_FIGURES_H

#include "exact.h"
#include "model.h"

void figure_claims(const sus_model *m, const sus_exact *ex);

#endif
