/* The stability boundaries of each integrator, for the ledger: one registered method (the m-th)
 * at a time. */
#ifndef SUSLOV_CLAIMS_STABILITY_H
#define SUSLOV_CLAIMS_STABILITY_H

#include "exact.h"

/* The linear stability limit against theory, on every body. */
void stability_boundary_claims(int m);
/* Where an implicit step stops being solvable on the paper's energy ellipse. */
void stability_solvable_claims(const sus_exact *paper, int m);
/* The exponent of |det J| at a fold the map meets. */
void stability_fold_claims(const sus_exact *paper, int m);

#endif
