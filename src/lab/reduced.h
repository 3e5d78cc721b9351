/* The reduced problem: w(t) is known in closed form (exact.h), so only the attitude is left to
 * integrate, the linear equation q' = 1/2 q (x) (0, w(t)) for a quaternion q (R = R(q/|q|)). make
 * bench gives it to the library integrators, so that they meet our methods that use the closed
 * form on the same structure (y = q, 4 unknowns).
 *
 * w(t) is evaluated cheaply, with one exponential: exact.h writes w = L^{-T} u with
 * u = r Rot(beta) (cos psi, sin psi) and (cos psi, sin psi) = sigma (sech s, tanh s),
 * s = s0 + sigma k t; so w = M (sech s, tanh s) with the fixed matrix M = sigma r L^{-T} Rot(beta),
 * and with E = e^{-|s|}: sech s = 2E / (1 + E^2), tanh s = sign(s) (1 - E^2) / (1 + E^2). Each of
 * E, sech, tanh and the product with M adds a few roundings, so w agrees with sus_exact_omega to a
 * few u |M| (tests/unit/test_peers.c holds it to that). */
#ifndef SUS_LAB_REDUCED_H
#define SUS_LAB_REDUCED_H

#include "exact.h"

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double M[2][2]; /* w = c + M (sech s, tanh s) */
    double c[2];    /* 0; w0 for a motion that stays at w0 (exact.h's fixed), where M = 0 */
    double s0, ks;  /* s = s0 + ks t, ks = sigma k */
} sus_lab_reduced;

/* From a closed form sus_exact_init accepted. Returns 0, or -1 when ex was refused. */
int sus_lab_reduced_init(sus_lab_reduced *r, const sus_exact *ex);

/* w(t), one exponential. */
static inline void sus_lab_reduced_omega(const sus_lab_reduced *r, double t, double w[2])
{
    const double s = r->s0 + r->ks * t, e = exp(-fabs(s)), e2 = e * e, d = 1.0 / (1.0 + e2);
    const double sech = 2.0 * e * d, th = copysign((1.0 - e2) * d, s);
    w[0] = r->c[0] + (r->M[0][0] * sech + r->M[0][1] * th);
    w[1] = r->c[1] + (r->M[1][0] * sech + r->M[1][1] * th);
}

/* The GSL odeiv2 right-hand side of the reduced problem, y = q; params is the sus_lab_reduced. */
int sus_lab_reduced_rhs(double t, const double y[], double f[], void *params);

#ifdef __cplusplus
}
#endif

#endif
