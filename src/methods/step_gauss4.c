/* The 2-stage Gauss-Legendre collocation method (order 4) as a general DSP (Discretization): the
 * stage values W_1, W_2 of (w1, w2) solve
 *   G_i = I_m (W_i - w^k) - eps sum_j a_ij l(W_j) = 0,   l(W) = c(W) (-W_2, W_1) = I_m f(W),
 * (ContDyn) multiplied by I_m as the midpoint DSP's l1, l2 are; then
 *   w^{k+1} = w^k + eps sum_i b_i f(W_i)
 * and lambda_{k+1} = lambda(w^{k+1}) from (LagMult). Four unknowns, one Newton on the 4 x 4
 * system. The attitude is the same collocation applied to the kinematics q' = 1/2 q (x) (0, w) of
 * a quaternion of R (R' = R w^, the reconstruction of (algo) at the method's order): given the
 * stages W_j its stages Q_i = q + eps/2 sum_j a_ij Q_j (x) (0, W_j) are a linear system, solved
 * in quaternion algebra (attitude_step).
 * Gauss collocation conserves every quadratic invariant (Hairer, Lubich & Wanner, Geometric
 * Numerical Integration, Thm. IV.2.1): E = 1/2 <I_m w, w> and |q|. Its stability function is
 * the (2,2) Pade approximant of exp, |R(-h)| < 1 for every h > 0. Tableau: c = 1/2 -+ sqrt(3)/6,
 * A = [[1/4, 1/4 - sqrt(3)/6], [1/4 + sqrt(3)/6, 1/4]], b = (1/2, 1/2). */
#include "newton_core.h"
#include "implicit_step.h"
#include "quaternion.h"

#include <math.h>

#define SQRT3_6 0.28867513459481288225 /* sqrt(3)/6 */
static const double A[2][2] = {{0.25, 0.25 - SQRT3_6}, {0.25 + SQRT3_6, 0.25}};
static const double B[2] = {0.5, 0.5};
static const double C[2] = {0.5 - SQRT3_6, 0.5 + SQRT3_6};

/* l(W) = I_m f(W) of (ContDyn), and its Jacobian dl/dW. */
static void l_of(const sus_model *m, const double W[2], double l[2], double dl[2][2])
{
    const double c = sus_c(m, W), *b = m->b;
    l[0] = -W[1] * c;
    l[1] = W[0] * c;
    dl[0][0] = -W[1] * b[0];
    dl[0][1] = -c - W[1] * b[1];
    dl[1][0] = c + W[0] * b[0];
    dl[1][1] = W[0] * b[1];
}

/* (Discretization) with the collocation l: G(x) for x = (W_1, W_2), its 4 x 4 Jacobian. */
static void gauss4_residual(const sus_model *m, double eps, const double w[2], const double *x,
                            double *g, double *J, double *scale)
{
    const double(*I)[3] = m->I;
    double l[2][2], dl[2][2][2];
    l_of(m, x, l[0], dl[0]);
    l_of(m, x + 2, l[1], dl[1]);
    const double sI = fabs(I[0][0]) + fabs(I[0][1]) + fabs(I[1][0]) + fabs(I[1][1]);
    const double sl = fabs(l[0][0]) + fabs(l[0][1]) + fabs(l[1][0]) + fabs(l[1][1]);
    *scale = 0.0;
    /* every loop unrolled: G and J in straight-line code, inlined into the Newton loop */
#pragma GCC unroll 4
    for (int i = 0; i < 2; i++) {
        const double *W = x + 2 * i, d0 = W[0] - w[0], d1 = W[1] - w[1];
        const double r[2] = {eps * (A[i][0] * l[0][0] + A[i][1] * l[1][0]),
                             eps * (A[i][0] * l[0][1] + A[i][1] * l[1][1])};
        g[2 * i] = I[0][0] * d0 + I[0][1] * d1 - r[0];
        g[2 * i + 1] = I[1][0] * d0 + I[1][1] * d1 - r[1];
#pragma GCC unroll 4
        for (int a = 0; a < 2; a++)
#pragma GCC unroll 4
            for (int j = 0; j < 2; j++)
#pragma GCC unroll 4
                for (int k = 0; k < 2; k++)
                    J[(2 * i + a) * 4 + 2 * j + k] =
                        (i == j ? I[a][k] : 0.0) - eps * A[i][j] * dl[j][a][k];
        /* clang-format off */
        *scale += sI * (fabs(W[0]) + fabs(W[1]) + fabs(w[0]) + fabs(w[1]))
                + eps * (fabs(A[i][0]) + fabs(A[i][1])) * sl;
        /* clang-format on */
    }
}

/* The stages from the explicit midpoint prediction to each node c_i eps. */
static void gauss4_guess(const sus_model *m, double eps, const double w[2], double *x)
{
    newton_predict(m, C[0] * eps, w, x);
    newton_predict(m, C[1] * eps, w, x + 2);
}

static void gauss4_result(const sus_model *m, double eps, const double w[2], const double *x,
                          double w_next[2])
{
    double f0[2], f1[2];
    sus_contdyn(m, x, f0);
    sus_contdyn(m, x + 2, f1);
    w_next[0] = w[0] + eps * (B[0] * f0[0] + B[1] * f1[0]);
    w_next[1] = w[1] + eps * (B[0] * f0[1] + B[1] * f1[1]);
}

/* R(z) = (1 + z/2 + z^2/12) / (1 - z/2 + z^2/12), the (2,2) Pade approximant of exp. */
static double gauss4_stability(double z)
{
    return (1.0 + z / 2.0 + z * z / 12.0) / (1.0 - z / 2.0 + z * z / 12.0);
}

/* The stages x = (W_1, W_2) on the branch continued from eps = 0 (newton.h), w^{k+1} and
 * lambda_{k+1} from them: the Newton loop of newton_core.h with this residual and its 4 x 4 solve
 * inlined. */
static int gauss4_stages(const sus_model *m, double eps, const double w[3], double x[4],
                         double w_next[3], double *lambda_next, sus_stepper_stats *st)
{
    const int status = newton_solve_branch(gauss4_residual, gauss4_guess, 4, m, eps, w, x, st);
    gauss4_result(m, eps, w, x, w_next);
    w_next[2] = 0.0;
    *lambda_next = sus_lagmult(m, w_next);
    return status;
}

static int gauss4_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                        double *lambda_next, sus_stepper_stats *st)
{
    double x[4];
    return gauss4_stages(m, eps, w, x, w_next, lambda_next, st);
}

/* x^{-1} = conj(x) / |x|^2 of a quaternion; -1 where |x|^2 is 0 or not finite. */
static int quat_inverse(const double x[4], double y[4])
{
    const double n = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    if (!(n > 0.0) || !isfinite(n))
        return -1;
    y[0] = x[0] / n;
    for (int i = 1; i < 4; i++)
        y[i] = -x[i] / n;
    return 0;
}

/* The stages Q_i = q + eps/2 sum_j a_ij Q_j (x) v_j, v_j = (0, W_j), are Q_i = q (x) Z_i with
 *   Z_i = 1 + sum_j c_ij Z_j (x) v_j,   c_ij = eps a_ij / 2,
 * a system in two quaternions that q does not enter, so the step is q <- q (x) S with
 *   S = 1 + eps/2 sum_j b_j Z_j (x) v_j.
 * Eliminating Z_2 = (1 + c21 Z_1 v_1) D^{-1}, D = 1 - c22 v_2 (real part 1: never 0), with
 * G = v_2 D^{-1} (v_2 and D commute) leaves
 *   Z_1 (1 - c11 v_1 - c12 c21 v_1 G) = 1 + c12 G.
 * A dozen quaternion products instead of an 8 x 8 elimination: the same collocation, cheaper.
 * The Gauss method keeps |q| (a quadratic invariant), so S is a unit quaternion up to round-off.
 * Returns -1 where the bracket or D is not invertible: never in exact arithmetic, as a Gauss
 * method's stage equations have one solution at every step for a flow that keeps norms (Hairer
 * & Wanner, Solving ODEs II, IV.14). */
static int collocation_increment(double eps, const double x[4], double S[4])
{
    const double c = 0.5 * eps, v1[3] = {x[0], x[1], 0.0}, v2[3] = {x[2], x[3], 0.0};
    const double c12 = c * A[0][1], c21 = c * A[1][0], v1q[4] = {0.0, x[0], x[1], 0.0};
    const double D[4] = {1.0, -c * A[1][1] * v2[0], -c * A[1][1] * v2[1], 0.0};
    double Dinv[4], G[4], v1G[4], X[4], Xinv[4], Y[4], Z1[4], Z1v1[4], Z2[4], Z2v2[4];
    if (quat_inverse(D, Dinv) != 0)
        return -1;
    sus_quat_mul_pure(G, Dinv, v2); /* D^{-1} v_2 = v_2 D^{-1} */
    sus_quat_mul(v1G, v1q, G);
    for (int i = 0; i < 4; i++) {
        X[i] = (i == 0) - c * A[0][0] * v1q[i] - c12 * c21 * v1G[i];
        Y[i] = (i == 0) + c12 * G[i];
    }
    if (quat_inverse(X, Xinv) != 0)
        return -1;
    sus_quat_mul(Z1, Y, Xinv);
    sus_quat_mul_pure(Z1v1, Z1, v1);
    for (int i = 0; i < 4; i++)
        Y[i] = (i == 0) + c21 * Z1v1[i];
    sus_quat_mul(Z2, Y, Dinv);
    sus_quat_mul_pure(Z2v2, Z2, v2);
    for (int i = 0; i < 4; i++)
        S[i] = (i == 0) + c * (B[0] * Z1v1[i] + B[1] * Z2v2[i]);
    return 0;
}

/* q <- q (x) S: the attitude's collocation step given the stages x = (W_1, W_2). */
static int attitude_step(double eps, const double x[4], double q[4])
{
    double S[4], p[4];
    if (collocation_increment(eps, x, S) != 0)
        return -1;
    sus_quat_mul(p, q, S);
    for (int i = 0; i < 4; i++)
        q[i] = p[i];
    return 0;
}

/* The whole step: w by the collocation above, the attitude by the same collocation (whatever
 * reconstruction is asked for: it is the method's own). */
static int gauss4_apply_full(const sus_model *m, double eps, sus_recon recon, sus_attitude *att,
                             const double w[3], double w_next[3], double *lambda_next,
                             sus_stepper_stats *st)
{
    (void)recon;
    double x[4], q[4];
    const int status = gauss4_stages(m, eps, w, x, w_next, lambda_next, st);
    if (status != SUS_STEPPER_OK)
        return status;
    sus_quat_of_attitude(att, q);
    if (attitude_step(eps, x, q) != 0)
        return SUS_STEPPER_SINGULAR;
    sus_quat_to_attitude(q, att);
    return SUS_STEPPER_OK;
}

static const sus_step_equation GAUSS4_EQUATION = {
    .unknowns = 4, .residual = gauss4_residual, .guess = gauss4_guess, .result = gauss4_result};
static const sus_step_ops GAUSS4_STEP = {.apply = gauss4_apply, .apply_full = gauss4_apply_full};

const sus_stepper_type sus_step_gauss4_type = {.name = "gauss4",
                                               .step = &GAUSS4_STEP,
                                               .equation = &GAUSS4_EQUATION,
                                               .desc = {.order = 4,
                                                        .lambda_order = 4,
                                                        .implicit = 1,
                                                        .conserves_energy = 1,
                                                        .attitude = SUS_ATTITUDE_QUAT,
                                                        .substeps = 1,
                                                        .stability = gauss4_stability,
                                                        .source = __FILE__}};
