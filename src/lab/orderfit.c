#include "orderfit.h"

#include <math.h>

#define ORDERFIT_MAXPTS 64

/* The least-squares line y = a + b x through m points: b = cov(x, y) / var(x), a = mean y - b mean
 * x, with the means and the centred second moments accumulated as running means (each update adds
 * (v - mean) / (i + 1)), the order of operations of GSL's gsl_fit_linear, so that the ledger's
 * slopes keep their bits. Written here, not linked from GSL, because the browser's WebAssembly
 * build of this file (the convergence page) has no GSL. */
static void line_fit(const double *x, const double *y, int m, double *a, double *b)
{
    double mx = 0.0, my = 0.0, sxx = 0.0, sxy = 0.0;
    for (int i = 0; i < m; i++) {
        mx += (x[i] - mx) / (i + 1.0);
        my += (y[i] - my) / (i + 1.0);
    }
    for (int i = 0; i < m; i++) {
        const double dx = x[i] - mx, dy = y[i] - my;
        sxx += (dx * dx - sxx) / (i + 1.0);
        sxy += (dx * dy - sxy) / (i + 1.0);
    }
    *b = sxy / sxx;
    *a = my - mx * *b;
}

int sus_lab_fit_order(const double *eps, const double *err, int n, double eps_max, double floor,
                      sus_lab_order_fit *fit)
{
    double x[ORDERFIT_MAXPTS], y[ORDERFIT_MAXPTS];
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
    line_fit(x, y, m, &fit->intercept, &fit->slope);
    return 0;
}
