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
