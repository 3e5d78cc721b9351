/* Section 6 (TheoPer, PerTh with the appendix's elimination, Per11), made constructive for every
 * method in the registry: the eps-periodic perturbation is built, its period map is integrated,
 * and its size is fitted against eps (src/lab/perturbation.h). */
#ifndef SUSLOV_CLAIMS_SECTION6_H
#define SUSLOV_CLAIMS_SECTION6_H

#include "exact.h"
#include "model.h"

void section6_claims(const sus_model *m, const sus_exact *ex);

#endif
