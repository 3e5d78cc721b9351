/* Reference attitude: R(t) with R' = R w^(t), w(t) the solution of (ContDyn), integrated in long
 * double by a Taylor series of order SUS_REFATT_ORDER: the Cauchy-product recursions of (ContDyn),
 * in the Cholesky coordinates u = L^T w of exact.h (no cancellation however near-singular I_m
 * is), and of the quaternion kinematics q' = 1/2 q (x) (0, w). Each step starts from u(t) of the
 * closed form in long double (refattitude.c), not from the last step's sum: the motion near the
 * repelling rotation amplifies any error in u by up to 1 / (its distance from it). Past the time
 * t_s where w(t) is the steady rotation w* to within a total angle of 2^-64, R(t) = R(t_s) exp((t -
 * t_s) w*^) in closed form, so any time costs at most the steps to t_s.
 *
 * The step is proved, for every body and start, from the closed form: w(t) is analytic in the
 * strip |Im t| < pi / (2k) and bounded there by what the closed form gives, so Cauchy's estimate
 * bounds every Taylor coefficient of u and of q, and the step of sus_refatt_step keeps the
 * truncated tail of both series below 2^-64 (one long-double rounding) relative to |u| and |q|
 * at every step (refattitude.c derives it). The step is one number for the whole motion (k, |u|
 * and L are invariants): both it and t_s scale as 1 / |w0| and 1 / k, so the number of steps to
 * the tail depends on neither (sus_exact_reference_steps).
 *
 * Accuracy, for the inputs as the doubles they are: each step adds its truncation and a few
 * long-double roundings (2^-64 each) to q, and rotations carry an error on unchanged; the tail's
 * speed |w*| and angle are formed in 113-bit arithmetic, so its error does not grow with t while
 * the angle (t - t_s) |w*| is below about 2^60 (its rounding is 2^-53 there). Before its one
 * rounding to double, R(t) is within about 10 * 2^-64 per step to the tail plus a few 2^-64: the
 * stated accuracy is 2^-51 in every entry, at every t with that angle below 2^60, for up to a
 * thousand steps to the tail (sus_exact_reference_steps). tests/unit/test_highorder.c checks it
 * against an independent long-double Magnus integration along the closed-form w(t) on every test
 * body, stiff ones included. */
#ifndef SUS_REFATTITUDE_H
#define SUS_REFATTITUDE_H

#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_REFATT_ORDER 28

/* The Cholesky coordinates of exact.h in long double: L = [[l11, 0], [l21, l22]], v = L^{-1} b,
 * g = 1 / |L|. */
typedef struct {
    long double l11, l21, l22, v[2], g;
} sus_refatt_chol;

/* The closed form of exact.h in long double, u(t) = L^T w(t) = r Rot(beta) sigma (sech s, tanh s),
 * s = s0 + sigma k t; fixed: an equilibrium, u = u0. */
typedef struct {
    long double r, cb, sb, k, s0, sigma, u0[2];
    int fixed;
} sus_refatt_closed;

typedef struct {
    const sus_exact *ex;
    sus_refatt_chol chol;
    sus_refatt_closed closed; /* u at every grid point, where each step starts */
    long double h;            /* the proved step, sus_refatt_step */
    double rho, W; /* its disc: the n-th scaled terms of a step h' <= h are within W (h' / rho)^n */
    double t;
    long double u[2], q[4]; /* u = L^T w(t) and the attitude as a quaternion (not normalised) */
    double t0, grid;        /* sus_refatt_at: the start, and the whole grid steps taken from it */
    double t_s;             /* the steady tail from here on (refattitude.c) */
    long double axis[2];    /* the steady rotation w*: its axis (third entry 0) */
    long double speed[2];   /* and |w*| to 128 bits, hi + lo */
    long double q_s[4];     /* q(t_s), once steady */
    int steady;
} sus_refatt;

/* The step of the reference for the motion of ex: the largest of a grid of candidates whose
 * truncation bound (refattitude.c) holds; positive for every motion (infinite for w = 0, which
 * needs no step). */
long double sus_refatt_step(const sus_exact *ex);

/* Starts at t0 with R(t0) = R0 (a rotation) and w(t0) from the closed form. The integration
 * cannot fail and allocates nothing, so there is nothing to check and nothing to free. */
void sus_refatt_init(sus_refatt *ra, const sus_exact *ex, double t0, const double R0[3][3]);
/* Advances to t1 >= the current time and copies R(t1). The steps depend on the times asked
 * for before (each stretch is cut into equal steps of at most h). */
void sus_refatt_advance(sus_refatt *ra, double t1, double R[3][3]);
/* R(t1) for t1 at or after the times asked for before: the state is carried only along the
 * grid t0 + j h, and R(t1) is one more, partial step from the last grid point, not kept. So R(t1)
 * is the same whichever times were asked for before (a row of the exact run does not depend on
 * which rows are written). Not to be mixed with sus_refatt_advance on one sus_refatt. */
void sus_refatt_at(sus_refatt *ra, double t1, double R[3][3]);

/* w(T) and R(T) from w(0) = w0, R(0) = I. */
void sus_refatt_precise(const sus_model *m, const double w0[2], double T, double w[2],
                        double R[3][3]);

/* R(t0)^{-1} R(t1): the exact increment over one step, from the identity. */
void sus_refatt_increment(const sus_exact *ex, double t0, double t1, double Phi[3][3]);

#ifdef __cplusplus
}
#endif

#endif
