#include "claims_fit.h"

#include "orderfit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* An order is an integer: a tenth of the gap tells p from p +- 1 (as in claims.c). Over the
 * widened window (steps up to h = eps k = 0.29) the next term of the expansion bends the line by
 * up to ~k eps; a quarter of the gap still tells p from p +- 1. */
#define ORDER_TOL 0.1
#define ORDER_TOL_WIDE 0.25
#define MAXN 32

int claims_order_or_floor(const char *id, const char *ref, const char *what, const double *eps,
                          const double *err, const double *need, int n, double floor_c, int floor_pow,
                          double shift, double expected, ledger_assert truth)
{
    sus_exp_order_fit f;
    char q[400];
    double e[MAXN], emax = SUS_EXP_FIT_EPS_MAX, big = 0.0;
    if (n > MAXN)
        n = MAXN;
    for (int j = 0; j < n; j++) {
        e[j] = err[j] > floor_c / pow(eps[j], floor_pow) ? err[j] : 0.0;
        big = fmax(big, eps[j]);
    }
    int ok = sus_exp_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    if (!ok) {
        emax = big;
        ok = sus_exp_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    }
    if (ok) {
        const int wide = emax > SUS_EXP_FIT_EPS_MAX;
        snprintf(q, sizeof q, "%s; fit eps in [%.3g, %.3g], %d pts%s", what, f.eps_lo, f.eps_hi, f.used,
                 wide ? " (window widened: round-off below)" : "");
        ledger_add(id, ref, q, f.slope - shift, expected, wide ? ORDER_TOL_WIDE : ORDER_TOL, truth);
        return 1;
    }
    /* No slope: the sizes are at round-off over the fit window. Where theory puts a lower
     * estimate on the size (need: for Section 6 the step's local error over eps) that rises 10
     * times above the floor, the measured size must carry at least a tenth of it (need is a lower
     * estimate up to the blend's chi' <= 3 and sup against mean), so a zeroed or truncated
     * measurement fails. Where no such eps exists, nothing above round-off can be checked: no line
     * (the caller counts them); without need (no theory) the line fails. */
    double carry = INFINITY;
    int measurable = 0;
    for (int j = 0; j < n; j++) {
        const double fl = floor_c / pow(eps[j], floor_pow);
        if (need && need[j] > 10.0 * fl) {
            measurable++;
            carry = fmin(carry, err[j] / need[j]);
        }
    }
    if (need && !measurable)
        return 0;
    char eref[128];
    snprintf(eref, sizeof eref, "%s%s", ref, strstr(ref, "extension") ? "" : " (extension)");
    /* the numbers first: the quantity column holds 255 characters */
    snprintf(q, sizeof q, "[no slope (order %g at round-off); size / theory's lower estimate >= 0.1 at the "
                          "%d eps "
             "where the estimate is above 10 floors] %s", expected, measurable, what);
    ledger_add_bound(id, eref, q, need ? carry : -INFINITY, 0.1, 1, LEDGER_EXTENSION);
    return 1;
}
