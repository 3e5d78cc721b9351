#include "inertia_check.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

/* I_m (upper-left 2x2 of I) must be symmetric and positive definite, tested relative to
 * M = max |I_m entry| so that nothing overflows (the unscaled sum of |entries| is inf at
 * 1e308, and inf > 4u inf is false), and its determinant, which (ContDyn) divides by, must
 * be a finite normal number. The tolerance 4u (1 + 1 + 1 + 1) allows the rounding of four
 * entries of size <= M; sus_model_init repeats the unscaled test for the other callers. */
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
        return snprintf(msg, len, "--inertia: I_m is not symmetric: I12 = %.17g but I21 = %.17g", I[1], I[3]),
               -1;
    if (!(a > 0.0) || !(a * d - b * c > 0.0))
        return snprintf(msg, len, "--inertia: I_m is not positive definite (I11 = %.17g, I22 = %.17g, "
                        "I12 = %.17g)", I[0], I[4], I[1]), -1;
    const double det = I[0] * I[4] - I[1] * I[3];
    if (!isfinite(det) || !(det >= DBL_MIN))
        return snprintf(msg, len, "--inertia: the determinant of I_m, %.17g * %.17g - %.17g * %.17g, is not "
                        "a finite normal number (entries too large or too small)", I[0], I[4], I[1], I[3]),
               -1;
    return 0;
}
