/* Reference attitude: R(t) with R' = R w^(t), w(t) the solution of (ContDyn), integrated in long
 * double by a Taylor series of order SUS_REFATT_PRECISE_ORDER (the Cauchy-product
 * recursions of (ContDyn) and of the quaternion kinematics q' = 1/2 q (x) (0, w)), with steps of
 * at most 1/SUSLOV_REFATT_PRECISE_STEPS time units. Truncation per step is ~(h/rho)^29 with
 * rho ~ 10.8 the distance of the field's complex singularity from the real axis (below 1e-40);
 * round-off is a few long-double ulps (5.4e-20) per step, so R(t) is good to ~1e-17 for t <= 50,
 * well below double's 1.1e-16, enough to judge errors of 1e-12 and below. Its w(t) agrees
 * with the closed form of exact.h to round-off. It is checked against an independent
 * computation, a long-double fourth-order Magnus integration along the closed-form w(t) with
 * Richardson extrapolation (magnus4.h), in tests/unit/test_highorder.c and in the claims ledger.
 * (GSL's rk8pd at tolerance 1e-13, the earlier reference, is about 1e-13 off at t = 50.) */
#ifndef SUS_REFATTITUDE_H
#define SUS_REFATTITUDE_H

#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_REFATT_PRECISE_ORDER 28
#define SUS_REFATT_PRECISE_STEPS 4

typedef struct {
    const sus_exact *ex;
    double t;
    long double w[2], q[4]; /* w(t) and the attitude as a quaternion (not normalised) */
    double t0, grid;        /* sus_refatt_at: the start, and the whole grid steps taken from it */
} sus_refatt;

/* Starts at t0 with R(t0) = R0 (a rotation) and w(t0) from the closed form. The integration
 * cannot fail and allocates nothing, so there is nothing to check and nothing to free. */
void sus_refatt_init(sus_refatt *ra, const sus_exact *ex, double t0, const double R0[3][3]);
/* Advances to t1 >= the current time and copies R(t1). The steps depend on the times asked
 * for before (each stretch is cut into equal steps). */
void sus_refatt_advance(sus_refatt *ra, double t1, double R[3][3]);
/* R(t1) for t1 at or after the times asked for before: the state is carried only along the
 * grid t0 + j / SUS_REFATT_PRECISE_STEPS, and R(t1) is one more, partial step from the last
 * grid point, not kept. So R(t1) is the same whichever times were asked for before (a row of
 * the exact run does not depend on which rows are written). Not to be mixed with
 * sus_refatt_advance on one sus_refatt. */
void sus_refatt_at(sus_refatt *ra, double t1, double R[3][3]);

/* w(T) and R(T) from w(0) = w0, R(0) = I. */
void sus_refatt_precise(const sus_model *m, const double w0[2], double T, double w[2], double R[3][3]);

/* R(t0)^{-1} R(t1): the exact increment over one step, from the identity. */
void sus_refatt_increment(const sus_exact *ex, double t0, double t1, double Phi[3][3]);

#ifdef __cplusplus
}
#endif

#endif
