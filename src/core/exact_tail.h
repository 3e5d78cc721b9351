/* How far the motion of exact.h is from its steady rotation w_inf after a time t, in closed form:
 * a bound of the integral of |w - w_inf| from t to infinity. It bounds what replacing w by w_inf
 * from t on does to the attitude: two solutions of R' = R w^ from the same R(t), one along w and
 * one along w_inf, differ at any later time by at most that integral (their difference obeys
 * D' = D w^ + R_inf (w - w_inf)^, and the flow of D' = D w^ keeps norms; in quaternions, half of
 * it).
 *
 * Derivation. With a = sigma s = sigma s0 + k t (exact.h), (cos psi, sin psi) = (sigma sech a,
 * tanh a) and the steady rotation is (0, 1); the distance between them is
 *     sqrt(sech^2 a + (1 - tanh a)^2) = sqrt(2 - 2 tanh a) = 2 E / sqrt(1 + E^2) <= 2 E,
 * E = e^{-a}, for every real a. So |w - w_inf| = |L^{-T} (u - u_inf)| <= 2 |L^{-1}|_F r e^{-a(t)},
 * and its integral from t on is at most 2 |L^{-1}|_F r e^{-a(t)} / k. A motion that stays at w0
 * (exact.h's fixed) is its own steady rotation: the bound is 0. */
#ifndef SUS_EXACT_TAIL_H
#define SUS_EXACT_TAIL_H

#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The bound of the integral of |w - w_inf| over [t, infinity); NaN for a NULL or refused ex. */
double sus_exact_tail_bound(const sus_exact *ex, double t);
/* The earliest t at which that bound is budget (budget > 0): -INFINITY for a motion that stays at
 * w0, NaN for a NULL or refused ex or a budget that is not a positive number. */
double sus_exact_tail_time(const sus_exact *ex, double budget);

/* Bounds that follow the direction w - w_inf takes, for a caller near w_inf (taylor-adaptive's
 * jump, step_taylor_adaptive.c) where |L^{-1}|_F can overstate it by up to sqrt(cond(I_m)). With
 * u - u_inf = r R(beta) (sigma sech a, tanh a - 1) (exact.h: cos psi = sigma sech a, sin psi =
 * tanh a) and t1, t2 = L^{-T} R(beta) e1, e2 (t1 the ellipse's tangent at w_inf),
 *     |w - w_inf| <= r (sech a |t1| + (1 - tanh a) |t2|),
 * and integrating over a from a(t) (dt = da / k): int sech = 2 atan(e^{-a}), int (1 - tanh) =
 * ln(1 + e^{-2a}). *dev gets the first's largest value from t on (1 - tanh decreases; sech
 * decreases for a >= 0 and is at most 1), *integral the second; both exceed the truth by a
 * fraction of order e^{-a} only. 0 for a motion that stays at w0. Returns 0, or -1 with NaN for a
 * NULL or refused ex. */
int sus_exact_tail_bounds(const sus_exact *ex, double t, double *dev, double *integral);

#ifdef __cplusplus
}
#endif

#endif
