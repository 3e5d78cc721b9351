#include "so3.h"
#include "mat3.h"

/* (Isom): w -> w^, so that w^ v = w x v. */
void sus_so3_hat(const double w[3], double W[3][3])
{
    W[0][0] = 0.0;
    W[0][1] = -w[2];
    W[0][2] = w[1];
    W[1][0] = w[2];
    W[1][1] = 0.0;
    W[1][2] = -w[0];
    W[2][0] = -w[1];
    W[2][1] = w[0];
    W[2][2] = 0.0;
}

/* Inverse of (Isom) on the skew part, so a matrix that is skew only up to round-off
 * still gives the nearest vector. */
void sus_so3_vee(const double W[3][3], double w[3])
{
    w[0] = 0.5 * (W[2][1] - W[1][2]);
    w[1] = 0.5 * (W[0][2] - W[2][0]);
    w[2] = 0.5 * (W[1][0] - W[0][1]);
}

/* (caypart) without its leading I: cay(w^) - I = (w^ + w^2/2) / (1 + |w/2|^2). Small for
 * small w, so it can be accumulated without losing its low-order bits against I. */
void sus_so3_cay_minus_identity(const double w[3], double D[3][3])
{
    double W[3][3], W2[3][3];
    sus_so3_hat(w, W);
    sus_mat3_mul(W2, W, W);
    const double a = 1.0 / (1.0 + 0.25 * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[i][j] = a * (W[i][j] + 0.5 * W2[i][j]);
}

/* (caypart): cay(w^) = I + (w^ + w^2/2) / (1 + |w/2|^2). */
void sus_so3_cay(const double w[3], double R[3][3])
{
    sus_so3_cay_minus_identity(w, R);
    for (int i = 0; i < 3; i++)
        R[i][i] += 1.0;
}

/* Inverse of (caypart): w = 2 vee(R - R^T) / (1 + tr R), valid away from tr R = -1
 * (rotations by pi, where the Cayley chart ends). */
void sus_so3_cay_inv(const double R[3][3], double w[3])
{
    const double s = 2.0 / (1.0 + R[0][0] + R[1][1] + R[2][2]);
    w[0] = s * (R[2][1] - R[1][2]);
    w[1] = s * (R[0][2] - R[2][0]);
    w[2] = s * (R[1][0] - R[0][1]);
}

/* dcay_w = (I + w^/2) / (1 + |w/2|^2), the formula after (caypart). */
void sus_so3_dcay(const double w[3], double D[3][3])
{
    double W[3][3];
    sus_so3_hat(w, W);
    const double a = 1.0 / (1.0 + 0.25 * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[i][j] = a * ((i == j) + 0.5 * W[i][j]);
}

/* dcay_w^{-1} = I - w^/2 + w w^T / 4, the formula after (caypart). */
void sus_so3_dcay_inv(const double w[3], double D[3][3])
{
    double W[3][3];
    sus_so3_hat(w, W);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[i][j] = (i == j) - 0.5 * W[i][j] + 0.25 * w[i] * w[j];
}

/* (cayinver): dcay^{-1}_{eps w} for w_3 = 0, entry by entry as printed. Note the printed
 * (3,3) entry is 0, whereas sus_so3_dcay_inv gives 1 there; tests and the claims ledger
 * measure what that single entry does to (taualg). */
void sus_so3_cayinver_printed(double eps, const double w[2], double D[3][3])
{
    const double e2 = 0.25 * eps * eps, e1 = 0.5 * eps;
    D[0][0] = 1.0 + e2 * w[0] * w[0];
    D[0][1] = e2 * w[0] * w[1];
    D[0][2] = -e1 * w[1];
    D[1][0] = e2 * w[0] * w[1];
    D[1][1] = 1.0 + e2 * w[1] * w[1];
    D[1][2] = e1 * w[0];
    D[2][0] = e1 * w[1];
    D[2][1] = -e1 * w[0];
    D[2][2] = 0.0;
}

/* Rodrigues' formula without its leading I: exp(w^) - I = a w^ + b w^2 with a = sin t / t and
 * b = (1 - cos t)/t^2 = (sin(t/2)/(t/2))^2 / 2, t = |w|. The half-angle form has no cancellation,
 * so a and b keep full relative accuracy at every angle (1 - cos t loses them all near t = 0),
 * and the result, small for small w, can be accumulated against I like the Cayley increment.
 * sinc t = sin t / t comes from so3_trig.c, not the C library, so that every build gets the same
 * bits. */
void sus_so3_exp_minus_identity(const double w[3], double D[3][3])
{
    double W[3][3], W2[3][3];
    sus_so3_hat(w, W);
    sus_mat3_mul(W2, W, W);
    const double th = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double s = sus_so3_sinc(0.5 * th), a = sus_so3_sinc(th), b = 0.5 * s * s;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            D[i][j] = a * W[i][j] + b * W2[i][j];
}

/* Rodrigues' formula for exp(w^). */
void sus_so3_exp(const double w[3], double R[3][3])
{
    sus_so3_exp_minus_identity(w, R);
    for (int i = 0; i < 3; i++)
        R[i][i] += 1.0;
}

/* (MetMat): dist(R1, R2) = |I - R1 R2^T| in the Frobenius norm. */
double sus_so3_dist(const double R1[3][3], const double R2[3][3])
{
    double P[3][3];
    sus_mat3_mul_bt(P, R1, R2);
    for (int i = 0; i < 3; i++)
        P[i][i] -= 1.0;
    return sus_mat3_frobenius(P);
}

/* (Groudist): |R^T R - I| (= |I - R R^T| for square R), how far a matrix is from the group. */
double sus_so3_orth_defect(const double R[3][3])
{
    double P[3][3];
    sus_mat3_mul_at(P, R, R);
    for (int i = 0; i < 3; i++)
        P[i][i] -= 1.0;
    return sus_mat3_frobenius(P);
}
