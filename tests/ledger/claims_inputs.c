/* The reference attitude against binary128, and the paper's inputs read as exact decimals.
 *
 * The reference R(t) (refattitude.h) solves the problem for the inputs as the doubles that the
 * program reads; its stated accuracy, 2^-51 in every entry, is for those inputs. The paper prints
 * decimals (0.1, 0.2, 0.4), which no double holds. Here (w, q) is integrated afresh in binary128
 * (__float128, u = 2^-112; GCC's software arithmetic) by a Taylor series of the printed
 * (ContDyn) and of q' = 1/2 q (x) (0, w), once from the doubles and once from the decimals
 * formed in binary128 (within 2^-113 relative of the decimals), both to T = 50:
 *   - R(50) from the doubles against the reference: the stated accuracy, max entry <= 2^-51;
 *   - R(50) from the decimals against R(50) from the doubles: the effect of reading the inputs
 *     one way or the other. Theory, before measuring: each rounded input (I12 = I21 = I32 = 0.1,
 *     I31 = 0.2, w01 = 0.4) is off by at most u/2 relative (u = SUS_U = 2^-52, as in every bound of
 *     the ledger); the motion is a rotation by
 *     the angle Theta(T) = int_0^T |w| dt, whose rate depends on each input with a relative
 *     condition of about one (w scales with w0; the rate k and the direction of the limit with
 *     I's entries), so R(T) moves by at most about 5 (u/2) Theta; tolerance 4 u Theta, with Theta
 *     bounded by T |w|max on the energy ellipse, |w|max = sqrt(2 E / lambda_min(I_m)).
 * The series: the field is quadratic, so the coefficients follow by Cauchy products; the nearest
 * singularity of w(t) on the paper's body is ~10.8 time units off the real axis, so at the step
 * 1/4 the tail of QN = 40 terms is below (1/43)^40 ~ 1e-65. */
#include "claims_inputs.h"

#include "ledger.h"
#include "model.h"
#include "refattitude.h"

#include <math.h>

typedef __float128 qreal;

#define QN 40
#define QSTEPS 200 /* steps of 1/4 to T */
#define T_END 50.0
#define HALF_U (SUS_U / 2.0) /* a correctly rounded input's relative error, at most */

typedef struct {
    qreal I11, I12, I21, I22, I31, I32, det;
} qbody;

static qreal qabs(qreal x) { return x < 0 ? -x : x; }

/* sqrt in binary128 without libquadmath: two Newton steps from double's (53 -> 106 -> 113 bits) */
static qreal qsqrt(qreal x)
{
    qreal y = sqrt((double)x);
    for (int i = 0; i < 2; i++)
        y = (y + x / y) / 2;
    return y;
}

/* [t^k] of the field of (ContDyn) for the series w (known through k):
 * w1' = -(I22 w2 + I12 w1) c / det, w2' = (I21 w2 + I11 w1) c / det, c = I31 w1 + I32 w2 */
static void qfield_coeff(const qbody *b, qreal w[2][QN], int k, qreal out[2])
{
    out[0] = out[1] = 0;
    for (int i = 0; i <= k; i++) {
        const qreal c = b->I31 * w[0][i] + b->I32 * w[1][i];
        const int j = k - i;
        out[0] -= c * (b->I22 * w[1][j] + b->I12 * w[0][j]);
        out[1] += c * (b->I21 * w[1][j] + b->I11 * w[0][j]);
    }
    out[0] /= b->det;
    out[1] /= b->det;
}

/* [t^k] of 1/2 q (x) (0, w1, w2, 0) */
static void qkin_coeff(qreal q[4][QN], qreal w[2][QN], int k, qreal out[4])
{
    out[0] = out[1] = out[2] = out[3] = 0;
    for (int i = 0; i <= k; i++) {
        const int j = k - i;
        const qreal a = w[0][j], b = w[1][j];
        out[0] += -q[1][i] * a - q[2][i] * b;
        out[1] += q[0][i] * a - q[3][i] * b;
        out[2] += q[0][i] * b + q[3][i] * a;
        out[3] += q[1][i] * b - q[2][i] * a;
    }
    for (int r = 0; r < 4; r++)
        out[r] /= 2;
}

/* one Taylor step of length h: the state (w, q) replaced by its series summed at h */
static void qstep(const qbody *b, qreal x[6], qreal h)
{
    qreal w[2][QN], q[4][QN];
    for (int r = 0; r < 2; r++)
        w[r][0] = x[r];
    for (int r = 0; r < 4; r++)
        q[r][0] = x[2 + r];
    for (int k = 0; k + 1 < QN; k++) {
        qreal f[2], g[4];
        qfield_coeff(b, w, k, f);
        qkin_coeff(q, w, k, g);
        for (int r = 0; r < 2; r++)
            w[r][k + 1] = f[r] / (k + 1);
        for (int r = 0; r < 4; r++)
            q[r][k + 1] = g[r] / (k + 1);
    }
    for (int r = 0; r < 6; r++) {
        qreal s = 0;
        for (int k = QN - 1; k >= 0; k--)
            s = s * h + (r < 2 ? w[r][k] : q[r - 2][k]);
        x[r] = s;
    }
}

/* R(T) from w(0) = w0, R(0) = I, as the rotation of the unit quaternion */
static void qattitude(const qbody *b, const qreal w0[2], qreal R[3][3])
{
    qreal x[6] = {w0[0], w0[1], 1, 0, 0, 0};
    for (int s = 0; s < QSTEPS; s++)
        qstep(b, x, (qreal)T_END / QSTEPS);
    qreal n = 0;
    for (int r = 2; r < 6; r++)
        n += x[r] * x[r];
    const qreal r = qsqrt(n), a = x[2] / r, i = x[3] / r, j = x[4] / r, k = x[5] / r;
    R[0][0] = 1 - 2 * (j * j + k * k), R[0][1] = 2 * (i * j - a * k), R[0][2] = 2 * (i * k + a * j);
    R[1][0] = 2 * (i * j + a * k), R[1][1] = 1 - 2 * (i * i + k * k), R[1][2] = 2 * (j * k - a * i);
    R[2][0] = 2 * (i * k - a * j), R[2][1] = 2 * (j * k + a * i), R[2][2] = 1 - 2 * (i * i + j * j);
}

static qbody qbody_of(const qreal I[9])
{
    return (qbody){I[0], I[1], I[3], I[4], I[6], I[7], I[0] * I[4] - I[1] * I[3]};
}

/* the largest entry of |A - B|; NaN if any entry is (a run that blew up fails its line) */
static double max_entry_diff(qreal A[3][3], qreal B[3][3])
{
    qreal d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const qreal e = qabs(A[i][j] - B[i][j]);
            d = !(e <= d) ? e : d;
        }
    return (double)d;
}

void inputs_claims(const sus_model *m)
{
    /* the paper's inputs: as the doubles the program reads, and as the decimals it prints */
    qreal I_dbl[9], w_dbl[2], R_dbl[3][3], R_dec[3][3];
    for (int i = 0; i < 9; i++)
        I_dbl[i] = SUS_PAPER_INERTIA[i];
    for (int i = 0; i < 2; i++)
        w_dbl[i] = SUS_PAPER_OMEGA0[i];
    const qreal tenth = (qreal)1 / 10;
    const qreal I_dec[9] = {1, tenth, 2 * tenth, tenth, 1, 2 * tenth, 2 * tenth, tenth, 1};
    const qreal w_dec[2] = {4 * tenth, 5 * tenth};
    for (int i = 0; i < 9; i++)
        if (qabs(I_dec[i] - I_dbl[i]) > HALF_U * qabs(I_dbl[i]))
            ledger_die("the paper's decimals against SUS_PAPER_INERTIA");
    if (I_dec[1] == I_dbl[1] || w_dec[0] == w_dbl[0])
        ledger_die("forming 0.1 and 0.4 in binary128 (they equal the doubles)");
    const qbody b_dbl = qbody_of(I_dbl), b_dec = qbody_of(I_dec);
    qattitude(&b_dbl, w_dbl, R_dbl);
    qattitude(&b_dec, w_dec, R_dec);

    double w_ref[2], R_ref[3][3];
    qreal R_refq[3][3];
    sus_refatt_precise(m, SUS_PAPER_OMEGA0, T_END, w_ref, R_ref);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R_refq[i][j] = R_ref[i][j];
    /* the reference's stated accuracy (refattitude.h), for the inputs as doubles */
    ledger_add("reference-attitude-quad", "(method)",
               "$\\max_{ij} |R_\\mathrm{ref}(50) - R_{128}(50)|_{ij}$: the reference against a "
               "binary128 Taylor integration of \\eqref{ContDyn} and the quaternion, both from the "
               "doubles nearest the paper's inputs; the stated accuracy, $\\le 2^{-51}$",
               max_entry_diff(R_refq, R_dbl), 0.0, 0x1p-51, LEDGER_EXTENSION);
    /* theory's bound (above): 4 u Theta, Theta <= T sqrt(2 E / lambda_min(I_m)) */
    const double a = m->I[0][0], c = m->I[1][1], off = m->I[0][1];
    const double lmin = (a + c) / 2 - hypot((a - c) / 2, off);
    const double theta = T_END * sqrt(2.0 * sus_energy(m, SUS_PAPER_OMEGA0) / lmin);
    ledger_add("reference-inputs-decimal", "(method)",
               "$\\max_{ij} |R_\\mathrm{dec}(50) - R_\\mathrm{dbl}(50)|_{ij}$ in binary128: the "
               "paper's inputs read as exact decimals against the doubles nearest them (each off "
               "by $\\le u/2$ relative, $u = 2^{-52}$); bound $4\\,u\\,\\Theta$, "
               "$\\Theta = T |\\omega|_{\\max}$ the angle turned",
               max_entry_diff(R_dec, R_dbl), 0.0, 4.0 * SUS_U * theta, LEDGER_EXTENSION);
}
