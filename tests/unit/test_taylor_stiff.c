/* taylor-adaptive on stiff bodies (step_taylor_adaptive.c, "Stiffness"): near a steady rotation
 * whose rate k is large (a near-singular I_m, a large I31) an explicit series is held at its
 * stability limit h k = beta_p unless the run settles on the steady rotation. Checked here, on the
 * family of tests/unit/bodies.h and on the hard bodies below:
 *   - effort: over a ladder of tolerances 1e-2 ... 1e-15 and 2^-52 to t = 50, every run ends
 *     within a budget of 10^4 steps; at one order a looser tolerance takes no more steps than a
 *     tighter one, and across orders no more work, (accepted + rejected tries) (p + 1)^2, the
 *     Cauchy products of a step. (Steps alone are not monotone across an order change: a higher
 *     order takes longer steps at the same tolerance, so the first tolerance of a new order can
 *     take fewer steps than the last of the old.) And w(50) within 10 N TOL of the closed form
 *     (exact.h), the bound of claims_adaptive.c;
 *   - a near-singular case: I_m = [1 1-1e-10; 1-1e-10 1] to t = 10 at TOL 1e-6 costs no more steps
 *     than at 1e-15 (it took 10^6 steps and failed);
 *   - the settling step keeps the promise of a step: from the state it starts at, its w and its
 *     attitude increment are within TOL of the exact motion over the rest of the run (w by the
 *     closed form; R by the long-double reference attitude, sus_refatt_precise, on the family: on
 *     the hard bodies it is not yet to be trusted), over TOL 1e-1 ... 1e-8 by half decades,
 * wherever a run to t = 200 settles; the attitude's allowance adds the rounding of the angle (T -
 * t_k) |w_inf|, 16 u of it, the problem's own conditioning;
 *   - dense output after settling: rows every 1 to t = 200 at TOL 1e-4 on the family, against the
 *     closed-form w and the reference attitude, within 10 N TOL (claims_adaptive.c's bound; N the
 *     steps the run takes) plus the angle's rounding;
 *   - the floor: a start a few roundings (4 u |w_inf|) from the steady rotation, at TOL 2^-52,
 *     settles in its first step, on w_inf to 16 u times E's rounding over u (the size of E's terms
 *     over E: w_inf is found through E, and a near-singular I_m makes that cond(I_m)).
 * Expected values come from the closed form and the reference attitude, never from the stepper. */
#include "check_body.h"
#include "check_dense.h"
#include "driver.h"
#include "exact.h"
#include "refattitude.h"
#include "so3.h"
#include "taylor.h"

#include <math.h>
#include <string.h>

/* The hard bodies: I_m with a condition number up to 2e10, a large I31 or I32, |w0| = 1.4. */
static const body HARD[] = {
    {{1, 0.9999999999, 0.2, 0.9999999999, 1, 0.2, 0.2, 0.1, 1}, {0.4, 0.5}, "cond2e10"},
    {{1, 0.999, 0.2, 0.999, 1, 0.2, 0.2, 0.1, 1}, {0.4, 0.5}, "cond2e3"},
    {{1, 0, 0, 0, 1, 0, 100, 0, 1}, {0.4, 0.5}, "I31=100"},
    {{1, 0, 0, 0, 0.1, 0, 0, 5, 1}, {0.4, 0.5}, "I32=5"},
    {{1, 0, 0, 0, 1, 0, 8, 4, 1}, {1.0, 1.0}, "I3.=8,4"},
};
#define NHARD ((int)(sizeof HARD / sizeof HARD[0]))
#define NBODY (BODIES_COUNT + NHARD)
#define NLADDER 15 /* 1e-2 ... 1e-15 and 2^-52 */
#define BUDGET 10000L

static void body_at(int i, body *b)
{
    if (i < BODIES_COUNT)
        body_get(i, b);
    else
        *b = HARD[i - BODIES_COUNT];
}

static double ladder_tol(int j) { return j < NLADDER - 1 ? pow(10.0, -2.0 - j) : 0x1p-52; }

typedef struct {
    int rc;
    long steps, tries;
    double w[3];
} run_result;

static run_result run(const sus_model *m, const double w0[2], double tol, double T)
{
    const sus_tol_config cfg = {m, &sus_step_taylor_adaptive_type, tol, T, 0.0, BUDGET};
    sus_row last;
    sus_run_report rep;
    run_result r = {sus_run_tol(&cfg, w0, sus_keep_last, &last, &rep),
                    last.k,
                    rep.sus_newton_iterations,
                    {last.w[0], last.w[1], last.w[2]}};
    return r;
}

/* One body over the ladder: failures, pairs of neighbours (looser, tighter) that break the
 * rules, and the worst |w(50) - w_exact| / (10 N TOL). */
static void body_ladder(const sus_model *m, const double w0[2], int *failed, int *more_steps,
                        int *more_work, double *worst_w)
{
    sus_exact ex;
    double we[2];
    sus_exact_init(&ex, m, w0);
    sus_exact_omega(&ex, 50.0, we);
    long prev_steps = 0, prev_work = 0;
    int prev_p = 0;
    for (int j = 0; j < NLADDER; j++) {
        const double tol = ladder_tol(j);
        const int p = sus_step_taylor_adaptive_order(tol);
        const run_result r = run(m, w0, tol, 50.0);
        if (r.rc != SUS_RUN_OK) {
            (*failed)++;
            continue;
        }
        const long work = (r.steps + r.tries) * (long)(p + 1) * (p + 1);
        *more_steps += j > 0 && p == prev_p && prev_steps > r.steps;
        *more_work += j > 0 && prev_work > work;
        const double bound = 10.0 * (double)r.steps * tol;
        *worst_w = fmax(*worst_w, hypot(r.w[0] - we[0], r.w[1] - we[1]) / bound);
        prev_steps = r.steps, prev_work = work, prev_p = p;
    }
}

static void effort_ladder(void)
{
    int failed = 0, more_steps = 0, more_work = 0;
    double worst_w = 0.0;
    for (int i = 0; i < NBODY; i++) {
        body b;
        sus_model m;
        body_at(i, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        int f = 0, s = 0, w = 0;
        double ww = 0.0;
        body_ladder(&m, b.w0, &f, &s, &w, &ww);
        CHECK(f == 0 && s == 0 && w == 0 && ww <= 1.0,
              "%s: TOL 1e-2 ... 2^-52 to t = 50: %d runs over %ld steps; %d tighter TOL of the "
              "same order with fewer steps, %d with less work; |w(50) - w_exact| <= %.2g of 10 N "
              "TOL",
              b.name, f, BUDGET, s, w, ww);
        failed += f, more_steps += s, more_work += w;
        worst_w = fmax(worst_w, ww);
    }
    CHECK(failed == 0 && more_steps == 0 && more_work == 0 && worst_w <= 1.0,
          "%d bodies (%d of them hard): a looser TOL never costs more "
          "steps at one order, nor more work ((tries) (p+1)^2) across "
          "orders; every run within %ld steps and 10 N TOL of w_exact",
          NBODY, NHARD, BUDGET);
}

/* The case that took 10^6 steps at TOL 1e-6 and 31 at 1e-15. */
static void issue_case(void)
{
    sus_model m;
    body b = HARD[0];
    if (check_body_model(&b, &m) != 0)
        return;
    const run_result loose = run(&m, b.w0, 1e-6, 10.0), tight = run(&m, b.w0, 1e-15, 10.0);
    CHECK(loose.rc == SUS_RUN_OK && tight.rc == SUS_RUN_OK && loose.steps <= tight.steps,
          "I_m = [1 1-1e-10; 1-1e-10 1], w0 = (0.4, 0.5), t = 10: TOL "
          "1e-6 in %ld steps, 1e-15 in %ld (no more at the looser TOL)",
          loose.steps, tight.steps);
}

/* A run to T taken step by step; the state before its settling step (the step that ends the run
 * with stats.residual 0 and w the closed form's limit) in *wk_state, its time in *tk, and the
 * attitude increment of that step in D. Returns 0 when the run settles, -1 when it does not. */
static int settling_step(const sus_model *m, const double w0[2], double tol, double T,
                         double wk_state[2], double *tk, double D[3][3], double w_end[2])
{
    const sus_tol_ops *ops = sus_step_taylor_adaptive_type.tol;
    sus_tol_work *wk = ops->alloc(m, tol, w0);
    double w[3] = {w0[0], w0[1], 0.0}, t = 0.0, lam, R0[3][3], R1[3][3];
    sus_attitude att;
    sus_stepper_stats st;
    sus_attitude_identity(&att);
    int rc = -1;
    for (long n = 0; wk && t < T && n < BUDGET; n++) {
        const double t0 = t, ws[2] = {w[0], w[1]};
        sus_attitude_get(&att, R0);
        if (ops->step(wk, T, &t, w, &lam, &att, &st) != SUS_STEPPER_OK)
            break;
        if (t == T && st.residual == 0.0 && st.iterations == 0 &&
            (w[0] != ws[0] || w[1] != ws[1])) {
            sus_attitude_get(&att, R1);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    D[i][j] = R0[0][i] * R1[0][j] + R0[1][i] * R1[1][j] + R0[2][i] * R1[2][j];
            wk_state[0] = ws[0], wk_state[1] = ws[1], *tk = t0;
            w_end[0] = w[0], w_end[1] = w[1];
            rc = 0;
        }
    }
    ops->free(wk);
    return rc;
}

/* The settling step's local error against the exact motion from its start, over the rest of the
 * run, in units of TOL: w (closed form) and R (reference attitude, when finite). */
static void settle_errors(const sus_model *m, const double w0[2], int with_R, double *ew,
                          double *eR, int *n, int *nR)
{
    for (int j = 0; j <= 14; j++) {
        const double tol = pow(10.0, -1.0 - 0.5 * j), T = 200.0;
        double ws[2], tk, D[3][3], w_end[2], we[2], wr[2], Rr[3][3];
        if (settling_step(m, w0, tol, T, ws, &tk, D, w_end) != 0)
            continue;
        sus_exact ex;
        sus_exact_init(&ex, m, ws);
        sus_exact_omega(&ex, T - tk, we);
        *ew = fmax(*ew, hypot(w_end[0] - we[0], w_end[1] - we[1]) / tol);
        (*n)++;
        if (!with_R)
            continue;
        sus_refatt_precise(m, ws, T - tk, wr, Rr);
        *eR = fmax(*eR, sus_so3_dist(Rr, D) /
                            (tol + 16.0 * SUS_U * (1.0 + (T - tk) * hypot(ws[0], ws[1]))));
        (*nR)++;
    }
}

static void settling(void)
{
    double ew = 0.0, eR = 0.0;
    int n = 0, nR = 0, bodies = 0;
    for (int i = 0; i < NBODY; i++) {
        body b;
        sus_model m;
        body_at(i, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        const int before = n;
        settle_errors(&m, b.w0, i < BODIES_COUNT, &ew, &eR, &n, &nR);
        bodies += n > before;
    }
    CHECK(bodies == NBODY && nR > 0 && ew <= 1.0 && eR <= 1.0,
          "the settling step's local error over the rest of the run (t = 200), %d runs on %d of "
          "%d bodies (R on %d): w %.3g TOL, R %.3g TOL (at most 1 TOL)",
          n, bodies, NBODY, nR, ew, eR);
}

static void dense_after_settling(void)
{
    static const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double tol = 1e-4, T = 200.0;
    double worst = 0.0;
    int n = 0, settled = 0;
    for (int i = 0; i < BODIES_COUNT; i++) {
        body b;
        sus_model m;
        body_at(i, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        dense_ctx c = {.worst_R = 0.0};
        sus_exact_init(&c.ex, &m, b.w0);
        sus_refatt_init(&c.ref, &c.ex, 0.0, I3);
        const sus_tol_config cfg = {&m, &sus_step_taylor_adaptive_type, tol, T, 1.0, BUDGET};
        sus_run_report rep;
        const int rc = sus_run_tol(&cfg, b.w0, against_reference, &c, &rep);
        const run_result steps = run(&m, b.w0, tol, T);
        double wl[2], ws[2], tk, D[3][3], we[2];
        sus_exact_limit(&c.ex, wl);
        const double bound =
            10.0 * (double)steps.steps * tol + 16.0 * SUS_U * (1.0 + T * hypot(wl[0], wl[1]));
        worst = rc == SUS_RUN_OK ? fmax(worst, fmax(c.worst_R, c.worst_w) / bound) : INFINITY;
        settled += settling_step(&m, b.w0, tol, T, ws, &tk, D, we) == 0;
        n++;
    }
    CHECK(worst <= 1.0 && settled == n,
          "%d bodies, rows every 1 to t = 200 at TOL 1e-4 (%d runs settle): "
          "|R - R_ref| and |w - w(t)| within %.3g of 10 N TOL",
          n, settled, worst);
}

/* A start 4 u |w_inf| from the steady rotation (exact.h's limit) along the ellipse's tangent
 * A w_inf: within the floor, so at TOL 2^-52 the run to t = 50 is one step ending on w_inf. */
static void floor_settles(void)
{
    int bad = 0, n = 0;
    for (int i = 0; i < NBODY; i++) {
        body b;
        sus_model m;
        sus_exact ex;
        double ws[2];
        body_at(i, &b);
        if (check_body_model(&b, &m) != 0)
            continue;
        sus_exact_init(&ex, &m, b.w0);
        sus_exact_limit(&ex, ws);
        const double a0 = m.fA[0][0] * ws[0] + m.fA[0][1] * ws[1],
                     a1 = m.fA[1][0] * ws[0] + m.fA[1][1] * ws[1];
        const double s = 4.0 * SUS_U * hypot(ws[0], ws[1]) / hypot(a0, a1),
                     w0[2] = {ws[0] + s * a0, ws[1] + s * a1};
        const run_result r = run(&m, w0, 0x1p-52, 50.0);
        /* w_inf from E carries E's rounding: u times the size of E's terms over E */
        const double *I = b.I, x = ws[0], y = ws[1];
        const double terms = 0.5 * (fabs(I[0]) * x * x + (fabs(I[1]) + fabs(I[3])) * fabs(x * y) +
                                    fabs(I[4]) * y * y);
        const double tol =
            16.0 * SUS_U * hypot(ws[0], ws[1]) * fmax(1.0, terms / sus_energy(&m, ws));
        bad += r.rc != SUS_RUN_OK || r.steps != 1 || hypot(r.w[0] - ws[0], r.w[1] - ws[1]) > tol;
        n++;
    }
    CHECK(bad == 0,
          "%d bodies: from 4 u |w_inf| off the steady rotation, TOL 2^-52: one step to t = 50, "
          "ending on w_inf (to 16 u, times E's rounding over u): %d do not",
          n, bad);
}

int main(void)
{
    effort_ladder();
    issue_case();
    settling();
    floor_settles();
    dense_after_settling();
    return check_summary("test_taylor_stiff");
}
