/* The rules taylor-adaptive states for itself (step_taylor_adaptive.c), each checked against its
 * statement, not against the code:
 *  - the order is the smallest even p in 6 .. 20 with p >= -ln(tol)/2 + 1 + 2 (Jorba & Zou's
 *    -ln(tol)/2 + 1, two orders up): at each tol where the bound crosses an even integer, tol 1e-6
 *    above it gives that order and 1e-6 below it the next (the bound moves by 5e-7 there);
 *  - a step's error estimate (stats.residual) is max over the two groups, w rows and quaternion
 *    rows, of T_p^2 / T_{p-1}, T_n = the largest entry of the group's coefficient n scaled by h^n.
 *    The coefficients are computed here in long double from (ContDyn) and from q' = 1/2 q (x) (0,
 * w), dq(0) = 1; on every body of the family, from w0 and from w0 turned, at three tolerances and
 *    three steps, the step's estimate matches to the double recursion's rounding, 12 p u cond(I_m)
 *    relative (estimate_error). A group's entry left out or a coefficient index off by one moves it
 *    by O(1). */
#include "check_body.h"
#include "check_exact.h"
#include "driver.h"
#include "exact.h"
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
    const int loose = sus_step_taylor_adaptive_order(0.5),
              tight = sus_step_taylor_adaptive_order(1e-300);
    CHECK(bad == 0 && loose == 6 && tight == 20,
          "taylor-adaptive's order is the smallest even p in 6 .. 20 "
          "with p >= -ln(tol)/2 + 3: %d of 8 boundaries off; tol 0.5 -> %d (6), 1e-300 -> %d (20)",
          bad, loose, tight);
}

/* The largest entry of coefficient n of each group, scaled by h^n, up to order p, in long double
 * from (ContDyn) with |I_m| exact (check_exact.h) and from q' = 1/2 q (x) (0, w), q(0) = 1. */
static void group_sizes(const double I[9], const double w0[2], ld h, int p, ld Tw[], ld Tq[])
{
    const ld d = check_cross_diff_exact(I[0], I[4], I[1], I[3]);
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
        Tq[n] =
            fmaxl(fmaxl(fabsl(q[n][0]), fabsl(q[n][1])), fmaxl(fabsl(q[n][2]), fabsl(q[n][3]))) *
            hn;
        hn *= h;
    }
}

static ld group_estimate(ld last2, ld last) { return last2 > 0 ? last * last / last2 : last; }

/* cond(I_m), the ratio of its eigenvalues. */
static double condition(const double I[9])
{
    const double mid = 0.5 * (I[0] + I[4]), rad = hypot(0.5 * (I[0] - I[4]), I[1]);
    return (mid + rad) * (mid + rad) / (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]);
}

/* |estimate - expected| over its rounding for one step from w; -1 if the step fails. The double
 * recursion rounds each coefficient by a few u (4 u) per order it builds on, so p of them; where fA
 * w_n cancels (fA = J I_m / |I_m|: |fA w| can be |fA| |w| / cond(I_m)) that is relative to |fA|
 * |w_n|, up to cond(I_m) times the coefficient; T_p^2 / T_{p-1} triples it: 12 p u cond(I_m)
 * relative. */
static double estimate_error(const sus_model *m, const double I[9], const double w0[2], double tol,
                             double h)
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
    return (double)(fabsl(st.residual - e) / (e * 12 * p * SUS_U * condition(I)));
}

/* On every body, from w0 and w0 turned, at three tolerances and three steps 0.05, 0.4 and 1.5 times
 * the body's own time (check_body_time; the proved radius may shorten them). */
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
        const double s = check_body_time(&m, b.w0);
        for (int j = 0; j < 2; j++) {
            /* w0, and w0 turned by a quarter turn (the other component leads) */
            const double w0[2] = {j ? -b.w0[1] : b.w0[0], j ? b.w0[0] : b.w0[1]};
            for (int i = 0; i < 9; i++) {
                const double d = estimate_error(&m, b.I, w0, tols[i / 3], steps[i % 3] * s);
                worst = d > worst || d < 0.0 || isnan(d) ? (d < 0.0 ? INFINITY : d) : worst;
                n++;
            }
        }
    }
    CHECK(worst <= 1.0,
          "taylor-adaptive's estimate is max over the w and quaternion rows of "
          "T_p^2/T_{p-1} on %d steps (%d bodies x 2 states x 3 tol x 3 steps): "
          "worst difference %.2g of its rounding, 12 p u cond(I_m) (at most 1)",
          n, BODIES_COUNT, worst);
}

/* One step of taylor-adaptive from (t, w) towards t_end with a fresh workspace, or continuing wk.
 */
static int one_step(sus_tol_work *wk, double t_end, double *t, double w[3], sus_stepper_stats *st)
{
    double lam;
    sus_attitude att;
    sus_attitude_identity(&att);
    return sus_step_taylor_adaptive_type.tol->step(wk, t_end, t, w, &lam, &att, st);
}

/* The next step is h min(5, 0.9 (tol/err)^{1/(p+1)}) (Hairer, Norsett & Wanner I, II.4), read off
 * the second step when it is accepted at once and no radius or interval end shortens it; and a
 * rejected try is retried at h max(0.1, min(0.9, 0.9 (tol/err)^{1/(p+1)})), with err the estimate
 * (computed here as in estimates()) of the first try, read off a step rejected once. Both to
 * 1e-12 relative (pow's rounding and the estimate's, 1e-14, with room). */
static void step_size_rules(void)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    double wn = 0.0, wr = 0.0;
    int nn = 0, nr = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        for (int j = 0; j < 2; j++) {
            const double tol = j ? 1e-12 : 1e-6;
            const int p = ops->order(tol);
            sus_stepper_stats s1, s2;
            double w[3] = {b.w0[0], b.w0[1], 0.0}, t = 0.0;
            sus_tol_work *wk = ops->alloc(&m, tol, w);
            if (!wk || one_step(wk, 1e3, &t, w, &s1) != SUS_STEPPER_OK) {
                wn = INFINITY;
                ops->free(wk);
                continue;
            }
            const double want = s1.det * fmin(5.0, 0.9 * pow(tol / s1.residual, 1.0 / (p + 1)));
            const double rho = sus_step_taylor_radius(&m, w);
            if (one_step(wk, 1e3, &t, w, &s2) == SUS_STEPPER_OK && s2.iterations == 0 &&
                want < 0.98 * rho) {
                wn = fmax(wn, fabs(s2.det - want) / want);
                nn++;
            }
            ops->free(wk);
            /* a first try of 0.9 rho (the interval's end) at a tolerance it misses */
            const double h0 = 0.9 * sus_step_taylor_radius(&m, b.w0);
            ld Tw[NMAX + 1], Tq[NMAX + 1];
            group_sizes(b.I, b.w0, h0, p, Tw, Tq);
            const double e0 =
                (double)fmaxl(group_estimate(Tw[p - 1], Tw[p]), group_estimate(Tq[p - 1], Tq[p]));
            const double sh = fmax(0.1, fmin(0.9, 0.9 * pow(tol / e0, 1.0 / (p + 1))));
            double w2[3] = {b.w0[0], b.w0[1], 0.0};
            t = 0.0;
            wk = ops->alloc(&m, tol, w2);
            if (wk && e0 > tol && one_step(wk, h0, &t, w2, &s1) == SUS_STEPPER_OK &&
                s1.iterations == 1) {
                wr = fmax(wr, fabs(s1.det - h0 * sh) / (h0 * sh));
                nr++;
            }
            ops->free(wk);
        }
    }
    CHECK(nn >= BODIES_COUNT && wn <= 1e-12,
          "taylor-adaptive's next step is h min(5, 0.9 (tol/err)^(1/(p+1))) "
          "on %d second steps (at least %d): worst relative difference %.2g (at most 1e-12)",
          nn, BODIES_COUNT, wn);
    CHECK(nr >= BODIES_COUNT && wr <= 1e-12,
          "taylor-adaptive's retry is h max(0.1, min(0.9, 0.9 (tol/err)^(1/(p+1)))) on %d steps "
          "rejected once (at least %d): worst relative difference %.2g (at most 1e-12)",
          nr, BODIES_COUNT, wr);
}

/* Every accepted step stays inside 0.99 times the radius the series is proved to converge in at its
 * start (sus_step_taylor_radius, checked against quadrature in test_taylor_radius), whatever the
 * estimate allows: at tol 0.1 (order 6) and at tol 1e30, which no estimate exceeds, so that the
 * radius alone limits the steps as they try to grow five-fold; |w| = 3 times each body's w0, over
 * [0, 20 s] in the body's own time s (check_body_time, at most 10^4 steps a run); the family and a
 * body whose I_m is near singular (det 0.19, ||A|| about 10: the cheap radius test K |w| h < 1 is
 * then far from the bound a slip in K would give). A run that settles on the steady rotation
 * (step_taylor_adaptive.c) ends in one step that sums the quaternion's series for a constant w in
 * closed form, whose radius is infinite: that step, the last of its run with w the steady rotation
 * (the closed form's limit, exact.h, to 64 u), is counted apart; every run must still take series
 * steps first (at least one each): each starts from whichever of
 * +-3 w0 has g(w) = b . (A w) >= 0, the repelling side, from which the motion crosses the ellipse
 * (the radius is the same at -w). */
static int settled_on(const sus_model *m, const double w0[2], const double w[3], double t,
                      double t_end)
{
    sus_exact ex;
    double ws[2];
    sus_exact_init(&ex, m, w0);
    sus_exact_limit(&ex, ws);
    return t == t_end && hypot(w[0] - ws[0], w[1] - ws[1]) <= 64.0 * SUS_U * hypot(ws[0], ws[1]);
}

static void steps_within_radius(void)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    double worst = 0.0;
    int n = 0, failed = 0, settled = 0, runs = 0;
    for (int i = 0; i < 2 * BODIES_COUNT + 2; i++) {
        const int k = i / 2;
        body b = {{1.0, 0.9, 0.3, 0.9, 1.0, 0.2, 0.1, 0.4, 1.0}, {0.3, -0.5}, "near-singular"};
        sus_model m;
        if (k < BODIES_COUNT)
            body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        const double *I = b.I, x = b.w0[0], y = b.w0[1];
        const double g = I[6] * (-I[1] * x - I[4] * y) + I[7] * (I[0] * x + I[3] * y); /* |I_m| g */
        const double s =
            g * (I[0] * I[4] - I[1] * I[3]) < 0.0 ? -3.0 : 3.0; /* g(w) >= 0: see above */
        double w[3] = {s * b.w0[0], s * b.w0[1], 0.0}, t = 0.0, lam;
        const double w0[2] = {w[0], w[1]}, t_end = 20.0 * check_body_time(&m, w);
        sus_attitude att;
        sus_attitude_identity(&att);
        sus_tol_work *wk = ops->alloc(&m, i % 2 ? 1e30 : 0.1, w);
        int series = 0;
        for (int steps = 0; wk && t < t_end && steps < 10000; steps++) {
            const double rho = sus_step_taylor_radius(&m, w);
            sus_stepper_stats st;
            if (ops->step(wk, t_end, &t, w, &lam, &att, &st) != SUS_STEPPER_OK) {
                failed++;
                break;
            }
            if (settled_on(&m, w0, w, t, t_end) && st.residual == 0.0) {
                settled++;
                continue;
            }
            worst = fmax(worst, st.det / rho);
            n++;
            series++;
        }
        failed += !wk || series == 0;
        runs++;
        ops->free(wk);
    }
    CHECK(failed == 0 && worst <= 0.99 * (1.0 + 1e-15),
          "taylor-adaptive at tol 0.1 and 1e30, |w| = 3 |w0|, on %d bodies and a near-singular "
          "I_m: %d series steps, the longest %.4g of the proved radius (at most 0.99), %d of "
          "%d runs failed or took no series step (%d settled on the steady rotation)",
          BODIES_COUNT, n, worst, failed, runs, settled);
}

/* The unit top right singular vector of (ContDyn)'s A = [-I12 -I22; I11 I21] / |I_m| (the
 * eigenvector of the largest eigenvalue of A^T A in closed form), from the printed entries. */
static void top_singular(const double I[9], double v[2])
{
    const double d =
        (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]); /* exact, rounded once */
    const double a = -I[1] / d, b = -I[4] / d, c = I[0] / d, e = I[3] / d;
    const double p = a * a + c * c, r = b * b + e * e, q = a * b + c * e;
    const double lam = 0.5 * (p + r) + hypot(0.5 * (p - r), q);
    const int first = fabs(lam - r) >= fabs(lam - p);
    const double x = first ? lam - r : q, y = first ? q : lam - p;
    v[0] = x / hypot(x, y);
    v[1] = y / hypot(x, y);
}

/* Where b and w lie along A's top singular vector the proved radius is exactly 1/(K |w|)
 * (test_taylor_radius), so the cheap test K |w| h < 1 has no slack: a step proposed at 1 + 1e-7 or
 * 1.2 times 1/(K |w|) must still be cut to 0.99 rho. On each body so turned, tol 1e30 (no estimate
 * binds, the proposal is five times the first step), |w| = 0.25 and 4 (both components above 1 in
 * size for some bodies), from a first state sized so that the proposal lands there. A = J I_m /
 * |I_m| (J the quarter turn) and v is an eigenvector of I_m, so g(w) = b . (A w) = 0 there, a
 * rounding's sign from settling (step_taylor_adaptive.c settles where g < 0, at tol 1e30 at once):
 * b is turned 1e-9 off v to the side where g > 0, which moves the radius by O(1e-18) only. */
static void cheap_test_window(void)
{
    const double ratio[2] = {1.0 + 1e-7, 1.2}, size[2] = {0.25, 4.0};
    double worst = 0.0;
    int n = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        double v[2];
        body_get(k, &b);
        top_singular(b.I, v);
        const double nb = hypot(b.I[6], b.I[7]), *I = b.I;
        /* the sign of v_perp . A v, v_perp = (-v2, v1), A as in top_singular (|I_m| > 0) */
        const double av0 = -I[1] * v[0] - I[4] * v[1], av1 = I[0] * v[0] + I[3] * v[1];
        const double side = -v[1] * av0 + v[0] * av1 > 0.0 ? 1e-9 : -1e-9;
        b.I[6] = nb * (v[0] - side * v[1]);
        b.I[7] = nb * (v[1] + side * v[0]);
        if (check_body_model(&b, &m) != 0)
            continue;
        for (int i = 0; i < 4; i++) {
            const double a = size[i / 2], s0 = 4.95 * a / ratio[i % 2] * (1.0 - 1e-12);
            double w[3] = {s0 * v[0], s0 * v[1], 0.0}, t = 0.0;
            sus_stepper_stats st;
            sus_tol_work *wk = sus_step_taylor_adaptive_type.tol->alloc(&m, 1e30, w);
            const int ok1 = wk && one_step(wk, 1e30, &t, w, &st) == SUS_STEPPER_OK;
            w[0] = a * v[0];
            w[1] = a * v[1];
            const double rho = sus_step_taylor_radius(&m, w);
            const int ok2 = ok1 && one_step(wk, 1e30, &t, w, &st) == SUS_STEPPER_OK;
            worst = ok2 ? fmax(worst, st.det / rho) : INFINITY;
            n++;
            sus_step_taylor_adaptive_type.tol->free(wk);
        }
    }
    CHECK(
        worst <= 0.99 * (1.0 + 1e-12),
        "taylor-adaptive with b and w along A's top singular vector, a step "
        "proposed just past 1/(K |w|) = rho: %d cases, the longest step %.4g of rho (at most 0.99)",
        n, worst);
}

/* A step that reaches t_end ends exactly there (stepper.h), also where t + (t_end - t) rounds
 * away from t_end; and a series that overflows (|w| = 1e160: the products in the recursion exceed
 * the doubles) fails with SUS_STEPPER_REJECTED after MAX_TRIES = 12 tries, each retry at most 0.9
 * times as long as the try before (a NaN estimate asks for 0.9, an infinite one for 0.1). */
static void interval_end_and_overflow(void)
{
    sus_model m;
    body b;
    body_get(1, &b);
    if (check_body_model(&b, &m) != 0)
        return;
    int exact = 0, rounding = 0, cases = 0;
    for (int i = 1; i <= 40; i++) {
        const double t0 = i / 97.0, te = 1.0 + i / 89.0; /* t_end - t0 rounded: t_end > 2 t0 */
        volatile double d = te - t0;
        rounding += t0 + d != te;
        double w[3] = {b.w0[0], b.w0[1], 0.0}, t = t0;
        sus_stepper_stats st;
        sus_tol_work *wk = sus_step_taylor_adaptive_type.tol->alloc(&m, 1e-4, w);
        exact += wk && one_step(wk, te, &t, w, &st) == SUS_STEPPER_OK && t == te;
        cases++;
        sus_step_taylor_adaptive_type.tol->free(wk);
    }
    CHECK(exact == cases && rounding > 0,
          "a taylor-adaptive step that reaches t_end ends at t_end exactly: %d "
          "of %d, %d of them where t + (t_end - t) rounds off t_end",
          exact, cases, rounding);
    double w[3] = {1e160 * b.w0[0], 1e160 * b.w0[1], 0.0}, t = 0.0;
    const double h0 = 0.99 * sus_step_taylor_radius(&m, w);
    sus_stepper_stats st;
    sus_tol_work *wk = sus_step_taylor_adaptive_type.tol->alloc(&m, 1e-8, w);
    const int rc = wk ? one_step(wk, 1.0, &t, w, &st) : -1;
    sus_step_taylor_adaptive_type.tol->free(wk);
    CHECK(rc == SUS_STEPPER_REJECTED && st.det <= pow(0.9, 11) * h0 * (1.0 + 1e-12),
          "|w| = 1e160: the series overflows; the step fails REJECTED (%d) "
          "after its tries shrank to %.3g of the first (at most 0.9^11 = "
          "0.314: eleven retries, each at most 0.9 times the last)",
          rc, rc == SUS_STEPPER_REJECTED ? st.det / h0 : NAN);
}

/* The driver's report counts the rejected tries of the run (stats.iterations of each step): their
 * total and their largest per step, against the same steps taken by hand, over [0, 20 s] in the
 * body's own time (check_body_time), at tol 1e-10 and 1e-14, where the first try (0.99 rho) is
 * rejected on the paper's body. A body whose proved radius holds every step far inside what the
 * tolerance allows has no rejected try to count (the near-singular I_m: the estimate at the radius
 * is below 1e-16): a NOTE says so, and its totals are compared at 0. Returns the number of
 * differences; *max the largest. */
static int report_against_hand(const body *b, const sus_model *m, double tol, int *max)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    const double t_end = 20.0 * check_body_time(m, b->w0);
    const sus_tol_config cfg = {m, &sus_step_taylor_adaptive_type, tol, t_end, 0.0, 0};
    sus_row last;
    sus_run_report rep;
    const int rc = sus_run_tol(&cfg, b->w0, sus_keep_last, &last, &rep);
    double w[3] = {b->w0[0], b->w0[1], 0.0}, t = 0.0;
    long total = 0;
    *max = 0;
    sus_tol_work *wk = ops->alloc(m, cfg.tol, b->w0);
    for (sus_stepper_stats st;
         wk && t < t_end && one_step(wk, t_end, &t, w, &st) == SUS_STEPPER_OK;) {
        total += st.iterations;
        *max = st.iterations > *max ? st.iterations : *max;
    }
    ops->free(wk);
    return rc != SUS_RUN_OK || rep.sus_newton_iterations != total || rep.max_iterations != *max;
}

static void driver_report(void)
{
    int bad = 0, most = 0, paper = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        int seen = 0;
        for (int j = 0; j < 2; j++) {
            int max;
            bad += report_against_hand(&b, &m, j ? 1e-14 : 1e-10, &max);
            seen = max > seen ? max : seen;
        }
        paper = k == 0 ? seen : paper;
        most = seen > most ? seen : most;
        if (seen == 0)
            printf("NOTE %s: no try rejected at tol 1e-10 or 1e-14 (every step held by the proved "
                   "radius): rejections compared at 0\n",
                   b.name);
    }
    CHECK(bad == 0 && paper > 0,
          "sus_run_tol reports the total and the largest number of rejected tries "
          "per step as taken by hand, on %d bodies (tol 1e-10 and 1e-14, [0, 20 "
          "s], at most %d per step, %d on the paper's body): %d differ",
          BODIES_COUNT, most, paper, bad);
}

static int stop_after_three(void *ctx, const sus_row *row)
{
    (void)row;
    return ++*(int *)ctx >= 3; /* non-zero: stop */
}

/* An emit that asks to stop ends the run with SUS_RUN_STOPPED after exactly that row, its
 * workspace freed once (a second free would abort here; a missing one is LeakSanitizer's, SAN=1).
 */
static void driver_stops(void)
{
    sus_model m;
    body b;
    body_get(2, &b);
    if (check_body_model(&b, &m) != 0)
        return;
    const sus_tol_config cfg = {&m, &sus_step_taylor_adaptive_type, 1e-8, 50.0, 0.5, 0};
    sus_run_report rep;
    int rows = 0;
    const int rc = sus_run_tol(&cfg, b.w0, stop_after_three, &rows, &rep);
    CHECK(rc == SUS_RUN_STOPPED && rows == 3,
          "sus_run_tol stops when emit asks, after its row: rc %d (STOPPED "
          "is %d), %d rows (3)",
          rc, SUS_RUN_STOPPED, rows);
}

/* A run given a budget of steps stops short of t_end with SUS_STEPPER_STEP_LIMIT, reporting the
 * step after the budget, the time reached and the length of the last step taken (stats.det),
 * against the same steps taken by hand. */
static void driver_budget(void)
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    sus_model m;
    body b;
    body_get(3, &b);
    if (check_body_model(&b, &m) != 0)
        return;
    const sus_tol_config cfg = {&m, &sus_step_taylor_adaptive_type, 1e-9, 50.0, 0.0, 5};
    sus_row last;
    sus_run_report rep;
    const int rc = sus_run_tol(&cfg, b.w0, sus_keep_last, &last, &rep);
    double w[3] = {b.w0[0], b.w0[1], 0.0}, t = 0.0, t4 = 0.0;
    sus_stepper_stats st;
    sus_tol_work *wk = ops->alloc(&m, cfg.tol, b.w0);
    for (int i = 0; wk && i < 5 && one_step(wk, cfg.t_end, &t, w, &st) == SUS_STEPPER_OK; i++)
        t4 = i == 3 ? t : t4;
    ops->free(wk);
    CHECK(rc == SUS_RUN_STEP_FAILED && rep.status == SUS_STEPPER_STEP_LIMIT && rep.step == 6 &&
              rep.t == t && rep.stats.det == t - t4,
          "a budget of 5 steps: status %d (STEP_LIMIT %d), step %ld "
          "(6), t %.17g (%.17g by hand), last step %.17g (%.17g)",
          rep.status, SUS_STEPPER_STEP_LIMIT, rep.step, rep.t, t, rep.stats.det, t - t4);
}

int main(void)
{
    order_rule();
    estimates();
    steps_within_radius();
    step_size_rules();
    cheap_test_window();
    interval_end_and_overflow();
    driver_report();
    driver_stops();
    driver_budget();
    return check_summary("test_adaptive_rules");
}
