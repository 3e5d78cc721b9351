/* exact-attitude (src/methods/step_exact_attitude.c) and its closed-form helpers, on the paper's
 * body and every body of tests/unit/bodies.h:
 *   - exact_fast.h's w(t) (one exp) agrees with sus_exact_omega to a few roundings of w's scale;
 *   - exact_tail.h's bound is above the integral of |w - w_inf| (by quadrature of the closed form)
 *     and within the factor the derivation allows of it; its time gives the bound asked for;
 *   - each accepted step's local error (against the long-double reference's exact increment) is at
 *     most its estimate plus the step's round-off, and the error at t = 50 at most TOL plus the
 *     steps' round-off;
 *   - the tail: a run to T = 1e6 takes as many steps as one to T = 1e3 (the tail is one step), and
 *     the tail step, and a dense row inside it, is the steady rotation to ROUND_TAIL u, at T = 1e4,
 *     1e6 and 1e9 alike, against a rotation about w* derived from I_m and b with its angle in 113
 *     bits (check_steady.h; the method forms the angle in two doubles: in one, its error would be
 *     u T |w_inf|);
 *   - dense output half way through a step is within the step's estimate, and at its end it is
 *     the step's own state; a body with I31 = I32 = 0 (w constant) is one step, the rotation
 *     exp(T w0^).
 * Round-off allowances, fixed from counts of roundings before measuring:
 *   - ROUND_STEP = 34 u per step in dist(R, .): the quaternion product q (x) dq rounds each
 *     component by at most 4 u (four products summed), the sum of the series and the normalisation
 *     add 2 u, so |dq| moves by about 12 u, and dist <= 2 sqrt2 |dq|;
 *   - ROUND_W = 16 u r |L^{-1}|_F for w: w = L^{-T} u, |u| = r, and each of the two ways of
 * computing it rounds a handful of times (exact_fast.h), every rounding relative to that scale;
 *   - ROUND_C = 4 u r |v| for c = sigma r |v| sech s: both ways share s and exp(-|s|), and their
 *     sech (2E / (1 + E^2) against 2E (1 / (1 + E^2))) and the product with r |v| round at most
 *     twice each;
 *   - COND = 32 u per radian turned: a step that turns R by the angle theta = h |w| computes that
 *     angle in double, so its result carries about u theta (the problem's conditioning), and
 *     dist = sqrt2 angle for small angles. A step's allowance is ROUND_STEP u + COND u h
 *     max(|w(t0)|, |w(t1)|), a run's the sum over its steps;
 *   - ROUND_TAIL = 128 u for the tail step, whatever its angle: the half angle reduced to [-pi, pi]
 *     carries about three roundings of pi (10 u), so the angle 20 u and dist sqrt2 times that
 *     (28 u); the axis w_inf / |w_inf| carries ROUND_W's 16 u relative, which moves R by at most
 *     2 sqrt2 times it (45 u); the quaternion product and R from q, ROUND_STEP (34 u). */
#include "check.h"
#include "check_body.h"
#include "check_steady.h"
#include "driver.h"
#include "exact.h"
#include "exact_attitude.h"
#include "exact_fast.h"
#include "exact_tail.h"
#include "quaternion.h"
#include "refattitude.h"
#include "so3.h"
#include "taylor.h"

#include <math.h>
#include <string.h>

#define U SUS_U
#define ROUND_STEP 34.0
#define ROUND_TAIL 128.0
#define ROUND_W 16.0
#define COND 32.0
#define ROUND_C 4.0

static const sus_tol_ops *ops(void) { return sus_step_exact_attitude_type.tol; }

/* The family's bodies, then two of the paper's own altered to stress the step rule: "slow" with a
 * third row a tenth of the paper's (k ten times smaller: steps so long that the rotation over a
 * step, not w's singularity, bounds the series' terms) and "fast" with w0 eight times the paper's
 * (k and the rotation eight times larger); then two with I_m nearer singular than the family's
 * (I12 = 1 - 1e-9 and 1 - 1e-12, conditions 2e9 and 2e12) and a third row (-1, -1), w0 = (1, 1):
 * |w| grows to 4e4 and 1.4e6 along I_m's soft axis, where c(w) = -(w1 + w2) at the rounded w is
 * a cancellation that (ContDyn) multiplies by 1 / |I_m|. */
#define TEST_BODIES (BODIES_COUNT + 4)

static void test_body(int j, body *b)
{
    if (j < BODIES_COUNT) {
        body_get(j, b);
        return;
    }
    if (j >= BODIES_COUNT + 2) { /* I12 = I21 = 1 - d */
        const double d = j == BODIES_COUNT + 2 ? 1e-9 : 1e-12;
        *b = (body){{1.0, 1.0 - d, 0.0, 1.0 - d, 1.0, 0.0, -1.0, -1.0, 1.0}, {1.0, 1.0}, "sing"};
        return;
    }
    check_body_paper_variant(j == BODIES_COUNT, b);
}

/* |L^{-1}|_F r: the scale of w and of its roundings (exact.h's Cholesky factor). */
static double w_scale(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    return sqrt(a * a + b * b + c * c) * ex->r;
}

/* ---- the closed form with one exp ---- */

static void fast_omega_agrees(void)
{
    double worst = 0.0, worst_c = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        sus_exact_fast f;
        if (check_body_exact(k, &b, &m, &ex) || sus_exact_fast_init(&f, &ex))
            continue;
        const double span = 60.0 / fmax(ex.k, 1e-3); /* the whole transient and the tail */
        for (int i = 1; i <= 4000; i++) {
            double w1[2], w2[2];
            const double t = span * i / 4000.0, c = sus_exact_fast_omega_c(&f, t, w2);
            sus_exact_omega(&ex, t, w1);
            worst = fmax(worst, hypot(w1[0] - w2[0], w1[1] - w2[1]) / (ROUND_W * U * w_scale(&ex)));
            worst_c = fmax(worst_c, fabs(c - sus_exact_c(&ex, t)) / (ROUND_C * U * ex.cmax));
        }
    }
    CHECK(worst <= 1.0,
          "exact_fast's w(t) within %g u r |L^-1|_F of sus_exact_omega on %d bodies, t in (0, "
          "60/k]: worst %.3g of that",
          ROUND_W, BODIES_COUNT, worst);
    CHECK(worst_c <= 1.0,
          "exact_fast's c(t) within %g u r |v| of sus_exact_c on the same bodies and times (the "
          "sign sigma included): worst %.3g of that",
          ROUND_C, worst_c);
}

/* ---- the tail's bound ---- */

/* The integral of |w - w_inf| over [t, t + 60/k] by composite Simpson on n panels (the rest is
 * below e^{-60} of the bound). */
static double tail_integral(const sus_exact *ex, double t)
{
    const int n = 20000;
    const double len = 60.0 / ex->k, h = len / n;
    double winf[2], sum = 0.0;
    sus_exact_limit(ex, winf);
    for (int i = 0; i <= n; i++) {
        double w[2];
        sus_exact_omega(ex, t + i * h, w);
        const double g = hypot(w[0] - winf[0], w[1] - winf[1]);
        sum += g * (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0);
    }
    return sum * h / 3.0;
}

/* The smallest singular value of L^{-1} over |L^{-1}|_F: the derivation's bound uses |L^{-1}|_F
 * where |L^{-T} (u - u_inf)| may be as small as sigma_min |u - u_inf|. */
static double norm_ratio(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, d = 1.0 / ex->l22, c = -ex->l21 / (ex->l11 * ex->l22);
    const double fro2 = a * a + c * c + d * d, det = a * d;
    const double smax2 = 0.5 * (fro2 + sqrt(fro2 * fro2 - 4.0 * det * det));
    return fabs(det) / sqrt(smax2) / sqrt(fro2);
}

static void tail_bound_holds(void)
{
    double over = 0.0, under = INFINITY, inv = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        const double t0 = fmax(0.0, -ex.sigma * ex.s0 / ex.k); /* a(t) >= 0 from here on */
        for (int j = 0; j < 4; j++) {
            const double t = t0 + j * 5.0 / ex.k, B = sus_exact_tail_bound(&ex, t),
                         I = tail_integral(&ex, t);
            over = fmax(over, I / B);
            /* for a >= 0: |u - u_inf| >= 2 E / sqrt2, and |L^{-T} x| >= sigma_min |x| */
            under = fmin(under, I / (B * norm_ratio(&ex) / sqrt(2.0)));
        }
        for (int j = 0; j < 3; j++) {
            const double budget = pow(10.0, -4.0 - 5.0 * j);
            inv = fmax(
                inv,
                fabs(sus_exact_tail_bound(&ex, sus_exact_tail_time(&ex, budget)) / budget - 1.0));
        }
    }
    CHECK(over <= 1.0 + 1e-9,
          "the tail's bound is above the integral of |w - w_inf| (Simpson, 20000 panels) "
          "on %d bodies, 4 times each: largest integral / bound %.6f",
          BODIES_COUNT, over);
    CHECK(under >= 1.0 - 1e-9,
          "and not loose beyond the derivation's factor (sigma_min |L^-1|_F^-1 / sqrt2 "
          "for a >= 0): smallest integral / (bound x factor) %.4f",
          under);
    CHECK(inv <= 1e-12,
          "the bound at sus_exact_tail_time(budget) is the budget, 1e-4 ... 1e-14: worst "
          "relative difference %.3g",
          inv);
}

/* ---- steps against the reference ---- */

/* R0 Phi with Phi the reference's exact increment over [t0, t1]. */
static void exact_after(const sus_exact *ex, const double R0[3][3], double t0, double t1,
                        double R[3][3])
{
    double Phi[3][3];
    sus_refatt_increment(ex, t0, t1, Phi);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = R0[i][0] * Phi[0][j] + R0[i][1] * Phi[1][j] + R0[i][2] * Phi[2][j];
}

typedef struct {
    double local;  /* worst (local error - round-off) / estimate over steps */
    double dense;  /* the same for dense output half way through each step */
    double global; /* worst dist(R, R_ref)(T) / (TOL + the steps' round-off) */
    long steps;
} step_check;

/* A step's round-off allowance (the top of the file). */
static double step_roundoff(double h, const double w0[3], const double w1[3])
{
    return (ROUND_STEP + COND * h * fmax(hypot(w0[0], w0[1]), hypot(w1[0], w1[1]))) * U;
}

/* Dense output tau into the last step (from t0, where R was R0) against the reference's increment,
 * less its round-off: the terms past the last degree enter at theta = tau / h <= 1 as theta^n <= 1
 * times their size over the whole step, and the tail's integral of |w - w_inf| over [t*, t* + tau]
 * is within that over [t*, T], so the step's own estimate bounds this error too. */
static double dense_excess(const sus_tol_work *wk, const sus_exact *ex, const double R0[3][3],
                           double t0, double tau, const double w0[3], const sus_attitude *att)
{
    double wd[3], ld, Rd[3][3], Re[3][3];
    sus_attitude ad = *att;
    ops()->dense(wk, t0 + tau, wd, &ld, &ad);
    sus_attitude_get(&ad, Rd);
    exact_after(ex, R0, t0, t0 + tau, Re);
    const double excess = sus_so3_dist(Re, Rd) - step_roundoff(tau, w0, wd);
    return excess > 0.0 ? excess : 0.0;
}

/* One run to T at tol, each step's local error against its estimate; Rr: the reference R(T). */
static void run_checked(const sus_model *m, const double w0[2], double tol, double T,
                        double Rr[3][3], step_check *c)
{
    sus_exact ex;
    sus_exact_init(&ex, m, w0);
    sus_tol_work *wk = ops()->alloc(m, tol, w0);
    double t = 0.0, w[3] = {w0[0], w0[1], 0.0}, lam, R[3][3], Rn[3][3], Re[3][3];
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    long n = 0;
    double round = 0.0;
    while (wk && t < T) {
        const double t0 = t, wb[3] = {w[0], w[1], 0.0};
        sus_attitude_get(&att, R);
        if (ops()->step(wk, T, &t, w, &lam, &att, &st) != SUS_STEPPER_OK)
            break;
        n++;
        sus_attitude_get(&att, Rn);
        exact_after(&ex, R, t0, t, Re);
        const double r = step_roundoff(t - t0, wb, w), excess = sus_so3_dist(Re, Rn) - r;
        round += r;
        c->local = fmax(c->local, excess > 0.0 ? excess / st.residual : 0.0);
        /* tau such that t0 + tau is a double: the reference is taken there, without a rounding
         * of t0 + tau, which would turn R by up to u t |w| */
        const double tau = (t0 + 0.5 * (t - t0)) - t0;
        c->dense = fmax(c->dense, dense_excess(wk, &ex, R, t0, tau, wb, &att) / st.residual);
    }
    if (wk)
        ops()->free(wk);
    sus_attitude_get(&att, R);
    c->global = fmax(c->global, t < T ? INFINITY : sus_so3_dist(R, Rr) / (tol + round));
    c->steps += n;
}

/* Each body from its own w0, every half decade of TOL (a dip in the terms shows at some TOLs only),
 * and moved back along its motion to 1 / E = 0.5, just before the inflection, every decade: the
 * Taylor steps that cross it, where q's terms grow by w's poles' exponent (the method's file). */
static void steps_within_estimates(void)
{
    step_check c = {0};
    for (int k = 0; k < TEST_BODIES; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        test_body(k, &b);
        if (check_body_model(&b, &m) || sus_exact_init(&ex, &m, b.w0))
            continue;
        double wb[2], wr[2], Rr[3][3], Rb[3][3]; /* the references depend on w0, not on TOL */
        sus_exact_omega(&ex, (log(0.5) - ex.sigma * ex.s0) / ex.k, wb);
        sus_refatt_precise(&m, b.w0, 50.0, wr, Rr);
        if (!ex.fixed)
            sus_refatt_precise(&m, wb, 50.0, wr, Rb);
        for (int j = 6; j <= 28; j++) {
            run_checked(&m, b.w0, pow(10.0, -0.5 * j), 50.0, Rr, &c);
            if (j % 2 == 0 && !ex.fixed)
                run_checked(&m, wb, pow(10.0, -0.5 * j), 50.0, Rb, &c);
        }
    }
    CHECK(c.local <= 1.0,
          "every step's local error (against the reference's increment) is at most "
          "its estimate + (%g + %g h |w|) u: worst (error - round-off) / estimate "
          "%.3g over %ld steps, %d bodies from w0 and from 1 / E = 1/2, TOL 1e-3 ... 1e-14",
          ROUND_STEP, COND, c.local, c.steps, TEST_BODIES);
    CHECK(c.dense <= 1.0,
          "dense output half way through each step is within the step's estimate + its "
          "round-off on the same runs: worst (error - round-off) / estimate %.3g",
          c.dense);
    CHECK(c.global <= 1.0,
          "dist(R, R_ref)(50) <= TOL + the steps' round-off on the same runs: worst ratio %.3g",
          c.global);
}

/* ---- the method's own rules: the budget ---- */

typedef struct {
    double sum;  /* worst (sum of the estimates) / TOL over runs */
    double step; /* worst estimate / share over the integration steps */
} budget_check;

static void run_budget(const sus_model *m, const double w0[2], double tol, double T,
                       budget_check *c)
{
    sus_tol_work *wk = ops()->alloc(m, tol, w0);
    double t = 0.0, w[3] = {w0[0], w0[1], 0.0}, lam, sum = 0.0;
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    while (wk && t < T && ops()->step(wk, T, &t, w, &lam, &att, &st) == SUS_STEPPER_OK) {
        sum += st.residual;
        if (st.scale > 0.0) /* an integration step (the tail's has no share: its bound is fixed) */
            c->step = fmax(c->step, st.residual / st.scale);
    }
    if (wk)
        ops()->free(wk);
    c->sum = fmax(c->sum, t < T ? INFINITY : sum / tol);
}

/* The top of step_exact_attitude.c: every integration step's estimate is at most its share rate h,
 * and the estimates with the tail's bound sum to at most TOL; runs to T = 400 reach the tail. */
static void budget_kept(void)
{
    budget_check c = {0.0, 0.0};
    for (int k = 0; k < TEST_BODIES; k++) {
        body b;
        sus_model m;
        test_body(k, &b);
        if (check_body_model(&b, &m))
            continue;
        for (int e = 4; e <= 12; e += 4) {
            run_budget(&m, b.w0, pow(10.0, -e), 50.0, &c);
            run_budget(&m, b.w0, pow(10.0, -e), 400.0, &c);
        }
    }
    CHECK(c.step <= 1.0 + 1e-12,
          "every step's estimate is at most its share of the budget, rate h: worst "
          "ratio %.15g (%d bodies, TOL 1e-4, 1e-8, 1e-12, T = 50 and 400)",
          c.step, TEST_BODIES);
    CHECK(c.sum <= 1.0 + 1e-12,
          "the steps' estimates and the tail's bound sum to at most TOL: worst sum / TOL %.15g",
          c.sum);
}

/* ---- the tail ---- */

/* The last step of a run: where it started, and R there; and R by dense output at t_d, DENSE_AT of
 * the way from there to T. */
typedef struct {
    double t, R[3][3];
    double t_d, R_d[3][3];
} last_start;

/* Where in the last step its dense row is taken: a time whose distance from the step's start a
 * double does not hold, so that rounding it would show. */
#define DENSE_AT 0.7

/* Steps to T; R(T), w(T) and the last step's start (w and last may be NULL). */
static long steps_to_w(const sus_model *m, const double w0[2], double tol, double T, double R[3][3],
                       double wT[3], last_start *last)
{
    sus_tol_work *wk = ops()->alloc(m, tol, w0);
    double t = 0.0, w[3] = {w0[0], w0[1], 0.0}, lam;
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    long n = 0;
    for (double t0 = t; wk && t < T; t0 = t) {
        if (last) {
            last->t = t0;
            sus_attitude_get(&att, last->R);
        }
        if (ops()->step(wk, T, &t, w, &lam, &att, &st) != SUS_STEPPER_OK)
            break;
        n++;
    }
    if (wk && last) {
        double wd[3], ld;
        sus_attitude ad = att;
        last->t_d = last->t + DENSE_AT * (T - last->t);
        ops()->dense(wk, last->t_d, wd, &ld, &ad);
        sus_attitude_get(&ad, last->R_d);
    }
    if (wk)
        ops()->free(wk);
    sus_attitude_get(&att, R);
    if (wT)
        memcpy(wT, w, sizeof w);
    return t < T ? -1 : n;
}

static long steps_to(const sus_model *m, const double w0[2], double tol, double T, double R[3][3])
{
    return steps_to_w(m, w0, tol, T, R, NULL, NULL);
}

/* The reference at T past the tail: R(t_s) from the long-double integration, with t_s where the
 * tail's integral is below 1e-20, then the steady rotation (steady_far). */
static void reference_far(const sus_model *m, const sus_exact *ex, double T, double R[3][3])
{
    const double t_s = fmax(0.0, sus_exact_tail_time(ex, 1e-20));
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double Rs[3][3];
    sus_refatt ra;
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, t_s, Rs);
    steady_far(m, ex, Rs, t_s, T, R);
}

static void tail_is_one_step(void)
{
    const double tol = 1e-10, Ts[3] = {1e4, 1e6, 1e9};
    int same = 1;
    double tail = 0.0, run = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        double R[3][3], Rr[3][3], winf[2];
        last_start ls;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        const long n3 = steps_to(&m, b.w0, tol, 1e3, R);
        same &= n3 > 0 && steps_to(&m, b.w0, tol, 1e6, R) == n3;
        sus_exact_limit(&ex, winf);
        for (int i = 0; i < 3; i++) {
            const long n = steps_to_w(&m, b.w0, tol, Ts[i], R, NULL, &ls);
            steady_far(&m, &ex, ls.R, ls.t, Ts[i], Rr);
            tail = fmax(tail, sus_so3_dist(R, Rr) / (ROUND_TAIL * U));
            steady_far(&m, &ex, ls.R, ls.t, ls.t_d, Rr);
            tail = fmax(tail, sus_so3_dist(ls.R_d, Rr) / (ROUND_TAIL * U));
            /* the whole run: TOL, the steps' round-off before the tail, and the tail's */
            const double before = (ROUND_STEP * (double)n + COND * ls.t * w_scale(&ex)) * U;
            reference_far(&m, &ex, Ts[i], Rr);
            run = fmax(run, sus_so3_dist(R, Rr) / (tol + before + ROUND_TAIL * U));
        }
    }
    CHECK(same,
          "a run to T = 1e6 takes as many steps as one to T "
          "= 1e3 (TOL %g, %d bodies): the tail is one step",
          tol, BODIES_COUNT);
    CHECK(tail <= 1.0,
          "the tail step turns R by exp((T - t*) w*^) to %g u at T = 1e4, 1e6, 1e9 (%d bodies), "
          "not u T |w*|, and so does a dense row inside it: worst %.3g of it",
          ROUND_TAIL, BODIES_COUNT, tail);
    CHECK(run <= 1.0,
          "dist(R, R_ref)(T) <= TOL + the steps' round-off before the tail + %g u at T = 1e4, "
          "1e6, 1e9: worst %.3g of it",
          ROUND_TAIL, run);
}

/* ---- dense output and a constant w ---- */

static void dense_ends_at_the_step(void)
{
    body b;
    sus_model m;
    body_get(1, &b);
    if (check_body_model(&b, &m))
        return;
    int same = 1, steps = 0;
    sus_tol_work *wk = ops()->alloc(&m, 1e-8, b.w0);
    double t = 0.0, w[3] = {b.w0[0], b.w0[1], 0.0}, lam;
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    while (wk && t < 400.0 && ops()->step(wk, 400.0, &t, w, &lam, &att, &st) == SUS_STEPPER_OK) {
        double wd[3], ld, R[3][3], Rd[3][3];
        sus_attitude ad = att;
        ops()->dense(wk, t, wd, &ld, &ad);
        sus_attitude_get(&att, R);
        sus_attitude_get(&ad, Rd);
        same &= memcmp(R, Rd, sizeof R) == 0 && wd[0] == w[0] && wd[1] == w[1] && wd[2] == 0.0 &&
                ld == lam;
        steps++;
    }
    if (wk)
        ops()->free(wk);
    CHECK(same && t == 400.0,
          "dense output at each step's length is the step's own state (w, lambda, R), "
          "%d steps to t = 400 (tail included)",
          steps);
}

static void constant_w_is_one_rotation(void)
{
    double I[9];
    memcpy(I, SUS_PAPER_INERTIA, sizeof I);
    I[6] = I[7] = 0.0; /* I31 = I32 = 0: c(w) = 0, w stays w0 */
    sus_model m;
    if (sus_model_init(&m, I, NULL, 0) != 0) {
        CHECK(0, "the body with I31 = I32 = 0");
        return;
    }
    const double w0[2] = {0.4, 0.5}, T = 123.25, v[3] = {T * w0[0], T * w0[1], 0.0};
    double R[3][3], Rx[3][3], w[3];
    const long n = steps_to_w(&m, w0, 1e-12, T, R, w, NULL);
    sus_so3_exp(v, Rx);
    const double err = sus_so3_dist(R, Rx), bound = 1e-12 + COND * U * T * hypot(w0[0], w0[1]);
    CHECK(n == 1 && err <= bound && w[0] == w0[0] && w[1] == w0[1] && w[2] == 0.0,
          "I31 = I32 = 0: one step (%ld), w(T) = w0 exactly, "
          "R(T) = exp(T w0^) within %.3g (bound %.3g)",
          n, err, bound);
}

/* A long transient (a slow approach, k ~ 1e-5 |w|, and |w| ~ 1e3: some 7e4 steps to t = 50 at
 * the tightest TOL) against the long-double reference: the steps' time and the rows' must agree,
 * else each step loses the rounding of t + h, u t |w| in angle, and the error grows like N u T |w|
 * whatever TOL. The allowance: TOL, the conditioning COND u T |w|max (every step's angle rounded,
 * as in the run allowance above), and the steps' other roundings as a random walk, 3 ROUND_STEP u
 * sqrt N (independent roundings to nearest, three deviations), not ROUND_STEP u N. */
static void long_transient(void)
{
    const double T = SLOW_T;
    sus_model m;
    sus_exact ex;
    double w0[2], R[3][3], Rr[3][3];
    if (check_slow_body(&m, &ex, w0, Rr))
        return;
    const double tols[2] = {1e-12, 3e-16}, w_max = w_scale(&ex);
    for (int i = 0; i < 2; i++) {
        const long n = steps_to(&m, w0, tols[i], T, R);
        const double err = sus_so3_dist(R, Rr), bound = tols[i] + COND * U * T * w_max +
                                                        3.0 * ROUND_STEP * U * sqrt((double)n);
        CHECK(n > 0 && err <= bound,
              "slow body, |w0| = %.0f, TOL %.0e: %ld steps to t = %g, dist(R, R_ref) = %.3g <= "
              "TOL + COND u T |w|max + 3 ROUND_STEP u sqrt N = %.3g",
              hypot(w0[0], w0[1]), tols[i], n, T, err, bound);
    }
}

static void degree_rule(void)
{
    int mono = 1, lo = 99, hi = 0;
    for (int e = 0; e <= 160; e++) {
        const double tol = pow(10.0, -0.1 * e);
        const int d = sus_step_exact_attitude_order(tol),
                  d2 = sus_step_exact_attitude_order(tol * 0.99);
        mono &= d2 >= d;
        lo = d < lo ? d : lo;
        hi = d > hi ? d : hi;
    }
    CHECK(mono && lo >= 9 && hi <= SUS_STEP_TAYLOR_MAX_ORDER - 1,
          "the degree never falls as TOL tightens, "
          "within the series' range: %d ... %d over TOL = 1 ... 1e-16",
          lo, hi);
}

static int count_row(void *ctx, const sus_row *row)
{
    (void)row;
    ++*(long *)ctx;
    return 0;
}

/* A tolerance far below round-off (the library takes any tol in (0, 1)): its steps would be shorter
 * than a rounding of the longest allowed, and a run to t = 10 would take ~1e20 of them. It fails
 * at its first step instead (SUS_RUN_STEP_FAILED), as taylor-adaptive does; 2^-52, the CLI's
 * least, still runs. */
static void unreachable_tol(void)
{
    sus_model m;
    sus_model_init(&m, SUS_PAPER_INERTIA, NULL, 0);
    sus_run_report rep;
    long rows = 0;
    /* a budget of 1000 steps, so that a crawl ends too, as a step limit, not a rejection */
    sus_tol_config tc = {&m, &sus_step_exact_attitude_type, 1e-300, 10.0, 0.0, 1000};
    const int rc = sus_run_tol(&tc, SUS_PAPER_OMEGA0, count_row, &rows, &rep);
    const int status = rep.status, step = (int)rep.step;
    tc.tol = 0x1p-52;
    const int ok = sus_run_tol(&tc, SUS_PAPER_OMEGA0, count_row, &rows, &rep);
    CHECK(rc == SUS_RUN_STEP_FAILED && status == SUS_STEPPER_REJECTED && step == 1 &&
              ok == SUS_RUN_OK,
          "tol 1e-300: the run fails at step %d (1) with status %d (rejected, %d); tol 2^-52 "
          "runs (%d)",
          step, status, SUS_STEPPER_REJECTED, ok);
}

int main(void)
{
    fast_omega_agrees();
    tail_bound_holds();
    steps_within_estimates();
    budget_kept();
    tail_is_one_step();
    dense_ends_at_the_step();
    constant_w_is_one_rotation();
    long_transient();
    degree_rule();
    unreachable_tol();
    return check_summary("test_exact_attitude");
}
