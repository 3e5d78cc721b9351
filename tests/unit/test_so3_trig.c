/* The exponential map's own sin, cos and sinc (so3_trig.c) against the C library's, which serve
 * as the independent reference here. Bounds, from so3_trig.c's error argument, fixed before
 * measuring: ours is within about 2 u of the true value (reduction 1.1 u |r| <= 0.9 u, the
 * polynomial about 1 u) and the library within 1 ulp, <= u for results below 1 in size; so
 * 3 u absolute where t is reduced (|t| > pi/4), and 3 u relative where it is not (the quotient
 * adds u/2). u = 2^-53. */
#include "check.h"
#include "so3.h"

#include <gsl/gsl_rng.h>
#include <math.h>

static const double U = 0x1p-53, PI_2 = 1.5707963267948966, PI_4 = 0.78539816339744831;

/* The worst |ours - libm| / u over n points t = lo + (hi - lo) x, x uniform, both signs. */
static double worst_abs(gsl_rng *r, double lo, double hi, int n)
{
    double worst = 0.0;
    for (int i = 0; i < n; i++) {
        const double t = (i % 2 ? -1.0 : 1.0) * (lo + (hi - lo) * gsl_rng_uniform(r));
        double s, c;
        sus_so3_sincos(t, &s, &c);
        worst = fmax(worst, fmax(fabs(s - sin(t)), fabs(c - cos(t))) / U);
    }
    return worst;
}

/* Near the multiples k pi/2 (k <= 4000), where r is smallest and the reduction matters most. */
static double worst_near_multiples(void)
{
    double worst = 0.0;
    for (int k = 1; k <= 4000; k++)
        for (int d = -3; d <= 3; d++) {
            const double t = nextafter(k * PI_2, d < 0 ? 0.0 : INFINITY) + d * 1e-12;
            double s, c;
            sus_so3_sincos(t, &s, &c);
            worst = fmax(worst, fmax(fabs(s - sin(t)), fabs(c - cos(t))) / U);
        }
    return worst;
}

/* The worst relative difference / u of sin, cos and sinc on (0, pi/4], and of sinc on (pi/4, 8]
 * the worst absolute difference times t. */
static void relative(gsl_rng *r)
{
    double ws = 0.0, wc = 0.0, wsinc = 0.0, wbig = 0.0;
    for (int i = 0; i < 200000; i++) {
        const double t = PI_4 * gsl_rng_uniform_pos(r) * (i % 3 ? 1.0 : 1e-6);
        const double t8 = 8.0 * gsl_rng_uniform_pos(r);
        double s, c;
        sus_so3_sincos(t, &s, &c);
        ws = fmax(ws, fabs(s / sin(t) - 1.0) / U);
        wc = fmax(wc, fabs(c / cos(t) - 1.0) / U);
        wsinc = fmax(wsinc, fabs(sus_so3_sinc(t) / (sin(t) / t) - 1.0) / U);
        /* sin t8 / t8 from a sin that is only absolutely accurate: compare t8 sinc */
        if (t8 > PI_4)
            wbig = fmax(wbig, fabs(sus_so3_sinc(t8) - sin(t8) / t8) * t8 / U);
    }
    CHECK(ws <= 3.0 && wc <= 3.0,
          "sin, cos on (0, pi/4] (no reduction): within 3 u relative of libm; "
          "worst %.2f u (sin), %.2f u (cos)",
          ws, wc);
    CHECK(wsinc <= 3.0,
          "sinc t = sin t / t on (0, pi/4]: within 3 u relative of libm's quotient; worst %.2f u",
          wsinc);
    /* 3 u for the two sines, u/2 for each quotient's rounding (times t, |sin t| <= 1) */
    CHECK(wbig <= 4.0,
          "sinc t on (pi/4, 8]: t |sinc t - sin t / t| within 4 u of libm's; worst %.2f u", wbig);
}

int main(void)
{
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20261123);
    relative(rng);
    const double w8 = worst_abs(rng, 0.0, 8.0, 200000), wbig = worst_abs(rng, 8.0, 1.6e6, 200000);
    CHECK(w8 <= 3.0, "sin, cos on |t| <= 8 (exp-mid's steps): within 3 u of libm; worst %.2f u",
          w8);
    CHECK(wbig <= 3.0, "sin, cos on 8 < |t| < 1.6e6 (n < 2^20): within 3 u of libm; worst %.2f u",
          wbig);
    const double wm = worst_near_multiples();
    CHECK(wm <= 3.0, "sin, cos next to k pi/2, k <= 4000: within 3 u of libm; worst %.2f u", wm);
    double s, c;
    sus_so3_sincos(0.0, &s, &c);
    CHECK(s == 0.0 && c == 1.0 && sus_so3_sinc(0.0) == 1.0 && sus_so3_sinc(1e-300) == 1.0,
          "sin 0 = 0, cos 0 = 1, sinc 0 = sinc 1e-300 = 1 exactly");
    /* any finite t gives a point of the unit circle (2^52 and past: an angle of the circle) */
    double worst_unit = 0.0;
    for (double t = 1e15; t < 1e308; t *= 7.3) {
        sus_so3_sincos(t, &s, &c);
        worst_unit = fmax(worst_unit, isfinite(s) && isfinite(c) ? fabs(s * s + c * c - 1.0) : 1.0);
    }
    CHECK(worst_unit <= 4.0 * U, "sin^2 + cos^2 = 1 to 4 u for t = 1e15 .. 1e308: worst %.2g",
          worst_unit);
    sus_so3_sincos(INFINITY, &s, &c);
    CHECK(isnan(s) && isnan(c) && isnan(sus_so3_sinc(NAN)), "sin, cos, sinc of inf or NaN: NaN");
    gsl_rng_free(rng);
    return check_summary("test_so3_trig");
}
