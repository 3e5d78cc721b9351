/* An order for the ledger from a fitted slope, when the sizes allow one (shared by the claims
 * files of Remark 5.5 and Section 6). */
#ifndef SUSLOV_CLAIMS_FIT_H
#define SUSLOV_CLAIMS_FIT_H

#include "ledger.h"

/* Fits log err against log eps over eps <= 2^-2 (orderfit.h's window) for the points above the
 * round-off floor floor_c / eps^floor_pow, and records slope - shift against expected (tolerance
 * 0.1). A method so accurate that fewer than three points qualify is fitted over all eps given
 * instead (tolerance 0.25, said in the line). When even that leaves fewer than three, the order
 * is not measurable and the line (an extension) asserts that the sizes stay at round-off, max over
 * eps <= 2^-2 of err / floor below 100, and that this is what theory predicts: need[j] is the
 * size theory puts a lower estimate on (for Section 6 the step's local error over eps); where it
 * is above 10 floors, err must be at least need / 10, else the line fails (NaN). need = NULL: no
 * such estimate, and the line fails. */
void claims_order_or_floor(const char *id, const char *ref, const char *what, const double *eps, const double *err,
                           const double *need, int n, double floor_c, int floor_pow, double shift, double expected,
                           ledger_assert truth);

#endif
