/* Order of convergence as the least-squares slope of log(error) against log(eps)
 * (GSL's gsl_fit_linear, written out in orderfit.c for the browser's build), over the points
 * that are neither pre-asymptotic nor at round-off. */
#ifndef SUS_LAB_ORDERFIT_H
#define SUS_LAB_ORDERFIT_H

#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The fit window used by the claims ledger and the convergence figure alike.
 * eps <= 2^-2 keeps k eps <= 0.036 (k = 0.145 is the rate of the paper's motion), so the next
 * term of the error expansion bends the log-log line by a few percent at most. Points below a
 * thousand times the round-off of the quantity itself (u times its size: |w| <= 0.8,
 * |lambda| <= 0.04, entries of R <= 1) are left out, so that round-off moves no fitted point by
 * more than 0.1%. */
#define SUS_LAB_FIT_EPS_MAX 0.25
#define SUS_LAB_FIT_FLOOR_REL (1000.0 * SUS_U)
#define SUS_LAB_SIZE_W 0.8
#define SUS_LAB_SIZE_LAMBDA 0.04
#define SUS_LAB_SIZE_R 1.0

typedef struct {
    double slope, intercept;
    int used;              /* points in the fit */
    double eps_lo, eps_hi; /* the eps range actually fitted */
} sus_lab_order_fit;

/* Fits the points with eps <= eps_max and floor < err. Returns 0, or -1 when fewer than
 * three points qualify or a point inside the window is not finite (no honest slope then). */
int sus_lab_fit_order(const double *eps, const double *err, int n, double eps_max, double floor,
                      sus_lab_order_fit *fit);

#ifdef __cplusplus
}
#endif

#endif
