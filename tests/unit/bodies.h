/* A seeded family of general bodies for the tests, generated here from a fixed seed and never
 * from the code under test. The paper's body has I13 = I31 and I12 = I21 > 0, so a test on it
 * alone cannot tell a row of I from a column, nor a sign slip on an off-diagonal entry. Every
 * body of this family has
 *   - I13 != I31 and I23 != I32 (the field reads the third ROW, (RGB2); a column mix-up moves it),
 *   - off-diagonal entries of both signs (the sign pattern of I12, I31, I32 differs per body),
 *   - a positive definite symmetric part (I_m itself symmetric positive definite, as (ContDyn)
 *     needs; the third row and column are drawn until (I + I^T)/2 is positive definite),
 *   - w(0) in a different quadrant from the previous body's, with c(w0) = I_3i w0_i away from 0.
 * Body 0 of a family is always the paper's (body_get(0)), so loops over bodies keep it.
 * After the general bodies come BODIES_STIFF hard ones, drawn the same way but at the edges a
 * reference or a method meets first (body_stiff):
 *   - "bigb":  |I31|, |I32| 4 to 10 times the largest entry of I_m (a fast approach, rate k);
 *   - "cond":  I_m with condition number 1e5 to 1e6 (an elongated energy ellipse);
 *   - "fast":  |w0| from 2 to 3 (four times the paper's);
 *   - "all":   the three at once.
 * Only I_m must be symmetric positive definite for (ContDyn); with a third row ten times I_m the
 * whole tensor would need I33 in the hundreds to be definite, so the stiff bodies' third row and
 * column are drawn without that condition (as `suslov --inertia` accepts them). */
#ifndef SUSLOV_BODIES_H
#define SUSLOV_BODIES_H

#include "model.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#define BODIES_SEED 20261123u
#define BODIES_GENERAL 6 /* general bodies after the paper's */
#define BODIES_STIFF 4   /* hard bodies after the general ones */
#define BODIES_COUNT (1 + BODIES_GENERAL + BODIES_STIFF)

typedef struct {
    double I[9]; /* rows as printed */
    double w0[2];
    char name[16]; /* "paper" or "body1" .. */
} body;

/* splitmix64: a fixed, documented generator, so the family is the same on every platform. */
static inline uint64_t body_rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in [lo, hi) */
static inline double body_uniform(uint64_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(body_rng_next(s) >> 11) * 0x1.0p-53;
}

/* Leading minors of the symmetric part: Sylvester's criterion. */
static inline int body_sym_posdef(const double I[9])
{
    const double a = I[0], b = 0.5 * (I[1] + I[3]), c = 0.5 * (I[2] + I[6]);
    const double d = I[4], e = 0.5 * (I[5] + I[7]), f = I[8];
    const double det = a * (d * f - e * e) - b * (b * f - e * c) + c * (b * e - d * c);
    return a > 0.0 && a * d - b * b > 0.0 && det > 0.0;
}

/* A magnitude in [lo, hi) with the sign bit `neg`. */
static inline double body_signed(uint64_t *s, double lo, double hi, int neg)
{
    const double v = body_uniform(s, lo, hi);
    return neg ? -v : v;
}

/* Body k >= 1 of the family drawn from `seed`: its own stream, so bodies do not depend on
 * each other's rejections. Sign pattern: bit 0 of k for I12, bit 1 for I31, bit 2 for I32. */
static inline void body_general(uint32_t seed, int k, body *b)
{
    uint64_t s = ((uint64_t)seed << 32) ^ (uint64_t)k;
    double *I = b->I;
    do {
        I[0] = body_uniform(&s, 0.6, 2.0);
        I[4] = body_uniform(&s, 0.6, 2.0);
        I[1] = I[3] = body_signed(&s, 0.05, 0.5, k & 1) * sqrt(I[0] * I[4]);
        I[6] = body_signed(&s, 0.05, 0.6, (k >> 1) & 1);
        I[7] = body_signed(&s, 0.05, 0.6, (k >> 2) & 1);
        /* the transposed entries differ from the row by at least 0.05, either way */
        I[2] = I[6] + body_signed(&s, 0.05, 0.3, (k + 1) & 1);
        I[5] = I[7] + body_signed(&s, 0.05, 0.3, k & 1);
        I[8] = body_uniform(&s, 0.8, 2.5);
    } while (!body_sym_posdef(b->I));
    /* quadrant k mod 4, away from the axes; radius so that |w| ~ the paper's 0.64 */
    const double r = body_uniform(&s, 0.4, 0.9), bn = hypot(I[6], I[7]);
    do {
        const double a = 1.5707963267948966 * ((k % 4) + body_uniform(&s, 0.2, 0.8));
        b->w0[0] = r * cos(a);
        b->w0[1] = r * sin(a);
    } while (fabs(I[6] * b->w0[0] + I[7] * b->w0[1]) <
             0.2 * r * bn); /* far from a steady rotation */
    snprintf(b->name, sizeof b->name, "body%d", k);
}

/* I_m = Q diag(l1, l1 / cond) Q^T, Q the rotation by a, with I12 = I21 exactly. */
static inline void body_conditioned(uint64_t *s, double cond_lo, double cond_hi, double *I)
{
    const double l1 = body_uniform(s, 0.6, 2.0),
                 l2 = l1 / exp(body_uniform(s, log(cond_lo), log(cond_hi)));
    const double a = body_uniform(s, 0.3, 1.3), c = cos(a), sn = sin(a);
    I[0] = c * c * l1 + sn * sn * l2;
    I[4] = sn * sn * l1 + c * c * l2;
    I[1] = I[3] = c * sn * (l1 - l2);
}

/* Stiff body j = 0 .. BODIES_STIFF - 1 (body BODIES_GENERAL + 1 + j of the family): bit 0 of its
 * kind a large third row, bit 1 a near-singular I_m, bit 2 a large |w0| (bigb 1, cond 2, fast 4,
 * all 7); signs as body_general's, by the body's index. */
static inline void body_stiff(uint32_t seed, int j, body *b)
{
    static const int kinds[BODIES_STIFF] = {1, 2, 4, 7};
    static const char *names[BODIES_STIFF] = {"bigb", "cond", "fast", "all"};
    const int kind = kinds[j], k = BODIES_GENERAL + 1 + j;
    uint64_t s = ((uint64_t)seed << 32) ^ (uint64_t)k;
    double *I = b->I;
    if (kind & 2) {
        body_conditioned(&s, 1e5, 1e6, I);
    } else {
        I[0] = body_uniform(&s, 0.6, 2.0);
        I[4] = body_uniform(&s, 0.6, 2.0);
        I[1] = I[3] = body_signed(&s, 0.05, 0.5, k & 1) * sqrt(I[0] * I[4]);
    }
    const double big = (kind & 1) ? fmax(I[0], I[4]) : 1.0;
    const double lo = (kind & 1) ? 4.0 * big : 0.05, hi = (kind & 1) ? 10.0 * big : 0.6;
    I[6] = body_signed(&s, lo, hi, (k >> 1) & 1);
    I[7] = body_signed(&s, lo, hi, (k >> 2) & 1);
    I[2] = I[6] + body_signed(&s, 0.05, 0.3, (k + 1) & 1);
    I[5] = I[7] + body_signed(&s, 0.05, 0.3, k & 1);
    I[8] = body_uniform(&s, 0.8, 2.5);
    const double r = (kind & 4) ? body_uniform(&s, 2.0, 3.0) : body_uniform(&s, 0.4, 0.9);
    const double bn = hypot(I[6], I[7]);
    do {
        const double a = 1.5707963267948966 * ((k % 4) + body_uniform(&s, 0.2, 0.8));
        b->w0[0] = r * cos(a);
        b->w0[1] = r * sin(a);
    } while (fabs(I[6] * b->w0[0] + I[7] * b->w0[1]) < 0.2 * r * bn);
    snprintf(b->name, sizeof b->name, "%s", names[j]);
}

/* Body k of the family: 0 is the paper's, 1 .. BODIES_GENERAL general, then the stiff ones. */
static inline void body_get(int k, body *b)
{
    if (k == 0) {
        for (int i = 0; i < 9; i++)
            b->I[i] = SUS_PAPER_INERTIA[i];
        b->w0[0] = SUS_PAPER_OMEGA0[0];
        b->w0[1] = SUS_PAPER_OMEGA0[1];
        snprintf(b->name, sizeof b->name, "paper");
        return;
    }
    if (k > BODIES_GENERAL) {
        body_stiff(BODIES_SEED, k - BODIES_GENERAL - 1, b);
        return;
    }
    body_general(BODIES_SEED, k, b);
}

/* One line describing the body, for test output and the ledger. */
static inline void body_describe(const body *b, char *buf, size_t len)
{
    snprintf(buf, len,
             "%s: I = [%.4g %.4g %.4g; %.4g %.4g %.4g; %.4g %.4g %.4g], w0 = (%.4g, %.4g)", b->name,
             b->I[0], b->I[1], b->I[2], b->I[3], b->I[4], b->I[5], b->I[6], b->I[7], b->I[8],
             b->w0[0], b->w0[1]);
}

#endif
