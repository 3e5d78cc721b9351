/* taylor-adaptive's tail jump (step_taylor_adaptive.c, "The tail" and "Conditioning") on the
 * family of tests/unit/bodies.h (the paper's, the general and the stiff bodies). Checked here, each
 * threshold from the argument beside it:
 *   - exact_tail.h's sus_exact_tail_bounds hold: dev is at least the largest |w(s) - w_inf| from t
 *     on and the integral at least the integral of |w - w_inf| (both from the closed form,
 *     sampled; Simpson as in test_exact_attitude), at a(t) = a0 and a = 0, 2, ..., 14 past it;
 *     and they are tight where they claim to be: with x = e^{-a} sqrt(cond(I_m)) <= 1/2
 *     (|t2| / |t1| is at most sqrt(cond(I_m)), the condition number of L), each within
 *     (1 + x) / (1 - x) of what it bounds (the triangle inequality's worst case for two terms in
 *     the ratio x);
 *   - the cost of a run stops growing with t_end: the same number of steps to T = 1e3, 1e4, 1e6
 *     and 1e9 (in each body's own time, t k = T k_paper), at TOL 1e-6, 1e-10, 1e-14;
 *   - and so does its error: at T = 1e4, 1e6 and 1e9 against the long-double reference attitude,
 *     dist(R, R_ref) <= 10 N TOL (claims_adaptive.c's bound, N steps) + 16 rho u (the roundings
 *     of w_inf's direction, rho the size of E's terms over E, and of the turn; not growing with
 *     T, as the turn's angle is formed in two doubles: steady_turn.h) + 3 2^-51 (the reference's
 *     own accuracy, 2^-51 an entry). An angle formed in one double would add about u T |w_inf|,
 *     some 1e-10 at T = 1e6 for |w_inf| near 1, far above this bound at TOL 1e-14;
 *   - the conditioning it states: R(T (1 + e)) against R(T), both the reference's, e = 2^-40, is
 *     sqrt 2 e T |w_inf| to 1 % (R(t) turns at w_inf for t >= T: the angle e T |w_inf|, and
 *     dist = 2 sqrt 2 sin(angle / 2); 1 % covers the reference's 2^-51 against the 1e-9 and more
 *     measured, and e^{-k T}); a relative change e of w0's scale is exactly this change of time.
 * Expected values come from the closed form and the reference attitude, never from the stepper. */
#include "check_body.h"
#include "driver.h"
#include "exact.h"
#include "exact_tail.h"
#include "refattitude.h"
#include "so3.h"
#include "taylor.h"

#include <math.h>

#define U SUS_U
#define ROUND_W 64.0 /* the closed form's w to 64 u r |L^-1|_F (test_exact_attitude) */
#define F_UNDERSHOOT 10.0
#define ROUND_ANGLE 16.0
#define REF_DIST (3.0 * 0x1p-51)

/* r |L^{-1}|_F, the scale of w's rounding in the closed form. */
static double w_scale(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    return ex->r * sqrt(a * a + b * b + c * c);
}

/* cond(I_m) from the printed entries of its symmetric 2x2 (I_m is symmetric: bodies.h). */
static double cond_im(const double I[9])
{
    const double a = I[0], b = I[1], d = I[4], h = hypot(0.5 * (a - d), b);
    return (0.5 * (a + d) + h) / (0.5 * (a + d) - h);
}

/* The largest |w(s) - w_inf| over 4000 samples of [t, t + 40 / k] and the integral by Simpson over
 * [t, t + 60 / k] (20000 panels; the rest lies below e^{-40} of either). */
static void sampled(const sus_exact *ex, double t, double *sup, double *integral)
{
    double winf[2], sum = 0.0;
    const int n = 20000;
    const double h = 60.0 / ex->k / n;
    sus_exact_limit(ex, winf);
    *sup = 0.0;
    for (int i = 0; i <= n; i++) {
        double w[2];
        sus_exact_omega(ex, t + i * h, w);
        const double g = hypot(w[0] - winf[0], w[1] - winf[1]);
        if (i <= 2 * n / 3)
            *sup = fmax(*sup, g);
        sum += g * (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0);
    }
    *integral = sum * h / 3.0;
}

static void bounds_hold(void)
{
    double below = 0.0, loose = 0.0;
    int n = 0, tight = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        const double a0 = ex.sigma * ex.s0, sq = sqrt(cond_im(b.I));
        const double slack = ROUND_W * U * w_scale(&ex), islack = slack * 60.0 / ex.k;
        for (int j = -1; j <= 7; j++) {
            const double a = j < 0 ? a0 : 2.0 * j;
            if (a < a0)
                continue;
            const double t = (a - a0) / ex.k;
            double dev, in, sup, I;
            sus_exact_tail_bounds(&ex, t, &dev, &in);
            sampled(&ex, t, &sup, &I);
            below = fmax(below, fmax((sup - slack) / dev, (I - islack) / in));
            n++;
            const double x = exp(-a) * sq, f = (1.0 + x) / (1.0 - x);
            if (!(x <= 0.5))
                continue;
            loose = fmax(loose, fmax(dev / (f * (sup + slack)), in / (f * (I + islack))));
            tight++;
        }
    }
    CHECK(n > 0 && below <= 1.0 + 1e-9,
          "sus_exact_tail_bounds on %d bodies, %d starts (a = a0, 0, 2, ..., 14): the sampled "
          "largest |w - w_inf| ahead and its integral over the bounds, at most %.9f (at most 1, to "
          "the sampling's rounding)",
          BODIES_COUNT, n, below);
    CHECK(tight > 0 && loose <= 1.0 + 1e-9,
          "and tight: at the %d starts with x = e^-a sqrt(cond I_m) <= 1/2, each bound over "
          "(1 + x) / (1 - x) times what it bounds: at most %.6f (at most 1)",
          tight, loose);
}

/* Steps and final attitude of a run of taylor-adaptive to T. */
static int run_to(const sus_model *m, const double w0[2], double tol, double T, long *steps,
                  double R[3][3])
{
    const sus_tol_config cfg = {m, &sus_step_taylor_adaptive_type, tol, T, 0.0, 0};
    sus_row last;
    sus_run_report rep;
    const int rc = sus_run_tol(&cfg, w0, sus_keep_last, &last, &rep);
    *steps = last.k;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = last.R[i][j];
    return rc;
}

/* The size of E's terms over E at w (>= 1; up to cond(I_m) along the soft direction). */
static double energy_ratio(const double I[9], const sus_model *m, const double w[2])
{
    const double x = w[0], y = w[1];
    const double t =
        0.5 * (fabs(I[0]) * x * x + (fabs(I[1]) + fabs(I[3])) * fabs(x * y) + fabs(I[4]) * y * y);
    return fmax(1.0, t / sus_energy(m, w));
}

/* One body at one TOL: equal steps to T = 1e3, 1e4, 1e6, 1e9 (its own time), and the error at the
 * three long ones in units of the bound (top of the file). */
static void one_body(const body *b, const sus_model *m, double tol, int *unequal, double *worst)
{
    sus_exact ex;
    double winf[2], R[3][3], wr[2], Rr[3][3];
    sus_exact_init(&ex, m, b->w0);
    sus_exact_limit(&ex, winf);
    const double scale = check_body_time(m, b->w0);
    const double rho = fmax(energy_ratio(b->I, m, b->w0), energy_ratio(b->I, m, winf));
    long first = -1;
    static const int DECADES[4] = {3, 4, 6, 9};
    for (int i = 0; i < 4; i++) {
        const int e = DECADES[i];
        const double T = pow(10.0, e) * scale;
        long steps;
        if (run_to(m, b->w0, tol, T, &steps, R) != SUS_RUN_OK) {
            *worst = INFINITY;
            return;
        }
        *unequal += first >= 0 && steps != first;
        first = first < 0 ? steps : first;
        if (e == 3)
            continue;
        sus_refatt_precise(m, b->w0, T, wr, Rr);
        const double bound = F_UNDERSHOOT * steps * tol + ROUND_ANGLE * rho * U + REF_DIST;
        *worst = fmax(*worst, sus_so3_dist(R, Rr) / bound);
    }
}

static void long_runs(void)
{
    static const double TOLS[3] = {1e-6, 1e-10, 1e-14};
    int unequal = 0;
    double worst = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (check_body_model(&b, &m))
            continue;
        for (int j = 0; j < 3; j++)
            one_body(&b, &m, TOLS[j], &unequal, &worst);
    }
    CHECK(unequal == 0,
          "%d bodies at TOL 1e-6, 1e-10, 1e-14: the same number of steps to T = 1e3, "
          "1e4, 1e6 and 1e9 (t k = T k_paper): %d differ",
          BODIES_COUNT, unequal);
    CHECK(worst <= 1.0,
          "and dist(R, R_ref) at T = 1e4, 1e6 and 1e9 within 10 N TOL + 16 rho u + 3 2^-51, "
          "not growing with T: worst %.3g of that (at most 1)",
          worst);
}

static void conditioning(void)
{
    const double e = 0x1p-40;
    double lo = INFINITY, hi = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        double winf[2], w1[2], w2[2], R1[3][3], R2[3][3];
        sus_exact_limit(&ex, winf);
        for (int p = 4; p <= 6; p += 2) {
            const double T = pow(10.0, p) * check_body_time(&m, b.w0);
            sus_refatt_precise(&m, b.w0, T, w1, R1);
            sus_refatt_precise(&m, b.w0, T * (1.0 + e), w2, R2);
            const double wn = hypot(winf[0], winf[1]);
            const double r = sus_so3_dist(R1, R2) / (sqrt(2.0) * e * T * wn);
            lo = fmin(lo, r), hi = fmax(hi, r);
        }
    }
    CHECK(lo >= 0.99 && hi <= 1.01,
          "%d bodies, T = 1e4 and 1e6: dist(R(T), R(T (1 + 2^-40))) / (sqrt2 2^-40 T |w_inf|) "
          "in [%.6f, %.6f] (within 1 %% of 1: the attitude's sensitivity to a relative change of "
          "time or of w0's scale is T |w_inf|)",
          BODIES_COUNT, lo, hi);
}

int main(void)
{
    bounds_hold();
    long_runs();
    conditioning();
    return check_summary("test_taylor_tail");
}
