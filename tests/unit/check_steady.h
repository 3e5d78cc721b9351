/* An independent steady rotation for the unit tests: R exp((T - t_s) w*^) with w* derived from I_m
 * and b (not from the code under test) and its angle in 113 bits, so that the check's own error
 * does not grow with T. */
#ifndef SUSLOV_CHECK_STEADY_H
#define SUSLOV_CHECK_STEADY_H

#include "exact.h"
#include "model.h"

#include <math.h>

/* The steady rotation's angle in 113 bits (__float128 where long double is shorter, as
 * refattitude.c), so that this reference's own error does not grow with T as a long double's
 * would (2^-64 T |w*|, and the quadratic forms' cancellation on a near-singular I_m besides). */
#if defined(__SIZEOF_FLOAT128__) && __LDBL_MANT_DIG__ < 113
typedef __float128 quad;
#else
typedef long double quad;
#endif

/* x^T I_m x, x = (x, y), in 113 bits. */
static inline quad quad_form(const sus_model *m, quad x, quad y)
{
    return x * (m->I[0][0] * x + m->I[0][1] * y) + y * (m->I[1][0] * x + m->I[1][1] * y);
}

/* sqrt in 113 bits: one Newton step from the long-double root. */
static inline quad sqrt_q(quad x)
{
    const long double y = sqrtl((long double)x);
    return y > 0.0L ? ((quad)y + x / y) / 2 : (quad)y;
}

/* Rs exp((T - t_s) w*^), the steady rotation from (t_s, Rs): w* on the line c(w) = 0 at the energy
 * E0 (the attracting steady rotation), on the side the closed form approaches, derived here from
 * I_m and b, not from the method's w_inf; the angle reduced modulo 2 pi in 113 bits. */
static inline void steady_far(const sus_model *m, const sus_exact *ex, const double Rs[3][3],
                              double t_s, double T, double R[3][3])
{
    double winf[2];
    sus_exact_limit(ex, winf);
    const quad v0 = -(quad)m->b[1], v1 = m->b[0];
    const quad e0 = quad_form(m, ex->w0[0], ex->w0[1]), ev = quad_form(m, v0, v1);
    const quad g = sqrt_q(e0 / ev) * (v0 * winf[0] + v1 * winf[1] >= 0 ? 1 : -1);
    const quad n = sqrt_q(g * g * (v0 * v0 + v1 * v1));
    const quad two_pi = (quad)6.283185307179586 + (quad)2.4492935982947064e-16 -
                        (quad)5.989539619436679e-33; /* 2 pi to 160 bits */
    quad th = ((quad)T - t_s) * n;
    th -= two_pi * (quad)floorl((long double)(th / two_pi));
    const long double c = cosl((long double)th), s = sinl((long double)th),
                      x = (long double)(g * v0 / n), y = (long double)(g * v1 / n);
    /* Rodrigues: exp(th n^) = I + sin th n^ + (1 - cos th) n^2, n = (x, y, 0) */
    const long double E[3][3] = {{c + (1 - c) * x * x, (1 - c) * x * y, s * y},
                                 {(1 - c) * x * y, c + (1 - c) * y * y, -s * x},
                                 {-s * y, s * x, c}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = (double)(Rs[i][0] * E[0][j] + Rs[i][1] * E[1][j] + Rs[i][2] * E[2][j]);
}

#endif
