/* Quick checks of the library's formulas against the paper's printed equations, written out here
 * independently of src/, on general bodies (I13 != I31, I23 != I32, off-diagonal terms of both
 * signs) and states drawn from a fixed seed. They run in milliseconds, so that the generated
 * mutation campaign (make mutants-ops) meets them first: a coefficient scaled by 1 + 1e-6, a sign
 * or an index changed in the model, the Cayley map or the quaternions moves a result by far more
 * than the tolerances, which are a few roundings of O(1) terms (1e-13). */
#include "check.h"
#include "model.h"
#include "quaternion.h"
#include "registry.h"
#include "so3.h"
#include "dsp.h"

#include <math.h>
#include <string.h>

#define TOL                                                                                        \
    1e-13 /* a few roundings of sums of O(1) terms; any mutant changes >= 1e-7 of a term           \
           */
#define SEED 20261123u
#define NSTATE 8

/* Printed inertia matrices, rows as printed: the paper's body and three general ones. */
static const double BODIES[4][9] = {{1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0},
                                    {2.0, -0.3, 0.15, -0.3, 1.5, -0.25, 0.4, -0.2, 1.2},
                                    {1.2, 0.25, -0.35, 0.25, 0.9, 0.05, -0.1, 0.3, 1.1},
                                    {0.8, -0.1, 0.5, -0.1, 1.7, 0.3, 0.35, -0.45, 2.0}};

static unsigned rng_state = SEED;
static double uniform(double a, double b) /* a small LCG: the same states on every platform */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return a + (b - a) * (double)(rng_state >> 8) / 16777216.0;
}

/* (ContDyn): w1' = -(I22 w2 + I12 w1) c / |I_m|, w2' = (I21 w2 + I11 w1) c / |I_m|, c = I3i wi. */
static void contdyn_printed(const double I[9], const double w[2], double f[2])
{
    const double c = I[6] * w[0] + I[7] * w[1], d = I[0] * I[4] - I[1] * I[3];
    f[0] = -(I[4] * w[1] + I[1] * w[0]) * c / d;
    f[1] = (I[3] * w[1] + I[0] * w[0]) * c / d;
}

/* (LagMult) as printed. */
static double lagmult_printed(const double I[9], const double w[2])
{
    const double c = I[6] * w[0] + I[7] * w[1], d = I[0] * I[4] - I[1] * I[3];
    return w[0] * (I[3] * w[0] + I[4] * w[1]) - w[1] * (I[0] * w[0] + I[1] * w[1]) +
           c / d * ((I[7] * I[3] - I[6] * I[4]) * w[1] + (I[7] * I[0] - I[6] * I[1]) * w[0]);
}

static double rel(double a, double b) { return fabs(a - b) / fmax(1.0, fabs(b)); }

/* The model: (ContDyn), (LagMult), E = 1/2 <I_m w, w>, and Df, which is exact as a central
 * difference with any step because f is quadratic (h = 1/2: no rounding in w +- h). */
static void model_checks(int b, const sus_model *m, const double w[2])
{
    const double *I = BODIES[b];
    double f[2], g[2], J[2][2], fp[2], fm[2];
    sus_contdyn(m, w, f);
    contdyn_printed(I, w, g);
    CHECK(rel(f[0], g[0]) <= TOL && rel(f[1], g[1]) <= TOL, "body %d: (ContDyn) f = (%.17g, %.17g)",
          b, f[0], f[1]);
    const double lam = sus_lagmult(m, w), lp = lagmult_printed(I, w);
    CHECK(rel(lam, lp) <= TOL, "body %d: (LagMult) %.17g against %.17g", b, lam, lp);
    const double e = 0.5 * (I[0] * w[0] * w[0] + (I[1] + I[3]) * w[0] * w[1] + I[4] * w[1] * w[1]);
    CHECK(rel(sus_energy(m, w), e) <= TOL, "body %d: E %.17g against %.17g", b, sus_energy(m, w),
          e);
    sus_contdyn_jacobian(m, w, J);
    for (int j = 0; j < 2; j++) {
        double wp[2] = {w[0], w[1]}, wm[2] = {w[0], w[1]};
        wp[j] += 0.5;
        wm[j] -= 0.5;
        contdyn_printed(I, wp, fp);
        contdyn_printed(I, wm, fm);
        CHECK(rel(J[0][j], fp[0] - fm[0]) <= 10 * TOL && rel(J[1][j], fp[1] - fm[1]) <= 10 * TOL,
              "body %d: Df column %d (%.17g, %.17g)", b, j, J[0][j], J[1][j]);
    }
}

static void mat_mul(const double A[3][3], const double B[3][3], double C[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
}

static double max_diff(const double A[3][3], const double B[3][3])
{
    double d = 0.0;
    for (int i = 0; i < 9; i++)
        d = fmax(d, fabs(A[i / 3][i % 3] - B[i / 3][i % 3]));
    return d;
}

/* exp(w^) as its power series, summed to round-off (|w| <= 2: 40 terms). */
static void exp_series(const double W[3][3], double E[3][3])
{
    double T[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, N[3][3];
    for (int i = 0; i < 9; i++)
        E[i / 3][i % 3] = T[i / 3][i % 3];
    for (int k = 1; k <= 40; k++) {
        mat_mul(T, W, N);
        for (int i = 0; i < 9; i++) {
            T[i / 3][i % 3] = N[i / 3][i % 3] / k;
            E[i / 3][i % 3] += T[i / 3][i % 3];
        }
    }
}

/* (caypart): (I - w^/2) cay(w) = I + w^/2; dcay and dcay^{-1} as printed after it; exp. */
static void so3_checks(const double w[3])
{
    const double W[3][3] = {{0, -w[2], w[1]}, {w[2], 0, -w[0]}, {-w[1], w[0], 0}};
    double H[3][3], R[3][3], L[3][3], P[3][3], Q[3][3], D[3][3], Di[3][3], E[3][3], v[3];
    sus_so3_hat(w, H);
    CHECK(max_diff(H, W) == 0.0, "(Isom) hat of (%.3g, %.3g, %.3g)", w[0], w[1], w[2]);
    sus_so3_cay(w, R);
    const double n2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    for (int i = 0; i < 9; i++) {
        L[i / 3][i % 3] = (i % 4 == 0) - 0.5 * W[i / 3][i % 3];
        P[i / 3][i % 3] = (i % 4 == 0) + 0.5 * W[i / 3][i % 3];
    }
    mat_mul(L, R, Q);
    CHECK(max_diff(Q, P) <= TOL, "(caypart) (I - w^/2) cay(w) = I + w^/2: %.3g", max_diff(Q, P));
    sus_so3_cay_inv(R, v);
    CHECK(fmax(fabs(v[0] - w[0]), fmax(fabs(v[1] - w[1]), fabs(v[2] - w[2]))) <= TOL,
          "cay^{-1}(cay(w)) = w");
    sus_so3_dcay(w, D);
    sus_so3_dcay_inv(w, Di);
    for (int i = 0; i < 9;
         i++) { /* dcay = (I + w^/2) / (1 + |w/2|^2), dcay^{-1} = I - w^/2 + w w^T / 4 */
        P[i / 3][i % 3] /= 1.0 + 0.25 * n2;
        L[i / 3][i % 3] += 0.25 * w[i / 3] * w[i % 3];
    }
    CHECK(max_diff(D, P) <= TOL && max_diff(Di, L) <= TOL, "dcay, dcay^{-1} as printed: %.3g, %.3g",
          max_diff(D, P), max_diff(Di, L));
    sus_so3_exp(w, R);
    exp_series(W, E);
    CHECK(max_diff(R, E) <= TOL, "exp(w^) against its series: %.3g", max_diff(R, E));
    sus_so3_exp_minus_identity(w, D);
    for (int i = 0; i < 3; i++)
        E[i][i] -= 1.0;
    CHECK(max_diff(D, E) <= TOL, "exp(w^) - I against its series: %.3g", max_diff(D, E));
}

/* R(q) of a unit quaternion (s, v): I + 2 s v^ + 2 v^ v^; and back with sus_quat_from_rotation. */
static void quaternion_checks(const double q_in[4])
{
    const double nq =
        sqrt(q_in[0] * q_in[0] + q_in[1] * q_in[1] + q_in[2] * q_in[2] + q_in[3] * q_in[3]);
    const double sgn = q_in[0] < 0.0 ? -1.0 : 1.0;
    const double q[4] = {sgn * q_in[0] / nq, sgn * q_in[1] / nq, sgn * q_in[2] / nq,
                         sgn * q_in[3] / nq};
    const double V[3][3] = {{0, -q[3], q[2]}, {q[3], 0, -q[1]}, {-q[2], q[1], 0}};
    double V2[3][3], Rq[3][3], R[3][3], back[4];
    mat_mul(V, V, V2);
    for (int i = 0; i < 9; i++)
        Rq[i / 3][i % 3] = (i % 4 == 0) + 2.0 * q[0] * V[i / 3][i % 3] + 2.0 * V2[i / 3][i % 3];
    sus_quat_rotation(q_in, R);
    CHECK(max_diff(R, Rq) <= TOL, "R(q) of q/|q|: %.3g", max_diff(R, Rq));
    sus_quat_from_rotation(R, back);
    double d = 0.0;
    for (int i = 0; i < 4; i++)
        d = fmax(d, fabs(back[i] - q[i]));
    CHECK(d <= TOL, "q(R(q)) = q (q0 >= 0): %.3g", d);
}

/* The paper's body and initial state as printed in Section 5.6, entry by entry. */
static void paper_data_checks(void)
{
    const double printed[9] = {1, 0.1, 0.2, 0.1, 1, 0.2, 0.2, 0.1, 1};
    for (int i = 0; i < 9; i++)
        CHECK(SUS_PAPER_INERTIA[i] == printed[i], "the paper's I, entry %d: %.17g", i + 1,
              SUS_PAPER_INERTIA[i]);
    CHECK(SUS_PAPER_OMEGA0[0] == 0.4 && SUS_PAPER_OMEGA0[1] == 0.5,
          "the paper's w(0) = (%.17g, %.17g)", SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]);
}

/* Every entry that is not finite is refused and named (as the CLI's --inertia reports it). */
static void model_init_checks(void)
{
    const double bad[2] = {INFINITY, NAN};
    for (int i = 0; i < 9; i++)
        for (int k = 0; k < 2; k++) {
            double I[9];
            char err[128] = "", want[48];
            for (int j = 0; j < 9; j++)
                I[j] = BODIES[1][j];
            I[i] = bad[k];
            sus_model m;
            const int rc = sus_model_init(&m, I, err, sizeof err);
            snprintf(want, sizeof want, "entry %d is not finite", i + 1);
            CHECK(rc == -1 && strstr(err, want), "entry %d = %g refused: \"%s\"", i + 1, bad[k],
                  err);
        }
}

/* I_m's symmetry is checked to round-off, as documented in src/model.c: |I12 - I21| <= 4 u S with
 * S = |I11| + |I12| + |I21| + |I22|. An asymmetry just above that bound is refused, one just
 * below accepted: 1e-8 (relative) from it with I12 ~ 1e-9, which makes the asymmetry adjustable
 * that finely, and 10 % from it with I12 = -0.3, where every term of S weighs (ulp(0.3) is 2 %
 * of the bound). */
static void symmetry_bound_checks(void)
{
    const double u = 2.220446049250313e-16, i12[2] = {1e-9, -0.3}, margin[2] = {1e-8, 0.1};
    for (int k = 0; k < 4; k++) {
        const int above = k % 2, b = k / 2;
        double I[9] = {1.3, i12[b], 0.0, i12[b], 0.7, 0.0, 0.2, -0.1, 1.0};
        const double S = 1.3 + 2.0 * fabs(i12[b]) + 0.7;
        I[3] = I[1] + 4.0 * u * S * (above ? 1.0 + margin[b] : 1.0 - margin[b]);
        sus_model m;
        char err[128] = "";
        const int rc = sus_model_init(&m, I, err, sizeof err);
        char names[96]; /* a refusal names both entries */
        snprintf(names, sizeof names, "I12 = %.17g but I21 = %.17g", I[1], I[3]);
        CHECK(rc == (above ? -1 : 0) && (!above || strstr(err, names)),
              "asymmetry %.10g of the bound 4 u S %s: %s", fabs(I[3] - I[1]) / (4.0 * u * S),
              above ? "refused" : "accepted", rc ? err : "ok");
    }
}

/* The yardstick of the implicit step equations (stepper.h: scale = the sum of |terms| of G, what
 * Newton's stopping test and the round-off checks measure against), recomputed from the terms of
 * the equation as written: the midpoint DSP's I_m (x - w) - eps l(mid) and (taudyn)'s
 * I_m (x - w) + eps/2 (x c(x) + w c(w))^perp + eps^2/4 (x s(x) - w s(w)), s(v) = <v, I_m v>. The
 * states run over two decades of |w|, where a yardstick scaled wrongly by |x| shows. */
static double terms_scale(const sus_model *m, const sus_stepper_type *st, double eps,
                          const double w[2], const double x[2])
{
    double sI = 0.0;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            sI += fabs(m->I[i][j]);
    const double sx = fabs(x[0]) + fabs(x[1]) + fabs(w[0]) + fabs(w[1]);
    if (st == sus_step_midpoint) {
        const double mid[2] = {0.5 * (x[0] + w[0]), 0.5 * (x[1] + w[1])}, c = sus_c(m, mid);
        return sI * sx + eps * (fabs(mid[1] * c) + fabs(mid[0] * c));
    }
    double sv[2];
    for (int k = 0; k < 2; k++) {
        const double *v = k ? w : x;
        sv[k] = 0.0;
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                sv[k] += v[i] * m->I[i][j] * v[j];
    }
    const double cx = sus_c(m, x), cw = sus_c(m, w);
    return sI * sx +
           0.5 * eps * (fabs(x[1] * cx) + fabs(w[1] * cw) + fabs(x[0] * cx) + fabs(w[0] * cw)) +
           0.25 * eps * eps *
               (fabs(x[0] * sv[0]) + fabs(w[0] * sv[1]) + fabs(x[1] * sv[0]) + fabs(w[1] * sv[1]));
}

static void scale_checks(int b, const sus_model *m)
{
    const sus_stepper_type *const st[2] = {sus_step_midpoint, sus_step_variational};
    for (int k = 0; k < 2; k++) {
        double worst = 0.0;
        for (int n = 0; n < 12; n++) {
            const double r = pow(10.0, -1.0 + 0.2 * n), eps = uniform(0.05, 1.0);
            const double w[2] = {r * uniform(-1, 1), r * uniform(-1, 1)},
                         x[2] = {r * uniform(-1, 1), r * uniform(-1, 1)};
            double g[2], J[4], sc;
            st[k]->equation->residual(m, eps, w, x, g, J, &sc);
            worst = fmax(worst, rel(sc, terms_scale(m, st[k], eps, w, x)));
        }
        CHECK(worst <= 8 * TOL,
              "body %d, %s: the residual's scale is the sum of |terms| of G (%.2g)", b, st[k]->name,
              worst);
    }
}

int main(void)
{
    printf("test_mutant_kills: seed %u\n", SEED);
    paper_data_checks();
    model_init_checks();
    symmetry_bound_checks();
    for (int b = 0; b < 4; b++) {
        sus_model m;
        char err[128];
        if (sus_model_init(&m, BODIES[b], err, sizeof err) != 0) {
            CHECK(0, "body %d: %s", b, err);
            continue;
        }
        for (int k = 0; k < NSTATE; k++) {
            const double w[2] = {uniform(-1.5, 1.5), uniform(-1.5, 1.5)};
            model_checks(b, &m, w);
        }
        scale_checks(b, &m);
    }
    for (int k = 0; k < NSTATE; k++) {
        const double w[3] = {uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
        so3_checks(w);
        /* the largest component changes with k, so every branch of Shepperd's method is taken */
        double q[4] = {uniform(-0.3, 0.3), uniform(-0.3, 0.3), uniform(-0.3, 0.3),
                       uniform(-0.3, 0.3)};
        q[k % 4] += k % 2 ? -1.0 : 1.0;
        quaternion_checks(q);
    }
    return check_summary("test_mutant_kills");
}
