/* The reference attitude's contract (src/core/refattitude.h) at its edges: R(q) of a quaternion
 * that is not of unit length, as the long-double integration leaves it after a long run, and a
 * stretch too long to integrate, which gives no answer rather than a wrong one. Its accuracy is
 * tested in test_highorder.c (against an independent Magnus integration) and test_exact_run.c. */
#include "check_body.h"
#include "check_exact.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"

#include <float.h>
#include <math.h>

static int all_finite(const double R[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!isfinite(R[i][j]))
                return 0;
    return 1;
}

static int none_finite(const double R[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (isfinite(R[i][j]))
                return 0;
    return 1;
}

/* q = c (cos(a/2), sin(a/2) n) for scales c far from 1: R(q) is exp(a n^) whatever c is. Both sides
 * round each entry of an exact rotation once, and exp adds a few u: the bound is 8 u (u = 2^-53).
 */
static void nonunit_quaternion(const sus_exact *ex)
{
    const double a = 2.0, n[3] = {2.0 / 7.0, -3.0 / 7.0, 6.0 / 7.0};
    const double xi[3] = {a * n[0], a * n[1], a * n[2]}, c[] = {0.5, 2.0, 1e-3, 1e3};
    double E[3][3], I3[3][3];
    sus_so3_exp(xi, E);
    sus_mat3_identity(I3);
    for (int k = 0; k < 4; k++) {
        sus_refatt ra;
        sus_refatt_init(&ra, ex, 0.0, I3);
        ra.q[0] = c[k] * cosl(a / 2.0L);
        for (int i = 0; i < 3; i++)
            ra.q[i + 1] = c[k] * sinl(a / 2.0L) * n[i];
        double R[3][3];
        sus_refatt_advance(&ra, ra.t, R);
        const double d = sus_mat3_dist(R, E), bound = 8.0 * DBL_EPSILON / 2.0;
        CHECK(d <= bound,
              "R(q) for |q| = %g: %.2e from exp(a n^) (bound 8u = %.2e): q is divided by |q|^2",
              c[k], d, bound);
    }
}

/* A stretch of 2^62 steps or more before the steady tail cannot run: R is non-finite, at once. A
 * body whose I31, I32 are 1e-20 approaches its steady rotation at k ~ 1e-20, so its tail starts
 * near t = 1e21, past 2^62 steps of h ~ 1; a time that is no number gives no answer either. Within
 * the tail any time is served at once (the tail is closed-form): a short run and t = 1e30 on an
 * ordinary body stay finite. */
static void too_long_stretch(const sus_model *m, const double w0[2])
{
    double I[9] = {1, 0.1, 0.2, 0.1, 1, 0.2, 1e-20, 1e-20, 1}, w[2], R[3][3];
    char err[128];
    sus_model slow;
    if (sus_model_init(&slow, I, err, sizeof err) != 0) {
        CHECK(0, "a body with I31 = I32 = 1e-20: %s", err);
        return;
    }
    sus_refatt_precise(&slow, w0, 1e30, w, R);
    CHECK(none_finite(R),
          "reference to T = 1e30 on a body whose tail starts near 1e21: R not finite");
    sus_refatt_precise(m, w0, NAN, w, R);
    CHECK(none_finite(R), "reference to T = NaN: R not finite");
    const double T[] = {1.0, 1e30};
    for (int k = 0; k < 2; k++) {
        sus_refatt_precise(m, w0, T[k], w, R);
        CHECK(all_finite(R) && isfinite(w[0]) && isfinite(w[1]),
              "reference to T = %g: w and R finite", T[k]);
    }
}

/* Started at t0 = 0, the reference starts from w0 itself, not from the closed form's value at 0 (an
 * ulp or so off), so it is the same long-double computation as sus_refatt_precise: R(50) agrees to
 * the rounding of q(I) (exact) and of the nine entries, 2 u. */
static void start_from_w0(const sus_model *m, const sus_exact *ex, const char *name)
{
    double I3[3][3], R[3][3], Rp[3][3], w[2];
    sus_mat3_identity(I3);
    sus_refatt ra;
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, 50.0, R);
    sus_refatt_precise(m, ex->w0, 50.0, w, Rp);
    const double d = sus_mat3_dist(R, Rp), bound = 2.0 * DBL_EPSILON / 2.0;
    CHECK(d <= bound,
          "%s: R(50) started at t0 = 0 is %.1e from the run started from w0 (bound 2u = %.1e)",
          name, d, bound);
}

/* sus_refatt_at restarted at t0 = 3 tau from R(3 tau) as the run from 0 gives it lands where that
 * run does at t = 5 tau: they differ only by the roundings of the restart (R(3 tau) in double, u(3
 * tau) in long double), a few u carried over the stretch: 1e-14. tau = 1 on the family's bodies (3
 * is a grid point of both runs); on the near-singular ones below it is inside their transient,
 * where u(t0) formed as L^T of the double closed form w(t0) would carry r |L| |L^{-1}| u. */
static void restart_at(const sus_exact *ex, const char *name, double tau)
{
    double I3[3][3], R3[3][3], R5[3][3], Rr[3][3];
    sus_mat3_identity(I3);
    sus_refatt a, b;
    sus_refatt_init(&a, ex, 0.0, I3);
    sus_refatt_at(&a, 3.0 * tau, R3);
    sus_refatt_at(&a, 5.0 * tau, R5);
    sus_refatt_init(&b, ex, 3.0 * tau, R3);
    sus_refatt_at(&b, 5.0 * tau, Rr);
    const double d = sus_mat3_dist(R5, Rr);
    CHECK(d <= 1e-14,
          "%s: R(5 tau) restarted at t0 = 3 tau is %.1e from the run from 0, tau = %g (bound "
          "1e-14)",
          name, d, tau);
}

/* I12 = I21 = 1 - d, third row (-1, -1), w0 = (1, 1): |w| grows to about 2 / sqrt(2 d) along I_m's
 * soft axis, with tau = 0.3 / k. */
static void restart_near_singular(double d, const char *name)
{
    body b = {{1.0, 1.0 - d, 0.0, 1.0 - d, 1.0, 0.0, -1.0, -1.0, 1.0}, {1.0, 1.0}, ""};
    sus_model m;
    sus_exact ex;
    snprintf(b.name, sizeof b.name, "%s", name);
    if (check_body_model(&b, &m) || sus_exact_init(&ex, &m, b.w0))
        return;
    restart_at(&ex, b.name, 0.3 / ex.k);
}

/* The reference's Cholesky coordinates (refattitude.c) in long double, with |I_m| and v2's
 * numerator I11 I32 - I21 I31 formed as a b - c d in two roundings of 2^-64 = uL/2 (uL =
 * LDBL_EPSILON) whatever their cancellation, against the exact differences (check_exact.h): l11 l22
 * = sqrt|I_m| within 3 uL
 * (|I_m| uL and its square root uL, the division by l11 uL/2, here the product and sqrtl uL/2
 * more), and v2 l11 l11 l22 = I11 I32 - I21 I31 within 4 uL (the numerator uL, l11 sd and the
 * division uL, here l11 l22 and two products 2 uL). Formed plainly they would err by uL/2 of I21^2
 * or |I21 I31|, cond(I_m) times more on a near-singular I_m: the stiff bodies "cond" and "all" show
 * it. */
static void cholesky_coordinates(const sus_exact *ex, const char *name)
{
    const double(*I)[3] = ex->model->I, I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const long double uL = LDBL_EPSILON;
    sus_refatt ra;
    sus_refatt_init(&ra, ex, 0.0, I3);
    const sus_refatt_chol *c = &ra.chol;
    const long double sd = sqrtl(check_cross_diff_exact(I[0][0], I[1][1], I[1][0], I[1][0]));
    const long double x = check_cross_diff_exact(I[0][0], I[2][1], I[1][0], I[2][0]),
                      l = c->l11 * c->l22;
    const double dl = (double)(fabsl(l - sd) / (sd * uL)),
                 dv = (double)(fabsl(c->v[1] * c->l11 * l - x) / (fabsl(x) * uL));
    CHECK(dl <= 3.0 && dv <= 4.0,
          "%s: the reference's l11 l22 against sqrt|I_m| exact: %.2g uL (at most 3 "
          "uL); v2 l11^2 l22 against I11 I32 - I21 I31 exact: %.2g uL (at most 4 uL)",
          name, dl, dv);
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        start_from_w0(&m, &ex, b.name);
        restart_at(&ex, b.name, 1.0);
        cholesky_coordinates(&ex, b.name);
        if (k == 1) { /* neither edge depends on the body: once, on a general one */
            nonunit_quaternion(&ex);
            too_long_stretch(&m, b.w0);
        }
    }
    restart_near_singular(1e-9, "I12 = 1 - 1e-9");
    restart_near_singular(1e-12, "I12 = 1 - 1e-12");
    return check_summary("test_refattitude");
}
