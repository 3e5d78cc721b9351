/* Gauss4's step is the two-stage Gauss-Legendre collocation (Hairer, Lubich & Wanner, II.1) of
 * (ContDyn) and, at the same stages, of the quaternion kinematics q' = 1/2 q (x) (0, w) (R' = R w^,
 * the reconstruction equation in continuous time). Here both are solved independently of the
 * step: (ContDyn) written out from the printed entries, the stages by fixed-point iteration in long
 * double, c = 1/2 -+ sqrt(3)/6, a = [1/4, 1/4 - sqrt(3)/6; 1/4 + sqrt(3)/6, 1/4], b = (1/2, 1/2).
 * On every body of the family, from w0 and an attitude away from the identity, at eps = 1/2, 1/8:
 * w^{k+1} and R^{k+1} agree with it to 1e-14 (Newton stops at 16 u of its scale and polishes once;
 * a few u each for the stage sums and the normalised quaternion). A change of the attitude system's
 * coefficients by a relative 1e-6 moves R by about 1e-6 eps^3 |w|^2 |w'|, above that bound. */
#include "check_body.h"
#include "reconstruct.h"
#include "registry.h"

#include <math.h>

extern const sus_stepper_type sus_step_gauss4_type;

typedef long double ld;

/* (ContDyn) from the printed entries, I in rows as printed. */
static void contdyn(const double I[9], const ld w[2], ld f[2])
{
    const ld det = (ld)I[0] * I[4] - (ld)I[1] * I[3], c = (ld)I[6] * w[0] + (ld)I[7] * w[1];
    f[0] = -((ld)I[4] * w[1] + (ld)I[1] * w[0]) * c / det;
    f[1] = ((ld)I[3] * w[1] + (ld)I[0] * w[0]) * c / det;
}

/* p = q (x) (0, v0, v1, 0), Hamilton's product. */
static void mul_pure(const ld q[4], const ld v[2], ld p[4])
{
    p[0] = -q[1] * v[0] - q[2] * v[1];
    p[1] = q[0] * v[0] - q[3] * v[1];
    p[2] = q[0] * v[1] + q[3] * v[0];
    p[3] = q[1] * v[1] - q[2] * v[0];
}

static const ld S36 = 0.28867513459481288225457439025097872782L; /* sqrt(3)/6 */

/* One collocation step from (w, q = 1): w1 and the unit quaternion q1. */
static void collocation(const double I[9], ld eps, const double w0[2], ld w1[2], ld q1[4])
{
    const ld a[2][2] = {{0.25L, 0.25L - S36}, {0.25L + S36, 0.25L}};
    ld W[2][2] = {{w0[0], w0[1]}, {w0[0], w0[1]}}, F[2][2];
    ld Q[2][4] = {{1, 0, 0, 0}, {1, 0, 0, 0}}, P[2][4];
    for (int it = 0; it < 400; it++) {
        contdyn(I, W[0], F[0]);
        contdyn(I, W[1], F[1]);
        mul_pure(Q[0], W[0], P[0]);
        mul_pure(Q[1], W[1], P[1]);
        for (int i = 0; i < 2; i++) {
            for (int k = 0; k < 2; k++)
                W[i][k] = w0[k] + eps * (a[i][0] * F[0][k] + a[i][1] * F[1][k]);
            for (int k = 0; k < 4; k++)
                Q[i][k] = (k == 0) + 0.5L * eps * (a[i][0] * P[0][k] + a[i][1] * P[1][k]);
        }
    }
    contdyn(I, W[0], F[0]);
    contdyn(I, W[1], F[1]);
    mul_pure(Q[0], W[0], P[0]);
    mul_pure(Q[1], W[1], P[1]);
    for (int k = 0; k < 2; k++)
        w1[k] = w0[k] + eps * 0.5L * (F[0][k] + F[1][k]);
    ld n = 0;
    for (int k = 0; k < 4; k++) {
        q1[k] = (k == 0) + 0.25L * eps * (P[0][k] + P[1][k]);
        n += q1[k] * q1[k];
    }
    for (int k = 0; k < 4; k++)
        q1[k] /= sqrtl(n);
}

/* R(q) of a unit quaternion, for R' = R w^ with q' = 1/2 q (x) (0, w). */
static void rotation(const ld q[4], ld R[3][3])
{
    const ld s = q[0], x = q[1], y = q[2], z = q[3];
    const ld R0[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - s * z), 2 * (x * z + s * y)},
                         {2 * (x * y + s * z), 1 - 2 * (x * x + z * z), 2 * (y * z - s * x)},
                         {2 * (x * z - s * y), 2 * (y * z + s * x), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = R0[i][j];
}

/* The attitude the step starts from: a unit quaternion (0.8, 0.1, -0.5, 0.3) / |.| away from
 * the identity, so that the order of the product q (x) dq matters. */
static const double Q0[4] = {0.8040302522073697, 0.10050378152592121, -0.502518907629606,
                             0.30151134457776363};

/* Q0 (x) q, Hamilton's product in long double. */
static void start_times(const ld q[4], ld p[4])
{
    const ld a[4] = {Q0[0], Q0[1], Q0[2], Q0[3]};
    p[0] = a[0] * q[0] - a[1] * q[1] - a[2] * q[2] - a[3] * q[3];
    p[1] = a[0] * q[1] + a[1] * q[0] + a[2] * q[3] - a[3] * q[2];
    p[2] = a[0] * q[2] - a[1] * q[3] + a[2] * q[0] + a[3] * q[1];
    p[3] = a[0] * q[3] + a[1] * q[2] - a[2] * q[1] + a[3] * q[0];
}

/* The largest difference in w and in R over the family at step eps; -1 if a step fails. */
static double worst_at(double eps, double *dR)
{
    double dw = 0.0;
    *dR = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            return -1.0;
        const double w[3] = {b.w0[0], b.w0[1], 0.0};
        double wn[3], lam, R[3][3];
        ld we[2], qe[4], q0e[4], Re[3][3];
        sus_stepper_stats st;
        sus_attitude att;
        sus_quat_to_attitude(Q0, &att);
        const sus_stepper_type *g = &sus_step_gauss4_type;
        if (g->step->apply_full(&m, eps, SUS_RECON_CAYLEY, &att, w, wn, &lam, &st) !=
            SUS_STEPPER_OK)
            return -1.0;
        sus_attitude_get(&att, R);
        collocation(b.I, eps, b.w0, we, qe);
        start_times(qe, q0e);
        rotation(q0e, Re);
        for (int i = 0; i < 2; i++)
            dw = fmax(dw, (double)fabsl(wn[i] - we[i]) / hypot(b.w0[0], b.w0[1]));
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                *dR = fmax(*dR, (double)fabsl(R[i][j] - Re[i][j]));
    }
    return dw;
}

int main(void)
{
    const double steps[2] = {0.5, 0.125};
    for (int i = 0; i < 2; i++) {
        double dR;
        const double dw = worst_at(steps[i], &dR);
        CHECK(dw >= 0.0 && dw <= 1e-14 && dR <= 1e-14,
              "gauss4 at eps = %g is the Gauss-Legendre collocation on %d bodies: "
              "|w - w_col| / |w0| %.2g, |R - R_col| %.2g (each at most 1e-14)",
              steps[i], BODIES_COUNT, dw, dR);
    }
    return check_summary("test_gauss4_collocation");
}
