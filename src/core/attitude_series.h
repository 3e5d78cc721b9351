/* The attitude along the closed form (exact.h) past the inflection of its transient, in one power
 * series in E = e^{-(sigma s0 + k t)}, the variable in which w is a rational function:
 *     w = (2 E M e1 + (1 - E^2) w_inf) / (1 + E^2),   w_inf = sigma M e2,   dE/dt = -k E
 * (exact_fast.h's M; sech s = 2E / (1 + E^2), sigma tanh s = (1 - E^2) / (1 + E^2) once sigma s
 * > 0). The continuous reconstruction R' = R w^ (the proof of Proposition 5.1), as a unit
 * quaternion q' = 1/2 q (x) w, has the solutions q(t) = C (x) g(t) (x) P(E(t)): g(t) = exp(t w_inf
 * / 2), the steady rotation, and P = sum_n P_n E^n with P_0 = 1 and, from P' = 1/2 (P (x) w -
 * w_inf (x) P),
 *     k n P_n + 1/2 (P_n (x) w_inf - w_inf (x) P_n) = -1/2 sum_{j=1..n} P_{n-j} (x) w_j,
 * w_j the coefficients of w: 2 (-1)^m M e1 for j = 2m + 1, 2 (-1)^m w_inf for j = 2m >= 2. The
 * left side is k n on the scalar part and k n - w_inf x on the vector part, invertible for n >= 1
 * (eigenvalues k n and k n +- i |w_inf|): the series exists and is unique. The sum on the right
 * is U_n (x) 2 M e1 + V_n (x) 2 w_inf with U_n = P_{n-1} - U_{n-2}, V_n = -P_{n-2} - V_{n-2} (the
 * alternating sums of P over odd and even j): each degree costs a few products, not n.
 *
 * P is analytic in |E| < 1: the ODE's only other singular points are w's poles E = +-i and E =
 * infinity (t = -infinity). So from any t_a past the inflection (E(t_a) < 1) one series gives the
 * attitude at every later time,
 *     q(t) = q(t_a) (x) P(E(t_a))^{-1} (x) exp((t - t_a) w_inf / 2) (x) P(E(t)),
 * the steady rotation over t - t_a in closed form (steady_turn.h) between two sums of the series.
 *
 * Truncation. The terms |P_n| E^n fall by E per degree times the growth of |P_n|. At E = +-i the
 * ODE has regular singular points whose exponents are at most |w|'s residue over 2 k in size,
 * (|M e1| + |M e2|) / (2 k) =: alpha, so |P_n| grows at most like n^(alpha - 1), by (1 + 1/n)^alpha
 * <= e^(alpha / n) per degree. As for the Taylor steps (step_exact_attitude.c), each of the last
 * five terms is projected at that ratio, a = E e^(alpha / n): the terms past degree n are
 * estimated to sum to at most B / (1 - a), B = max_{j < 5} |P_{n-j}| E^{n-j} a^{j+1}. An
 * estimate, not a proof (the exponent bound holds for the envelope only as n grows); the tests
 * hold every step to it (tests/unit/test_exact_attitude.c). Both sums are cut at the same degree,
 * and the later one's E is smaller, so q carries at most twice that.
 *
 * Before the inflection (E > 1) the same holds in the variable 1 / E = e^{sigma s0 + k t} < 1,
 * which grows with t: w is the same rational function of it with w_inf replaced by w_-inf =
 * -w_inf, the repelling steady rotation (sigma tanh s = -(1 - E^-2) / (1 + E^-2)), and k by -k
 * (d(1/E)/dt = k / E). Its left side is then -k n and -k n - w_-inf x, invertible as before, and
 * q(t) = q(t_a) (x) P(1/E(t_a))^{-1} (x) exp((t - t_a) w_-inf / 2) (x) P(1/E(t)) as long as 1 / E
 * stays below 1: up to a t_b before the inflection, where 1 / E is largest, so the degree is
 * chosen there, and the estimate made there bounds both sums.
 *
 * Round-off: the sums add terms whose sizes sum to at most SUS_ATT_SERIES_MASS (P is a unit
 * quaternion, so more is cancellation), so each carries a few roundings of that. */
#ifndef SUS_ATTITUDE_SERIES_H
#define SUS_ATTITUDE_SERIES_H

#include "exact_fast.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_ATT_SERIES_MAX 96   /* the highest degree tried */
#define SUS_ATT_SERIES_MASS 4.0 /* the terms' sizes sum to at most this: two bits lost, at most */

typedef struct {
    int n;                               /* the degree: P_0 .. P_n */
    int dir;                             /* 1: the series in E; -1: in 1 / E (above) */
    double P[SUS_ATT_SERIES_MAX + 1][4]; /* the coefficients */
    double ta, Xmax;                     /* where it starts; the variable's largest value on it */
    double wlim[2];                      /* w_inf, or w_-inf = -w_inf for dir = -1 */
    double ew[2];                        /* wlim / |wlim|: the series' frame (the .c file) */
    double mass;                         /* sum of |P_n| Xmax^n: the sums' scale */
    double left[4];                      /* q(t_a) (x) P(X(t_a))^{-1}, X = E or 1 / E */
} sus_att_series;

/* E(t) = e^{-(sigma s0 + k t)} for f's motion; 1 or more before the inflection (and for a motion
 * that stays where it is: k = 0). */
double sus_att_series_E(const sus_exact_fast *f, double t);

/* The series from q(ta) = qa for t in [ta, tb], to the degree at which twice its estimate (above)
 * is at most budget, in |dq|: in E past the inflection (E(ta) < 1; tb may be infinite), in 1 / E
 * before it (E(ta) > 1, and 1 / E(tb) < 1: tb before the inflection too). Returns that twice the
 * estimate, or -1 when it declines: E(ta) = 1, tb < ta, tb at or past the inflection for a
 * start before it, no degree up to SUS_ATT_SERIES_MAX meets the budget, the terms' sizes sum past
 * SUS_ATT_SERIES_MASS, or a term is not finite. */
double sus_att_series_build(sus_att_series *s, const sus_exact_fast *f, double ta, double tb,
                            const double qa[4], double budget);

/* q(t), t in [s->ta, tb], by the formula above; speed = |w_inf| as steady_turn.h has it. */
void sus_att_series_at(const sus_att_series *s, const sus_exact_fast *f, const double speed[2],
                       double t, double q[4]);

#ifdef __cplusplus
}
#endif

#endif
