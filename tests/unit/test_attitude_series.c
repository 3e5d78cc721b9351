/* The attitude as a series in E = e^{-(sigma s0 + k t)} (src/core/attitude_series.h), against the
 * long-double reference attitude (refattitude.h), on every body of tests/unit/bodies.h and two of
 * the paper's altered ("slow": a third row a tenth of the paper's, so the coefficients grow
 * fastest; "fast": w0 eight times the paper's):
 *   - each of the two sums the series takes is truncated by at most half its estimate: from t_a,
 *     where E = E_a, to t_f = t_a + 40 / k, where E(t_f) = e^{-40} E_a leaves the later sum's
 *     truncation far below round-off, the error is the earlier sum's alone. Expected: the
 *     reference's q(t_f); E_a from 0.05 to 0.7, budgets 1e-3 ... 1e-13, wherever the series
 *     accepts the budget;
 *   - it declines a start before the inflection (E >= 1) whose interval reaches past it;
 *   - before the inflection, the series in 1 / E: from a start moved back along each body's motion
 *     to where 1 / E = e^{-20} X_b, to t_b where 1 / E = X_b (0.3, 0.5, 0.7), the sum at t_b is
 *     truncated by at most half its estimate (the earlier sum's truncation, e^{-20} smaller per
 *     degree, is far below round-off); expected: the reference's q(t_b), budgets 1e-3 ... 1e-13;
 *   - in exact-attitude, from such a start (1 / E = 1e-6), the first step is that series: it ends
 *     at t = 50 or where 1 / E >= 1/4 (a Taylor step ends at most half way to w's nearest
 * singularity, so where |s| has at most halved, 1 / E <= 1e-3), and the run ends within TOL of the
 * reference at t = 50;
 *   - in exact-attitude (src/methods/step_exact_attitude.c) it takes the rest of a run in one
 *     step from a start past the inflection: from E(0) <= 1/2 its degree for TOL 1e-6 by the
 *     terms' fall alone is log(TOL / (4 sqrt2)) / log(1/2) = 22, within the method's
 *     SERIES_TERMS (40), so a run to t = 50 is that step and, where the tail starts before
 *     t = 50, the tail's.
 * Round-off allowance, fixed from counts of roundings before measuring: ROUND_STEP = 34 u and
 * COND = 32 u per radian the steady rotation turns between t_a and t_f, as for a step of
 * exact-attitude (tests/unit/test_exact_attitude.c gives the reasons), in |dq| divided by
 * 2 sqrt2. */
#include "attitude_series.h"
#include "check.h"
#include "check_body.h"
#include "driver.h"
#include "exact_attitude.h"
#include "quaternion.h"
#include "refattitude.h"
#include "so3.h"
#include "steady_turn.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define U SUS_U
#define ROUND_STEP 34.0
#define COND 32.0
#define DIST_PER_Q 2.8284271247461903 /* dist(R, R') <= 2 sqrt2 |q - q'| */

/* The family's bodies, then "slow" and "fast" (the top of the file). */
static void series_body(int j, body *b)
{
    if (j < BODIES_COUNT) {
        body_get(j, b);
        return;
    }
    check_body_paper_variant(j == BODIES_COUNT, b);
}

/* The worst (error - round-off) / (estimate / 2) at tf of the series from q(ta) = qa on [ta, tb]
 * over the budgets 1e-3 ... 1e-13, against the reference Rf; counts the series built. */
static double over_budgets(const sus_exact *ex, const sus_exact_fast *f, double ta, double tb,
                           const double qa[4], double tf, const double Rf[3][3], int *built)
{
    double speed[2], winf[2], worst = 0.0;
    sus_steady_speed(ex, speed);
    sus_exact_limit(ex, winf);
    const double round = (ROUND_STEP + COND * (tf - ta) * hypot(winf[0], winf[1])) * U;
    for (int d = 3; d <= 13; d++) {
        static sus_att_series s;
        const double est = sus_att_series_build(&s, f, ta, tb, qa, pow(10.0, -d));
        if (est < 0.0)
            continue;
        double q[4], R[3][3];
        sus_att_series_at(&s, f, speed, tf, q);
        sus_quat_unit_rotation(q, R);
        worst = fmax(worst, (sus_so3_dist(R, Rf) - round) / (DIST_PER_Q * 0.5 * est));
        (*built)++;
    }
    return worst;
}

/* over_budgets at t_f of the series in E from t_a where E = Ea. */
static double one_start(const sus_exact *ex, const sus_exact_fast *f, double Ea, int *built)
{
    const double ta = (-ex->sigma * ex->s0 - log(Ea)) / ex->k, tf = ta + 40.0 / ex->k;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double Ra[3][3], Rf[3][3], qa[4];
    if (!(ta >= 0.0))
        return 0.0;
    sus_refatt ra;
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, ta, Ra);
    sus_refatt_advance(&ra, tf, Rf);
    sus_quat_from_rotation(Ra, qa);
    return over_budgets(ex, f, ta, INFINITY, qa, tf, Rf, built);
}

static void each_sum_within_half(void)
{
    static const double EA[] = {0.05, 0.1, 0.2, 0.35, 0.5, 0.7};
    double worst = 0.0;
    int built = 0, bodies = 0;
    for (int k = 0; k < BODIES_COUNT + 2; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        sus_exact_fast f;
        series_body(k, &b);
        if (check_body_model(&b, &m) || sus_exact_init(&ex, &m, b.w0) != 0 || ex.fixed ||
            sus_exact_fast_init(&f, &ex) != 0)
            continue;
        bodies++;
        for (size_t e = 0; e < sizeof EA / sizeof EA[0]; e++)
            worst = fmax(worst, one_start(&ex, &f, EA[e], &built));
    }
    CHECK(built >= 100 && worst <= 1.0,
          "each sum of the series in E is truncated by at most half its estimate (+ %g u + %g u "
          "per radian): worst (error - round-off) / (estimate / 2) %.3g over %d series, %d "
          "bodies, E_a 0.05 ... 0.7, budgets 1e-3 ... 1e-13",
          ROUND_STEP, COND, worst, built, bodies);
}

/* Body j's motion moved back so that 1 / E = X0 at t = 0: its w at the time where 1 / E was X0
 * becomes w0. Returns -1 for a body without a transient. */
static int moved_back(int j, double X0, sus_model *m, sus_exact *ex, sus_exact_fast *f)
{
    body b;
    series_body(j, &b);
    if (check_body_model(&b, m) || sus_exact_init(ex, m, b.w0) != 0 || ex->fixed)
        return -1;
    double w0[2];
    sus_exact_omega(ex, (log(X0) - ex->sigma * ex->s0) / ex->k, w0);
    if (sus_exact_init(ex, m, w0) != 0 || ex->fixed || sus_exact_fast_init(f, ex) != 0)
        return -1;
    return 0;
}

/* over_budgets at t_b of the series in 1 / E from t = 0 to t_b, where 1 / E = Xb. */
static double one_back(const sus_exact *ex, const sus_exact_fast *f, double Xb, int *built)
{
    const double tb = (log(Xb) - ex->sigma * ex->s0) / ex->k;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, q0[4] = {1, 0, 0, 0};
    double Rb[3][3];
    sus_refatt ra;
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, tb, Rb);
    return over_budgets(ex, f, 0.0, tb, q0, tb, Rb, built);
}

static void back_sum_within_half(void)
{
    static const double XB[] = {0.3, 0.5, 0.7};
    double worst = 0.0;
    int built = 0, bodies = 0;
    for (int j = 0; j < BODIES_COUNT + 2; j++)
        for (size_t i = 0; i < sizeof XB / sizeof XB[0]; i++) {
            sus_model m;
            sus_exact ex;
            sus_exact_fast f;
            if (moved_back(j, exp(-20.0) * XB[i], &m, &ex, &f) != 0)
                continue;
            bodies += i == 0;
            worst = fmax(worst, one_back(&ex, &f, XB[i], &built));
        }
    CHECK(built >= 100 && worst <= 1.0,
          "before the inflection, the series in 1 / E is truncated at t_b by at most half its "
          "estimate (+ %g u + %g u per radian): worst %.3g over %d series, %d bodies, 1 / E(t_b) "
          "0.3 ... 0.7, budgets 1e-3 ... 1e-13",
          ROUND_STEP, COND, worst, built, bodies);
}

/* From 1 / E = 1e-6 at t = 0 the first step of exact-attitude ends where 1 / E >= 1/4 or at
 * t = 50, and the run is within TOL + round-off of the reference at t = 50. */
typedef struct {
    long rows;
    double t1;
    double R[3][3];
} first_ctx;

static int first_row(void *ctx, const sus_row *row)
{
    first_ctx *c = ctx;
    if (c->rows++ == 1)
        c->t1 = row->t;
    memcpy(c->R, row->R, sizeof c->R);
    return 0;
}

/* The worst dist(R, R_ref) - round-off over the rows of a run by dense output. */
typedef struct {
    sus_refatt ra;
    double round_per_t, worst;
} dense_ctx;

static int dense_row(void *ctx, const sus_row *row)
{
    dense_ctx *c = ctx;
    double R[3][3];
    sus_refatt_at(&c->ra, row->t, R);
    c->worst = fmax(c->worst, sus_so3_dist(row->R, R) - (ROUND_STEP + c->round_per_t * row->t) * U);
    return 0;
}

/* The run of tc from ex.w0 with rows every 2.5 by dense output: its worst excess over TOL. */
static double dense_excess(const sus_tol_config *tc, const sus_exact *ex)
{
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    static dense_ctx c;
    double winf[2];
    sus_exact_limit(ex, winf);
    sus_refatt_init(&c.ra, ex, 0.0, I3);
    c.round_per_t = COND * hypot(winf[0], winf[1]);
    c.worst = 0.0;
    sus_tol_config dense = *tc;
    dense.every_time = 2.5;
    if (sus_run_tol(&dense, ex->w0, dense_row, &c, &(sus_run_report){0}) != SUS_RUN_OK)
        return INFINITY;
    return c.worst / tc->tol;
}

static void back_first_step(void)
{
    static const double TOL[] = {1e-4, 1e-8, 1e-12};
    double least = INFINITY, worst = 0.0, dense = 0.0;
    int runs = 0;
    for (int j = 0; j < BODIES_COUNT + 2; j++)
        for (size_t i = 0; i < sizeof TOL / sizeof TOL[0]; i++) {
            sus_model m;
            sus_exact ex;
            sus_exact_fast f;
            if (moved_back(j, 1e-6, &m, &ex, &f) != 0)
                continue;
            const sus_tol_config tc = {&m, &sus_step_exact_attitude_type, TOL[i], 50.0, 0.0, 0};
            first_ctx c = {0, NAN, {{0}}};
            double w[2], Rref[3][3], winf[2];
            if (sus_run_tol(&tc, ex.w0, first_row, &c, &(sus_run_report){0}) != SUS_RUN_OK)
                c.t1 = NAN;
            /* a step to t = 50 itself ends the run before the inflection: as far as it goes */
            least = fmin(least, c.t1 == 50.0 ? 1.0 : 1.0 / sus_att_series_E(&f, c.t1));
            least = isnan(c.t1) ? -1.0 : least; /* fmin drops a NaN */
            sus_refatt_precise(&m, ex.w0, 50.0, w, Rref);
            sus_exact_limit(&ex, winf);
            const double round = (ROUND_STEP + COND * 50.0 * hypot(winf[0], winf[1])) * U;
            worst = fmax(worst, (sus_so3_dist(c.R, Rref) - round) / TOL[i]);
            dense = fmax(dense, dense_excess(&tc, &ex));
            runs++;
        }
    CHECK(runs >= 30 && least >= 0.25 && worst <= 1.0 && dense <= 1.0,
          "exact-attitude from 1 / E(0) = 1e-6 (%d runs, TOL 1e-4, 1e-8, 1e-12): the first step "
          "ends at t = 50 or where 1 / E >= 1/4 (least %.3g), and dist(R, R_ref)(50) <= TOL + "
          "round-off (worst %.3g of it), as are its rows every 2.5 by dense output (%.3g)",
          runs, least, worst, dense);
}

static void declines_before_the_inflection(void)
{
    int tried = 0, declined = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        sus_exact_fast f;
        if (check_body_exact(k, &b, &m, &ex) || ex.fixed || sus_exact_fast_init(&f, &ex) != 0 ||
            !(exp(-ex.sigma * ex.s0) >= 1.0))
            continue;
        static sus_att_series s;
        const double q[4] = {1.0, 0.0, 0.0, 0.0};
        tried++;
        declined += sus_att_series_build(&s, &f, 0.0, INFINITY, q, 1.0) < 0.0;
    }
    CHECK(tried >= 2 && declined == tried,
          "a start before the inflection (E(0) >= 1), to t = infinity, is declined: %d of %d "
          "bodies",
          declined, tried);
}

static int count_row(void *ctx, const sus_row *row)
{
    (void)row;
    (*(long *)ctx)++;
    return 0;
}

static void one_step_from_past_the_inflection(void)
{
    int bodies = 0;
    long most = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex) || ex.fixed || !(exp(-ex.sigma * ex.s0) <= 0.5))
            continue;
        sus_run_report rep;
        long rows = 0; /* row 0 and one a step */
        const sus_tol_config tc = {&m, &sus_step_exact_attitude_type, 1e-6, 50.0, 0.0, 0};
        const int rc = sus_run_tol(&tc, b.w0, count_row, &rows, &rep);
        const long steps = rc == SUS_RUN_OK ? rows - 1 : 99; /* a failed run fails the check */
        if (steps > most)
            most = steps;
        bodies++;
    }
    CHECK(bodies >= 3 && most <= 2,
          "exact-attitude from a start past the inflection (E(0) <= 1/2, %d bodies): a run to "
          "t = 50 at TOL 1e-6 takes at most 2 steps, the series in E and the tail: at most %ld",
          bodies, most);
}

int main(void)
{
    each_sum_within_half();
    declines_before_the_inflection();
    back_sum_within_half();
    back_first_step();
    one_step_from_past_the_inflection();
    return check_summary("test_attitude_series");
}
