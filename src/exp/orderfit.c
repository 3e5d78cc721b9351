#include "orderfit.h"

#include <gsl/gsl_fit.h>
#include <math.h>

#define ORDERFIT_MAXPTS 64

int sus_exp_fit_order(const double *eps, const double *err, int n, double eps_max, double floor,
                     sus_exp_order_fit *fit)
{
    double x[ORDERFIT_MAXPTS], y[ORDERFIT_MAXPTS], c00, c01, c11, sumsq;
    int m = 0;
    fit->eps_lo = INFINITY;
    fit->eps_hi = 0.0;
    fit->used = 0;
    fit->slope = fit->intercept = NAN;
    for (int i = 0; i < n && m < ORDERFIT_MAXPTS; i++) {
        if (!(eps[i] <= eps_max))
            continue;
        if (!isfinite(err[i])) /* a failed or blown-up run inside the window: no honest slope */
            return -1;
        if (!(err[i] > floor))
            continue;
        x[m] = log(eps[i]);
        y[m] = log(err[i]);
        fit->eps_lo = fmin(fit->eps_lo, eps[i]);
        fit->eps_hi = fmax(fit->eps_hi, eps[i]);
        m++;
    }
    fit->used = m;
    if (m < 3)
        return -1;
    gsl_fit_linear(x, 1, y, 1, (size_t)m, &fit->intercept, &fit->slope, &c00, &c01, &c11, &sumsq);
    return 0;
}
