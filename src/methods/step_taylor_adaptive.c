/* A tolerance-driven Taylor method: the series of step_taylor.c (taylor_series.h: the same
 * recursion, the same structure: w3 = 0 exactly, a unit quaternion, E restored onto E(w_0)),
 * with the order chosen from the tolerance and each step from the series' last two terms.
 *
 * Order (Jorba & Zou 2005, Sect. 3; heyoka's rule): a series with terms ~ r^n meets tol at
 * least cost per unit time near p = -ln(tol)/2 + 1 when a step costs as its Cauchy products,
 * ~p^2. A step here also has a part that does not grow with p (the estimate, the next step's
 * pow, the quaternion's normalisation, the driver), which moves the least cost per unit time to
 * a higher order; ORDER_SHIFT = 2 orders more (one even order) is what a measurement of the work
 * at equal error chose: instructions per run to t = 50 on the paper's body, with the rule shifted
 * by 0, 2 and 4 orders, where 2 took fewer than 0 at every tolerance and no more than 4 from 1e-8
 * down. Rounded up to an even order of ADAPTIVE_ORDERS, so p = 8 (tol >= 1e-4) ... 20 (tol near
 * round-off).
 *
 * Error estimate, per group (the w rows, the quaternion rows), from the scaled coefficients
 * (W_n = w_n h^n, so h is folded into the recursion): if the terms decay geometrically, the
 * first term left out is about T_{p+1} = T_p^2 / T_{p-1}, T_n = |coefficient n|_inf of the
 * group. A group whose last two rows vanish (w3 = 0 is never a row; an equilibrium makes every
 * w row vanish) estimates 0: no division by zero and rho = inf for it; with T_{p-1} = 0 < T_p
 * no ratio exists and T_p itself is the estimate. The quaternion group holds (q0, q3) and
 * (q1, q2) together: for a steady rotation one pair has only even and the other only odd
 * powers, so either alone would estimate 0 at every other order.
 *
 * Step control: since T_{p+1} ~ h^{p+1}, the step that would give tol is h (tol/err)^{1/(p+1)};
 * the next step is that times SAFETY, at most GROW times the last (from the previous step's
 * coefficients: no extra series). A step whose estimate exceeds tol (or is not a number) is
 * rejected and retried as short as its estimate asks (at most SHRINK_MIN times shorter; the
 * retry rescales the rejected series, recomputing it only when it overflowed); after MAX_TRIES
 * the step fails (SUS_STEPPER_REJECTED) instead of returning an answer that missed tol. Every
 * step stays inside the radius the series is proved to converge in (step_taylor.c).
 *
 * Stiffness. With c = c(w) = I_3i w_i and g(w) = c(fA w) (linear in w), (ContDyn) gives
 * c' = g(w) c exactly: c keeps its sign, and w moves along the energy ellipse from the
 * steady rotation -w_inf (c = 0, g > 0) to the attracting one w_inf (c = 0, g < 0), at the rate
 * k = -g(w_inf). On the half of the ellipse where g < 0 (it holds w_inf and the whole way there)
 * |c| only shrinks. Where k is large (a near-singular I_m: k ~ 1/|I_m|) an explicit series is
 * stiff near w_inf: its linear stability (step_taylor.c) holds h k below beta_p (5.07 at p = 10),
 * and the series' radius stays ~ 1/k while c != 0. The controller then settles where the
 * estimate meets tol at |sum_n (-hk)^n/n!| = 1, a deviation from w_inf of a fraction of tol that
 * never decays: steps of beta_p / k for ever (10^9 for t = 10 at |I_m| = 2e-10), and a tighter
 * tol escapes only when w lands exactly on c(w) = 0 in floating point. At that balance the step
 * h = beta_p / k is the controller's fixed point, err = SAFETY^{p+1} tol, and the deviation's own
 * series, dev (hk)^n / n!, gives err = dev beta_p^{p+1} / (p! p): dev = 0.29 tol at p = 6 down to
 * 0.07 tol at p = 20.
 *
 * The tail. Every start on the ellipse but -w_inf flows to w_inf, and the closed form (exact.h)
 * from the current w bounds, along the direction w - w_inf takes (exact_tail.h's
 * sus_exact_tail_bounds), both dev, the largest |w(s) - w_inf| from here on, and the integral of
 * |w - w_inf| from here on. Replacing the rest of the motion by the steady rotation moves w by at
 * most dev (plus the floor below: the rounding of the w_inf found through E(w_0)) and R by at most
 * sqrt 2 times that integral (R' = R w^ driven by w_inf instead of w: the difference D obeys
 * D' = D w^ + R_inf (w - w_inf)^, whose homogeneous flow keeps norms, and the Frobenius norm of
 * v^ is sqrt 2 |v|). So once both are within tol, on the g < 0 half (from the other the whole
 * transient lies ahead), w is set to w_inf and the rest of the run is one step, the quaternion's
 * series for a constant w, exp(h w_inf^/2), summed in closed form: its error is within tol, the
 * promise of every other step, proved rather than estimated, and the cost of a run stops growing
 * with t_end. Near w_inf the bounds exceed the truth by a fraction ~ e^{-a} ~ dev / r (exact.h's
 * r), so at the stiff balance above (dev <= 0.29 tol, and the integral about dev / k) the run jumps
 * instead of stalling. A w within SETTLE_FLOOR u |w_inf| of w_inf, times the rounding of E that
 * w_inf inherits (up to cond(I_m)), settles at any tol: there c(w) is rounding noise, which would
 * otherwise drive the stiff series. And a w exactly on c(w) = 0 (w_0 = 0, I31 = I32 = 0, a start on
 * a steady rotation) is a rest point of the series itself, whose every later term vanishes: the
 * rest of the run is one such step there too, about that w (at_rest).
 *
 * Conditioning. The jump turns R by the angle (T - t*) |w_inf| (T = t_end, t* the jump's start),
 * formed in two doubles (steady_turn.h): T - t* exactly, and |w_inf| in double-double from the
 * inputs, so the angle is right to a few roundings however long the tail, and the run's error,
 * like its cost, stops growing with T (tests/unit/test_taylor_tail.c: at T = 1e4, 1e6 and 1e9).
 * The problem itself is conditioned by T |w_inf|: the field is homogeneous
 * of degree 2, so a relative change e of w_0's scale is one of the time (w_l(t) = l w(l t), R_l(t)
 * = R(l t)) and moves R(T) by sqrt 2 e T |w_inf|. The inputs are exact doubles, so this is what a
 * change of them would do, not an error of the method. */
#include "taylor.h"
#include "taylor_series.h"

#include "exact.h"
#include "exact_tail.h"
#include "quaternion.h"
#include "reconstruct.h"
#include "steady_turn.h"

#include <math.h>
#include <stdlib.h>

/* Hairer, Norsett & Wanner, Solving ODEs I, II.4: the usual safety factor and growth limit. */
#define SAFETY 0.9
#define GROW 5.0
#define SHRINK_MIN 0.1
/* Each retry is sized by the estimate of the try before, which meets tol at once when the
 * estimate scales as h^{p+1}; a few more allow for steps near the radius, where it does not. */
#define MAX_TRIES 12
/* A step stays this fraction inside the proved radius (any fraction below 1 proves convergence;
 * the estimate, not this, decides the accuracy). */
#define RADIUS_FRACTION 0.99
#define ORDER_SHIFT 2.0
/* The tail (see the top): the floor is a few roundings of a state of size |w_inf|. */
#define SETTLE_FLOOR 8.0

struct sus_tol_work {
    const sus_model *m;
    double tol, e0; /* the tolerance and E(w_0), the energy every step restores */
    const struct adaptive_order *order;
    double h_next;          /* the next step to try (0: none yet) */
    double t0, h;           /* the last accepted step: its start and length */
    double q0[4];           /* the attitude quaternion at its start */
    taylor_series t;        /* its series, for dense output */
    double w_inf[2], k_inf; /* the attracting steady rotation on E(w_0) and its rate (0: none) */
    double w0[2];           /* the start, whose closed form gives the tail's speed */
    double speed[2];        /* |w_inf| in double-double, speed[0] + speed[1]; set at the tail */
    double floor; /* w within this of w_inf settles at any tol: the rounding of w_inf itself */
    int settled;  /* 1 once w is w_inf: the last step is exp(h w_inf^/2) */
};

/* max(|a|_inf, |b|_inf) of two pairs; NaN if any entry is NaN. */
static double pair_norm(v2d a, v2d b)
{
    const double x = fabs(a[0]), y = fabs(a[1]), u = fabs(b[0]), v = fabs(b[1]);
    const double m1 = (x >= y || isnan(x)) ? x : y, m2 = (u >= v || isnan(u)) ? u : v;
    return (m1 >= m2 || isnan(m1)) ? m1 : m2;
}

/* T_{p+1} ~ T_p^2 / T_{p-1}, or T_p when T_{p-1} = 0 (see the top of the file). */
static double group_estimate(double last2, double last)
{
    return last2 > 0.0 ? last * (last / last2) : last;
}

/* The step's error estimate: the larger of the two groups' (NaN if either is NaN). */
static double estimate(const taylor_series *t, int p)
{
    const v2d z = {0.0, 0.0};
    const double ew = group_estimate(pair_norm(t->W[p - 1], z), pair_norm(t->W[p], z));
    const double eq =
        group_estimate(pair_norm(t->P[p - 1], t->M[p - 1]), pair_norm(t->P[p], t->M[p]));
    return (ew >= eq || isnan(ew)) ? ew : eq;
}

/* One order's series, estimate and sums, with p a constant (the recursion unrolled). */
typedef struct adaptive_order {
    int p;
    double (*try_step)(sus_tol_work *wk, double h, const double w[2]);
    void (*sums)(const sus_tol_work *wk, double w_next[3], double dq[4]);
} adaptive_order;

#define ADAPTIVE_ORDER(N)                                                                          \
    static double try##N(sus_tol_work *wk, double h, const double w[2])                            \
    {                                                                                              \
        series(wk->m, N, h, w, 1, &wk->t);                                                         \
        return estimate(&wk->t, N);                                                                \
    }                                                                                              \
    static void sums##N(const sus_tol_work *wk, double w_next[3], double dq[4])                    \
    {                                                                                              \
        dq_from(&wk->t, N, dq);                                                                    \
        w_next_from(wk->m, N, &wk->t, wk->e0, w_next);                                             \
    }
ADAPTIVE_ORDER(6)
ADAPTIVE_ORDER(8)
ADAPTIVE_ORDER(10)
ADAPTIVE_ORDER(12)
ADAPTIVE_ORDER(14)
ADAPTIVE_ORDER(16)
ADAPTIVE_ORDER(18)
ADAPTIVE_ORDER(20)
#define ENTRY(N)                                                                                   \
    {                                                                                              \
        N, try##N, sums##N                                                                         \
    }
static const adaptive_order ADAPTIVE_ORDERS[] = {ENTRY(6),  ENTRY(8),  ENTRY(10), ENTRY(12),
                                                 ENTRY(14), ENTRY(16), ENTRY(18), ENTRY(20)};
#define NORDERS ((int)(sizeof ADAPTIVE_ORDERS / sizeof ADAPTIVE_ORDERS[0]))

static const adaptive_order *order_for(double tol)
{
    const double want = -0.5 * log(tol) + 1.0 + ORDER_SHIFT;
    for (int i = 0; i < NORDERS; i++)
        if (ADAPTIVE_ORDERS[i].p >= want)
            return &ADAPTIVE_ORDERS[i];
    return &ADAPTIVE_ORDERS[NORDERS - 1];
}

int sus_step_taylor_adaptive_order(double tol) { return order_for(tol)->p; }

/* The size of the terms E(w) sums, 1/2 sum |w_i I_ij w_j|, over E(w): the factor by which E's
 * rounding exceeds u (up to cond(I_m) for a w along I_m's soft direction). */
static double energy_terms_ratio(const sus_model *m, const double w[2], double e)
{
    const double(*I)[3] = m->I;
    const double t =
        0.5 * (fabs(I[0][0]) * w[0] * w[0] + (fabs(I[0][1]) + fabs(I[1][0])) * fabs(w[0] * w[1]) +
               fabs(I[1][1]) * w[1] * w[1]);
    return t / e;
}

/* The attracting steady rotation on E(w_0): of the two points of the ellipse on c(w) = 0,
 * +-s (-I32, I31), the one where g < 0. None (k_inf = 0) for w_0 = 0, for I31 = I32 = 0 (every
 * w is steady) and where g vanishes there too (no exponential approach to settle on). Its
 * rounding: s = sqrt(E0 / E(d)) carries half the relative roundings of the two energies, each a
 * few u times the size of its terms over its value. */
static void steady_rotation(sus_tol_work *wk, const double w0[2])
{
    const sus_model *m = wk->m;
    const double d[2] = {-m->b[1], m->b[0]}, ed = sus_energy(m, d);
    if (!(ed > 0.0) || !(wk->e0 > 0.0))
        return;
    const double s = sus_contdyn_rate(m, d) > 0.0 ? -sqrt(wk->e0 / ed) : sqrt(wk->e0 / ed);
    wk->w_inf[0] = s * d[0];
    wk->w_inf[1] = s * d[1];
    const double k = -sus_contdyn_rate(m, wk->w_inf);
    wk->k_inf = k > 0.0 && isfinite(k) ? k : 0.0;
    const double terms = fmax(energy_terms_ratio(m, w0, wk->e0), energy_terms_ratio(m, d, ed));
    wk->floor = SETTLE_FLOOR * SUS_U * hypot(wk->w_inf[0], wk->w_inf[1]) * fmax(1.0, terms);
}

static sus_tol_work *adaptive_alloc(const sus_model *m, double tol, const double w0[2])
{
    sus_tol_work *wk = malloc(sizeof *wk);
    if (!wk)
        return NULL;
    *wk = (sus_tol_work){
        .m = m, .tol = tol, .e0 = sus_energy(m, w0), .order = order_for(tol), .w0 = {w0[0], w0[1]}};
    steady_rotation(wk, w0);
    return wk;
}

static void adaptive_free(sus_tol_work *wk) { free(wk); }

/* The step to try first: the longest the proved radius allows within [t, t_end]. */
static double first_try(const sus_tol_work *wk, const double w[2], double left)
{
    const double h =
        wk->h_next > 0.0 ? wk->h_next : RADIUS_FRACTION * sus_step_taylor_radius(wk->m, w);
    return fmin(h, left);
}

/* Shortened to the proved radius when the cheap bound K |w| h < 1 does not already prove it. */
static double within_radius(const sus_model *m, const double w[2], double h)
{
    const double kh = m->norm_b * m->norm_fA * h; /* K |w| h < 1, squared: no hypot on every step */
    if (kh * kh * (w[0] * w[0] + w[1] * w[1]) < 1.0)
        return h;
    return fmin(h, RADIUS_FRACTION * sus_step_taylor_radius(m, w));
}

/* The accepted step: w, the quaternion and t advance, and the next step is proposed. */
static void accept(sus_tol_work *wk, double h, double err, double t_next, double *t, double w[3],
                   double *lambda, sus_attitude *att)
{
    const int p = wk->order->p;
    double dq[4], q1[4];
    sus_quat_of_attitude(att, wk->q0);
    wk->order->sums(wk, w, dq);
    sus_quat_mul(q1, wk->q0, dq);
    sus_quat_to_attitude(q1, att);
    *lambda = sus_lagmult(wk->m, w);
    wk->t0 = *t;
    *t = t_next;
    wk->h = h;
    wk->h_next = h * fmin(GROW, SAFETY * pow(wk->tol / err, 1.0 / (p + 1)));
}

/* The error of the tail jump from w (see the top of the file): w stays within dev of the closed
 * form's w_inf, and w_inf is the one found through E0 to the floor; R within sqrt 2 times the
 * integral of |w - w_inf| (exact_tail.h's bounds along the direction w - w_inf takes).
 * INFINITY where the closed form refuses w. */
static double tail_error(const sus_tol_work *wk, const double w[2])
{
    sus_exact ex;
    double dev, integral;
    if (sus_exact_init(&ex, wk->m, w) != 0 || sus_exact_tail_bounds(&ex, 0.0, &dev, &integral) != 0)
        return INFINITY;
    const double e = fmax(dev + wk->floor, 1.4142135623730951 * integral);
    return isnan(e) ? INFINITY : e;
}

/* Does the run jump its tail from w (see the top of the file)? On the g < 0 half only: from the
 * other the whole transient lies ahead. dev > tol cannot pass (the closed form's dev is at least
 * |w - w_inf|), so the closed form is set up for the last steps only. */
static int settles(const sus_tol_work *wk, const double w[2])
{
    if (!(wk->k_inf > 0.0))
        return 0;
    const double dev = hypot(w[0] - wk->w_inf[0], w[1] - wk->w_inf[1]);
    if (dev <= wk->floor)
        return 1;
    if (!(sus_contdyn_rate(wk->m, w) < 0.0) || !(dev <= wk->tol))
        return 0;
    return tail_error(wk, w) <= wk->tol;
}

/* Is w a rest point of the series? c(w) = 0 makes every W_n, n >= 1, vanish (W_1 = h c_0 U_0, and
 * each later sum holds a factor c_j, 0 < j < n, or W_n), so the steps keep w (exactly from w_0,
 * whose energy is E(w_0); to the energy restoration's rounding from a landing) and turn R by
 * exp(h w^/2), which the rest of the run then takes in closed form instead of adding each step's
 * truncation, about w as the run's w_inf. */
static int at_rest(const sus_model *m, const double w[2]) { return sus_c(m, w) == 0.0; }

/* The tail's speed |w_inf| in double-double (steady_turn.h), from the closed form's setup of w_0:
 * the speed of both steady rotations on E(w_0), so also of a w at rest on one of them; |w_inf| in
 * double where the closed form refuses w_0. */
static void tail_speed(sus_tol_work *wk)
{
    sus_exact ex;
    if (sus_exact_init(&ex, wk->m, wk->w0) == 0) {
        sus_steady_speed(&ex, wk->speed);
        return;
    }
    wk->speed[0] = hypot(wk->w_inf[0], wk->w_inf[1]);
    wk->speed[1] = 0.0;
}

/* The attitude at t in a settled step: q0 (x) exp((t - t0) w_inf^/2), t - t0 to the bit. */
static void settled_attitude(const sus_tol_work *wk, double t, sus_attitude *att)
{
    double q[4] = {wk->q0[0], wk->q0[1], wk->q0[2], wk->q0[3]};
    sus_steady_turn(wk->w_inf, wk->speed, wk->t0, t, q);
    sus_quat_to_attitude(q, att);
}

/* The rest of the run once w has settled: w = w_inf, the attitude by exp(h w_inf^/2), one step. */
static int settled_step(sus_tol_work *wk, double t_end, double *t, double w[3], double *lambda,
                        sus_attitude *att, sus_stepper_stats *st)
{
    const double h = t_end - *t;
    wk->settled = 1;
    wk->t0 = *t;
    tail_speed(wk);
    sus_quat_of_attitude(att, wk->q0);
    settled_attitude(wk, t_end, att);
    w[0] = wk->w_inf[0], w[1] = wk->w_inf[1], w[2] = 0.0;
    *lambda = sus_lagmult(wk->m, w);
    *t = t_end;
    wk->h = h;
    *st = (sus_stepper_stats){.iterations = 0, .residual = 0.0, .scale = wk->tol, .det = h};
    return SUS_STEPPER_OK;
}

/* The series of a try rescaled to a step s times as long: with h folded into the coefficients
 * (X_n = x_n h^n) the series of the step s h is X_n s^n, exactly the same polynomial, so a rejected
 * try needs no new recursion; its estimate is recomputed from the rescaled rows. */
static double rescaled_try(sus_tol_work *wk, int p, double s)
{
    double sn = 1.0;
    for (int n = 1; n <= p; n++) {
        sn *= s;
        wk->t.W[n] *= sn;
        wk->t.P[n] *= sn;
        wk->t.M[n] *= sn;
    }
    return estimate(&wk->t, p);
}

static int adaptive_step(sus_tol_work *wk, double t_end, double *t, double w[3], double *lambda,
                         sus_attitude *att, sus_stepper_stats *st)
{
    if (settles(wk, w))
        return settled_step(wk, t_end, t, w, lambda, att, st);
    if (at_rest(wk->m, w)) {
        wk->w_inf[0] = w[0], wk->w_inf[1] = w[1];
        return settled_step(wk, t_end, t, w, lambda, att, st);
    }
    const int p = wk->order->p;
    double h = within_radius(wk->m, w, first_try(wk, w, t_end - *t));
    double err = wk->order->try_step(wk, h, w);
    int tries = 0;
    while (!(err <= wk->tol)) { /* NaN is rejected too */
        if (++tries == MAX_TRIES || !(*t + h > *t)) {
            *st = (sus_stepper_stats){
                .iterations = tries, .residual = err, .scale = wk->tol, .det = h};
            return SUS_STEPPER_REJECTED;
        }
        const double s = fmax(SHRINK_MIN, fmin(SAFETY, SAFETY * pow(wk->tol / err, 1.0 / (p + 1))));
        /* a finite estimate rescales this try; an overflowed series (inf or NaN) is recomputed */
        err = isfinite(err) ? rescaled_try(wk, p, s) : wk->order->try_step(wk, h * s, w);
        h *= s;
    }
    /* The series is summed over the step the clock represents (stepper.h): h' <= h (but for a
     * rounding on reaching t_end), so the try's estimate still bounds it, and the attitude's time
     * is the row's to the bit; adding h to t instead lost u t per step, a phase error growing like
     * t^2 whatever tol. */
    const double t_next = sus_step_end(*t, h, t_end), h_clock = t_next - *t;
    *st =
        (sus_stepper_stats){.iterations = tries, .residual = err, .scale = wk->tol, .det = h_clock};
    if (!(h_clock > 0.0)) /* h below an ulp of t: the clock cannot advance */
        return SUS_STEPPER_REJECTED;
    if (h_clock != h)
        rescaled_try(wk, p, h_clock / h);
    accept(wk, h_clock, err, t_next, t, w, lambda, att);
    return SUS_STEPPER_OK;
}

/* The state at t in the last step, tau = t - t0 into it: the step's own polynomials at
 * theta = tau / h (the coefficients are scaled by h^n), w restored onto E(w_0), the quaternion
 * normalised. */
static void adaptive_dense(const sus_tol_work *wk, double t, double w[3], double *lambda,
                           sus_attitude *att)
{
    const double tau = t - wk->t0;
    if (wk->settled) {
        settled_attitude(wk, t, att);
        w[0] = wk->w_inf[0], w[1] = wk->w_inf[1], w[2] = 0.0;
        *lambda = sus_lagmult(wk->m, w);
        return;
    }
    const double th = wk->h > 0.0 ? tau / wk->h : 0.0;
    v2d W = {0.0, 0.0}, P = {0.0, 0.0}, M = {0.0, 0.0};
    for (int n = wk->order->p; n >= 0; n--) {
        W = W * th + wk->t.W[n];
        P = P * th + wk->t.P[n];
        M = M * th + wk->t.M[n];
    }
    const double dq[4] = {P[0], M[0], M[1], P[1]};
    double q[4];
    w[0] = W[0], w[1] = W[1], w[2] = 0.0;
    taylor_energy_onto(wk->m, wk->e0, w);
    *lambda = sus_lagmult(wk->m, w);
    sus_quat_mul(q, wk->q0, dq);
    sus_quat_to_attitude(q, att);
}

static const sus_tol_ops ADAPTIVE_OPS = {adaptive_alloc,
                                         adaptive_step,
                                         adaptive_dense,
                                         adaptive_free,
                                         sus_step_taylor_adaptive_order,
                                         SUS_STEADY_TURN_MAX_ANGLE,
                                         NULL};

const sus_stepper_type sus_step_taylor_adaptive_type = {
    .name = "taylor-adaptive",
    .tol = &ADAPTIVE_OPS,
    .desc = {
        .conserves_energy = 1, .attitude = SUS_ATTITUDE_QUAT, .substeps = 1, .source = __FILE__}};
