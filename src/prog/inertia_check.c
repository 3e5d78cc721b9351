#include "inertia_check.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

/* Positive definite, with a determinant double precision resolves and holds. */
static int check_definite(const double I[9], char *msg, size_t len)
{
    const long double p = (long double)I[0] * I[4], q = (long double)I[1] * I[3];
    if (!(I[0] > 0.0) || !(p - q > 0.0L))
        return snprintf(msg, len,
                        "--inertia: I_m is not positive definite "
                        "(I11 = %.17g, I22 = %.17g, I12 = %.17g)",
                        I[0], I[4], I[1]),
               -1;
    /* The model forms I11 I22 - I12 I21 in double: within 2 DBL_EPSILON of its terms, its rounding
     * (u = DBL_EPSILON / 2 for each product and for the difference) can be all of it. Past this
     * test the double determinant is within a quarter of the true one, so one out of range is the
     * entries' doing. */
    if (p - q <= 2.0L * DBL_EPSILON * (p + fabsl(q)))
        return snprintf(msg, len,
                        "--inertia: too ill-conditioned for double precision: I11 I22 and I12 I21 "
                        "agree to their rounding, so |I_m| is lost to cancellation (I11 = %.17g, "
                        "I22 = %.17g, I12 = %.17g)",
                        I[0], I[4], I[1]),
               -1;
    const double det = I[0] * I[4] - I[1] * I[3];
    if (!isfinite(det) || !(det >= DBL_MIN))
        return snprintf(msg, len,
                        "--inertia: the determinant of I_m, %.17g * %.17g - %.17g * %.17g, is not "
                        "a finite normal number (entries too large or too small)",
                        I[0], I[4], I[1], I[3]),
               -1;
    return 0;
}

/* I_m (upper-left 2x2 of I) must be symmetric and positive definite, and its determinant, which
 * (ContDyn) divides by, a finite normal number that double precision resolves.
 * Symmetry is tested relative to M = max |I_m entry|, so that nothing overflows (the unscaled
 * sum of |entries| is inf at 1e308, and inf > 4u inf is false); the tolerance 4u (1 + 1 + 1 + 1)
 * allows the rounding of four entries of size <= M. Definiteness is decided on the unscaled
 * products in long double, whose range holds the product of any two doubles (scaled by M, an
 * entry such as 1e-200 next to 1e200 underflowed to 0 and a positive definite I_m was called
 * indefinite). sus_model_init repeats the unscaled tests for the other callers and checks the
 * coefficients it derives. */
int suslov_inertia_check(const double I[9], char *msg, size_t len)
{
    for (int i = 0; i < 9; i++)
        if (!isfinite(I[i]))
            return snprintf(msg, len, "--inertia: entry %d is not finite", i + 1), -1;
    const double M = fmax(fmax(fabs(I[0]), fabs(I[1])), fmax(fabs(I[3]), fabs(I[4])));
    if (M == 0.0)
        return snprintf(msg, len, "--inertia: I_m is zero, not positive definite"), -1;
    const double a = I[0] / M, b = I[1] / M, c = I[3] / M, d = I[4] / M;
    if (fabs(b - c) > 4.0 * DBL_EPSILON * (fabs(a) + fabs(b) + fabs(c) + fabs(d)))
        return snprintf(msg, len, "--inertia: I_m is not symmetric: I12 = %.17g but I21 = %.17g",
                        I[1], I[3]),
               -1;
    return check_definite(I, msg, len);
}
