/* Remark 5.5 (RemarkLambda) made explicit: the multiplier lambda_{k+1} = lambda(w^{k+1}) + l_lambda
 * with l_lambda built from the method's local error expansion.
 *
 * (ContDyn) is f(w) = c(w) A w, quadratic, so the exact flow F(eps, w) and the steps of euler,
 * midpoint, rk4 and the variational integrator (taudyn) are power series in eps whose
 * coefficients follow from f by Cauchy products: the flow from y_{n+1} = [t^n] f(y) / (n + 1);
 * an explicit step stage by stage; an implicit one by Picard iteration on the series (each pass
 * fixes one more coefficient). The local error is w^{k+1} - F(eps, w^k) = sum_j e_j eps^j with
 * e_j = 0 for j <= p; l_lambda = -grad lambda(w^{k+1}) . sum_{j=p+1}^{p+n} e_j(w^k) eps^j removes n
 * terms of lambda(w^{k+1}) - lambda(F(eps, w^k)), whose error then starts at eps^{p+n+1} (or at
 * the Hessian term eps^{2p+2}, whichever comes first). */
#ifndef SUS_LAB_LAMBDA_SHIFT_H
#define SUS_LAB_LAMBDA_SHIFT_H

#include "model.h"
#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_LAB_SERIES_N 12 /* coefficients of eps^0 .. eps^11 */

typedef struct {
    double c[2][SUS_LAB_SERIES_N];
} sus_lab_wseries;

/* Taylor coefficients in eps of F(eps, w). */
void sus_lab_series_flow(const sus_model *m, const double w[2], sus_lab_wseries *s);
/* Taylor coefficients in eps of one step of st (euler, midpoint, rk4, variational: the steps whose
 * series is derived). Returns 0, or -1 for another step. */
int sus_lab_series_step(const sus_model *m, const sus_stepper_type *st, const double w[2],
                        sus_lab_wseries *s);
/* sum_j s_j eps^j */
void sus_lab_series_eval(const sus_lab_wseries *s, double eps, double out[2]);
/* grad lambda(w) of (LagMult) (a quadratic form: central differences are exact up to round-off). */
void sus_lab_lagmult_grad(const sus_model *m, const double w[2], double g[2]);
/* l_lambda of RemarkLambda from the local error coefficients e_{p+1} .. e_{p+nterms} at w = w^k,
 * the gradient at x = w^{k+1}. Returns 0, or -1 for a method without a series. */
int sus_lab_lambda_shift(const sus_model *m, const sus_stepper_type *st, int p, int nterms,
                         double eps, const double w[2], const double x[2], double *l_lambda);

#ifdef __cplusplus
}
#endif

#endif
