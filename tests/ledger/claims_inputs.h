/* The reference attitude against a binary128 integration from the same double inputs (its stated
 * accuracy), and what reading the paper's printed decimals as exact instead does to R(50). */
#ifndef SUSLOV_CLAIMS_INPUTS_H
#define SUSLOV_CLAIMS_INPUTS_H

#include "model.h"

void inputs_claims(const sus_model *m);

#endif
