#include "claims_fit.h"

#include "exact.h"
#include "model.h"
#include "notation.h"
#include "orderfit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* An order is an integer: a tenth of the gap tells p from p +- 1 (as in claims.c). */
#define ORDER_TOL 0.1
#define MAXN 32

/* The tolerance of a window widened up to eps_hi, out of the asymptotic range. There the error is
 * C eps^p (1 + a eps + ...), whose local slope is p + a eps / (1 + a eps): every local slope, and
 * so the least-squares one, lies within a eps_hi / (1 - a eps_hi) of p. a is the ratio of
 * consecutive Taylor coefficients of the solution, 1 / rho for rho its radius of analyticity in t:
 * the exact w and lambda are tanh and sech of k t + s0 (exact.c), analytic for |Im t| < pi / (2k),
 * so a = 2k / pi, taking the method's consecutive error constants as alike. Every caller runs the
 * paper's body. Never below the fixed window's tenth; a bend reaching half the gap could not tell
 * p from p +- 1, and the caller's line then fails (tolerance 0). */
static double wide_tolerance(double eps_hi)
{
    sus_model m;
    sus_exact ex;
    char err[128];
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0)
        return 0.0;
    sus_exact_init(&ex, &m, SUS_PAPER_OMEGA0);
    const double ae = 2.0 * ex.k / acos(-1.0) * eps_hi; /* a eps_hi, a = 2k / pi */
    const double bend = ae / (1.0 - ae);
    return ae < 1.0 && bend < 0.5 ? fmax(ORDER_TOL, bend) : 0.0;
}

/* The id of a line that holds a ratio of sizes, not an order, says so: "-ratio-" in place of
 * "-order-" (sec6-size-order-X -> sec6-size-ratio-X), or after the family's first two words when
 * the id names no order (sec6-per11-cayley-X -> sec6-per11-ratio-cayley-X). */
static void ratio_id(const char *id, char *out, size_t len)
{
    const char *o = strstr(id, "-order-");
    if (o) {
        snprintf(out, len, "%.*s-ratio-%s", (int)(o - id), id, o + strlen("-order-"));
        return;
    }
    const char *h = strchr(id, '-');
    h = h ? strchr(h + 1, '-') : NULL;
    if (h)
        snprintf(out, len, "%.*s-ratio%s", (int)(h - id), id, h);
    else
        snprintf(out, len, "%s-ratio", id);
}

int claims_order_or_floor(const char *id, const char *ref, const char *what, const double *eps,
                          const double *err, const double *need, int n, double floor_c,
                          int floor_pow, double shift, double expected, ledger_assert truth)
{
    sus_lab_order_fit f;
    char q[640];
    double e[MAXN], emax = SUS_LAB_FIT_EPS_MAX, big = 0.0;
    if (n > MAXN)
        n = MAXN;
    for (int j = 0; j < n; j++) {
        e[j] = err[j] > floor_c / pow(eps[j], floor_pow) ? err[j] : 0.0;
        big = fmax(big, eps[j]);
    }
    int ok = sus_lab_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    if (!ok) {
        emax = big;
        ok = sus_lab_fit_order(eps, e, n, emax, 0.0, &f) == 0;
    }
    if (ok) {
        const int wide = emax > SUS_LAB_FIT_EPS_MAX;
        char wref[200];
        snprintf(q, sizeof q, "%s; fit $\\varepsilon \\in [%s, %s]$, %d points%s", what,
                 notation_g(f.eps_lo, 3).s, notation_g(f.eps_hi, 3).s, f.used,
                 wide ? " (window widened: round-off below)" : "");
        /* A widened window is a reading of ours, its tolerance a rule set with such slopes
         * already measured (paper/tolerances.tsv, order-wide): an extension, never the test of a
         * claim of the paper, which binary128 makes in the fixed window (claims_quad.c). */
        snprintf(wref, sizeof wref, "%s%s", ref, strstr(ref, "extension") ? "" : ", extension");
        ledger_add(id, wide ? wref : ref, q, f.slope - shift, expected,
                   wide ? wide_tolerance(f.eps_hi) : ORDER_TOL, wide ? LEDGER_EXTENSION : truth);
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
    char eref[200], rid[96];
    snprintf(eref, sizeof eref, "%s%s", ref, strstr(ref, "extension") ? "" : ", extension");
    ratio_id(id, rid, sizeof rid);
    snprintf(
        q, sizeof q,
        "[no slope (order %g at round-off); size over theory's lower estimate $\\ge 0.1$ at the "
        "%d $\\varepsilon$ where the estimate is above 10 floors] %s",
        expected, measurable, what);
    ledger_add_bound(rid, eref, q, need ? carry : -INFINITY, 0.1, 1, LEDGER_EXTENSION);
    return 1;
}
