/* exact-attitude: a tolerance-driven method that uses what is known. w(t) and lambda(t) come from
 * the closed form (exact.h, evaluated by exact_fast.h with one exp; lambda = (LagMult) of it), so
 * the only equation left to integrate is the linear one R' = R w^(t), carried as a unit
 * quaternion, q' = 1/2 q (x) (0, w).
 *
 * Tolerance. TOL bounds dist(R, R_ref) = |R R_ref^T - I|_F over the whole run, up to round-off. For
 * unit quaternions dist <= 2 sqrt2 |q - q_ref| (a rotation by theta has dist 2 sqrt2 sin(theta/2),
 * and |q - q_ref| = 2 sin(theta/4) for the nearer sign), so the method works with tolq = TOL /
 * (2 sqrt2) in |dq|. The flow of q' = 1/2 q (x) (0, w) keeps norms, so the error at any time is at
 * most the sum of the local errors of the steps taken so far, plus the tail's (below). The steps
 * share a budget: each accepted step's local error estimate is at most rate h, rate = (budget -
 * spent) / (t_stop - t), so the estimates summed never exceed the budget: tolq for a run that ends
 * before the tail, tolq / 2 for one that reaches it, the tail taking the other half. t_stop is
 * t_end or the start of the tail, where the integration stops exactly.
 *
 * The tail. w(t) -> w_inf at the rate k. Once half the closed-form bound of the integral of
 * |w - w_inf| from t on (exact_tail.h; half: the quaternion's share) is at most tolq / 2, one step
 * jumps to t_end: q(T) = q(t*) (x) exp((T - t*) w_inf / 2), the steady rotation in closed form. So
 * the cost of a run stops growing with T, and so does its error: the angle (T - t*) |w_inf| is
 * formed in two doubles (steady_turn.h), from T - t* exactly and |w_inf| in double-double, so it
 * is right to a few roundings of pi however large. In one double it would be off by u (T - t*)
 * |w_inf|, an error growing with T that the inputs, exact doubles, do not have
 * (tests/unit/test_exact_attitude.c holds the tail step, and a dense row inside it, to 128 u at
 * T = 1e4, 1e6 and 1e9). A dense row forms its t - t* exactly too.
 *
 * Steps: the Taylor series of w (the closed form's own, closed_series below) and of q (the
 * recursion of taylor_series.h), to degree d, over the longest step allowed, H = rho(t) / 2 with
 * rho(t) = |s(t) + i pi/2| / k the distance from t to w's nearest complex singularity (sech and
 * tanh of s = s0 + sigma k t have poles at s = i pi/2 + i pi n). The sum through d (the
 * degree-(d-1) sum locally extrapolated) is off by the terms past d. Over a step s H they fall,
 * from one degree to the next, by at most a s with a = H max(g / rho, |w|_max / (2 (d + 2))): the
 * nearest singularity's ratio, and the rotation's, whose terms go like x^n / n!, x = h |w| / 2.
 * At w's pole q has a branch point, q ~ (t - t_p)^-beta (pole_exponent), so its terms grow like
 * n^(beta - 1) rho^-n, by (n + beta) / (n + 1) per degree beyond 1 / rho: g is that factor at n =
 * d - 4, the earliest term projected. Projected from each of the last five terms (a conjugate
 * pair of singularities makes the terms oscillate about their envelope and dip, on a stiff body
 * for several degrees running, so the last few alone can mislead), the terms past d are estimated
 * to sum to at most
 *     est(s) = s^{d+1} B / (1 - a s),   B = max_{j < 5} |Q_{d-j}| a^{j+1},
 * with h folded into the coefficients (X_n = x_n H^n, so the step s H has X_n s^n). An estimate,
 * not a proof (the ratio a holds for the envelope only as n grows): test_exact_attitude holds
 * every step's local error to it, on every test body, from its own start at TOL every half
 * decade and from just before the inflection (1 / E = 1/2) every decade. The step takes the
 * largest s <= 1 with a s <= 1/2, |Q_d| s <= |Q_{d-1}| / 2 (past the rotation's rising terms) and
 * 2 B s^d <= rate H, so that est(s) <= rate s H: one series a step, never a retry.
 *
 * The series in E. Past the inflection of the transient, E = e^{-(sigma s0 + k t)} < 1, one power
 * series in E gives q at every later time (attitude_series.h): it converges for |E| < 1, where a
 * series in t stops at w's nearest singularity. So once E(t) is small enough that the series'
 * degree for the budget left, by the terms' fall alone, log(budget) / log(E), is at most
 * SERIES_TERMS, one step of it takes the rest of the way to t_stop, with the whole budget left as
 * its share. A start past the inflection is then one step to t_stop. Before it, where 1 / E < 1 is
 * small, one step of the series in 1 / E (attitude_series.h) goes to where 1 / E has grown to
 * about the same size, with its share of the budget like a Taylor step, and Taylor steps cross
 * the inflection between the two series' disks.
 *
 * The degree, by TOL (DEGREES): the one with the least measured time to t = 50 over the paper's,
 * the general and the stiff bodies of tests/unit/bodies.h (geometric mean of time over the best
 * degree's), decade by decade, measured before the series in E took over past the inflection;
 * within two degrees of it the time changes little. A Magnus6 step
 * (Blanes, Casas & Ros; three Gauss nodes) on the same closed-form w was measured beside these:
 * with an error estimate worth the name (step doubling: two halves against one whole step) a pair
 * of half steps costs as much as a Taylor step of low degree and advances less far than a step of
 * the best degree, so the Taylor series was the cheaper at every tolerance on the general bodies;
 * it is not part of the method. Fixed Magnus6 steps along the same w are timed by make bench, as
 * a peer on the reduced problem (src/lab/magnus6.c): its error carries the rotation per step
 * h |w| through nested commutators, so it needs short steps where the Taylor series takes long
 * ones; the recorded run says where it stands against this method and taylor10.
 *
 * R stays in SO(3) to round-off: q is normalised at every step and R built from it. w is the
 * closed form at every step's end (|E - E0| a few u: w = L^{-T} u with |u| = r), w3 = 0. */
#include "exact_attitude.h"

#include "attitude_series.h"
#include "exact.h"
#include "exact_fast.h"
#include "exact_tail.h"
#include "quaternion.h"
#include "steady_turn.h"
#include "taylor_series.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TAIL_SHARE 0.5
#define RADIUS_SHARE 0.5
#define DIST_PER_Q 2.8284271247461903 /* 2 sqrt2: dist(R, R') <= 2 sqrt2 |q - q'| */
#define HALF_PI 1.5707963267948966
/* The terms the envelope is projected from (top of the file): on the stiff test bodies the terms
 * dip for four degrees running, so the last three or four can all lie in one dip. */
#define ENVELOPE_TERMS 5
/* The series in E is tried where its degree for the budget left, log(budget) / log(E) (the terms'
 * fall alone), would be at most this: so many degrees cost about two Taylor steps. */
#define SERIES_TERMS 40
/* A step of the series in 1 / E from 1 / E = X to X_b is tried where ln X / ln X_b is at least
 * this: a Taylor step goes half way to w's nearest singularity, at least half way in s to the
 * inflection, so from X the Taylor steps reach X_b in at most about log2(ln X / ln X_b) + 1 steps,
 * and the series, about two Taylor steps' cost (SERIES_TERMS), pays where they would take three
 * or more. */
#define BACK_MIN_RATIO 8.0

typedef enum { KIND_TAYLOR, KIND_SERIES, KIND_TAIL } step_kind;

/* One degree of the series: series_of computes the rows to degree order over a step h from t,
 * where w is w(t). */
typedef struct {
    int order; /* N + 1, the degree of the sums */
    void (*series_of)(const sus_exact_fast *f, double h, double t, const double w[2],
                      taylor_series *ts);
} degree;

struct sus_tol_work {
    const sus_model *m;
    sus_exact ex;
    sus_exact_fast f;
    double tolq;   /* TOL in |dq| */
    double w_max;  /* r |L^{-1}|_F >= |w(t)| for real t */
    double t_tail; /* the tail from here on */
    double spent;  /* the accepted steps' estimates, summed */
    const degree *deg;
    step_kind kind; /* the last accepted step, for dense output: its kind, start, length, q0 */
    double t0, h, q0[4];
    double speed[2];       /* |w_inf| in double-double, speed[0] + speed[1]; set at alloc */
    double beta;           /* q's growth exponent at w's poles (pole_exponent); < 0: not yet */
    double e_try;          /* the series in E is tried from E(t) <= e_try on */
    int back_declined;     /* the series in 1 / E declined once: not tried again */
    taylor_series ts;      /* its series (q's rows scaled to its length) */
    sus_att_series series; /* or its series in E */
};

/* ---- the degree by TOL ---- */

/* (exact.h) w's rows from the closed form's own series, and q's from them. w = c + M (z, y) with
 * (z, y) = (sech s, tanh s), s = s0 + ks t, and z' = -ks z y, y' = ks z^2; so with the rows V_n =
 * (Z_n, Y_n) h^n and S = sum_j Z_j V_{n-j},
 *     V_{n+1} = ks h / (n + 1) (-S_2, S_1),   W_{n+1} = M V_{n+1}.
 * Not (ContDyn)'s recursion from w (taylor_series.h): that seeds it with c(w) = I31 w1 + I32 w2 of
 * the rounded w, which near the steady rotation is a rounding u |b| |w| of terms that cancel, and
 * on a near-singular I_m (ContDyn) multiplies it by 1 / |I_m|, far past any TOL (the
 * near-singular bodies of tests/unit/test_exact_attitude.c). Here |z|, |y| <= 1 and every row is a
 * few roundings of |M| times its own terms. */
static inline __attribute__((always_inline)) void closed_series(const sus_exact_fast *f,
                                                                const int p, const double h,
                                                                const double t, const double w[2],
                                                                taylor_series *ts)
{
    v2d V[SUS_STEP_TAYLOR_MAX_ORDER + 1];
    double st[2];
    sus_exact_fast_st(f, t, st);
    V[0] = (v2d){st[0], st[1]};
    ts->W[0] = (v2d){w[0], w[1]};
    ts->P[0] = (v2d){1.0, 0.0};
    ts->M[0] = (v2d){0.0, 0.0};
    const v2d m0 = {f->M[0][0], f->M[1][0]}, m1 = {f->M[0][1], f->M[1][1]};
#pragma GCC unroll 32
    for (int n = 0; n < p; n++) {
        const double g = f->ks * h / (double)(n + 1);
        v2d S = {0.0, 0.0};
#pragma GCC unroll 32
        for (int j = 0; j <= n; j++)
            S += V[j][0] * V[n - j];
        V[n + 1] = (v2d){-g * S[1], g * S[0]};
        ts->W[n + 1] = m0 * V[n + 1][0] + m1 * V[n + 1][1];
        q_row(ts, n, 0.5 * h / (double)(n + 1));
    }
}

#define SERIES(N)                                                                                  \
    static void series##N(const sus_exact_fast *f, double h, double t, const double w[2],          \
                          taylor_series *ts)                                                       \
    {                                                                                              \
        closed_series(f, N, h, t, w, ts);                                                          \
    }
SERIES(11)
SERIES(13)
SERIES(15)
SERIES(17)

/* The degree for TOL >= tol_min; the first row whose tol_min TOL reaches. */
static const struct {
    double tol_min;
    degree d;
} DEGREES[] = {
    {3.2e-4, {11, series11}},
    {3.2e-6, {13, series13}},
    {3.2e-10, {15, series15}},
    {0.0, {17, series17}},
};

static const degree *degree_for(double tol)
{
    int i = 0;
    while (!(tol >= DEGREES[i].tol_min))
        i++;
    return &DEGREES[i].d;
}

int sus_step_exact_attitude_order(double tol) { return degree_for(tol)->order; }

/* ---- one step ---- */

/* The distance from t to w's nearest complex singularity (top of the file). */
static double radius(const sus_tol_work *wk, double t)
{
    const double s = wk->f.s0 + wk->f.ks * t;
    return sqrt(s * s + HALF_PI * HALF_PI) / wk->ex.k; /* |s| < 1e150: no overflow */
}

/* Where the integration stops: t_end, or the start of the tail. */
static double stop_of(const sus_tol_work *wk, double t_end)
{
    return t_end > wk->t_tail ? wk->t_tail : t_end;
}

/* The allowed local error per unit time from t on (top of the file). */
static double rate_of(const sus_tol_work *wk, double t, double t_end)
{
    const double budget = t_end > wk->t_tail ? (1.0 - TAIL_SHARE) * wk->tolq : wk->tolq;
    /* a caller that moves t_end past the tail after spending more than its share gets a sixteenth
     * of the share to go on with (sus_run_tol never does: its t_end is fixed) */
    const double left = budget - wk->spent > 0.0 ? budget - wk->spent : budget / 16.0;
    return left / (stop_of(wk, t_end) - t);
}

/* |Q_n|_2 over the four components. */
static double quat_row(const taylor_series *ts, int n)
{
    const v2d p = ts->P[n], m = ts->M[n];
    return sqrt(p[0] * p[0] + p[1] * p[1] + m[0] * m[0] + m[1] * m[1]);
}

/* The envelope at d + 1: each of the last ENVELOPE_TERMS terms projected by a per degree (top of
 * the file). A NaN term is dropped as fmax drops it; the last's NaN or inf stays. */
static double envelope(const taylor_series *ts, int d, double a)
{
    double B = quat_row(ts, d) * a, an = a;
    for (int j = 1; j < ENVELOPE_TERMS; j++) {
        an *= a;
        B = fmax(B, quat_row(ts, d - j) * an);
    }
    return B;
}

/* q <- q (x) sum_{n <= d} Q_n, summed as dq_from sums. */
static void turn(double q[4], const taylor_series *ts, int d)
{
    double dq[4], p[4];
    dq_from(ts, d, dq);
    sus_quat_mul(p, q, dq);
    memcpy(q, p, sizeof p);
}

/* q's rows Q_n theta^n, n = 1..d, into out (which may be in); w's rows are left out, being read no
 * more. Returns theta^d. */
static double scale_rows(const taylor_series *in, int d, double theta, taylor_series *out)
{
    double tn = 1.0;
    for (int n = 1; n <= d; n++) {
        tn *= theta;
        out->P[n] = in->P[n] * tn;
        out->M[n] = in->M[n] * tn;
    }
    return tn;
}

/* q <- q (x) sum_{n <= d} Q_n theta^n: the rows scaled, then summed in tail_sum's interleaved
 * order (its two partial sums overlap, where a Horner scheme is one chain of d dependent steps);
 * at theta = 1, the step's end, the products are exact, so dense output there is the step's own
 * q to the bit. */
static void taylor_sum(const taylor_series *ts, int d, double theta, double q[4])
{
    taylor_series y;
    scale_rows(ts, d, theta, &y);
    turn(q, &y, d);
}

/* q's growth exponent at w's nearest poles (top of the file). Near a pole t_p, w ~ R / (t - t_p)
 * with R = M (-i, 1) / ks (sech s ~ -i / e, tanh s ~ 1 / e at s = i pi/2 + e), and q' = 1/2 q (x)
 * (0, w) has q ~ (t - t_p)^(+-mu), mu = i sqrt(R.R) / 2; the branch with Re(-mu) = -beta < 0 has
 * Taylor terms from t growing like n^(beta - 1) rho^-n. beta = |Im sqrt(R.R)| / 2. */
static double pole_exponent(const sus_exact_fast *f)
{
    if (f->fixed) /* w constant: no poles */
        return 0.0;
    double re = 0.0, im = 0.0; /* R.R ks^2 */
    for (int i = 0; i < 2; i++) {
        re += f->M[i][1] * f->M[i][1] - f->M[i][0] * f->M[i][0];
        im -= 2.0 * f->M[i][0] * f->M[i][1];
    }
    return 0.5 * sqrt(0.5 * (hypot(re, im) - re)) / fabs(f->ks);
}

/* The bound, per degree, on how the terms past the last fall over a step H from t (top of the
 * file): the nearest singularity's H / rho, or the rotation's x / (d + 2), x = H |w|_max / 2. */
static double decay_per_degree(const sus_tol_work *wk, double H, double rho, int d)
{
    const int n = d - (ENVELOPE_TERMS - 1);
    const double g = fmax(1.0, (n + wk->beta) / (n + 1));
    return H * fmax(g / rho, wk->w_max / (2.0 * (d + 2)));
}

/* A step from (t, w, q) to at most stop whose estimate is at most rate h (top of the file): the
 * series over H, the step s H shortened to the one the clock represents (stepper.h: its end *t_next
 * is the row's time to the bit, h = *t_next - t), q's rows rescaled to it (dense output reads
 * them), q advanced. Returns 0, or -1 for a series that overflowed or a step shorter than a
 * rounding of H (a tolerance far below round-off; nothing advanced). */
static int taylor_step(sus_tol_work *wk, double t, double stop, double rate, const double w[2],
                       double q[4], double *h, double *t_next, double *est)
{
    const int d = wk->deg->order;
    if (wk->beta < 0.0) /* at the first Taylor step: a run of series steps alone needs none */
        wk->beta = pole_exponent(&wk->f);
    const double rho = radius(wk, t), H = fmin(stop - t, RADIUS_SHARE * rho);
    wk->deg->series_of(&wk->f, H, t, w, &wk->ts);
    const double a = decay_per_degree(wk, H, rho, d);
    const double q1 = quat_row(&wk->ts, d - 1), q0 = quat_row(&wk->ts, d);
    const double B = envelope(&wk->ts, d, a);
    double s = fmin(1.0, 0.5 / a);
    if (s * q0 > 0.5 * q1) /* the last two terms halve too */
        s = 0.5 * q1 / q0;
    /* s^(d+1) B / (1 - s a) <= rate s H, as 1 - s a >= 1/2: one root, not a power to test first */
    const double s_rate = pow(rate * H / (2.0 * B), 1.0 / d);
    if (s > s_rate)
        s = s_rate;
    if (!(s >= SUS_U)) /* a tolerance no step of double can meet: fail, not crawl for ever */
        return -1;
    *t_next = sus_step_end(t, s * H, stop);
    *h = *t_next - t;
    s = *h / H; /* at most the s above, but for a rounding on reaching stop */
    const double sn = scale_rows(&wk->ts, d, s, &wk->ts); /* the rows of the step s H */
    *est = sn * s * B / (1.0 - s * a);
    if (!isfinite(B))
        return -1;
    turn(q, &wk->ts, d); /* taylor_sum at theta = 1, without the copy */
    return 0;
}

/* The rest of the way to stop in one step of the series in E (attitude_series.h), from where E(t)
 * is small enough for its degree to stay near SERIES_TERMS; 1 when taken, with its estimate (the
 * whole budget left, rate (stop - t), is its share). A series that declines is tried again only
 * once E has halved. */
static int series_step(sus_tol_work *wk, double t, double stop, double rate, double q[4], double *h,
                       double *est)
{
    const double E = sus_att_series_E(&wk->f, t), left = rate * (stop - t);
    if (!(E <= wk->e_try) || !(log(0.5 * left) / log(E) <= SERIES_TERMS))
        return 0;
    *est = sus_att_series_build(&wk->series, &wk->f, t, stop, q, left);
    if (*est < 0.0) {
        wk->e_try = 0.5 * E;
        return 0;
    }
    sus_att_series_at(&wk->series, &wk->f, wk->speed, stop, q);
    *h = stop - t;
    return 1;
}

/* Before the inflection: one step of the series in 1 / E (attitude_series.h) from t, where 1 / E
 * = X, to where 1 / E reaches the X_b at which the degree for the step's share, by the terms'
 * fall alone, is about SERIES_TERMS (or to stop), with its share of the budget, rate h; tried
 * only where it saves Taylor steps (BACK_MIN_RATIO) and not after the series has declined once.
 * 1 when taken, t_next the step's end. */
static int back_series_step(sus_tol_work *wk, double t, double stop, double rate, double q[4],
                            double *h, double *t_next, double *est)
{
    const double X = 1.0 / sus_att_series_E(&wk->f, t), k = wk->ex.k;
    if (wk->back_declined || !(X < 1.0))
        return 0;
    /* X_b from the share of the step to X_b = left^(1/SERIES_TERMS), the most the share can be */
    const double x0 = pow(0.5 * rate * (stop - t), 1.0 / SERIES_TERMS);
    const double share = rate * fmin(stop - t, log(x0 / X) / k);
    const double xb = pow(0.5 * share, 1.0 / SERIES_TERMS);
    if (!(log(X) <= BACK_MIN_RATIO * log(xb)))
        return 0;
    *t_next = sus_step_end(t, log(xb / X) / k, stop);
    *h = *t_next - t;
    *est = sus_att_series_build(&wk->series, &wk->f, t, *t_next, q, rate * *h);
    if (*est < 0.0) {
        wk->back_declined = 1;
        return 0;
    }
    sus_att_series_at(&wk->series, &wk->f, wk->speed, *t_next, q);
    return 1;
}

/* w and lambda at t from the closed form, and the attitude from q. */
static void state_at(const sus_tol_work *wk, double t, const double q[4], double w[3],
                     double *lambda, sus_attitude *att)
{
    /* c(t) from the closed form, as the reference's: I31 w1 + I32 w2 at the rounded w cancels
     * near the steady rotation, and (LagMult) divides it by |I_m| */
    const double c = sus_exact_fast_omega_c(&wk->f, t, w);
    w[2] = 0.0;
    *lambda = sus_lagmult_c(wk->m, w, c);
    sus_quat_to_attitude(q, att);
}

/* ---- the tolerance-driven operations ---- */

static sus_tol_work *ea_alloc(const sus_model *m, double tol, const double w0[2])
{
    sus_tol_work *wk = malloc(sizeof *wk);
    if (!wk)
        return NULL;
    *wk = (sus_tol_work){
        .m = m, .tolq = tol / DIST_PER_Q, .deg = degree_for(tol), .beta = -1.0, .e_try = 1.0};
    if (sus_exact_init(&wk->ex, m, w0) != 0 || sus_exact_fast_init(&wk->f, &wk->ex) != 0) {
        free(wk);
        return NULL;
    }
    const sus_exact *ex = &wk->ex;
    sus_steady_speed(ex, wk->speed);
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    wk->w_max = sqrt(a * a + b * b + c * c) * ex->r;
    /* half the bound is the quaternion's error; that half at most the tail's share of tolq */
    wk->t_tail = sus_exact_tail_time(&wk->ex, 2.0 * TAIL_SHARE * wk->tolq);
    return wk;
}

static void ea_free(sus_tol_work *wk) { free(wk); }

/* sus_exact_turn_angle from the closed form alloc built */
static double ea_turn_angle(const sus_tol_work *wk, double T)
{
    double w_inf[2];
    sus_exact_limit(&wk->ex, w_inf);
    return T * hypot(w_inf[0], w_inf[1]);
}

static int ea_step(sus_tol_work *wk, double t_end, double *t, double w[3], double *lambda,
                   sus_attitude *att, sus_stepper_stats *st)
{
    double q[4], h = t_end - *t, t_next = t_end, est = 0.0, rate = 0.0;
    int failed = 0;
    sus_quat_of_attitude(att, q);
    memcpy(wk->q0, q, sizeof q);
    if (*t >= wk->t_tail) {
        wk->kind = KIND_TAIL;
        sus_steady_turn(wk->f.winf, wk->speed, *t, t_end, q);
        est = 0.5 * sus_exact_tail_bound(&wk->ex, *t);
    } else {
        const double stop = stop_of(wk, t_end);
        rate = rate_of(wk, *t, t_end);
        wk->kind = KIND_SERIES;
        t_next = stop;
        if (!series_step(wk, *t, stop, rate, q, &h, &est) &&
            !back_series_step(wk, *t, stop, rate, q, &h, &t_next, &est)) {
            wk->kind = KIND_TAYLOR;
            failed = taylor_step(wk, *t, stop, rate, w, q, &h, &t_next, &est);
        }
    }
    *st =
        (sus_stepper_stats){.residual = DIST_PER_Q * est, .scale = DIST_PER_Q * rate * h, .det = h};
    if (failed || !(h > 0.0))
        return SUS_STEPPER_REJECTED;
    wk->spent += est;
    wk->t0 = *t;
    wk->h = h;
    *t = t_next; /* exactly at t_end, or at the tail's start */
    state_at(wk, *t, q, w, lambda, att);
    return SUS_STEPPER_OK;
}

/* The state at t in the last step: the steady rotation over t - t0 to the bit (tau and what
 * its rounding left out), the series in E at t, or the step's Taylor polynomial at tau / h; w and
 * lambda from the closed form. */
static void ea_dense(const sus_tol_work *wk, double t, double w[3], double *lambda,
                     sus_attitude *att)
{
    double q[4];
    const double tau = t - wk->t0;
    memcpy(q, wk->q0, sizeof q);
    if (wk->kind == KIND_TAIL)
        sus_steady_turn(wk->f.winf, wk->speed, wk->t0, t, q);
    else if (wk->kind == KIND_SERIES)
        sus_att_series_at(&wk->series, &wk->f, wk->speed, t, q);
    else
        taylor_sum(&wk->ts, wk->deg->order, wk->h > 0.0 ? tau / wk->h : 0.0, q);
    state_at(wk, t, q, w, lambda, att);
}

static const sus_tol_ops EA_OPS = {ea_alloc,
                                   ea_step,
                                   ea_dense,
                                   ea_free,
                                   sus_step_exact_attitude_order,
                                   SUS_STEADY_TURN_MAX_ANGLE,
                                   ea_turn_angle};

const sus_stepper_type sus_step_exact_attitude_type = {.name = "exact-attitude",
                                                       .tol = &EA_OPS,
                                                       .desc = {.conserves_energy = 1,
                                                                .w_closed_form = 1,
                                                                .attitude = SUS_ATTITUDE_QUAT,
                                                                .substeps = 1,
                                                                .source = __FILE__}};
