/* Statements of the paper that concern its geometry rather than a method's order: Corollary
 * CoroRetr (its identity and its sign), the negative claim of Section dreps (phi_d o tau need not
 * preserve the constraint subspace), (Isom) and the Killing form (Killing). */
#ifndef SUSLOV_CLAIMS_COVERAGE_H
#define SUSLOV_CLAIMS_COVERAGE_H

#include "model.h"

void coverage_claims(const sus_model *m);

#endif
