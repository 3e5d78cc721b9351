/* The reduced Suslov problem of Section 5.2: the differential part (ContDyn), the multiplier
 * (LagMult) and the reduced energy, for an inertia tensor given by rows as printed. Only the
 * block I_m = (I_ij), i,j in {1,2}, and the third row (I31, I32) enter, exactly as in (RGB2). */
#ifndef SUS_MODEL_H
#define SUS_MODEL_H

#include <float.h>
#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* u: the spacing of doubles at 1 (2^-52), the unit every round-off yardstick is counted in. */
#define SUS_U DBL_EPSILON

typedef struct {
    double I[3][3];  /* the inertia tensor, rows as printed */
    double det_m;    /* |I_m| */
    double b[2];     /* (I31, I32): c(w) = I_3i w_i drives the motion */
    double fA[2][2]; /* (ContDyn) as f = c(w) fA w: the printed coefficients over |I_m| */
    double inv_det_m;
    /* |b|_2 and ||fA||_2, rounded up, so |c(v) fA u| <= K |v| |u| with K = norm_b norm_fA: the
     * majorant that bounds the Taylor steps (step_taylor.c) */
    double norm_b, norm_fA;
    /* O_0's coefficients: sus_lagmult_o0 = c(w) / |I_m| (o0c[0] w1 + o0c[1] w2), with
     * o0c[0] = I32 I11 - I31 I12 and o0c[1] = I32 I21 - I31 I22 */
    double o0c[2];
    /* Last: what sus_model_init leaves here tells a model it filled, unchanged since, from any
     * other bytes (sus_model_sealed), far more cheaply than filling a copy and comparing. */
    unsigned long long seal;
} sus_model;

/* a b - c d to about one rounding however much the two products cancel: c d - fl(c d) is exact
 * and fma rounds a b - fl(c d) once. |I_m| and O_0's coefficients are formed so, so that a
 * near-singular I_m loses no digits in the coefficients every method shares. */
static inline double sus_cross_diff(double a, double b, double c, double d)
{
    const double p = c * d, e = __builtin_fma(c, d, -p);
    return __builtin_fma(a, b, -p) - e;
}

/* The paper's body: I = [[1,0.1,0.2],[0.1,1,0.2],[0.2,0.1,1]] and w(0) = (0.4, 0.5). */
extern const double SUS_PAPER_INERTIA[9];
extern const double SUS_PAPER_OMEGA0[2];

/* Returns 0, or -1 with a one-line reason in err when m or I is NULL, an entry is not finite,
 * I_m is not symmetric positive definite, or double precision cannot hold the body: |I_m| lost
 * to cancellation or not a finite normal number, or a coefficient the model derives overflows
 * (err may be NULL, errlen 0). The suslov command refuses --inertia with these same lines. */
int sus_model_init(sus_model *m, const double I[9], char *err, size_t errlen);
/* 1 when m's seal matches the fields before it: m is what a successful sus_model_init made and
 * no field has changed since; 0 for a NULL m, a failed sus_model_init and any other bytes. */
int sus_model_sealed(const sus_model *m);
/* NULL when the energy and the multiplier lambda at w (w3 = 0) are finite numbers, as the first
 * row of a run must be; else what overflows there: "energy" or "multiplier lambda"; "no model" for
 * a NULL w, or an m that is NULL or not what sus_model_init filled (sus_model_sealed). A body's
 * coefficients may be finite while their products at a w are not (I31 = I32 = 1e300 at
 * |w| ~ 1): the run functions refuse such a start, and so does the suslov command. */
const char *sus_model_start_overflow(const sus_model *m, const double w[2]);

/* The inline kernels below, sus_contdyn_jacobian and sus_energy give NaN for a NULL pointer. */

/* c(w) = I_3i w_i, i in {1,2}: the factor shared by (ContDyn) and (LagMult); m and w not tested,
 * for the hot paths that have tested them (a test inside slows rk4's w-step by some 7 %). */
static inline double sus_c_unchecked(const sus_model *m, const double w[2])
{
    return m->b[0] * w[0] + m->b[1] * w[1];
}

/* c(w) to about one rounding of itself however much its two terms cancel (sus_cross_diff), where
 * sus_c_unchecked is off by a rounding of the terms: near a steady rotation c is far below them. */
static inline double sus_c_accurate(const sus_model *m, const double w[2])
{
    return sus_cross_diff(m->b[0], w[0], -m->b[1], w[1]);
}

/* g(w) = c(fA w): along (ContDyn) c' = g(w) c, and g is linear in w; g > 0 near the repelling
 * steady rotation, g < 0 near the attracting one. */
static inline double sus_contdyn_rate(const sus_model *m, const double w[2])
{
    const double u0 = m->fA[0][0] * w[0] + m->fA[0][1] * w[1],
                 u1 = m->fA[1][0] * w[0] + m->fA[1][1] * w[1];
    return m->b[0] * u0 + m->b[1] * u1;
}

/* c(w), NaN for a NULL m or w. */
static inline double sus_c(const sus_model *m, const double w[2])
{
    if (!m || !w)
        return NAN;
    return sus_c_unchecked(m, w);
}

/* (ContDyn): w1' = -(I22 w2 + I12 w1) c / |I_m|,  w2' = (I21 w2 + I11 w1) c / |I_m|.
 * Inline, with the division done once in sus_model_init: every stepper evaluates it. */
static inline void sus_contdyn(const sus_model *m, const double w[2], double f[2])
{
    if (!f)
        return;
    if (!m || !w) {
        f[0] = f[1] = NAN;
        return;
    }
    const double c = sus_c(m, w);
    f[0] = c * (m->fA[0][0] * w[0] + m->fA[0][1] * w[1]);
    f[1] = c * (m->fA[1][0] * w[0] + m->fA[1][1] * w[1]);
}

void sus_contdyn_jacobian(const sus_model *m, const double w[2], double J[2][2]);

/* The last term of (LagMult) with its factor c = I_3i w_i given (c / |I_m| (o0c[0] w1 + o0c[1]
 * w2)): the exact solution gives c(t) in closed form (exact.h), where I31 w1 + I32 w2 at the
 * rounded w cancels near the steady rotation. */
static inline double sus_o0_with_c(const sus_model *m, const double w[2], double c)
{
    const double ci = c * m->inv_det_m, p = m->o0c[1] * w[1] + m->o0c[0] * w[0];
    /* c / |I_m| first, as printed; where that alone overflows (a near-singular I_m, a large c) and
     * the whole need not, c (p / |I_m|) */
    return isfinite(ci) ? ci * p : c * (m->inv_det_m * p);
}

/* The last term of (LagMult); it equals I31 w1' + I32 w2' along (ContDyn), and it is the
 * O_0 of the proof of PropoFinal. */
static inline double sus_lagmult_o0(const sus_model *m, const double w[2])
{
    if (!m || !w)
        return NAN;
    return sus_o0_with_c(m, w, sus_c(m, w));
}

/* (LagMult)'s terms, as printed and summed in that order. */
static inline double sus_lagmult_terms(const sus_model *m, const double w[2], double c)
{
    const double(*I)[3] = m->I;
    return w[0] * (I[1][0] * w[0] + I[1][1] * w[1]) - w[1] * (I[0][0] * w[0] + I[0][1] * w[1]) +
           sus_o0_with_c(m, w, c);
}

/* lambda and E are quadratic in (w, c): q(w, c) = 2^(2 s) q(2^-s w, 2^-s c), exactly, as a power of
 * two scales without rounding (away from the subnormals). Where a term overflows and the sum need
 * not (within a few percent of the largest double), the sum is formed at 2^-SUS_QUAD_SCALE. */
#define SUS_QUAD_SCALE 32

/* (LagMult) at w with its factor c = I_3i w_i given, not formed from w: term by term as printed,
 * and scaled (above) where a term overflows: inf only where lambda does. NaN for a NULL m or w. */
static inline double sus_lagmult_c(const sus_model *m, const double w[2], double c)
{
    if (!m || !w)
        return NAN;
    const double l = sus_lagmult_terms(m, w, c);
    if (isfinite(l) || !isfinite(w[0]) || !isfinite(w[1]) || !isfinite(c))
        return l;
    const double ws[2] = {ldexp(w[0], -SUS_QUAD_SCALE), ldexp(w[1], -SUS_QUAD_SCALE)};
    return ldexp(sus_lagmult_terms(m, ws, ldexp(c, -SUS_QUAD_SCALE)), 2 * SUS_QUAD_SCALE);
}

/* (LagMult): lambda(w), term by term as printed (inline: the DSPs evaluate it every step). */
static inline double sus_lagmult(const sus_model *m, const double w[2])
{
    if (!m || !w)
        return NAN;
    return sus_lagmult_c(m, w, sus_c_unchecked(m, w));
}
double sus_energy(const sus_model *m, const double w[2]);

#ifdef __cplusplus
}
#endif

#endif
