/* SO(3) tools: (Isom), (caypart) and its derivatives, (cayinver), exp, (MetMat). */
#include "check.h"
#include "mat3.h"
#include "reconstruct.h"
#include "so3.h"

#include <gsl/gsl_rng.h>
#include <math.h>

/* Every check below compares quantities of size O(1) computed with a few dozen flops; the
 * round-off is a few 1e-16, so 1e-14 is a tight but safe bound. */
#define ROUNDOFF_TOL 1e-14

static void random_vec(gsl_rng *r, double scale, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = scale * (2.0 * gsl_rng_uniform(r) - 1.0);
}

static double identity_defect(const double A[3][3])
{
    double I3[3][3];
    sus_mat3_identity(I3);
    return sus_mat3_dist(A, I3);
}

/* cay(w^) by its definition (caypart), (I - w^/2)^{-1} (I + w^/2), the inverse by the adjugate:
 * independent of the closed form in so3.c. */
static void cay_by_definition(const double w[3], double C[3][3])
{
    double W[3][3], A[3][3], B[3][3], adj[3][3];
    sus_so3_hat(w, W);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            A[i][j] = (i == j) - 0.5 * W[i][j];
            B[i][j] = (i == j) + 0.5 * W[i][j];
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) /* adj[j][i] = cofactor (i, j) */
            adj[j][i] = A[(i + 1) % 3][(j + 1) % 3] * A[(i + 2) % 3][(j + 2) % 3] -
                        A[(i + 1) % 3][(j + 2) % 3] * A[(i + 2) % 3][(j + 1) % 3];
    const double det = A[0][0] * adj[0][0] + A[0][1] * adj[1][0] + A[0][2] * adj[2][0];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = (adj[i][0] * B[0][j] + adj[i][1] * B[1][j] + adj[i][2] * B[2][j]) / det;
}

/* exp(w^) by its power series (40 terms: |w| <= 2 here, so the remainder is below 1e-30). */
static void exp_by_series(const double w[3], double E[3][3])
{
    double W[3][3], T[3][3], P[3][3];
    sus_so3_hat(w, W);
    sus_mat3_identity(E);
    sus_mat3_identity(T);
    for (int n = 1; n <= 40; n++) {
        sus_mat3_mul(P, T, W);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                T[i][j] = P[i][j] / n;
                E[i][j] += T[i][j];
            }
    }
}

/* Step 3 of (algo) and our two symmetric variants, two steps from R_0 = I: R_2 must be
 * tau(xi_0) tau(xi_1) with the tau and xi of each kind, built here from the definitions. */
static double reconstruct_vs_definition(sus_recon kind, double eps, const double w[3][3])
{
    sus_attitude a;
    sus_attitude_identity(&a);
    double R[3][3], T[3][3], P[3][3];
    sus_mat3_identity(R);
    for (int k = 0; k < 2; k++) {
        double xi[3];
        for (int i = 0; i < 3; i++)
            xi[i] = kind == SUS_RECON_CAYLEY ? eps * w[k][i] : 0.5 * eps * (w[k][i] + w[k + 1][i]);
        if (kind == SUS_RECON_EXP_MID)
            exp_by_series(xi, T);
        else
            cay_by_definition(xi, T);
        sus_mat3_mul(P, R, T);
        sus_mat3_copy(R, P);
        sus_reconstruct(kind, eps, &a, w[k], w[k + 1]);
    }
    double got[3][3], d = 0.0;
    sus_attitude_get(&a, got);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(got[i][j] - R[i][j]));
    return d;
}

/* Definition Retr at xi along eta by central differences: the worst of each derivative in w5, w6.
 */
static void retraction_fd(const double xi[3], const double eta[3], double *w5, double *w6)
{
    double C[3][3], D[3][3], Di[3][3];
    sus_so3_cay(xi, C);
    sus_so3_dcay(xi, D);
    sus_so3_dcay_inv(xi, Di);
    /* Definition Retr: d/ds cay(xi + s eta) = (dcay_xi eta)^ cay(xi), central differences */
    const double h = 1e-5;
    double xp[3], xm[3], Cp[3][3], Cmm[3][3], FD[3][3], de[3], DE[3][3], AN[3][3];
    for (int i = 0; i < 3; i++) {
        xp[i] = xi[i] + h * eta[i];
        xm[i] = xi[i] - h * eta[i];
    }
    sus_so3_cay(xp, Cp);
    sus_so3_cay(xm, Cmm);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            FD[i][j] = (Cp[i][j] - Cmm[i][j]) / (2.0 * h);
    sus_mat3_vec(de, D, eta);
    sus_so3_hat(de, DE);
    sus_mat3_mul(AN, DE, C);
    *w5 = fmax(*w5, sus_mat3_dist(FD, AN));
    /* and d/ds cay^{-1}(exp(s eta^) cay(xi)) = dcay^{-1}_xi eta */
    double E[3][3], G[3][3], yp[3], ym[3], se[3];
    for (int i = 0; i < 3; i++)
        se[i] = h * eta[i];
    sus_so3_exp(se, E);
    sus_mat3_mul(G, E, C);
    sus_so3_cay_inv(G, yp);
    for (int i = 0; i < 3; i++)
        se[i] = -h * eta[i];
    sus_so3_exp(se, E);
    sus_mat3_mul(G, E, C);
    sus_so3_cay_inv(G, ym);
    sus_mat3_vec(de, Di, eta);
    for (int i = 0; i < 3; i++)
        *w6 = fmax(*w6, fabs((yp[i] - ym[i]) / (2.0 * h) - de[i]));
}

/* (Isom), (caypart), the inverse chart, dcay, Definition Retr and exp on random samples. */
static void identities(gsl_rng *rng)
{
    double worst[10] = {0};
    for (int n = 0; n < 200; n++) {
        double xi[3], eta[3], W[3][3], v[3], a[3], b[3], C[3][3], Cm[3][3], P[3][3], D[3][3],
            Di[3][3];
        random_vec(rng, 3.0, xi);
        random_vec(rng, 1.0, eta);
        random_vec(rng, 1.0, v);
        /* (Isom): w^ v = w x v, and vee inverts hat */
        sus_so3_hat(xi, W);
        sus_mat3_vec(a, W, v);
        sus_vec3_cross(b, xi, v);
        sus_so3_vee(W, a);
        worst[0] = fmax(worst[0], fabs(a[0] - xi[0]) + fabs(a[1] - xi[1]) + fabs(a[2] - xi[2]));
        sus_mat3_vec(a, W, v);
        worst[0] = fmax(worst[0], fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2]));
        /* cay(xi) cay(-xi) = I and cay(xi) in SO(3) */
        const double mxi[3] = {-xi[0], -xi[1], -xi[2]};
        sus_so3_cay(xi, C);
        sus_so3_cay(mxi, Cm);
        sus_mat3_mul(P, C, Cm);
        worst[1] = fmax(worst[1], identity_defect(P));
        worst[2] = fmax(worst[2], sus_so3_orth_defect(C) + fabs(sus_mat3_det(C) - 1.0));
        /* the inverse chart */
        sus_so3_cay_inv(C, a);
        worst[3] = fmax(worst[3], fabs(a[0] - xi[0]) + fabs(a[1] - xi[1]) + fabs(a[2] - xi[2]));
        /* dcay^{-1} dcay = I */
        sus_so3_dcay(xi, D);
        sus_so3_dcay_inv(xi, Di);
        sus_mat3_mul(P, Di, D);
        worst[4] = fmax(worst[4], identity_defect(P));
        retraction_fd(xi, eta, &worst[5], &worst[6]);
        double E[3][3], G[3][3];
        /* exp: in SO(3), exp(w) exp(-w) = I */
        sus_so3_exp(xi, E);
        sus_so3_exp(mxi, G);
        sus_mat3_mul(P, E, G);
        worst[7] = fmax(worst[7], identity_defect(P) + sus_so3_orth_defect(E));
    }
    CHECK(worst[0] < ROUNDOFF_TOL, "(Isom): hat(w) v = w x v and vee(hat(w)) = w; worst %.2e",
          worst[0]);
    CHECK(worst[1] < ROUNDOFF_TOL, "(caypart): cay(xi) cay(-xi) = I, |xi| <= 5; worst %.2e",
          worst[1]);
    CHECK(worst[2] < ROUNDOFF_TOL,
          "(caypart): cay(xi) in SO(3); worst |R^T R - I| + |det - 1| %.2e", worst[2]);
    /* cay^{-1} divides by 1 + tr R, which is as small as ~0.2 for |xi| <= 5: allow 1e-13 */
    CHECK(worst[3] < 1e-13, "cay^{-1}(cay(xi)) = xi; worst %.2e", worst[3]);
    CHECK(worst[4] < ROUNDOFF_TOL, "dcay^{-1}_xi dcay_xi = I; worst %.2e", worst[4]);
    /* central differences with h = 1e-5: truncation O(h^2) ~ 1e-10, cancellation ~ u/h ~ 1e-11 */
    CHECK(worst[5] < 1e-8,
          "Definition Retr: d cay(xi)[eta] = (dcay_xi eta)^ cay(xi) (central "
          "differences); worst %.2e",
          worst[5]);
    CHECK(worst[6] < 1e-8,
          "Definition Retr: d cay^{-1} along eta^ cay(xi) = dcay^{-1}_xi eta (central "
          "differences); worst %.2e",
          worst[6]);
    CHECK(worst[7] < ROUNDOFF_TOL,
          "exp (Rodrigues): exp(w) in SO(3), exp(w) exp(-w) = I; worst %.2e", worst[7]);
}

/* (cayinver) as printed against dcay^{-1}_{eps w} with w_3 = 0: equal but for entry (3,3). */
static void cayinver(gsl_rng *rng)
{
    double off33 = 0.0, at33 = 0.0;
    for (int n = 0; n < 50; n++) {
        double w[3], M[3][3], D[3][3], ew[3];
        random_vec(rng, 1.0, w);
        w[2] = 0.0;
        const double eps = 2.0 * gsl_rng_uniform(rng);
        sus_so3_cayinver_printed(eps, w, M);
        for (int i = 0; i < 3; i++)
            ew[i] = eps * w[i];
        sus_so3_dcay_inv(ew, D);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                if (i == 2 && j == 2)
                    at33 = fmax(at33, fabs(D[i][j] - M[i][j]));
                else
                    off33 = fmax(off33, fabs(D[i][j] - M[i][j]));
    }
    CHECK(off33 < ROUNDOFF_TOL,
          "(cayinver) as printed equals dcay^{-1}_{eps w} off entry (3,3); worst %.2e", off33);
    CHECK(fabs(at33 - 1.0) < ROUNDOFF_TOL,
          "(cayinver) as printed has 0 at (3,3) where dcay^{-1} has 1; difference %.17g", at33);
}

/* (MetMat) is a metric on sampled rotations, and equals |R1 - R2| (Frobenius). */
static void metric(gsl_rng *rng)
{
    double sym = 0.0, self = 0.0, tri = -INFINITY, chord = 0.0, minpos = INFINITY;
    for (int n = 0; n < 300; n++) {
        double a[3], b[3], c[3], A[3][3], B[3][3], C[3][3], D[3][3];
        random_vec(rng, 3.0, a);
        random_vec(rng, 3.0, b);
        random_vec(rng, 3.0, c);
        sus_so3_exp(a, A);
        sus_so3_exp(b, B);
        sus_so3_exp(c, C);
        const double ab = sus_so3_dist(A, B), ba = sus_so3_dist(B, A), ac = sus_so3_dist(A, C),
                     cb = sus_so3_dist(C, B);
        sym = fmax(sym, fabs(ab - ba));
        self = fmax(self, sus_so3_dist(A, A));
        tri = fmax(tri, ab - (ac + cb));
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                D[i][j] = A[i][j] - B[i][j];
        chord = fmax(chord, fabs(ab - sus_mat3_frobenius(D)));
        minpos = fmin(minpos, ab / sus_mat3_frobenius(D));
    }
    CHECK(self < ROUNDOFF_TOL, "(MetMat): dist(R, R) = 0; worst %.2e", self);
    CHECK(sym < ROUNDOFF_TOL, "(MetMat): symmetric; worst %.2e", sym);
    CHECK(tri < ROUNDOFF_TOL, "(MetMat): triangle inequality on 300 triples; worst excess %.2e",
          tri);
    CHECK(chord < ROUNDOFF_TOL && minpos > 0.999,
          "(MetMat) on SO(3) equals |R1 - R2| (so it is positive for R1 != R2); worst %.2e", chord);
    double N[3][3] = {{1.0, 1e-3, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    CHECK(fabs(sus_so3_orth_defect(N) - sqrt(2.0e-6 + 1e-12)) < 1e-15,
          "(Groudist): orthogonality defect of a shear = its exact value %.6e",
          sus_so3_orth_defect(N));
}

int main(void)
{
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20261122);
    identities(rng);
    cayinver(rng);
    metric(rng);
    /* The reconstructions against their definitions; entries of size 1 after two products of
     * a few round-off each: 1e-15. */
    const double w[3][3] = {{0.4, 0.5, 0.0}, {-0.7, 0.9, 0.0}, {0.3, -0.2, 0.0}};
    for (int kind = 0; kind < SUS_RECON_COUNT; kind++) {
        const double d = reconstruct_vs_definition((sus_recon)kind, 0.8, w);
        CHECK(d < 1e-15,
              "(algo) step 3, %s: two steps from I equal the product of tau(xi_k) by definition; "
              "worst entry %.2e",
              SUS_RECON_NAMES[kind], d);
    }
    gsl_rng_free(rng);
    return check_summary("test_so3");
}
