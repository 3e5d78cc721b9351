#include "claims_window.h"

#include "orderfit.h"

#include <math.h>

/* Does lo .. hi span an octave? The grids are powers of 2^(1/4) or whole step counts, whose
 * quotients round within 1e-9 of 2. */
static int octave(const double *eps, int lo, int hi)
{
    return eps[lo] >= 2.0 * (1.0 - 1e-9) * eps[hi];
}

/* Is the run lo .. hi (inclusive) one slope: every neighbour slope within WINDOW_SLOPE_SPAN? */
static int one_slope(const double *eps, const double *err, int lo, int hi)
{
    double smin = INFINITY, smax = -INFINITY;
    for (int j = lo; j < hi; j++) {
        const double s = log(err[j + 1] / err[j]) / log(eps[j + 1] / eps[j]);
        smin = fmin(smin, s);
        smax = fmax(smax, s);
    }
    return smax - smin < WINDOW_SLOPE_SPAN;
}

/* Rule 1: the run of candidates with one slope that reaches the smallest eps (the largest j),
 * the longest of those. Returns its length, 0 when none. */
static int plateau(const double *eps, const double *err, const int *cand, int n, int *lo_out)
{
    int best_lo = -1, best_hi = -1;
    for (int lo = 0; lo < n; lo++)
        for (int hi = lo; hi < n && cand[hi]; hi++)
            if (octave(eps, lo, hi) && (hi > best_hi || (hi == best_hi && lo < best_lo)) &&
                one_slope(eps, err, lo, hi)) {
                best_lo = lo;
                best_hi = hi;
            }
    *lo_out = best_lo;
    return best_lo < 0 ? 0 : best_hi - best_lo + 1;
}

window_slope window_measure(const double *eps, const double *err, const int *cand, int n)
{
    window_slope w = {NAN, 1, 0, NAN, NAN};
    int lo, len = plateau(eps, err, cand, n, &lo);
    if (!len) { /* rule 2: the smallest-eps candidates, back to an octave */
        w.plateau = 0;
        int hi = n - 1;
        while (hi >= 0 && !cand[hi])
            hi--;
        for (lo = hi; lo > 0 && !octave(eps, lo, hi) && cand[lo - 1]; lo--)
            ;
        len = hi - lo + 1;
    }
    sus_lab_order_fit f;
    if (len >= 3 && sus_lab_fit_order(eps + lo, err + lo, len, INFINITY, 0.0, &f) == 0) {
        w.slope = f.slope;
        w.used = f.used;
        w.eps_lo = f.eps_lo;
        w.eps_hi = f.eps_hi;
    }
    return w;
}
