/* Stability boundaries (src/stability.h, figures/stability): the measured linear stability
 * limit of each method at the attracting steady rotation against the one derived from
 * psi' = k cos psi, and where the implicit steps stop being solvable. */
#include "claims_stability.h"

#include "ledger.h"
#include "stability.h"

#include <math.h>
#include <stdio.h>

#define H_MAX 1000.0

void stability_claims(const suslov_exact *paper)
{
    char id[64], q[256];
    for (int m = 0; m < 4; m++) {
        const suslov_stepper_type *st = suslov_stepper_get(m);
        const double predicted = suslov_linear_limit(st);
        const double measured = suslov_stability_limit(paper, st, 0.1, H_MAX);
        snprintf(id, sizeof id, "stability-boundary-%s", st->name);
        if (isfinite(predicted)) {
            /* The bisection stops at 1e-4 relative and 4000 steps resolve |R(-h)| - 1 to ~1e-4; the
             * start 1e-6 off the rotation keeps nonlinear terms at 1e-6: 1e-3 h is ample. */
            snprintf(q, sizeof q, "largest h = eps k at which a start 1e-6 off the steady rotation returns (bisection), "
                                  "against the linear limit |R(-h)| = 1 of %s", st->name);
            ledger_add(id, "(extension)", q, measured, predicted, 1e-3 * predicted, LEDGER_EXTENSION);
        } else {
            /* No linear limit predicted: the start near the rotation still returns at h = H_MAX. */
            snprintf(q, sizeof q, "%s has no linear stability limit: the start 1e-6 off the rotation still returns at "
                                  "h = %g (largest h tested)", st->name, H_MAX);
            ledger_add_bound(id, "(extension)", q, isnan(measured) ? H_MAX : measured, H_MAX, 1, LEDGER_EXTENSION);
        }
    }
    /* The implicit steps stop being solvable far beyond the paper's eps = 1 (h = 0.145): the
     * smallest h at which a run from the energy ellipse (12 angles, h = 10^0 .. 10^3 by 0.2
     * decades) meets a solver failure or a loss of regularity. Asserted: not below h = 1. */
    enum { NA = 12, NHS = 16 };
    double hs[NHS];
    for (int i = 0; i < NHS; i++)
        hs[i] = pow(10.0, 0.2 * i);
    for (int m = 1; m < 4; m += 2) {
        const suslov_stepper_type *st = suslov_stepper_get(m);
        stab_result res[NHS * NA];
        suslov_stability_map(paper, st, hs, NHS, NA, res);
        double first = INFINITY;
        for (int i = 0; i < NHS * NA; i++)
            if (res[i].cls == STAB_SOLVER || res[i].cls == STAB_REGULARITY)
                first = fmin(first, hs[i / NA]);
        snprintf(id, sizeof id, "stability-solvable-%s", st->name);
        snprintf(q, sizeof q, "smallest h at which a %s run (12 angles, h = 1..1000) fails to solve its step or loses "
                              "(REGLOC) regularity: at least 1, i.e. 7x the paper's eps = 1", st->name);
        ledger_add_bound(id, "(extension)", q, first, 1.0, 1, LEDGER_EXTENSION);
    }
}
