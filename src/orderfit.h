/* Order of convergence as the least-squares slope of log(error) against log(eps)
 * (gsl_fit_linear), over the points that are neither pre-asymptotic nor at round-off. */
#ifndef SUSLOV_ORDERFIT_H
#define SUSLOV_ORDERFIT_H

typedef struct {
    double slope, intercept;
    int used;               /* points in the fit */
    double eps_lo, eps_hi;  /* the eps range actually fitted */
} suslov_order_fit;

/* Fits the points with eps <= eps_max and floor < err. Returns 0, or -1 when fewer than
 * three points qualify (no honest slope then). */
int suslov_fit_order(const double *eps, const double *err, int n, double eps_max, double floor,
                     suslov_order_fit *fit);

#endif
