/* The attitude's contract (reconstruct.h), checked directly: the identity attitude is R = I with
 * lo = 0, and its quaternion is the unit quaternion (1, 0, 0, 0), the one a method carrying q
 * starts from. A q off unit length by a relative d is normalised away at the first step, so no
 * row a program prints moves by more than a rounding: it is checked here, where it is exact. */
#include "check.h"
#include "quaternion.h"
#include "reconstruct.h"

#include <math.h>
#include <string.h>

static void identity_checks(void)
{
    sus_attitude a;
    memset(&a, 0x7f, sizeof a); /* no field may keep what was there before */
    sus_attitude_identity(&a);
    double R[3][3], q[4];
    sus_attitude_get(&a, R);
    sus_quat_of_attitude(&a, q);
    int off = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            off += a.hi[i][j] != (i == j) || a.lo[i][j] != 0.0 || R[i][j] != (i == j);
    CHECK(off == 0, "the identity attitude: R = hi + lo = I, lo = 0 exactly (%d entries off)", off);
    CHECK(
        a.has_q && q[0] == 1.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0,
        "the identity attitude's quaternion is (1, 0, 0, 0) exactly: (%.17g, %g, %g, %g), has_q %d",
        q[0], q[1], q[2], q[3], a.has_q);
}

/* R = hi + lo (reconstruct.h): lo holds the compensated sum's low parts. Here each is a few
 * ulps of its hi entry, so that hi + lo and hi - lo are exact and differ: sus_attitude_get must
 * return hi + lo bit for bit. */
static void sum_checks(void)
{
    sus_attitude a;
    sus_attitude_identity(&a);
    a.has_q = 0;
    int off = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            a.hi[i][j] = (i == j) ? 0.75 : 0.5 - 0.25 * j;
            a.lo[i][j] = ldexp(1.0 + i + 3 * j, -52); /* nine different small parts */
        }
    double R[3][3];
    sus_attitude_get(&a, R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            off += R[i][j] != a.hi[i][j] + a.lo[i][j];
    CHECK(off == 0, "R = hi + lo, entry by entry (%d entries off)", off);
}

/* |q|^2 R(q/|q|) in the homogeneous form: a q off unit length gives a matrix off the rotation. */
static void rot_of(const double q[4], double R[3][3])
{
    const double s = q[0], x = q[1], y = q[2], z = q[3];
    const double M[3][3] = {
        {s * s + x * x - y * y - z * z, 2 * (x * y - s * z), 2 * (x * z + s * y)},
        {2 * (x * y + s * z), s * s - x * x + y * y - z * z, 2 * (y * z - s * x)},
        {2 * (x * z - s * y), 2 * (y * z + s * x), s * s - x * x - y * y + z * z}};
    memcpy(R, M, sizeof M);
}

/* tau(xi) by its closed form: (cay) I + 4/(4 + |xi|^2) (X + X^2/2), or Rodrigues for exp, X = xi^.
 */
static void tau_of(sus_recon kind, const double xi[3], double T[3][3])
{
    const double X[3][3] = {{0, -xi[2], xi[1]}, {xi[2], 0, -xi[0]}, {-xi[1], xi[0], 0}};
    const double n2 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2], th = sqrt(n2);
    const double a = kind == SUS_RECON_EXP_MID ? sin(th) / th : 4.0 / (4.0 + n2);
    const double b = kind == SUS_RECON_EXP_MID ? (1.0 - cos(th)) / n2 : 2.0 / (4.0 + n2);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double X2 = X[i][0] * X[0][j] + X[i][1] * X[1][j] + X[i][2] * X[2][j];
            T[i][j] = (i == j) + a * X[i][j] + b * X2;
        }
}

/* (algo), step 3, on a quaternion: R(q_{k+1}) = R(q_k) tau(xi), xi = eps w_k (cayley) or
 * eps (w_k + w_{k+1})/2, for general w (w3 != 0 too) and a general unit q_k. The bound, 1e-13
 * (450 u), is far above the rounding of a few dozen operations on entries of size 1. */
static void quat_step_checks(void)
{
    const double w[3] = {0.3, -0.7, 0.45}, wn[3] = {-0.2, 0.55, 0.1}, eps[2] = {0.1, 1.3};
    for (int k = 0; k < SUS_RECON_COUNT; k++)
        for (int e = 0; e < 2; e++) {
            double q[4] = {0.6, -0.3, 0.5, 0.2}, xi[3], R0[3][3], R1[3][3], T[3][3];
            const double nq = sqrt(0.74);
            for (int i = 0; i < 4; i++)
                q[i] /= nq;
            rot_of(q, R0);
            sus_reconstruct_quat((sus_recon)k, eps[e], q, w, wn);
            rot_of(q, R1);
            for (int i = 0; i < 3; i++)
                xi[i] = k == SUS_RECON_CAYLEY ? eps[e] * w[i] : 0.5 * eps[e] * (w[i] + wn[i]);
            tau_of((sus_recon)k, xi, T);
            double err = 0.0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    const double RT = R0[i][0] * T[0][j] + R0[i][1] * T[1][j] + R0[i][2] * T[2][j];
                    err = fmax(err, fabs(R1[i][j] - RT));
                }
            CHECK(err <= 1e-13, "%s, eps %g: R(q_{k+1}) = R(q_k) tau(xi) to %.1e (bound 1e-13)",
                  SUS_RECON_NAMES[k], eps[e], err);
        }
}

/* --reconstruct NAME: each listed name finds its own kind, and a name not listed none. */
static void name_checks(void)
{
    int found = 0;
    for (int k = 0; k < SUS_RECON_COUNT; k++) {
        sus_recon kind = SUS_RECON_COUNT;
        found += sus_recon_by_name(SUS_RECON_NAMES[k], &kind) == 0 && kind == (sus_recon)k;
    }
    sus_recon kind;
    CHECK(found == SUS_RECON_COUNT && sus_recon_by_name("cayley-end", &kind) == -1,
          "each of the %d reconstruction names finds its kind (%d do), an unlisted name none",
          SUS_RECON_COUNT, found);
}

int main(void)
{
    name_checks();
    quat_step_checks();
    identity_checks();
    sum_checks();
    return check_summary("test_attitude");
}
