/* An order for the ledger from a fitted slope, when the sizes allow one (shared by the claims
 * files of Remark 5.5 and Section 6). */
#ifndef SUSLOV_CLAIMS_FIT_H
#define SUSLOV_CLAIMS_FIT_H

#include "ledger.h"

/* Fits log err against log eps over eps <= 2^-2 (orderfit.h's window) for the points above the
 * round-off floor floor_c / eps^floor_pow, and records slope - shift against expected (tolerance
 * 0.1). A method so accurate that fewer than three points qualify is fitted over all eps given
 * instead (tolerance from the next term of the expansion over that window, claims_fit.c; said in
 * the line). When even that leaves fewer than three, the order
 * is not measurable, and what is tested is what theory predicts above round-off: need[j] is a
 * lower estimate of the size (for Section 6 the step's local error over eps); where it is above
 * 10 floors the size must be at least need / 10 (a one-sided line that a zeroed measurement
 * fails). Where no eps has need above 10 floors nothing can be tested: no line, and 0 is
 * returned (else 1). need = NULL: no such estimate, and the line fails. */
int claims_order_or_floor(const char *id, const char *ref, const char *what, const double *eps,
                          const double *err, const double *need, int n, double floor_c,
                          int floor_pow, double shift, double expected, ledger_assert truth);

#endif
