/* Closed-form solution of (ContDyn), used as the reference for w(t) and lambda(t).
 *
 * Derivation. E = 1/2 <I_m w, w> is conserved, so w stays on an ellipse. Let I_m = L L^T
 * (Cholesky, L lower triangular) and u = L^T w, so E = |u|^2 / 2 and |u| = r is constant.
 * (ContDyn) reads I_m w' = c(w) J w with J = [[0,-1],[1,0]] and c(w) = I_3i w_i, hence
 *     u' = c L^{-1} J L^{-T} u = c J u / det L,
 * because A J A^T = det(A) J for any 2x2 A. So u turns on a circle of radius r with angular
 * speed theta' = c / det L. Writing c = <L^{-1} b, u> = r |v| cos(theta - beta) with
 * v = L^{-1} (I31, I32) = |v| (cos beta, sin beta), the angle psi = theta - beta obeys
 *     psi' = k cos psi,   k = r |v| / det L.
 * For cos psi0 > 0: gd^{-1}(psi) = s0 + k t with gd the Gudermannian, so
 *     cos psi = sech s,  sin psi = tanh s,  s = asinh(tan psi0) + k t.
 * For cos psi0 < 0 the same holds for psi - pi with k -> -k. Both branches give
 *     (cos psi, sin psi) = sigma (sech s, tanh s),  s = asinh(S/C) + sigma k t,
 * with (C, S) = (cos psi0, sin psi0) and sigma = sign C. Every motion with C != 0 tends to
 * psi = pi/2: the steady rotation with c(w) = 0 reached at the rate k. Nothing here
 * overflows for any t: sech is evaluated as 2 e^{-|s|} / (1 + e^{-2|s|}).
 *
 * The factor c(w) = I_3i w_i of (ContDyn) and (LagMult) along the motion: c = <b, L^{-T} u> =
 * <v, u> = r |v| cos psi, so
 *     c(t) = sigma r |v| sech s,
 * to a few roundings of itself at every t, where I31 w1 + I32 w2 at the rounded w cancels to
 * about u |b| |w| near the steady rotation (and 1 / |I_m| in (LagMult) multiplies that).
 *
 * A motion whose k underflows is taken as fixed: |psi'| <= k, so w moves by at most
 * |L^{-T}| r k t, and k rounds to 0 only below 2^-1074, so for any double t (< 2^1024) that is
 * below 2^-50 |M|, |M| = r |L^{-T}|: the size of the closed form's own rounding of w. */
#ifndef SUS_EXACT_H
#define SUS_EXACT_H

#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const sus_model *model;
    double l11, l21, l22; /* Cholesky factor of I_m */
    double r;             /* |u| = sqrt(2E) */
    double cb, sb;        /* (cos beta, sin beta) */
    double k;             /* rate of approach to the steady rotation */
    double sigma, s0;
    double cmax; /* r |v|: c(t) = sigma cmax sech s */
    double c0;   /* c(w0) = I31 w1 + I32 w2, to about one rounding */
    /* w(0) is an equilibrium (or w(0) = 0, or I31 = I32 = 0), or k underflows */
    int fixed;
    double w0[2];
} sus_exact;

/* Returns 0, or -1 when ex is NULL, m is not a model sus_model_init filled (or was changed
 * since) or w0 is NULL or not finite; ex is then refused (model NULL) and gives w = NaN. The
 * two below write NaN for a NULL or refused ex, and nothing for a NULL w. */
int sus_exact_init(sus_exact *ex, const sus_model *m, const double w0[2]);
void sus_exact_omega(const sus_exact *ex, double t, double w[2]);
void sus_exact_limit(const sus_exact *ex, double w[2]);
/* c(w(t)) = I31 w1 + I32 w2 along the motion, from the closed form (above): c(w0) at t = 0 and
 * for a fixed motion; NaN for a NULL or refused ex. */
double sus_exact_c(const sus_exact *ex, double t);
/* The largest |lambda| of (LagMult) along the motion (its supremum over t), formed in long double:
 * inf where it passes the largest double (every run refuses that start: api_args.h), |lambda(w0)|
 * for a fixed motion, NaN for a NULL or refused ex. */
double sus_exact_lambda_max(const sus_exact *ex);

#ifdef __cplusplus
}
#endif

#endif
