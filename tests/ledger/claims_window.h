/* The fit window of an order, chosen from the error curve itself; one rule for the local orders
 * of every method (claims_methods.c) and the global orders on every body (claims_global.c). The
 * caller marks the candidates: errors above its round-off floor and below the size of the
 * quantity (an error as large as the quantity is no expansion in eps).
 *   1. The window is a run of consecutive candidates, spanning at least an octave of eps, whose
 *      neighbour slopes span less than WINDOW_SLOPE_SPAN (max - min): the asymptotic regime is
 *      where the slope is constant, the pre-asymptotic bend at large eps and round-off at small
 *      eps both make it vary. Of such runs, the one reaching the smallest eps (the nearest to the
 *      asymptotic regime), and of those the longest. The bound below holds where one term
 *      dominates the bend, which the run reaching the smallest eps is nearest to; a longer run at
 *      larger eps can be a pre-asymptotic part of another slope: a first-order reconstruction
 *      whose second-order part dominates over a long range of eps (claims_global.c: cayley on
 *      body2) has a run of slope 2 before its run of slope 1. The slope is the least-squares one
 *      over the window, and the caller asserts it within WINDOW_ORDER_TOL of the order.
 *   2. Where no run has one slope (an order so high that the error reaches round-off before its
 *      asymptotic regime: the slope still rises as eps falls), the fit is over the smallest-eps
 *      candidates, back to an octave or, where fewer remain, all of them (at least 3 points),
 *      the end nearest that regime. That slope is a lower estimate, and the caller asserts only
 *      order >= p / 2: what breaks a method of order p built from a second-order map (a weight
 *      that misses the order conditions, a dropped substep) leaves order 2 or less, a series
 *      truncated at half its degree order p/2.
 *      It cannot tell p from p - 1.
 *
 * Why the numbers. The first neglected term of the error expansion bends the log-log slope by a
 * eps^m (m >= 1; m = 2 for the global error of a symmetric method). The neighbour slopes are
 * chords, and the least-squares slope of a window leans toward its large-eps end; on a window of
 * one octave with a linear bend (the worst case: a larger m or a longer window gives less) the fit
 * then lies K x (the chords' span) from the asymptotic slope, K = 1.93 on a grid of ratio 2^(1/4)
 * and at most 2.11 on claims_global.c's grid of whole step counts N = round(4 * 2^(j/4)), whose
 * ratios run from 1.10 to 1.25 at small N. Round-off moves a candidate by at most 1% (above
 * claims_global.c's floor of 100 N s u, u = SUS_U = 2^-52, a hundredfold the worst-case sum of one
 * rounding per substep, and claims_bodies.c's 100 s u times the size of the terms a step rounds;
 * 0.1% above 1000 u times the quantity's size), which tilts a fit over an octave by at most 3.6 x
 * 0.01 = 0.036. A span below 0.10 thus keeps the fit within 2.11 x 0.10 + 0.036 = 0.247 of the
 * order, and such a run cannot straddle two orders. This assumes one term dominates the bend; where
 * two of opposite sign compete, the slope can pause below p on its way there (claims_highorder.c's
 * exp-mid comp8-kl at its largest steps), which the preference for the run reaching the smallest
 * eps only mitigates. */
#ifndef SUSLOV_CLAIMS_WINDOW_H
#define SUSLOV_CLAIMS_WINDOW_H

#define WINDOW_SLOPE_SPAN 0.10
/* An order is an integer: a quarter of the gap tells p from p +- 1 (as claims_fit.c's widened
 * window), and holds the bend and round-off the rule above allows. */
#define WINDOW_ORDER_TOL 0.25

typedef struct {
    double slope; /* NaN: fewer than 3 candidates at the small-eps end */
    int plateau;  /* 1: a window of one slope (rule 1), 0: the fallback of rule 2 */
    int used;     /* points in the fit */
    double eps_lo, eps_hi;
} window_slope;

/* The slope of log err against log eps by the rule above; eps falls with j (largest first) and
 * cand[j] is nonzero for a candidate. */
window_slope window_measure(const double *eps, const double *err, const int *cand, int n);

#endif
