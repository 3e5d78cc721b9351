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

void claims_order_or_floor(const char *id, const char *ref, const char *what, const double *eps, const double *err,
                           const double *need, int n, double floor_c, int floor_pow, double shift, double expected,
                           ledger_assert truth)
{
    suslov_order_fit f;
    char q[400];
    double e[MAXN], emax = SUSLOV_FIT_EPS_MAX, big = 0.0;
    if (n > MAXN)
        n = MAXN;
    for (int j = 0; j < n; j++) {
        e[j] = err[j] > floor_c / pow(eps[j], floor_pow) ? err[j] : 0.0;
        big = fmax(big, eps[j]);
    }
    int ok = suslov_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    if (!ok) {
        emax = big;
        ok = suslov_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    }
    if (ok) {
        const int wide = emax > SUSLOV_FIT_EPS_MAX;
        snprintf(q, sizeof q, "%s; fit eps in [%.3g, %.3g], %d pts%s", what, f.eps_lo, f.eps_hi, f.used,
                 wide ? " (window widened: round-off below)" : "");
        ledger_add(id, ref, q, f.slope - shift, expected, wide ? ORDER_TOL_WIDE : ORDER_TOL, truth);
        return;
    }
    /* No slope. Allowed only where theory puts the sizes at round-off: where the step's own
     * local error (need) rises 10 times above the floor, the measured size must carry at least a
     * tenth of it (need is a lower estimate up to the blend's chi' <= 3 and sup against mean), so a
     * zeroed or truncated measurement fails. Without need (no such theory) the line fails. */
    double worst = 0.0, carry = INFINITY, top = 0.0;
    int measurable = 0;
    for (int j = 0; j < n; j++) {
        const double fl = floor_c / pow(eps[j], floor_pow);
        if (eps[j] <= SUSLOV_FIT_EPS_MAX)
            worst = fmax(worst, err[j] / fl);
        if (need && need[j] > 10.0 * fl) {
            measurable++;
            carry = fmin(carry, err[j] / need[j]);
        }
        if (need)
            top = fmax(top, need[j] / fl);
    }
    const double m = !need || (measurable && carry < 0.1) ? NAN : worst;
    /* the numbers first: the quantity column holds 255 characters */
    snprintf(q, sizeof q, "[no slope, order %g not measurable: size/floor %.1e (eps <= 1/4); local error/floor <= %.1e; size/local error >= %.2g at %d eps] %s",
             expected, worst, top, measurable ? carry : NAN, measurable, what);
    char eref[128];
    snprintf(eref, sizeof eref, "%s%s", ref, strstr(ref, "extension") ? "" : " (extension)");
    ledger_add_bound(id, eref, q, m, 100.0, 0, LEDGER_EXTENSION);
}
