/* How far the motion of exact.h is from its steady rotation w_inf after a time t, in closed form:
 * a bound of the integral of |w - w_inf| from t to infinity. It bounds what replacing w by w_inf
 * from t on does to the attitude: two solutions of R' = R w^ from the same R(t), one along w and
 * one along w_inf, differ at any later time by at most that integral (their difference obeys
 * D' = D w^ + R_inf (w - w_inf)^, and the flow of D' = D w^ keeps norms; in quaternions, half of it).
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

#ifdef __cplusplus
}
#endif

#endif
