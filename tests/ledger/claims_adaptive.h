/* Ledger rows of the tolerance-driven Taylor method: its global error against TOL
 * (proportionality and a two-sided bound) and its structure at T = 1e4, on the paper's body and
 * the general bodies. */
#ifndef SUSLOV_CLAIMS_ADAPTIVE_H
#define SUSLOV_CLAIMS_ADAPTIVE_H

void adaptive_claims(void);

#endif
