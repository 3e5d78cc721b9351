/* The stability boundaries of each integrator, for the ledger. */
#ifndef SUSLOV_CLAIMS_STABILITY_H
#define SUSLOV_CLAIMS_STABILITY_H

#include "exact.h"

void stability_claims(const sus_exact *paper);

#endif
