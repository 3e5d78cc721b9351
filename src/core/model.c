#include "model.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

const double SUS_PAPER_INERTIA[9] = {1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0};
const double SUS_PAPER_OMEGA0[2] = {0.4, 0.5};

/* ||M||_2, the larger singular value of the 2x2 matrix [[a, b], [c, d]] in closed form,
 * (hypot(a + d, c - b) + hypot(a - d, c + b)) / 2: no entry is squared, so it overflows only where
 * the norm itself is near the largest double; rounded up by a few ulps (each hypot is within an
 * ulp, the sums within u (|a| + |d|) <= 2 u ||M||), so that the bound stays a bound after rounding.
 */
static double norm2x2(const double M[2][2])
{
    const double a = M[0][0], b = M[0][1], c = M[1][0], d = M[1][1];
    return 0.5 * (hypot(a + d, c - b) + hypot(a - d, c + b)) * (1.0 + 1e-14);
}

/* What the model derives from I must be finite: a coefficient that overflows makes every step's
 * arithmetic meaningless (an underflow cannot: past the checks on |I_m|, 1/|I_m| and the
 * inverse's diagonal are at least 1/DBL_MAX, which keeps 50 of its 53 bits). ||fA|| is finite
 * exactly when every entry of fA is (each entry is at most the norm, and hypot of an infinity is
 * infinite). Returns 0 or -1 with the reason. */
static int check_coefficients(const sus_model *m, char *err, size_t errlen)
{
    const char *what = NULL;
    if (!isfinite(m->norm_fA))
        what = "a coefficient I_ij/|I_m| of (ContDyn), or their norm ||I_m^-1||, overflows";
    else if (!isfinite(m->norm_b))
        what = "the size of the field of (ContDyn), |(I31, I32)|, overflows";
    else if (!(isfinite(m->o0c[0]) && isfinite(m->o0c[1])))
        what = "a coefficient I32 Ij1 - I31 Ij2 of (LagMult) overflows";
    if (!what)
        return 0;
    snprintf(err, errlen, "too extreme for double precision: %s (|I_m| = %.17g)", what, m->det_m);
    return -1;
}

/* Positive definite, with a determinant double precision resolves and holds. Definiteness is
 * decided on the unscaled products in long double, whose range holds the product of any two
 * doubles (scaled, an entry such as 1e-200 next to 1e200 underflowed to 0 and a positive definite
 * I_m was called indefinite). */
static int check_definite(const double I[9], char *err, size_t errlen)
{
    const long double p = (long double)I[0] * I[4], q = (long double)I[1] * I[3];
    if (!(I[0] > 0.0) || !(p - q > 0.0L))
        return snprintf(err, errlen,
                        "I_m is not positive definite (I11 = %.17g, I22 = %.17g, I12 = %.17g)",
                        I[0], I[4], I[1]),
               -1;
    /* |I_m| formed in double: within 2 DBL_EPSILON of its terms, its rounding (u = DBL_EPSILON / 2
     * for each product and for the difference) can be all of it. Past this test the double
     * determinant is within a quarter of the true one, so one out of range is the entries' doing.
     */
    if (p - q <= 2.0L * SUS_U * (p + fabsl(q)))
        return snprintf(err, errlen,
                        "too ill-conditioned for double precision: I11 I22 and I12 I21 agree to "
                        "their rounding, so |I_m| is lost to cancellation (I11 = %.17g, I22 = "
                        "%.17g, I12 = %.17g)",
                        I[0], I[4], I[1]),
               -1;
    const double det = I[0] * I[4] - I[1] * I[3];
    if (!isfinite(det) || !(det >= DBL_MIN))
        return snprintf(err, errlen,
                        "the determinant of I_m, %.17g * %.17g - %.17g * %.17g, is not a finite "
                        "normal number (entries too large or too small)",
                        I[0], I[4], I[1], I[3]),
               -1;
    return 0;
}

/* I_m (upper-left 2x2 of I) must be symmetric (for E to be conserved by (ContDyn)) and positive
 * definite, and its determinant, which (ContDyn) divides by, a finite normal number that double
 * precision resolves. Symmetry is tested relative to M = max |I_m entry|, so that nothing
 * overflows (the unscaled sum of |entries| is inf at 1e308, and inf > 4u inf is false); the
 * tolerance 4u (1 + 1 + 1 + 1) allows the rounding of four entries of size <= M. */
static int check_im(const double I[9], char *err, size_t errlen)
{
    const double M = fmax(fmax(fabs(I[0]), fabs(I[1])), fmax(fabs(I[3]), fabs(I[4])));
    if (M == 0.0)
        return snprintf(err, errlen, "I_m is zero, not positive definite"), -1;
    const double a = I[0] / M, b = I[1] / M, c = I[3] / M, d = I[4] / M;
    if (fabs(b - c) > 4.0 * SUS_U * (fabs(a) + fabs(b) + fabs(c) + fabs(d)))
        return snprintf(err, errlen, "I_m is not symmetric: I12 = %.17g but I21 = %.17g", I[1],
                        I[3]),
               -1;
    return check_definite(I, err, errlen);
}

/* The seal of the fields before it: the sum of their bit patterns, the i-th times the odd number
 * (2i + 1) g, modulo 2^64. Changing one field changes the sum, as an odd factor is invertible
 * modulo 2^64; other bytes match it by chance only, about once in 2^64. The products are
 * independent of one another, so they overlap. */
static unsigned long long seal_of(const sus_model *m)
{
    const unsigned long long g = 0x9E3779B97F4A7C15ull; /* odd: 2^64 over the golden ratio */
    const unsigned char *p = (const unsigned char *)m;
    unsigned long long h = g; /* not 0: a model of zero bytes must not match */
    for (size_t i = 0; i < offsetof(sus_model, seal) / sizeof h; i++) {
        unsigned long long x;
        memcpy(&x, p + i * sizeof h, sizeof h);
        h += x * ((2 * i + 1) * g);
    }
    return h;
}

int sus_model_sealed(const sus_model *m) { return m && m->seal == seal_of(m); }

static int fill(sus_model *m, const double I[9], char *err, size_t errlen)
{
    for (int i = 0; i < 9; i++) {
        if (!isfinite(I[i])) {
            snprintf(err, errlen, "inertia entry %d is not finite", i + 1);
            return -1;
        }
        m->I[i / 3][i % 3] = I[i];
    }
    if (check_im(I, err, errlen) != 0)
        return -1;
    m->det_m = sus_cross_diff(I[0], I[4], I[1], I[3]);
    m->b[0] = I[6];
    m->b[1] = I[7];
    m->inv_det_m = 1.0 / m->det_m;
    m->fA[0][0] = -I[1] / m->det_m; /* -I12 */
    m->fA[0][1] = -I[4] / m->det_m; /* -I22 */
    m->fA[1][0] = I[0] / m->det_m;  /*  I11 */
    m->fA[1][1] = I[3] / m->det_m;  /*  I21 */
    m->norm_fA = norm2x2(m->fA);
    m->o0c[0] = sus_cross_diff(I[7], I[0], I[6], I[1]); /* I32 I11 - I31 I12 */
    m->o0c[1] = sus_cross_diff(I[7], I[3], I[6], I[4]); /* I32 I21 - I31 I22 */
    m->norm_b = hypot(m->b[0], m->b[1]) * (1.0 + 1e-15);
    return check_coefficients(m, err, errlen);
}

int sus_model_init(sus_model *m, const double I[9], char *err, size_t errlen)
{
    if (!err)
        errlen = 0;
    if (!m || !I) {
        snprintf(err, errlen, "%s is NULL", m ? "the inertia" : "the model");
        return -1;
    }
    *m = (sus_model){0}; /* every field defined, also where fill stops early */
    const int rc = fill(m, I, err, errlen);
    m->seal = seal_of(m) ^ (rc != 0); /* a failed fill: a seal that never matches */
    return rc;
}

const char *sus_model_start_overflow(const sus_model *m, const double w[2])
{
    if (!w || !sus_model_sealed(m))
        return "no model";
    return !isfinite(sus_energy(m, w))    ? "energy"
           : !isfinite(sus_lagmult(m, w)) ? "multiplier lambda"
                                          : NULL;
}

/* Df of (ContDyn), for the Newton iterations and linear stability. */
void sus_contdyn_jacobian(const sus_model *m, const double w[2], double J[2][2])
{
    if (!J)
        return;
    if (!m || !w) {
        J[0][0] = J[0][1] = J[1][0] = J[1][1] = NAN;
        return;
    }
    const double(*I)[3] = m->I;
    const double d = m->det_m, c = sus_c(m, w);
    const double p = I[1][1] * w[1] + I[0][1] * w[0];
    const double q = I[1][0] * w[1] + I[0][0] * w[0];
    J[0][0] = -(I[0][1] * c + p * m->b[0]) / d;
    J[0][1] = -(I[1][1] * c + p * m->b[1]) / d;
    J[1][0] = (I[0][0] * c + q * m->b[0]) / d;
    J[1][1] = (I[1][0] * c + q * m->b[1]) / d;
}

/* 2 E = <I_m w, w>, term by term. */
static double twice_energy(const double (*I)[3], const double w[2])
{
    return w[0] * (I[0][0] * w[0] + I[0][1] * w[1]) + w[1] * (I[1][0] * w[0] + I[1][1] * w[1]);
}

/* E(w) = 1/2 <I_m w, w>; the paper's displayed E_l drops the 1/2 (a factor-2 slip). Scaled as
 * (LagMult) is (model.h: SUS_QUAD_SCALE) where 2 E or a term overflows and E need not. */
double sus_energy(const sus_model *m, const double w[2])
{
    if (!m || !w)
        return NAN;
    const double e = 0.5 * twice_energy(m->I, w);
    if (isfinite(e) || !isfinite(w[0]) || !isfinite(w[1]))
        return e;
    const double ws[2] = {ldexp(w[0], -SUS_QUAD_SCALE), ldexp(w[1], -SUS_QUAD_SCALE)};
    return ldexp(0.5 * twice_energy(m->I, ws), 2 * SUS_QUAD_SCALE);
}
