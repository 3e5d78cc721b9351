#include "exact.h"

#include "api_args.h"

#include <math.h>

int sus_exact_init(sus_exact *ex, const sus_model *m, const double w0[2])
{
    if (!ex)
        return -1;
    if (!sus_args_model_ready(m) || !sus_args_finite2(w0)) {
        *ex = (sus_exact){.model = NULL, .r = NAN, .k = NAN, .w0 = {NAN, NAN}};
        return -1;
    }
    const double(*I)[3] = m->I;
    ex->model = m;
    ex->w0[0] = w0[0];
    ex->w0[1] = w0[1];
    /* l22 = sqrt(|I_m| / I11) and v2 = (I11 I32 - I21 I31) / (l11 sqrt|I_m|), formed without the
     * cancellation of I22 - l21^2 and I32 - l21 v1 on a near-singular I_m */
    const double sd = sqrt(sus_cross_diff(I[0][0], I[1][1], I[1][0], I[1][0]));
    ex->l11 = sqrt(I[0][0]);
    ex->l21 = I[1][0] / ex->l11;
    ex->l22 = sd / ex->l11;
    const double u1 = ex->l11 * w0[0] + ex->l21 * w0[1], u2 = ex->l22 * w0[1];
    const double v1 = m->b[0] / ex->l11;
    const double v2 = sus_cross_diff(I[0][0], m->b[1], I[1][0], m->b[0]) / (ex->l11 * sd);
    const double vn = hypot(v1, v2);
    ex->r = hypot(u1, u2);
    ex->fixed = 0;
    ex->cb = 1.0;
    ex->sb = 0.0;
    ex->k = 0.0;
    ex->sigma = 1.0;
    ex->s0 = 0.0;
    if (ex->r == 0.0 || vn == 0.0) {
        ex->fixed = 1;
        return 0;
    }
    ex->cb = v1 / vn;
    ex->sb = v2 / vn;
    /* C = <v, u> / (|v| r) = c(w0) / (|v| r), as <v, u> = b^T L^{-T} L^T w0: c(w0) = I31 w1 + I32
     * w2 formed to about one rounding of itself (sus_cross_diff), not from the rounded u and v,
     * whose terms cancel near the line c = 0; there s0 = asinh(S / C) takes C's relative error as
     * an absolute one, and a start 1e-14 off the repelling rotation would leave it at a time off by
     * up to u / 1e-14 of 1 / k. */
    const double C = sus_cross_diff(m->b[0], w0[0], -m->b[1], w0[1]) / (vn * ex->r);
    const double S = (ex->cb * u2 - ex->sb * u1) / ex->r;
    if (C == 0.0) { /* an equilibrium: c(w0) = 0 */
        ex->fixed = 1;
        return 0;
    }
    ex->k = ex->r * vn / (ex->l11 * ex->l22);
    ex->sigma = C > 0.0 ? 1.0 : -1.0;
    ex->s0 = asinh(S / C);
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

void sus_exact_omega(const sus_exact *ex, double t, double w[2])
{
    if (!w || refused(ex, w))
        return;
    if (ex->fixed || t == 0.0) {
        w[0] = ex->w0[0];
        w[1] = ex->w0[1];
        return;
    }
    const double s = ex->s0 + ex->sigma * ex->k * t;
    const double e = exp(-fabs(s));
    const double sech = 2.0 * e / (1.0 + e * e);
    omega_from_psi(ex, ex->sigma * sech, ex->sigma * tanh(s), w);
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
