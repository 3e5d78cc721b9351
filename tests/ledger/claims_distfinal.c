/* (DistFinal) printed and restored, on the paper's body and the general ones (claims_bodies.h).
 *
 * The proof of TeoL expands R(t_k + eps) = R(t_k) + eps Ad_{R(t_k)} w^(t_k) + O(eps^2) and says the
 * terms linear in eps of |I - R(t_k + eps) R_{k+1}^T| cancel. The sentence after the display gives
 * R' = (Ad_R w^) R = R w^, so the first-order term is eps R w^ (Ad_R w^ = R w^ R^T). Theory before
 * measuring: with the printed term the linear terms leave eps R w^ R^T (I - R^T), an O(eps)
 * residual (slope 1) wherever R(t_k) != I; with the restored one they cancel and the residual is
 * eps^2 R w^2 R^T / 2 + O(eps^3) (slope 2). Both are measured on the exact motion: R(t_k) from the
 * long-double reference attitude, w(t_k) from the closed form. */
#include "claims_distfinal.h"

#include "claims_bodies.h"
#include "ledger.h"
#include "mat3.h"
#include "orderfit.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>
#include <stdio.h>

#define NJ 11 /* eps = 2^-j on the paper's body, j = 0 .. 10 */
/* The window: the next term of each residual is about eps (|w| + |w'| / |w|) times the leading one,
 * and |w'| / |w| is of the size of the rate k (ContDyn), so on the paper's body (|w| <= 1, k 0.15)
 * eps <= 2^-4 bends a slope by at most 0.06, below the tenth of an order that tells 1 from 2. Every
 * body is measured at the same eps s, s = max(|w|, k) along its motion, as the paper's at
 * eps = 2^-j: eps = 2^-j s_paper / s (the largest s eps_max is printed with the line). */
#define DF_EPS_MAX 0.0625
#define ORDER_TOL 0.1

/* the starts t_k k: the transient, away from t = 0 where R = I and both forms agree */
static const double TK_RATE[] = {0.45, 1.0, 1.75, 2.9};
#define NTK ((int)(sizeof TK_RATE / sizeof TK_RATE[0]))

typedef struct {
    double exp_printed[NJ], exp_restored[NJ]; /* |R(t_k+eps) - R - eps X| */
    double lin_printed[NJ], lin_restored[NJ]; /* |I - (R + eps X)(I - eps w^ + eps^2 w^2/2) R^T| */
} distfinal_data;

static void axpy3(double C[3][3], const double A[3][3], double s, const double B[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = A[i][j] + s * B[i][j];
}

/* |I - (R + eps X) C R^T| with C = I - eps W + eps^2 W^2 / 2, the truncated cay(eps w^)^T. */
static double product_residual(const double R[3][3], const double X[3][3], const double W[3][3],
                               double eps)
{
    double W2[3][3], C[3][3], I3[3][3], A[3][3], AC[3][3], P[3][3];
    sus_mat3_identity(I3);
    sus_mat3_mul(W2, W, W);
    axpy3(C, I3, -eps, W);
    axpy3(C, C, 0.5 * eps * eps, W2);
    axpy3(A, R, eps, X);
    sus_mat3_mul(AC, A, C);
    sus_mat3_mul_bt(P, AC, R);
    return sus_mat3_dist(I3, P);
}

/* One start of one body: both forms of the first-order term at every eps = 2^-j scale. */
static void distfinal_start(const sus_exact *ex, double tk, double scale, distfinal_data *d)
{
    double Rk[3][3], I3[3][3], w[3] = {0.0, 0.0, 0.0}, W[3][3], RW[3][3], Ad[3][3];
    sus_refatt ra;
    sus_mat3_identity(I3);
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, tk, Rk);
    sus_exact_omega(ex, tk, w);
    sus_so3_hat(w, W);
    sus_mat3_mul(RW, Rk, W);     /* restored: (Ad_R w^) R = R w^ */
    sus_mat3_mul_bt(Ad, RW, Rk); /* printed: Ad_R w^ = R w^ R^T */
    for (int j = 0; j < NJ; j++) {
        const double eps = ldexp(1.0, -j) * scale;
        double Phi[3][3], Rx[3][3], Ep[3][3], Er[3][3];
        sus_refatt_increment(ex, tk, tk + eps, Phi);
        sus_mat3_mul(Rx, Rk, Phi); /* R(t_k + eps) */
        axpy3(Ep, Rk, eps, Ad);
        axpy3(Er, Rk, eps, RW);
        d->exp_printed[j] = fmax(d->exp_printed[j], sus_mat3_dist(Rx, Ep));
        d->exp_restored[j] = fmax(d->exp_restored[j], sus_mat3_dist(Rx, Er));
        d->lin_printed[j] = fmax(d->lin_printed[j], product_residual(Rk, Ad, W, eps));
        d->lin_restored[j] = fmax(d->lin_restored[j], product_residual(Rk, RW, W, eps));
    }
}

/* The slope over the window. */
static double slope_of(const double *err)
{
    double e[NJ];
    sus_lab_order_fit f;
    for (int j = 0; j < NJ; j++)
        e[j] = ldexp(1.0, -j);
    return sus_lab_fit_order(e, err, NJ, DF_EPS_MAX, SUS_LAB_FIT_FLOOR_REL * SUS_LAB_SIZE_R, &f) ==
                   0
               ? f.slope
               : NAN;
}

static void distfinal_line(const char *id, const char *ref, const char *what, const double *err,
                           double expected, double s_paper, ledger_assert truth)
{
    char q[640];
    snprintf(
        q, sizeof q,
        "%s; max over %d bodies and $t_k k$ from 0.45 to 2.9, each at $\\varepsilon = 2^{-j} "
        "s_\\mathrm{paper}/s$, $s = \\max(|\\omega|, k)$ on its motion; fit over $j \\in [4, 10]$, "
        "errors above $1000\\,u$; $s \\varepsilon \\le %.2g$ at $j = 4$",
        what, BODIES_COUNT, s_paper * DF_EPS_MAX);
    ledger_add(id, ref, q, slope_of(err), expected, ORDER_TOL, truth);
}

/* s = max(|w|, k) along the body's motion (claims_bodies.h's size_w bounds |w|). */
static double body_scale(const claims_body *cb) { return fmax(cb->size_w, cb->ex.k); }

void distfinal_claims(void)
{
    distfinal_data d = {0}, paper = {0};
    const double s_paper = body_scale(claims_body_get(0));
    for (int b = 0; b < BODIES_COUNT; b++) {
        const claims_body *cb = claims_body_get(b);
        const double scale = s_paper / body_scale(cb);
        for (int t = 0; t < NTK; t++) {
            distfinal_start(&cb->ex, TK_RATE[t] / cb->ex.k, scale, &d);
            if (b == 0)
                distfinal_start(&cb->ex, TK_RATE[t] / cb->ex.k, scale, &paper);
        }
    }
    /* The display states R(t_k+eps) = R(t_k) + eps Ad_R w^ + O(eps^2) (slope 2): with Ad_R w^ the
     * remainder is eps R w^ R^T (I - R^T) + O(eps^2), slope 1. An erratum: the next sentence of
     * the proof, R' = (Ad_R w^) R, contradicts the printed term. */
    const char *proof = "\\eqref{DistFinal} in the proof of \\PaperRefOr{TeoL}";
    const char *ext = "\\eqref{DistFinal}, extension";
    distfinal_line("distfinal-expansion-printed", proof,
                   "slope of $|R(t_k+\\varepsilon) - R(t_k) - \\varepsilon \\mathrm{Ad}_{R(t_k)} "
                   "\\hat{\\omega}(t_k)|$, the expansion as printed: $O(\\varepsilon^2)$ means 2",
                   d.exp_printed, 2.0, s_paper, LEDGER_ERRATUM);
    distfinal_line(
        "distfinal-expansion-restored", ext,
        "the same with the factor $R$ restored, $\\varepsilon (\\mathrm{Ad}_R \\hat{\\omega}) "
        "R = \\varepsilon R \\hat{\\omega}$: 2",
        d.exp_restored, 2.0, s_paper, LEDGER_EXTENSION);
    distfinal_line(
        "distfinal-linear-terms-printed", proof,
        "slope of $|I - (R + \\varepsilon \\mathrm{Ad}_R \\hat{\\omega})(I - \\varepsilon "
        "\\hat{\\omega} + \\varepsilon^2 \\hat{\\omega}^2/2) R^\\top|$ as printed: the text "
        "says the linear terms cancel, so 2",
        d.lin_printed, 2.0, s_paper, LEDGER_ERRATUM);
    distfinal_line("distfinal-linear-terms-restored", ext,
                   "the same with $\\varepsilon R \\hat{\\omega}$ for $\\varepsilon \\mathrm{Ad}_R "
                   "\\hat{\\omega}$: the linear terms cancel, 2",
                   d.lin_restored, 2.0, s_paper, LEDGER_EXTENSION);
    /* for the text: the two residuals at eps = 2^-7 on the paper's body */
    ledger_number("DistFinalPrintedAtSeven", paper.lin_printed[7]);
    ledger_number("DistFinalRestoredAtSeven", paper.lin_restored[7]);
}
