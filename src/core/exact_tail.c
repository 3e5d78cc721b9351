#include "exact_tail.h"

#include <math.h>

/* 2 |L^{-1}|_F r / k: the bound at a = 0 (exact_tail.h). */
static double scale(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    return 2.0 * sqrt(a * a + b * b + c * c) * ex->r / ex->k;
}

double sus_exact_tail_bound(const sus_exact *ex, double t)
{
    if (!ex || !ex->model)
        return NAN;
    if (ex->fixed)
        return 0.0;
    return scale(ex) * exp(-(ex->sigma * ex->s0 + ex->k * t));
}

double sus_exact_tail_time(const sus_exact *ex, double budget)
{
    if (!ex || !ex->model || !(budget > 0.0))
        return NAN;
    if (ex->fixed)
        return -INFINITY;
    return (log(scale(ex) / budget) - ex->sigma * ex->s0) / ex->k;
}

int sus_exact_tail_bounds(const sus_exact *ex, double t, double *dev, double *integral)
{
    if (!ex || !ex->model) {
        *dev = *integral = NAN;
        return -1;
    }
    if (ex->fixed) {
        *dev = *integral = 0.0;
        return 0;
    }
    /* L^{-T} = [1 / l11, -l21 / d; 0, 1 / l22], d = l11 l22 */
    const double d = ex->l11 * ex->l22, cb = ex->cb, sb = ex->sb;
    const double t1 = hypot(cb / ex->l11 - ex->l21 * sb / d, sb / ex->l22);
    const double t2 = hypot(-sb / ex->l11 - ex->l21 * cb / d, cb / ex->l22);
    const double a = ex->sigma * ex->s0 + ex->k * t, e = exp(-fabs(a));
    const double sech_max = a >= 0.0 ? 2.0 * e / (1.0 + e * e) : 1.0;
    const double one_m_tanh = 2.0 / (1.0 + exp(2.0 * a)); /* 1 - tanh a, for every a */
    const double int_sech = 2.0 * atan(exp(-a));
    const double int_tanh = a >= 0.0 ? log1p(e * e) : -2.0 * a + log1p(e * e); /* ln(1 + e^{-2a}) */
    *dev = ex->r * (sech_max * t1 + one_m_tanh * t2);
    *integral = ex->r * (int_sech * t1 + int_tanh * t2) / ex->k;
    return 0;
}
