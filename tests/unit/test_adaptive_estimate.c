/* The rules taylor-adaptive states for itself (step_taylor_adaptive.c), each checked against its
 * statement, not against the code:
 *  - the order is the smallest even p in 6 .. 20 with p >= -ln(tol)/2 + 1 + 2 (Jorba & Zou's
 *    -ln(tol)/2 + 1, two orders up): at each tol where the bound crosses an even integer, tol 1e-6
 *    above it gives that order and 1e-6 below it the next (the bound moves by 5e-7 there);
 *  - a step's error estimate (stats.residual) is max over the two groups, w rows and quaternion
 *    rows, of T_p^2 / T_{p-1}, T_n = the largest entry of the group's coefficient n scaled by h^n.
 *    The coefficients are computed here in long double from (ContDyn) and from q' = 1/2 q (x) (0, w),
 *    dq(0) = 1; on every body of the family, from w0 and from w0 turned, at three tolerances and
 *    three steps, the step's estimate matches to 1e-10 relative (the double recursion's rounding,
 *    a few u times p per coefficient, tripled by the ratio, with room: the estimate only sizes
 *    steps). A group's entry left out or a coefficient index off by one moves it by O(1). */
#include "check_body.h"
#include "reconstruct.h"
#include "taylor.h"

#include <math.h>

typedef long double ld;
#define NMAX 24

static void order_rule(void)
{
    int bad = 0;
    for (int p = 6; p <= 20; p += 2) {
        const double tol = exp(-2.0 * (p - 3)); /* -ln(tol)/2 + 3 = p */
        const int above = sus_step_taylor_adaptive_order(tol * (1.0 + 1e-6));
        const int below = sus_step_taylor_adaptive_order(tol * (1.0 - 1e-6));
        bad += above != p || below != (p < 20 ? p + 2 : 20);
    }
    const int loose = sus_step_taylor_adaptive_order(0.5), tight = sus_step_taylor_adaptive_order(1e-300);
    CHECK(bad == 0 && loose == 6 && tight == 20, "taylor-adaptive's order is the smallest even p in 6 .. 20 "
          "with p >= -ln(tol)/2 + 3: %d of 8 boundaries off; tol 0.5 -> %d (6), 1e-300 -> %d (20)",
          bad, loose, tight);
}

/* The largest entry of coefficient n of each group, scaled by h^n, up to order p. */
static void group_sizes(const double I[9], const double w0[2], ld h, int p, ld Tw[], ld Tq[])
{
    const ld d = (ld)I[0] * I[4] - (ld)I[1] * I[3];
    ld w[NMAX + 1][2] = {{w0[0], w0[1]}}, q[NMAX + 1][4] = {{1, 0, 0, 0}}, hn = 1;
    for (int n = 0; n <= p; n++) {
        if (n < p) {
            ld f[2] = {0, 0}, g[4] = {0, 0, 0, 0};
            for (int j = 0; j <= n; j++) {
                const ld *a = w[n - j], c = (ld)I[6] * w[j][0] + (ld)I[7] * w[j][1]; /* I_3i w_i */
                f[0] += c * (-(ld)I[1] * a[0] - (ld)I[4] * a[1]) / d;
                f[1] += c * ((ld)I[0] * a[0] + (ld)I[3] * a[1]) / d;
                const ld *Q = q[j];
                g[0] += -Q[1] * a[0] - Q[2] * a[1];
                g[1] += Q[0] * a[0] - Q[3] * a[1];
                g[2] += Q[0] * a[1] + Q[3] * a[0];
                g[3] += Q[1] * a[1] - Q[2] * a[0];
            }
            for (int k = 0; k < 2; k++)
                w[n + 1][k] = f[k] / (n + 1);
            for (int k = 0; k < 4; k++)
                q[n + 1][k] = g[k] / (2 * (n + 1));
        }
        Tw[n] = fmaxl(fabsl(w[n][0]), fabsl(w[n][1])) * hn;
        Tq[n] = fmaxl(fmaxl(fabsl(q[n][0]), fabsl(q[n][1])), fmaxl(fabsl(q[n][2]), fabsl(q[n][3]))) * hn;
        hn *= h;
    }
}

static ld group_estimate(ld last2, ld last)
{
    return last2 > 0 ? last * last / last2 : last;
}

/* |estimate - expected| / expected for one step from w; -1 if the step fails. */
static double estimate_error(const sus_model *m, const double I[9], const double w0[2], double tol, double h)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    sus_tol_work *wk = ops->alloc(m, tol, w0);
    double w[3] = {w0[0], w0[1], 0.0}, t = 0.0, lam;
    sus_attitude att;
    sus_attitude_identity(&att);
    sus_stepper_stats st;
    const int rc = wk ? ops->step(wk, h, &t, w, &lam, &att, &st) : -1;
    ops->free(wk);
    if (rc != SUS_STEPPER_OK)
        return -1.0;
    const int p = ops->order(tol);
    ld Tw[NMAX + 1], Tq[NMAX + 1];
    group_sizes(I, w0, st.det, p, Tw, Tq); /* st.det: the step taken */
    const ld e = fmaxl(group_estimate(Tw[p - 1], Tw[p]), group_estimate(Tq[p - 1], Tq[p]));
    return (double)(fabsl(st.residual - e) / e);
}

static void estimates(void)
{
    const double tols[3] = {1e-4, 1e-9, 1e-14}, steps[3] = {0.05, 0.4, 1.5};
    double worst = 0.0;
    int n = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        for (int j = 0; j < 2; j++) {
            /* w0, and w0 turned by a quarter turn (the other component leads) */
            const double w0[2] = {j ? -b.w0[1] : b.w0[0], j ? b.w0[0] : b.w0[1]};
            for (int i = 0; i < 9; i++) {
                const double d = estimate_error(&m, b.I, w0, tols[i / 3], steps[i % 3]);
                worst = d > worst || d < 0.0 || isnan(d) ? (d < 0.0 ? INFINITY : d) : worst;
                n++;
            }
        }
    }
    CHECK(worst <= 1e-10, "taylor-adaptive's estimate is max over the w and quaternion rows of T_p^2/T_{p-1} "
          "on %d steps (%d bodies x 2 states x 3 tol x 3 steps): worst relative difference %.2g (at most "
          "1e-10)", n, BODIES_COUNT, worst);
}

/* Every accepted step stays inside 0.99 times the radius the series is proved to converge in at its
 * start (sus_step_taylor_radius, checked against quadrature in test_taylor_radius), whatever the
 * estimate allows: at tol 0.1 (order 6) and at tol 1e30, which no estimate exceeds, so that the
 * radius alone limits the steps as they try to grow five-fold; |w| = 3 times each body's w0, over
 * [0, 20]; the family and a body whose I_m is near singular (det 0.19, ||A|| about 10: the cheap
 * radius test K |w| h < 1 is then far from the bound a slip in K would give). */
static void steps_within_radius(void)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    double worst = 0.0;
    int n = 0, failed = 0;
    for (int i = 0; i < 2 * BODIES_COUNT + 2; i++) {
        const int k = i / 2;
        body b = {{1.0, 0.9, 0.3, 0.9, 1.0, 0.2, 0.1, 0.4, 1.0}, {0.3, -0.5}, "near-singular"};
        sus_model m;
        if (k < BODIES_COUNT)
            body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        double w[3] = {3.0 * b.w0[0], 3.0 * b.w0[1], 0.0}, t = 0.0, lam;
        sus_attitude att;
        sus_attitude_identity(&att);
        sus_tol_work *wk = ops->alloc(&m, i % 2 ? 1e30 : 0.1, w);
        while (wk && t < 20.0 && n < 100000) {
            const double rho = sus_step_taylor_radius(&m, w);
            sus_stepper_stats st;
            if (ops->step(wk, 20.0, &t, w, &lam, &att, &st) != SUS_STEPPER_OK) {
                failed++;
                break;
            }
            worst = fmax(worst, st.det / rho);
            n++;
        }
        failed += !wk;
        ops->free(wk);
    }
    CHECK(failed == 0 && worst <= 0.99 * (1.0 + 1e-15), "taylor-adaptive at tol 0.1 and 1e30, |w| = 3 |w0|, "
          "on %d bodies and a near-singular I_m: %d steps, the longest %.4g of the proved radius (at most "
          "0.99), %d runs failed", BODIES_COUNT, n, worst, failed);
}

int main(void)
{
    order_rule();
    estimates();
    steps_within_radius();
    return check_summary("test_adaptive_estimate");
}
