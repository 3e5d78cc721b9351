/* sus_lab_fit_order (orderfit.c) against GSL's gsl_fit_linear, which it writes out for the
 * browser's build: the same slope and intercept bit for bit on random point sets (the same
 * operations in the same order), and the slope of exact power laws. */
#include "check.h"
#include "orderfit.h"

#include <gsl/gsl_fit.h>
#include <gsl/gsl_rng.h>
#include <math.h>

int main(void)
{
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20261123);
    int differ = 0, sets = 0;
    for (int s = 0; s < 2000; s++) {
        const int n = 3 + (int)gsl_rng_uniform_int(rng, 30);
        double eps[40], err[40], x[40], y[40], a, b, c00, c01, c11, sumsq;
        for (int i = 0; i < n; i++) {
            eps[i] = ldexp(1.0, -i) * (1.0 + 0.1 * gsl_rng_uniform(rng));
            err[i] = pow(eps[i], 1.0 + 4.0 * gsl_rng_uniform(rng)) * (0.5 + gsl_rng_uniform(rng));
            x[i] = log(eps[i]);
            y[i] = log(err[i]);
        }
        sus_lab_order_fit f;
        if (sus_lab_fit_order(eps, err, n, INFINITY, 0.0, &f) != 0) {
            differ++;
            continue;
        }
        gsl_fit_linear(x, 1, y, 1, (size_t)n, &a, &b, &c00, &c01, &c11, &sumsq);
        differ += !(f.slope == b && f.intercept == a);
        sets++;
    }
    CHECK(differ == 0,
          "orderfit's line equals gsl_fit_linear's bit for bit: %d of %d random sets differ",
          differ, sets);
    /* err = 3 eps^p exactly on a log-log line: slope p to round-off in the logs (a few u of
     * |log eps| <= 7, over a spread of log eps of 7): 1e-13. */
    double worst = 0.0;
    for (int p = 1; p <= 10; p++) {
        double eps[11], err[11];
        for (int j = 0; j < 11; j++) {
            eps[j] = ldexp(1.0, -j);
            err[j] = 3.0 * pow(eps[j], p);
        }
        sus_lab_order_fit f;
        const int bad = sus_lab_fit_order(eps, err, 11, INFINITY, 0.0, &f);
        worst = fmax(worst, bad ? INFINITY : fabs(f.slope - p));
    }
    CHECK(worst <= 1e-13, "err = 3 eps^p, p = 1..10: fitted slope within 1e-13 of p; worst %.2e",
          worst);
    gsl_rng_free(rng);
    return check_summary("test_orderfit");
}
