#include "exact.h"

#include "api_args.h"

#include <float.h>
#include <math.h>

/* x scaled by a power of two to a largest entry in [1/2, 1): exact (save entries far below the
 * largest), and returns the power; 0 for x = 0. */
static int scaled(const double x[2], double xs[2])
{
    int e = 0;
    frexp(fmax(fabs(x[0]), fabs(x[1])), &e);
    xs[0] = ldexp(x[0], -e);
    xs[1] = ldexp(x[1], -e);
    return e;
}

/* s0 = asinh(S / C); where S / C overflows (a start within 2^-1024 of a steady rotation),
 * asinh x = sign(x) (ln 2|x| + O(x^-2)) with ln |x| = ln |S| - ln |C|: s0 stays finite, so the
 * motion still leaves a repelling rotation at the right time. */
static double phase0(double S, double C)
{
    const double x = S / C;
    if (isfinite(x))
        return asinh(x);
    const double a = log(2.0 * fabs(S)) - log(fabs(C));
    return (S > 0.0) == (C > 0.0) ? a : -a;
}

/* The Cholesky factor of I_m: l22 = sqrt(|I_m| / I11), formed without the cancellation of I22 -
 * l21^2 on a near-singular I_m; returns sqrt|I_m|. */
static double cholesky(sus_exact *ex, const double (*I)[3])
{
    const double sd = sqrt(sus_cross_diff(I[0][0], I[1][1], I[1][0], I[1][0]));
    ex->l11 = sqrt(I[0][0]);
    ex->l21 = I[1][0] / ex->l11;
    ex->l22 = sd / ex->l11;
    return sd;
}

static void set_fixed(sus_exact *ex)
{
    ex->fixed = 1;
    ex->cb = 1.0, ex->sb = 0.0, ex->k = 0.0, ex->sigma = 1.0, ex->s0 = 0.0, ex->cmax = 0.0;
}

int sus_exact_init(sus_exact *ex, const sus_model *m, const double w0[2])
{
    if (!ex)
        return -1;
    if (!sus_model_sealed(m) || !sus_args_finite2(w0)) {
        *ex = (sus_exact){.model = NULL, .r = NAN, .k = NAN, .c0 = NAN, .w0 = {NAN, NAN}};
        return -1;
    }
    const double(*I)[3] = m->I, *b = m->b;
    *ex = (sus_exact){.model = m, .w0 = {w0[0], w0[1]}};
    set_fixed(ex);
    const double sd = cholesky(ex, I);
    /* beta, C = cos psi0 and S = sin psi0 do not depend on the sizes of w0 and b: formed from
     * copies scaled to about 1, c(w0) and |v| r cannot underflow on the way. u1 = (I11 w1 + I21
     * w2) / l11 and v2 = (I11 I32 - I21 I31) / (l11 sqrt|I_m|) to about a rounding however much
     * their terms cancel. */
    double ws[2], bs[2];
    const int ew = scaled(w0, ws), eb = scaled(b, bs);
    const double u1 = sus_cross_diff(I[0][0], ws[0], -I[1][0], ws[1]) / ex->l11;
    const double u2 = ex->l22 * ws[1];
    const double v1 = bs[0] / ex->l11;
    const double v2 = sus_cross_diff(I[0][0], bs[1], I[1][0], bs[0]) / (ex->l11 * sd);
    const double vn = hypot(v1, v2), rs = hypot(u1, u2);
    ex->r = ldexp(rs, ew);
    ex->c0 = sus_c_accurate(m, w0);
    if (rs == 0.0 || vn == 0.0)
        return 0;
    /* C = <v, u> / (|v| r) = c(w0) / (|v| r), as <v, u> = b^T L^{-T} L^T w0: c(w0) formed to about
     * one rounding of itself, not from the rounded u and v, whose terms cancel near the line c =
     * 0; there s0 = asinh(S / C) takes C's relative error as an absolute one, and a start 1e-14
     * off the repelling rotation would leave it at a time off by up to u / 1e-14 of 1 / k. */
    const double C = sus_cross_diff(bs[0], ws[0], -bs[1], ws[1]) / (vn * rs);
    const double S = (v1 * u2 - v2 * u1) / (vn * rs);
    const double cmax = ldexp(rs * vn, ew + eb), k = ldexp(rs * vn / (ex->l11 * ex->l22), ew + eb);
    if (C == 0.0 || k == 0.0) /* an equilibrium, c(w0) = 0, or a k that underflows (exact.h) */
        return 0;
    ex->fixed = 0;
    ex->cb = v1 / vn;
    ex->sb = v2 / vn;
    ex->k = k;
    ex->cmax = cmax;
    ex->sigma = C > 0.0 ? 1.0 : -1.0;
    ex->s0 = phase0(S, C);
    return 0;
}

/* w = L^{-T} u with u = r R(beta) (cos psi, sin psi). */
static void omega_from_psi(const sus_exact *ex, double cp, double sp, double w[2])
{
    const double u1 = ex->r * (ex->cb * cp - ex->sb * sp);
    const double u2 = ex->r * (ex->sb * cp + ex->cb * sp);
    w[1] = u2 / ex->l22;
    w[0] = (u1 - ex->l21 * w[1]) / ex->l11;
}

/* At t = 0 w0 itself: its closed-form evaluation is an ulp or so off, and w(0) is what every
 * method starts from (its row 0). */
/* A refused (or NULL) ex: NaN, not a motion. */
static int refused(const sus_exact *ex, double w[2])
{
    if (ex && ex->model)
        return 0;
    w[0] = w[1] = NAN;
    return 1;
}

/* sech s at t, s = s0 + sigma k t into *s: 2 e^{-|s|} / (1 + e^{-2|s|}), which overflows for no t
 * (exact.h). */
static double sech_at(const sus_exact *ex, double t, double *s)
{
    *s = ex->s0 + ex->sigma * ex->k * t;
    const double e = exp(-fabs(*s));
    return 2.0 * e / (1.0 + e * e);
}

void sus_exact_omega(const sus_exact *ex, double t, double w[2])
{
    if (!w || refused(ex, w))
        return;
    if (ex->fixed || t == 0.0) {
        w[0] = ex->w0[0];
        w[1] = ex->w0[1];
        return;
    }
    double s;
    const double sech = sech_at(ex, t, &s);
    omega_from_psi(ex, ex->sigma * sech, ex->sigma * tanh(s), w);
}

/* (exact.h) c(t) = sigma r |v| sech s. */
double sus_exact_c(const sus_exact *ex, double t)
{
    if (!ex || !ex->model)
        return NAN;
    if (ex->fixed || t == 0.0)
        return ex->c0;
    double s;
    return ex->sigma * ex->cmax * sech_at(ex, t, &s);
}

/* The steady rotation w(t -> infinity): psi = pi/2. */
void sus_exact_limit(const sus_exact *ex, double w[2])
{
    if (!w || refused(ex, w))
        return;
    if (ex->fixed) {
        w[0] = ex->w0[0];
        w[1] = ex->w0[1];
        return;
    }
    omega_from_psi(ex, 0.0, 1.0, w);
}

/* (LagMult) at the point (z, y) = (sech s, tanh s) of the motion, in long double, whose range
 * holds any product of a few doubles: w = L^{-T} u, u = sigma r Rot(beta) (z, y), c = sigma cmax
 * z (omega_from_psi, sus_exact_c). */
static long double lambda_at(const sus_exact *ex, long double z, long double y)
{
    const double(*I)[3] = ex->model->I;
    const long double g = ex->sigma * (long double)ex->r;
    const long double u1 = g * (ex->cb * z - ex->sb * y), u2 = g * (ex->sb * z + ex->cb * y);
    const long double w1 = u2 / ex->l22, w0 = (u1 - ex->l21 * w1) / ex->l11;
    const long double c = ex->sigma * (long double)ex->cmax * z;
    return w0 * (I[1][0] * w0 + I[1][1] * w1) - w1 * (I[0][0] * w0 + I[0][1] * w1) +
           c * ex->model->inv_det_m * (ex->model->o0c[1] * w1 + ex->model->o0c[0] * w0);
}

/* (exact.h) lambda is a quadratic form in (z, y), which runs over the half circle z > 0 (sech^2 +
 * tanh^2 = 1) and, the form being even, comes as near its largest size on the whole circle: its
 * spectral radius, from its values at (1, 0), (0, 1) and (1, 1). */
double sus_exact_lambda_max(const sus_exact *ex)
{
    if (!ex || !ex->model)
        return NAN;
    if (ex->fixed)
        return fabs(sus_lagmult_c(ex->model, ex->w0, ex->c0));
    const long double a = lambda_at(ex, 1.0L, 0.0L), c = lambda_at(ex, 0.0L, 1.0L);
    const long double b = 0.5L * (lambda_at(ex, 1.0L, 1.0L) - a - c);
    const long double sup = fabsl(0.5L * (a + c)) + hypotl(0.5L * (a - c), b);
    return sup > DBL_MAX ? INFINITY : (double)sup;
}
