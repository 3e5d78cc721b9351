/* steady_turn.h's speed |w_inf|, in double-double, against the same quantity in 113 bits
 * (check_steady.h, derived from I_m and b, not from the code under test), on the family of
 * bodies.h, with w0 also scaled by 2^-600 and 2^600 (the speed is homogeneous of degree 1 in w0,
 * so the scaled one is exactly 2^s times the unscaled; the quadratic forms, unscaled, would leave
 * the range of doubles), and from the steady rotation w_inf rounded to doubles (|w0| itself where
 * the closed form takes that start as one that stays).
 * The bound: SPEED_ROUND 2^-104 rho |w_inf|, rho the size of the quadratic forms' terms over their
 * values at w0 and at d = (-I32, I31) (steady_turn.h: a few double-double roundings, each 2^-104
 * of the terms), plus the 113-bit check's own 2^-110 or so. A speed in one double is off by up to
 * 2^-53 relative: 2^51 times that allowance, and a dropped low part fails it as surely. */
#include "check_body.h"
#include "check_steady.h"
#include "steady_turn.h"

#include <math.h>

#define SPEED_ROUND 16.0

/* (|x^T I_m x|'s terms) / |x^T I_m x| at x, >= 1. */
static double form_ratio(const sus_model *m, const double x[2])
{
    const double a = fabs(m->I[0][0] * x[0] * x[0]), b = fabs(2.0 * m->I[1][0] * x[0] * x[1]),
                 c = fabs(m->I[1][1] * x[1] * x[1]);
    return fmax(1.0, (a + b + c) / fabs((double)quad_form(m, x[0], x[1])));
}

/* |w*| in 113 bits: |d| sqrt(E0 / E(d)), or |w0| for a motion that stays. */
static quad speed_q(const sus_model *m, const double w0[2], int fixed)
{
    const quad v0 = fixed ? w0[0] : -m->b[1], v1 = fixed ? w0[1] : m->b[0];
    const quad nv = v0 * v0 + v1 * v1;
    return fixed ? sqrt_q(nv) : sqrt_q(quad_form(m, w0[0], w0[1]) * nv / quad_form(m, v0, v1));
}

/* The error of sus_steady_speed in units of its bound for the motion from w0 * 2^s. */
static double speed_error(const sus_model *m, const double w0[2], int s)
{
    const double w[2] = {ldexp(w0[0], s), ldexp(w0[1], s)}, d[2] = {-m->b[1], m->b[0]};
    sus_exact ex;
    double sp[2];
    if (sus_exact_init(&ex, m, w) != 0)
        return INFINITY;
    sus_steady_speed(&ex, sp);
    const quad want = speed_q(m, w0, ex.fixed) * (quad)ldexp(1.0, s); /* 2^s: exact */
    const double rho = fmax(form_ratio(m, w0), ex.fixed ? 1.0 : form_ratio(m, d));
    const quad err = ((quad)sp[0] + sp[1]) - want;
    return fabs((double)(err / want)) / (SPEED_ROUND * 0x1p-104 * rho);
}

int main(void)
{
    static const int SCALES[3] = {0, -600, 600};
    double worst = 0.0, worst_fixed = 0.0;
    int n = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        double winf[2];
        sus_exact_limit(&ex, winf);
        for (int i = 0; i < 3; i++) {
            worst = fmax(worst, speed_error(&m, b.w0, SCALES[i]));
            worst_fixed = fmax(worst_fixed, speed_error(&m, winf, SCALES[i]));
            n++;
        }
    }
    CHECK(n == 3 * BODIES_COUNT && worst <= 1.0,
          "sus_steady_speed on %d bodies, w0 scaled by 1, 2^-600, 2^600: |w_inf| within "
          "%g 2^-104 rho of the 113-bit value: worst %.3g of that (at most 1)",
          BODIES_COUNT, SPEED_ROUND, worst);
    CHECK(worst_fixed <= 1.0,
          "and from the steady rotation rounded to doubles (scaled alike): worst %.3g of the "
          "bound (at most 1)",
          worst_fixed);
    return check_summary("test_steady_turn");
}
