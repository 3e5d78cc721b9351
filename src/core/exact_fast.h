/* The closed form of exact.h evaluated with one exponential and no tanh, for a method that calls
 * it at every step and row (src/methods/step_exact_attitude.c). With E = e^{-|s|},
 *     sech s = 2E / (1 + E^2),   tanh s = sign(s) (1 - E^2) / (1 + E^2),
 * and w = M (sech s, tanh s) with the fixed matrix M = sigma r L^{-T} Rot(beta) (exact.h: w =
 * L^{-T} u, u = r Rot(beta) (cos psi, sin psi), (cos psi, sin psi) = sigma (sech s, tanh s)).
 * Rounding: E carries exp's rounding and |s| u from the rounding of s; sech and tanh then a few
 * roundings each, and M (sech, tanh) two more, so w is within a few u |M| of the closed form: the
 * same size as sus_exact_omega's own rounding. (Not the addition formulas of tanh and sech from one
 * point to the next: their roundings would accumulate from step to step.) */
#ifndef SUS_EXACT_FAST_H
#define SUS_EXACT_FAST_H

#include "exact.h"

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double M[2][2]; /* w = c + M (sech s, tanh s) */
    double c[2];    /* 0, or w0 for a motion that stays at w0 (exact.h's fixed): then M = 0 */
    double s0, ks;  /* s = s0 + ks t, ks = sigma k */
    double winf[2]; /* w(t -> infinity), sus_exact_limit */
    double cs, c0;  /* c(t) = I31 w1 + I32 w2 = cs sech s (exact.h: sigma cmax), c0 = c(w0) */
    int fixed;      /* exact.h's fixed motion: c = c0 at every t */
} sus_exact_fast;

/* From a closed form that sus_exact_init accepted; returns 0, or -1 (f then gives NaN) when ex or
 * f is NULL or ex was refused. */
int sus_exact_fast_init(sus_exact_fast *f, const sus_exact *ex);

/* (sech s, tanh s) at t, the pair w is linear in (its Taylor coefficients give w's). */
static inline void sus_exact_fast_st(const sus_exact_fast *f, double t, double st[2])
{
    const double s = f->s0 + f->ks * t, e = exp(-fabs(s)), e2 = e * e, d = 1.0 / (1.0 + e2);
    st[0] = 2.0 * e * d;
    st[1] = copysign((1.0 - e2) * d, s);
}

/* w = c + M st. */
static inline void sus_exact_fast_map(const sus_exact_fast *f, const double st[2], double w[2])
{
    w[0] = f->c[0] + (f->M[0][0] * st[0] + f->M[0][1] * st[1]);
    w[1] = f->c[1] + (f->M[1][0] * st[0] + f->M[1][1] * st[1]);
}

/* w(t) from the closed form (exact.h). */
static inline void sus_exact_fast_omega(const sus_exact_fast *f, double t, double w[2])
{
    double st[2];
    sus_exact_fast_st(f, t, st);
    sus_exact_fast_map(f, st, w);
}

/* w(t) and c(t) from one sech, as sus_exact_omega and sus_exact_c give them (c0 at t = 0, as
 * sus_exact_c; the sech here is 2E times 1/(1 + E^2), sus_exact_c's 2E / (1 + E^2): a rounding
 * apart). Returns c. */
static inline double sus_exact_fast_omega_c(const sus_exact_fast *f, double t, double w[2])
{
    double st[2];
    sus_exact_fast_st(f, t, st);
    sus_exact_fast_map(f, st, w);
    return f->fixed || t == 0.0 ? f->c0 : f->cs * st[0];
}

#ifdef __cplusplus
}
#endif

#endif
