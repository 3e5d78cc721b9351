#include "model.h"

#include <math.h>
#include <stdio.h>

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

int sus_model_init(sus_model *m, const double I[9], char *err, size_t errlen)
{
    if (!err)
        errlen = 0;
    if (!m || !I) {
        snprintf(err, errlen, "%s is NULL", m ? "the inertia" : "the model");
        return -1;
    }
    for (int i = 0; i < 9; i++) {
        if (!isfinite(I[i])) {
            snprintf(err, errlen, "inertia entry %d is not finite", i + 1);
            return -1;
        }
        m->I[i / 3][i % 3] = I[i];
    }
    const double scale = fabs(I[0]) + fabs(I[1]) + fabs(I[3]) + fabs(I[4]);
    /* I_m must be symmetric for E to be conserved by (ContDyn); allow only round-off. */
    if (fabs(I[1] - I[3]) > 4.0 * SUS_U * scale) {
        snprintf(err, errlen, "I_m is not symmetric: I12 = %.17g but I21 = %.17g", I[1], I[3]);
        return -1;
    }
    m->det_m = sus_cross_diff(I[0], I[4], I[1], I[3]);
    if (!(I[0] > 0.0) || !(m->det_m > 0.0)) {
        snprintf(err, errlen,
                 "I_m is not positive definite (I11 = %.17g, I22 = %.17g, I12 = %.17g)", I[0], I[4],
                 I[1]);
        return -1;
    }
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

/* E(w) = 1/2 <I_m w, w>; the paper's displayed E_l drops the 1/2 (a factor-2 slip). */
double sus_energy(const sus_model *m, const double w[2])
{
    if (!m || !w)
        return NAN;
    const double(*I)[3] = m->I;
    const double e2 =
        w[0] * (I[0][0] * w[0] + I[0][1] * w[1]) + w[1] * (I[1][0] * w[0] + I[1][1] * w[1]);
    return 0.5 * e2;
}
