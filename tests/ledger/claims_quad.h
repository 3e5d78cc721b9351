/* The two lines that double precision cannot settle, measured again in binary128 (__float128):
 * Remark 5.5's s = 2p + 1 for rk4 (errors ~eps^10, below double's round-off at every eps) and
 * the order p of the multiplier shift of Theorem 6.3 for rk4 (fitted in double only over a
 * widened window). Euler, which double measures in the fixed window, is the control. */
#ifndef SUSLOV_CLAIMS_QUAD_H
#define SUSLOV_CLAIMS_QUAD_H

#include "exact.h"
#include "model.h"

void quad_claims(const sus_model *m, const sus_exact *ex);

#endif
