/* Figure 2's remaining statements: "converges much faster", "long-term behaviour much more
 * accurate", the label-swap reading, the trapezoidal reading of the midpoint rule. */
#ifndef SUSLOV_CLAIMS_FIG2MORE_H
#define SUSLOV_CLAIMS_FIG2MORE_H

#include "exact.h"
#include "model.h"
#include "stepper.h"

void fig2more_claims(const sus_model *m, const sus_exact *ex);

/* The trapezoidal reading of the midpoint rule: l = I_m (f(w^k) + f(w^{k+1}))/2 in
 * (Discretization), solved by fixed-point iteration. */
extern const sus_stepper_type fig2_trapezoidal;

/* The audit's readings of Figure 2 (tests/ledger/claims_fig2_ranges.c): "none loses energy faster"
 * over eps in [0.25, 8] for every reading of the midpoint rule, and the variational/midpoint
 * error ratio over t in [2, 60], as a ratio of maxima over [0, 60] and at t = 10. */
void fig2_range_claims(const sus_model *m, const sus_exact *ex);

#endif
