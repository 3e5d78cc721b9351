/* Unit tests of the high-order building blocks: the composition tables, the exponential
 * reconstruction (matrix and quaternion forms), quaternion <-> rotation, one Taylor step, one
 * composition step's energy, and the long-double reference attitude against an independent
 * computation; the steps on the paper's body and on the seeded general bodies
 * (tests/unit/bodies.h). */
#include "check_body.h"
#include "check_steady.h"
#include "composition.h"
#include "dsp.h"
#include "exact.h"
#include "magnus4.h"
#include "mat3.h"
#include "quaternion.h"
#include "reconstruct.h"
#include "refattitude.h"
#include "so3.h"
#include "taylor.h"

#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>
#include <math.h>

#define U SUS_U

static void tables(void)
{
    const sus_step_composition *c[] = {&sus_step_comp_suzuki4, &sus_step_comp_kahan_li6,
                                       &sus_step_comp_kahan_li8, &sus_step_comp_sofroniou10};
    for (int k = 0; k < 4; k++) {
        const int s = sus_step_composition_stages(c[k]);
        double sum = 0.0, cubes = 0.0, mag = 0.0;
        for (int i = 0; i < s; i++) {
            const double g = sus_step_composition_weight(c[k], i);
            sum += g;
            cubes += g * g * g;
            mag += fabs(g * g * g);
        }
        /* consistency: sum g = 1; order >= 3 of a symmetric composition: sum g^3 = 0 (HLW V.3).
         * The weights carry 26 digits rounded to double: s ulps of the sums at most. */
        CHECK(fabs(sum - 1.0) <= 4.0 * s * U, "%s: sum of the %d weights = 1 (off by %.2g)",
              c[k]->name, s, sum - 1.0);
        CHECK(fabs(cubes) <= 4.0 * s * U * fmax(1.0, mag),
              "%s: sum of cubes = 0, the order-3 condition (%.2g)", c[k]->name, cubes);
    }
}

static void exponential(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    double worst_small = 0.0, worst_orth = 0.0, worst_quat = 0.0;
    for (int t = 0; t < 200; t++) {
        const double scale = pow(10.0, -8.0 + 8.0 * gsl_rng_uniform(r));
        double x[3], D[3][3], W[3][3], W2[3][3], E[3][3];
        for (int i = 0; i < 3; i++)
            x[i] = scale * (2.0 * gsl_rng_uniform(r) - 1.0);
        sus_so3_exp_minus_identity(x, D);
        sus_so3_hat(x, W);
        sus_mat3_mul(W2, W, W);
        const double th2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        if (th2 < 1e-8) { /* series to th^4, truncation th^6/120 below 1e-24 relative here */
            double S[3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    S[i][j] = (1.0 - th2 / 6.0 + th2 * th2 / 120.0) * W[i][j] +
                              (0.5 - th2 / 24.0 + th2 * th2 / 720.0) * W2[i][j];
            worst_small = fmax(worst_small, sus_mat3_dist(D, S) / sus_mat3_frobenius(S));
        }
        sus_so3_exp(x, E);
        worst_orth = fmax(worst_orth, sus_so3_orth_defect(E));
        /* the quaternion form of exp-mid against the matrix form, from a random attitude */
        const double w0[3] = {x[0] / 0.3, x[1] / 0.3, x[2] / 0.3}, w1[3] = {x[1], x[2], x[0]};
        sus_attitude a;
        sus_attitude_identity(&a);
        double R0[3][3], q[4], Ra[3][3], Rq[3][3];
        sus_so3_exp((const double[3]){0.3, -1.2, 2.0}, R0);
        sus_mat3_copy(a.hi, R0);
        a.has_q = 0; /* R set by hand: the quaternion is not R's */
        sus_quat_from_rotation(R0, q);
        sus_reconstruct(SUS_RECON_EXP_MID, 0.3, &a, w0, w1);
        sus_reconstruct_quat(SUS_RECON_EXP_MID, 0.3, q, w0, w1);
        sus_attitude_get(&a, Ra);
        sus_quat_rotation(q, Rq);
        worst_quat = fmax(worst_quat, sus_mat3_dist(Ra, Rq));
    }
    gsl_rng_free(r);
    /* a and b in half-angle form keep full relative accuracy: a few ulps */
    CHECK(worst_small <= 10 * U,
          "exp(x^) - I at |x| < 1e-4 against its series: relative %.2g (<= 10 u)", worst_small);
    CHECK(worst_orth <= 10 * U, "exp(x^) orthogonal: |R^T R - I| <= %.2g (<= 10 u)", worst_orth);
    CHECK(worst_quat <= 20 * U, "exp-mid as a quaternion = exp-mid as a matrix: %.2g (<= 20 u)",
          worst_quat);
}

static void quaternions(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    double worst = 0.0;
    for (int t = 0; t < 400; t++) {
        /* angles up to pi, where Shepperd's choice of pivot matters */
        double x[3], R[3][3], q[4], R2[3][3];
        for (int i = 0; i < 3; i++)
            x[i] = 2.0 * gsl_rng_uniform(r) - 1.0;
        const double n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]),
                     ang = 3.14159265358979 * gsl_rng_uniform(r);
        for (int i = 0; i < 3; i++)
            x[i] *= ang / n;
        sus_so3_exp(x, R);
        sus_quat_from_rotation(R, q);
        sus_quat_rotation(q, R2);
        worst = fmax(worst, sus_mat3_dist(R, R2));
    }
    gsl_rng_free(r);
    CHECK(worst <= 20 * U, "R -> q -> R round trip over angles up to pi: %.2g (<= 20 u)", worst);
}

/* The reference against the independent long-double Magnus integration (Richardson). The Magnus
 * scheme has no tail and no proved step: its steps are as fine, in the body's own time and
 * rotation, as the 4000 steps to t = 50 that agreed with the reference to 1e-15 on the paper's body
 * (h max(k, |w|max) = 0.0117 there; here 1/125, |w|max <= |L^{-1}|_F r, exact.h); its rounding
 * grows with its step count, so each comparison spans a few relaxation times 1/k, and in the tail,
 * where w is constant to 2^-64 and the scheme exact for a constant w, its steps resolve only the
 * time 1/k on which w still moves:
 *   - the transient, [0, T1] with T1 k = 50 k_paper (t = 50 on the paper's body);
 *   - the closed-form tail (refattitude.h), [t_s, t_s + 20/k] from the reference's own R(t_s).
 * The bound 1e-15 is the reference's stated accuracy (refattitude.h: under u = 2^-53 before its
 * rounding) plus the rounding of both results to double and the Magnus scheme's own remainder. */
static void magnus_span(const sus_exact *ex, double t0, double t1, int tail, double R[3][3],
                        long *n)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    const double wmax = sqrt(a * a + b * b + c * c) * ex->r;
    *n = (long)ceil(125.0 * (t1 - t0) * (tail ? ex->k : fmax(ex->k, wmax)));
    sus_magnus4(ex, t0, t1, *n, R);
}

static void reference_against_magnus(const sus_exact *ex, double k_paper, const char *name)
{
    double Rr[3][3], Rm[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_refatt ra;
    long n;
    const double T1 = 50.0 * k_paper / ex->k;
    sus_refatt_init(&ra, ex, 0.0, Rm);
    sus_refatt_at(&ra, T1, Rr);
    magnus_span(ex, 0.0, T1, 0, Rm, &n);
    CHECK(sus_so3_dist(Rr, Rm) <= 1e-15,
          "%s: reference R(T1) against Magnus-4 (long double, Richardson, "
          "%ld and %ld steps), T1 k = 50 k_paper, T1 = %.3g: %.2g (<= 1e-15)",
          name, n, 2 * n, T1, sus_so3_dist(Rr, Rm));
    const double t_s = ra.t_s, T2 = t_s + 20.0 / ex->k;
    sus_refatt_at(&ra, t_s, Rm);
    sus_refatt_at(&ra, T2, Rr);
    magnus_span(ex, t_s, T2, 1, Rm, &n);
    CHECK(sus_so3_dist(Rr, Rm) <= 1e-15,
          "%s: reference's tail R(t_s + 20/k) against Magnus-4 from its "
          "R(t_s) (t_s = %.3g, %ld and %ld steps): %.2g (<= 1e-15)",
          name, t_s, n, 2 * n, sus_so3_dist(Rr, Rm));
}

/* The reference's radius r = |L^T w0| against r^2 = w0^T I_m w0 in 113 bits (check_steady.h), on
 * I_m with I12 = 1 - d and w0 along its soft axis, (-a, a + 1.4) with a = 1e6: l11 w1 and l21 w2
 * cancel to a part in 1e6, so a long-double rounding of either would move r by 1e6 2^-64. The
 * bound, 8 2^-64 relative on r^2: u1 and u2 carry a few long-double roundings each (refattitude.c),
 * r^2 twice their relative error; quad_form's own rounding is far below. */
static void reference_radius_on_soft_axis(void)
{
    double worst = 0.0;
    int n = 0;
    for (int j = 0; j < 2; j++) {
        const double d = j ? 1e-12 : 1e-9, w0[2] = {-1e6, 1e6 + 1.4};
        const body b = {{1.0, 1.0 - d, 0.0, 1.0 - d, 1.0, 0.0, -1.0, -1.0, 1.0}, {0, 0}, "sing"};
        sus_model m;
        sus_exact ex;
        sus_refatt ra;
        const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        if (check_body_model(&b, &m) || sus_exact_init(&ex, &m, w0))
            continue;
        sus_refatt_init(&ra, &ex, 0.0, I3);
        n++;
        const quad r2 = quad_form(&m, w0[0], w0[1]), rr = ra.closed.r;
        worst = fmax(worst, fabs((double)((rr * rr - r2) / r2)) / 0x1p-64);
    }
    CHECK(n == 2 && worst <= 8.0,
          "the reference's r, I12 = 1 - 1e-9 and 1 - 1e-12 (%d of 2 bodies), w0 along the soft "
          "axis, |w0| = 1.4e6: r^2 within %.3g 2^-64 of w0^T I_m w0 in 113 bits (<= 8)",
          n, worst);
}

/* |L^{-1}|_F r (exact.h): the largest |w| on the energy ellipse is at most this. */
static double ellipse_bound(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    return sqrt(a * a + b * b + c * c) * ex->r;
}

/* One Taylor step of order p at h = rho / 30 against the closed form, rho = pi / (4k): on the disc
 * |t| <= rho, s = s0 + sigma k t (exact.h) has |Im s| <= pi/4, where |sech s|^2 <= 2 and |tanh s|
 * <= 1, so |w| <= M = sqrt3 |L^{-1}|_F r (refattitude.c's bound) and Cauchy's estimate puts the
 * tail past degree p at most M x^(p+1) / (1 - x), x = h / rho. Summing rounds 4 u of |w0| and of
 * the other terms (at most M x / (1 - x)), and E's rounding moves the energy scaling by 2 u of E's
 * terms over E; restoring E multiplies the error by at most A = 1 + |w| |I_m w| / <I_m w, w> (a
 * radial scaling moves w by |w| <I_m w, dw> / 2E). h is also at most half the radius the step is
 * proved to converge in (taylor.h), so the step must run. */
static void taylor_one_step(const sus_model *m, const sus_exact *ex, const char *name)
{
    const sus_stepper_type *ty[3] = {&sus_step_taylor8_type, &sus_step_taylor10_type,
                                     &sus_step_taylor12_type};
    const double w0[3] = {ex->w0[0], ex->w0[1], 0.0}, rho = 0.25 * M_PI / ex->k;
    const double h = fmin(rho / 30.0, 0.5 * sus_step_taylor_radius(m, w0)), x = h / rho;
    const double M = sqrt(3.0) * ellipse_bound(ex), E0 = sus_energy(m, w0), (*I)[3] = m->I;
    const double Ea =
        0.5 * (fabs(I[0][0]) * w0[0] * w0[0] + fabs(I[0][1] + I[1][0]) * fabs(w0[0] * w0[1]) +
               fabs(I[1][1]) * w0[1] * w0[1]);
    double we[2];
    sus_exact_omega(ex, h, we);
    const double Iw[2] = {I[0][0] * we[0] + I[0][1] * we[1], I[1][0] * we[0] + I[1][1] * we[1]};
    const double A =
        1.0 + hypot(we[0], we[1]) * hypot(Iw[0], Iw[1]) / (Iw[0] * we[0] + Iw[1] * we[1]);
    const double rounding = 4 * U * (hypot(w0[0], w0[1]) * Ea / E0 + M * x / (1.0 - x));
    for (int i = 0; i < 3; i++) {
        double w1[3], lam;
        sus_stepper_stats st;
        const int rc = ty[i]->step->apply(m, h, w0, w1, &lam, &st);
        const double e = hypot(w1[0] - we[0], w1[1] - we[1]);
        const double bound = A * (M * pow(x, ty[i]->desc.order + 1) / (1.0 - x) + rounding);
        CHECK(rc == SUS_STEPPER_OK && e <= bound && w1[2] == 0.0,
              "%s: %s, one step h = %.3g (x = %.3g of "
              "pi / 4k) against the closed form: %.2g (<= %.2g), w3 = 0",
              name, ty[i]->name, h, x, e, bound);
    }
}

/* The terms of E(w), 1/2 (|I11| w1^2 + |I12 + I21| |w1 w2| + |I22| w2^2). */
static double energy_terms(const sus_model *m, const double w[2])
{
    const double(*I)[3] = m->I;
    return 0.5 * (fabs(I[0][0]) * w[0] * w[0] + fabs(I[0][1] + I[1][0]) * fabs(w[0] * w[1]) +
                  fabs(I[1][1]) * w[1] * w[1]);
}

/* A composition step of eps k = k_paper (s the body's time) keeps E. Its 17 substeps are midpoint
 * DSP steps of g_i eps, each taken here (test_guards.c checks that the composition's w is the last
 * one's): a substep changes E by at most |mid|_1 times its true residual (test_steppers.c), the
 * residual Newton reports plus 2 u of its scale and of g eps |mid|_1 c's terms, and E rounds 2 u of
 * its terms. The bound is the sum over the substeps. */
static void composition_energy(const sus_model *m, const sus_exact *ex, double s, const char *name)
{
    const sus_step_composition *c = &sus_step_comp_kahan_li8;
    const double w0[3] = {ex->w0[0], ex->w0[1], 0.0}, eps = s;
    double w[3] = {w0[0], w0[1], 0.0}, x[3], w1[3], lam, bound = 0.0;
    sus_stepper_stats st;
    int ok = 1;
    for (int i = 0; i < sus_step_composition_stages(c); i++) {
        const double ge = sus_step_composition_weight(c, i) * eps;
        ok &= sus_step_midpoint->step->apply(m, ge, w, x, &lam, &st) == SUS_STEPPER_OK;
        const double mid[2] = {0.5 * (x[0] + w[0]), 0.5 * (x[1] + w[1])},
                     n1 = fabs(mid[0]) + fabs(mid[1]);
        const double ca = fabs(m->b[0] * mid[0]) + fabs(m->b[1] * mid[1]);
        bound += n1 * (st.residual + 2 * U * (st.scale + fabs(ge) * n1 * ca)) +
                 2 * U * (energy_terms(m, x) + energy_terms(m, w));
        w[0] = x[0], w[1] = x[1];
    }
    ok &= sus_step_comp8_kl_type.step->apply(m, eps, w0, w1, &lam, &st) == SUS_STEPPER_OK;
    const double dE = fabs(sus_energy(m, w1) - sus_energy(m, w0));
    CHECK(ok && dE <= bound,
          "%s: comp8-kl, one step eps = %.3g (17 substeps): |E1 - E0| = %.2g (<= %.2g: "
          "the substeps' residuals and E's roundings)",
          name, eps, dE, bound);
}

static void steps(const body *b, double k_paper)
{
    sus_model m;
    if (check_body_model(b, &m) != 0)
        return;
    sus_exact ex;
    sus_exact_init(&ex, &m, b->w0);
    taylor_one_step(&m, &ex, b->name);
    composition_energy(&m, &ex, k_paper / ex.k, b->name);
    reference_against_magnus(&ex, k_paper, b->name);
}

int main(void)
{
    tables();
    exponential();
    quaternions();
    reference_radius_on_soft_axis();
    double k_paper = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        body_get(k, &b);
        if (k == 0) { /* the paper's body sets the time scale the others are compared at */
            sus_model m;
            sus_exact ex;
            check_body_model(&b, &m);
            sus_exact_init(&ex, &m, b.w0);
            k_paper = ex.k;
        }
        steps(&b, k_paper);
    }
    return check_summary("test_highorder");
}
