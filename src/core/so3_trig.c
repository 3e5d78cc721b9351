/* sin and cos for the exponential map (Rodrigues' formula, so3.c; the quaternion step,
 * reconstruct.c), computed here rather than by the C library so that every build gets the same
 * bits: the CLI links glibc, the browser's WebAssembly module wasi-libc (musl), and their sin and
 * cos differ in the last bit for some arguments. Everything below is IEEE double arithmetic
 * (+, -, *, / correctly rounded, rint exact) in a fixed order, so any conforming build computes
 * the same result; the one thing that could break it, fusing a product and a sum into an fma, is
 * off for the whole project (-ffp-contract=off in the Makefile).
 *
 * Method (Cody and Waite). t = n pi/2 + r with n the nearest integer to 2t/pi and |r| <= pi/4;
 * sin r and cos r are their Taylor polynomials, evaluated by Horner's rule in z = r^2.
 * Error: pi/2 is split as P1 + P2 + P3 with P1 and P2 of 33 significant bits and P3 of 53, so
 * for n < 2^20 the products n P1 and n P2 are exact, t - n P1 is exact (Sterbenz: the two are
 * within a factor 2), and r carries only the two roundings of the last subtractions, the rounding
 * of n P3 and the tail |pi/2 - P1 - P2 - P3| < 1.1e-37 times n: |r error| <= 1.1 u |r| + 1e-30.
 * The polynomials stop before r^19/19! (sin) and r^20/20! (cos), below 1.2e-19 and 3.3e-21
 * of the result on |r| <= pi/4, and their evaluation, dominated by the final addition of the
 * leading term, adds about 1 u. So sin and cos are within about 2 u of the true values for
 * |t| < 2^20 pi/2 (t up to 1.6e6 rad), and sinc (below) within about 1 u relative for
 * |t| <= pi/4. Beyond 2^20 pi/2 the same operations still give the same bits everywhere, but
 * n P1 is rounded and the absolute error grows like |t| u; from 2^52 on t is reduced first. */
#include "so3.h"

#include <math.h>

/* pi/2 = P1 + P2 + P3 + O(1e-37): P1, P2 of 33 significant bits, P3 of 53. */
static const double P1 = 0x1.921fb544p+0, P2 = 0x1.0b4611a6p-34, P3 = 0x1.3198a2e037073p-69;
static const double TWO_OVER_PI = 0x1.45f306dc9c883p-1;

/* The Taylor coefficients (-1)^k / (2k+1)! (sin r / r) and (-1)^k / (2k)! (cos r), each the
 * correctly rounded quotient of two exact doubles (every factorial here is below 2^53). */
/* clang-format off */
static const double SINC_C[9] = {1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0,
                                 -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0,
                                 1.0 / 355687428096000.0};
static const double COS_C[10] = {1.0, -1.0 / 2.0, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0,
                                 -1.0 / 3628800.0, 1.0 / 479001600.0, -1.0 / 87178291200.0,
                                 1.0 / 20922789888000.0, -1.0 / 6402373705728000.0};
/* clang-format on */

/* sum_k c[k] z^k by Horner's rule, highest term first. */
static double horner(const double *c, int n, double z)
{
    double p = c[n - 1];
    for (int k = n - 2; k >= 0; k--)
        p = p * z + c[k];
    return p;
}

/* sin r / r and cos r for |r| <= pi/4 (or a little more), z = r^2. */
static double sinc_poly(double z) { return horner(SINC_C, 9, z); }
static double cos_poly(double z) { return horner(COS_C, 10, z); }

void sus_so3_sincos(double t, double *s, double *c)
{
    if (!isfinite(t)) {
        *s = *c = NAN;
        return;
    }
    /* From 2^52 on a rounding of t is a radian or more, so no angle is better than another; the
     * remainder by 4 P1, 2 pi to 33 bits (fmod is exact, hence the same bits everywhere), keeps r
     * in range, where the reduction below would leave |r| growing like |t| u until the polynomials
     * overflow (at |t| near 1e33). */
    const double a = fabs(t) < 0x1p52 ? fabs(t) : fmod(fabs(t), 2.0 * (2.0 * P1)),
                 n = rint(a * TWO_OVER_PI);
    const double r = ((a - n * P1) - n * P2) - n * P3, z = r * r;
    const double sr = r * sinc_poly(z), cr = cos_poly(z);
    const int q = (int)fmod(n, 4.0); /* exact: n is a whole number */
    const double sa = q == 0 ? sr : q == 1 ? cr : q == 2 ? -sr : -cr;
    *c = q == 0 ? cr : q == 1 ? -sr : q == 2 ? -cr : sr;
    *s = t < 0.0 ? -sa : sa;
}

double sus_so3_sinc(double t)
{
    /* pi/4 rounded down: no reduction, full relative accuracy */
    if (fabs(t) <= 0.78539816339744828)
        return sinc_poly(t * t);
    double s, c;
    sus_so3_sincos(t, &s, &c);
    return s / t;
}
