/* The tolerance-driven Taylor method's edge cases, through its stepper type (stepper.h,
 * sus_tol_ops) and the driver (sus_run_tol), on the paper's body and general bodies:
 *   - a step whose estimate exceeds TOL is rejected and retried, and an accepted step's own
 *     estimate is at most TOL; the retry rescales the rejected series (its coefficients carry
 *     h^n) and lands on the fixed-step Taylor step of the same order and length;
 *   - a TOL no step can meet (1e-300, far below the rounding of any state) ends in
 *     SUS_STEPPER_REJECTED after the bounded retries, the state untouched, and the driver reports
 *     the step, its start time and the estimate (exit 3 in suslov);
 *   - w = 0 (E0 = 0): every coefficient row vanishes, rho = inf: no division by zero, no 0/0 in
 *     the energy scaling; the run stays at w = 0, R = I, finite;
 *   - a steady rotation (c(w) = 0 exactly in double) is a rest point of the series: one step, w
 *     stays exactly w*, R is the rotation exp(t w*^) (so3.h) to its rounding, also when fast; from
 *     the closed form's steady rotation (c(w*) u-small) w and R stay within N TOL;
 *   - over some 2.5e4 steps of a slow transient on a fast rotation, R stays within the steps'
 *     estimates and round-off of the long-double reference (the clock: t advances by the step the
 *     series is summed over);
 *   - dense output at the step's ends equals the step's states, and rows come at the requested
 *     times, t_end included, with w3 = 0, |R^T R - I| at round-off and E = E0.
 * Spans are in the body's own time (check_body_time): t = 20 on the paper's body is 20 k_paper / k.
 * Where the proved radius leaves nothing to test (no try rejected, a truncation below round-off), a
 * NOTE says so. Expected values come from the model (the steady rotation, the closed-form
 * exponential), never from the code under test. */
#include "check_body.h"
#include "check_dense.h"
#include "driver.h"
#include "exact.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"
#include "taylor.h"

#include <float.h>
#include <math.h>
#include <string.h>

static const sus_stepper_type *adaptive(void)
{
    for (int i = sus_step_method_count(); i < sus_step_method_count_all(); i++)
        if (sus_step_method_get(i)->type->tol)
            return sus_step_method_get(i)->type;
    return NULL;
}

typedef struct {
    const sus_model *m;
    double e0, worst_e, worst_er, worst_orth, w3, t_prev;
    int rows, monotone;
    sus_row last;
} rows_ctx;

static int take(void *vctx, const sus_row *r)
{
    rows_ctx *c = vctx;
    c->monotone &= c->rows == 0 || r->t > c->t_prev;
    c->t_prev = r->t;
    c->rows++;
    const double(*I)[3] = c->m->I, *w = r->w, de = fabs(sus_energy(c->m, w) - c->e0);
    /* E's terms, 1/2 (|I11| w1^2 + |I12 + I21| |w1 w2| + |I22| w2^2): its rounding's yardstick */
    const double terms =
        0.5 * (fabs(I[0][0]) * w[0] * w[0] + fabs(I[0][1] + I[1][0]) * fabs(w[0] * w[1]) +
               fabs(I[1][1]) * w[1] * w[1]);
    c->worst_e = fmax(c->worst_e, de);
    c->worst_er = fmax(c->worst_er, de / (terms + c->e0));
    c->worst_orth = fmax(c->worst_orth, sus_so3_orth_defect(r->R));
    c->w3 = fmax(c->w3, fabs(r->w[2]));
    c->last = *r;
    return 0;
}

static int run(const sus_model *m, const double w0[2], double tol, double T, double dt, rows_ctx *c,
               sus_run_report *rep)
{
    *c = (rows_ctx){.m = m, .e0 = sus_energy(m, w0), .monotone = 1};
    const sus_tol_config cfg = {m, adaptive(), tol, T, dt, 0};
    return sus_run_tol(&cfg, w0, take, c, rep);
}

/* The first step at tol (its first try the whole proved radius), from w0: its stats and rc. */
static int first_step(const sus_model *m, const double w0[2], double tol, double *t, double w[3],
                      sus_attitude *att, sus_stepper_stats *st)
{
    const sus_tol_ops *ops = adaptive()->tol;
    sus_tol_work *wk = ops->alloc(m, tol, w0);
    double lam = 0.0;
    w[0] = w0[0], w[1] = w0[1], w[2] = 0.0;
    *t = 0.0;
    sus_attitude_identity(att);
    const int rc = wk ? ops->step(wk, 50.0, t, w, &lam, att, st) : -1;
    ops->free(wk);
    return rc;
}

/* The first of TOL = 1e-12, 1e-13, 1e-14, 1e-15 at which the first try, the whole proved radius, is
 * rejected; 0 where none is: the radius, not the tolerance, then holds the step (a NOTE says so).
 */
static double rejecting_tol(const sus_model *m, const double w0[2], const char *name)
{
    for (double tol = 1e-12; tol >= 1e-15; tol *= 0.1) {
        double w[3], t;
        sus_attitude att;
        sus_stepper_stats st;
        if (first_step(m, w0, tol, &t, w, &att, &st) == SUS_STEPPER_OK && st.iterations >= 1)
            return tol;
    }
    printf("NOTE %s: the first try (the proved radius) meets TOL 1e-15: no try rejected to check\n",
           name);
    return 0.0;
}

/* Rejection and the accepted step's estimate, then the impossible tolerance. */
static void rejection(const sus_model *m, const double w0[2], const char *name, double tol)
{
    const sus_tol_ops *ops = adaptive()->tol;
    double w[3], t;
    sus_attitude att;
    sus_stepper_stats st;
    if (tol > 0.0) {
        const int rc = first_step(m, w0, tol, &t, w, &att, &st);
        CHECK(rc == SUS_STEPPER_OK && st.iterations >= 1 && st.residual <= tol && t > 0.0,
              "%s: first step rejected %d times, then accepted "
              "with estimate %.3g <= TOL = %.0e (t = %.3g)",
              name, st.iterations, st.residual, tol, t);
    }
    sus_tol_work *wk;
    double lam = 0.0;
    /* the contract on a fine grid of TOL (ten a decade, 1e-4 ... 1e-13): an accepted step's own
     * estimate is at most TOL, whatever the first try gave */
    int over = 0, tries = 0;
    for (int j = 0; j <= 90; j++) {
        const double tj_tol = pow(10.0, -4.0 - 0.1 * j);
        double wj[3] = {w0[0], w0[1], 0.0}, tj = 0.0;
        sus_tol_work *wj_work = ops->alloc(m, tj_tol, w0);
        sus_attitude_identity(&att);
        const int rc = ops->step(wj_work, 50.0, &tj, wj, &lam, &att, &st);
        over += rc != SUS_STEPPER_OK || !(st.residual <= tj_tol);
        tries += st.iterations;
        ops->free(wj_work);
    }
    CHECK(over == 0,
          "%s: 91 first steps (TOL 1e-4 ... 1e-13): %d accepted above TOL (%d rejections)", name,
          over, tries);

    wk = ops->alloc(m, 1e-300, w0);
    double w1[3] = {w0[0], w0[1], 0.0}, t1 = 0.0;
    sus_attitude_identity(&att);
    const int bad = ops->step(wk, 50.0, &t1, w1, &lam, &att, &st);
    CHECK(bad == SUS_STEPPER_REJECTED && st.iterations > 1 && st.residual > 1e-300 &&
              st.scale == 1e-300 && t1 == 0.0 && w1[0] == w0[0] && w1[1] == w0[1],
          "%s: TOL 1e-300 rejected after %d tries (estimate %.3g), state untouched", name,
          st.iterations, st.residual);
    ops->free(wk);

    rows_ctx c;
    sus_run_report rep;
    const int rrc = run(m, w0, 1e-300, 50.0, 0.0, &c, &rep);
    CHECK(rrc == SUS_RUN_STEP_FAILED && rep.status == SUS_STEPPER_REJECTED && rep.step == 1 &&
              rep.t == 0.0 && c.rows == 1,
          "%s: the driver reports the rejection at step %ld, t = %g, after row 0 only", name,
          rep.step, rep.t);
}

/* A rejected try is rescaled, not recomputed: the first step (its first try, the proved radius,
 * is rejected at tol, rejecting_tol) must equal the fixed-step Taylor step of the same order and
 * length from a fresh series (sus_step_taylor_apply_full; both restore E onto E(w_0)). The two
 * differ only by roundings: s^n formed in n <= 20 products and p <= 20 sums of terms at most |w|,
 * so 64 u |w| for w and 64 u for R; a wrong power of s moves w by about |W_2| (1 - s), far above.
 * Where no try is rejected (tol = 0: 1e-12 then), the step is still the fresh series', rescaled by
 * nothing. */
static void rescaled_retry(const sus_model *m, const double w0[2], const char *name, double tol)
{
    const sus_tol_ops *ops = adaptive()->tol;
    const double t_tol = tol > 0.0 ? tol : 1e-12, w00[3] = {w0[0], w0[1], 0.0};
    double w[3], wf[3], lamf = 0.0, t, Ra[3][3], Rf[3][3];
    sus_attitude att, attf;
    sus_stepper_stats st, stf;
    sus_attitude_identity(&attf);
    const int rc = first_step(m, w0, t_tol, &t, w, &att, &st);
    const int rf = sus_step_taylor_apply_full(ops->order(t_tol), m, t, &attf, w00, wf, &lamf, &stf);
    sus_attitude_get(&att, Ra);
    sus_attitude_get(&attf, Rf);
    double dw = fmax(fabs(w[0] - wf[0]), fabs(w[1] - wf[1])), dR = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            dR = fmax(dR, fabs(Ra[i][j] - Rf[i][j]));
    const double scale = fmax(1.0, hypot(w0[0], w0[1]));
    CHECK(
        rc == SUS_STEPPER_OK && (st.iterations >= 1 || tol == 0.0) && rf == SUS_STEPPER_OK &&
            dw <= 64.0 * SUS_U * scale && dR <= 64.0 * SUS_U,
        "%s: first step at TOL %.0e (%d rejected tries, h = %.4g) equals a fresh order-%d series: "
        "|dw| = %.2g, |dR| = %.2g",
        name, t_tol, st.iterations, t, ops->order(t_tol), dw, dR);
}

/* w = 0 and a steady rotation: vanishing rows. */
static void vanishing_rows(const sus_model *m, const double w0[2], const char *name, double s)
{
    rows_ctx c;
    sus_run_report rep;
    const double zero[2] = {0.0, 0.0};
    int rc = run(m, zero, 1e-10, 50.0, 5.0, &c, &rep);
    CHECK(rc == SUS_RUN_OK && c.rows == 11 && c.last.w[0] == 0.0 && c.last.w[1] == 0.0 &&
              c.last.R[0][0] == 1.0 && c.last.R[1][1] == 1.0 && c.last.R[2][2] == 1.0 &&
              c.last.t == 50.0,
          "%s: w0 = 0 (E0 = 0): %d rows to t = %g, w = 0 and R = I exactly", name, c.rows,
          c.last.t);
    /* a steady rotation with c(w*) = 0 exactly in double: w* = 2^j (-I32, I31), its size |w0|'s
     * within a factor 2 (I31 (-I32 2^j) and I32 (I31 2^j) round alike and cancel), so every w row
     * vanishes and w stays w* exactly: one step, exp(50 w*^) in closed form */
    const int j = ilogb(hypot(w0[0], w0[1]) / hypot(m->b[0], m->b[1]));
    const double ws[2] = {ldexp(-m->b[1], j), ldexp(m->b[0], j)};
    rc = run(m, ws, 1e-10, 50.0, 0.0, &c, &rep);
    double R[3][3], Wt[3] = {50.0 * ws[0], 50.0 * ws[1], 0.0};
    sus_so3_exp(Wt, R);
    double d = sus_so3_dist(R, c.last.R);
    CHECK(rc == SUS_RUN_OK && sus_c(m, ws) == 0.0 && c.last.w[0] == ws[0] && c.last.w[1] == ws[1] &&
              c.last.k == 1 && d <= 10.0 * 1e-10,
          "%s: steady rotation (c(w*) = 0 exactly): one step (%ld), w stays w* exactly, "
          "R = exp(50 w*^) to %.3g <= 10 TOL",
          name, c.last.k, d);
    /* the steady rotation the closed form tends to from w0, the attracting one of +-w*: c(w*) is
     * u-small but not 0, so the w rows are u-small; whatever they do, TOL bounds each step's error:
     * w and R within 10 N TOL of w* and exp(T w*^) over T = 50 s, s the body's own time */
    sus_exact ex;
    double wl[2];
    sus_exact_init(&ex, m, w0);
    sus_exact_limit(&ex, wl);
    const double T = 50.0 * s;
    rc = run(m, wl, 1e-10, T, 0.0, &c, &rep);
    double Wl[3] = {T * wl[0], T * wl[1], 0.0};
    sus_so3_exp(Wl, R);
    d = sus_so3_dist(R, c.last.R);
    const double dw = fmax(fabs(c.last.w[0] - wl[0]), fabs(c.last.w[1] - wl[1]));
    const double bound = 10.0 * (double)c.last.k * 1e-10;
    CHECK(rc == SUS_RUN_OK && dw <= bound && d <= bound,
          "%s: the closed form's steady rotation over T = 50 s = %.3g: w stays within "
          "%.2g of w*, R = exp(T w*^) to %.3g, both <= 10 N TOL (N = %ld)",
          name, T, dw, d, c.last.k);
}

/* exp(T w^) for w = (w1, w2, 0) in long double (Rodrigues): the angle T |w| carries a few
 * long-double roundings, below 1e-13 at T |w| = 2^20 on x86 (64-bit significands). */
static void rotation_ld(const double w[2], double T, double R[3][3])
{
    const long double n = hypotl(w[0], w[1]), th = (long double)T * n, c = cosl(th), s = sinl(th),
                      x = w[0] / n, y = w[1] / n;
    const long double E[3][3] = {{c + (1 - c) * x * x, (1 - c) * x * y, s * y},
                                 {(1 - c) * x * y, c + (1 - c) * y * y, -s * x},
                                 {-s * y, s * x, c}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = (double)E[i][j];
}

/* A fast steady rotation, c(w*) = 0 exactly (w* = +-2^j (-I32, I31), |w*| in [2^10, 2^11)), the
 * repelling one (no tail jump), turned through T |w*| = 2^20 radians at TOL 1e-12 and 2^17 at TOL
 * 3e-16: a rest point of the series (step_taylor_adaptive.c's at_rest), so the run is one step,
 * exp(T w*^) in closed form whatever TOL, and R(T) is within one step's roundings, ROUND_STEP u,
 * of it (the method forms the angle in two doubles, steady_turn.h, so its error does not grow
 * with T |w*|), plus the long-double reference's own, REF_ANGLE 2^-64 T |w*| (a few roundings of
 * the angle in rotation_ld). An angle rounded in one double would be off by about u T |w*|, 2^9
 * times that allowance. */
#define REF_ANGLE 8.0
#define ROUND_ANGLE 16.0
/* dist per step: the product q (x) dq, the sums, the norm (test_exact_attitude's count) */
#define ROUND_STEP 34.0
static void fast_steady_rotation(const sus_model *m, const double w0[2], const char *name)
{
    const double tols[2] = {1e-12, 3e-16}, turns[2] = {0x1p20, 0x1p17};
    const int j = 10 - ilogb(hypot(m->b[0], m->b[1]));
    sus_exact ex;
    double wl[2];
    sus_exact_init(&ex, m, w0);
    sus_exact_limit(&ex, wl); /* the attracting direction: w* is taken on the other side */
    const double sg = -m->b[1] * wl[0] + m->b[0] * wl[1] > 0.0 ? -1.0 : 1.0,
                 ws[2] = {sg * ldexp(-m->b[1], j), sg * ldexp(m->b[0], j)};
    for (int i = 0; i < 2; i++) {
        rows_ctx c;
        sus_run_report rep;
        double R[3][3];
        const double T = turns[i] / hypot(ws[0], ws[1]);
        const int rc = run(m, ws, tols[i], T, 0.0, &c, &rep);
        rotation_ld(ws, T, R);
        const double err = sus_so3_dist(R, c.last.R),
                     bound = REF_ANGLE * 0x1p-64 * turns[i] + ROUND_STEP * SUS_U;
        CHECK(rc == SUS_RUN_OK && sus_c(m, ws) == 0.0 && c.last.t == T && c.last.k == 1 &&
                  err <= bound,
              "%s: fast steady rotation |w*| = %.0f, T |w*| = 2^%d, TOL %.0e: %ld step, "
              "dist(R, exp(T w*^)) = %.3g <= %g 2^-64 T |w*| + %g u = %.3g",
              name, hypot(ws[0], ws[1]), ilogb(turns[i]), tols[i], c.last.k, err, REF_ANGLE,
              ROUND_STEP, bound);
    }
}

/* The clock over many steps: a slow transient on a fast rotation (check_body.h's slow body; some
 * 2.5e4 steps, none at rest, no tail), against the long-double reference: R(T) within the steps'
 * estimates summed, 2 sqrt2 N TOL (each step's quaternion error at most its estimate, the flow
 * keeping norms, dist <= 2 sqrt2 |dq|), plus ROUND_ANGLE u T |w0| (every step's angle rounded; |w|
 * = |w0| on this I_m) and the steps' other roundings as a random walk, 3 ROUND_STEP u sqrt N
 * (independent roundings to nearest, three deviations). A clock that adds h to t in place loses u t
 * per step instead, N u T |w| in all, whatever TOL. */
static void slow_transient(void)
{
    const double tols[2] = {1e-12, 3e-16}, T = SLOW_T;
    sus_model m;
    sus_exact ex;
    double w0[2], Rr[3][3];
    if (check_slow_body(&m, &ex, w0, Rr))
        return;
    for (int i = 0; i < 2; i++) {
        rows_ctx c;
        sus_run_report rep;
        const int rc = run(&m, w0, tols[i], T, 0.0, &c, &rep);
        const double n = (double)c.last.k, err = sus_so3_dist(Rr, c.last.R),
                     bound = 2.8284271247461903 * n * tols[i] +
                             ROUND_ANGLE * SUS_U * T * hypot(w0[0], w0[1]) +
                             3.0 * ROUND_STEP * SUS_U * sqrt(n);
        CHECK(rc == SUS_RUN_OK && c.last.t == T && n > 1e4 && err <= bound,
              "slow body, |w0| = %.0f, TOL %.0e: %.0f steps to t = %g, dist(R, R_ref) = %.3g <= "
              "2 sqrt2 N TOL + %g u T |w0| + 3 %g u sqrt N = %.3g",
              hypot(w0[0], w0[1]), tols[i], n, T, err, ROUND_ANGLE, ROUND_STEP, bound);
    }
}

/* Rows at requested times, structure, and dense output agreeing with the steps it lies between. */
static void rows_and_structure(const sus_model *m, const double w0[2], const char *name, double s)
{
    rows_ctx a, b;
    sus_run_report rep;
    const int ra = run(m, w0, 1e-9, 20.0 * s, 0.25 * s, &a, &rep);
    const int rb = run(m, w0, 1e-9, 20.0 * s, 0.0, &b, &rep);
    /* the next step is sized by the estimate's own law, err ~ h^{p+1}, aiming at SAFETY^{p+1} TOL:
     * a step is rejected only where the estimate's constant grows by more than SAFETY^{-(p+1)}
     * (>= 2) from one step to the next, which a smooth flow does on few steps: fewer than half */
    CHECK(rb == SUS_RUN_OK && 2 * rep.sus_newton_iterations < b.last.k,
          "%s: %ld rejected tries over %ld accepted steps to t = 20 s = %.3g (fewer than half)",
          name, rep.sus_newton_iterations, b.last.k, 20.0 * s);
    CHECK(ra == SUS_RUN_OK && a.rows == 81 && a.monotone && a.last.t == 20.0 * s,
          "%s: --every-time 0.25 s to 20 s: %d rows (81), increasing t, the last at %g", name,
          a.rows, a.last.t);
    /* E restored onto E0 rounds 8 u of E's terms (E0's and the scaled w's: 2 u each, the scaling 2
     * u) */
    CHECK(a.w3 == 0.0 && a.worst_orth <= 1e-14 && a.worst_er <= 8.0 * SUS_U,
          "%s: dense rows keep w3 = 0, |R^T R - I| = %.2g <= 1e-14, "
          "|E - E0| = %.2g, %.2g u of E's terms (<= 8 u)",
          name, a.worst_orth, a.worst_e, a.worst_er / SUS_U);
    /* the row at t_end is the step's own end in both runs: the same state */
    CHECK(rb == SUS_RUN_OK && memcmp(a.last.w, b.last.w, sizeof a.last.w) == 0 &&
              memcmp(a.last.R, b.last.R, sizeof a.last.R) == 0,
          "%s: the dense-output run ends in the same state as the step-by-step run", name);
}

/* Dense rows against the reference between steps: every row within 10 N TOL of the long-double
 * reference attitude and of the closed-form w (the bound of the ledger's claims_adaptive.c: N
 * local errors of at most TOL, the estimate within 10x), read by check_dense.h's callback. */

static void dense_accuracy(const sus_model *m, const double w0[2], const char *name, double s)
{
    static const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    dense_ctx c = {.worst_R = 0.0};
    sus_exact_init(&c.ex, m, w0);
    sus_refatt_init(&c.ref, &c.ex, 0.0, I3);
    const sus_tol_config cfg = {m, adaptive(), 1e-8, 30.0 * s, 0.1 * s, 0};
    sus_run_report rep;
    rows_ctx steps;
    const int rc = sus_run_tol(&cfg, w0, against_reference, &c, &rep);
    run(m, w0, 1e-8, 30.0 * s, 0.0, &steps, &rep);
    const double bound = 10.0 * (double)steps.last.k * 1e-8;
    CHECK(rc == SUS_RUN_OK && c.worst_R <= bound && c.worst_w <= bound,
          "%s: 301 dense rows to t = 30 s at TOL 1e-8: |R - R_ref| "
          "<= %.3g, |w - w(t)| <= %.3g, both <= 10 N TOL = %.3g",
          name, c.worst_R, c.worst_w, bound);
}

/* The step budget: with max_steps = 3 a run that needs more stops before step 4, at the time its
 * third step ended, with the rows of the steps it took (row 0 and one a step) and the last step's
 * length; a budget the run does not need changes nothing. */
static void step_budget(const sus_model *m, const double w0[2], const char *name, double s)
{
    rows_ctx all, cut;
    sus_run_report rep_all, rep;
    run(m, w0, 1e-10, 50.0 * s, 0.0, &all, &rep_all);
    cut = (rows_ctx){.m = m, .e0 = sus_energy(m, w0), .monotone = 1};
    sus_tol_config cfg = {m, adaptive(), 1e-10, 50.0 * s, 0.0, 3};
    const int rc = sus_run_tol(&cfg, w0, take, &cut, &rep);
    CHECK(all.last.k > 3 && rc == SUS_RUN_STEP_FAILED && rep.status == SUS_STEPPER_STEP_LIMIT &&
              rep.step == 4 && cut.rows == 4 && rep.t == cut.last.t && cut.last.t < 50.0 * s &&
              rep.stats.det > 0.0,
          "%s: a budget of 3 steps stops before step %ld "
          "at t = %.3g with %d rows (the run needs %ld)",
          name, rep.step, rep.t, cut.rows, all.last.k);
    cfg.max_steps = all.last.k;
    const int rc_enough = sus_run_tol(&cfg, w0, take, &cut, &rep);
    CHECK(rc_enough == SUS_RUN_OK && rep.status == SUS_STEPPER_OK,
          "%s: a budget of exactly the %ld steps the run needs ends it normally", name, all.last.k);
}

/* The estimate against the true local error of a first accepted step (closed-form w, long-double
 * reference R over the step): a last-two-terms estimate of a geometric tail is within F = 10 of
 * it either way (the undershoot factor claims_adaptive.c allows: ratio up to 0.9), over TOL
 * 1e-6 ... 1e-12 where the truncation, not round-off, is the local error: a true error below
 * 64 u max(|w0|, 1) (a few u of |w| and of R's entries) is round-off and not compared; a body where
 * every one is gets a NOTE (the near-singular I_m, whose first step the proved radius holds to a
 * truncation far below round-off). */
static void estimate_vs_truth(const sus_model *m, const double w0[2], const char *name)
{
    const double floor = 64.0 * SUS_U * fmax(1.0, hypot(w0[0], w0[1]));
    double lo = INFINITY, hi = 0.0;
    int counted = 0, failed = 0;
    for (double tol = 1e-6; tol >= 1e-12; tol *= 1e-2) {
        double w[3], t, wx[2], Rx[3][3], wr[2], R[3][3];
        sus_attitude att;
        sus_stepper_stats st;
        if (first_step(m, w0, tol, &t, w, &att, &st) != SUS_STEPPER_OK) {
            failed++;
            continue;
        }
        sus_refatt_precise(m, w0, t, wr, Rx);
        sus_exact omega;
        sus_exact_init(&omega, m, w0);
        sus_exact_omega(&omega, t, wx);
        sus_attitude_get(&att, R);
        const double truth = fmax(hypot(w[0] - wx[0], w[1] - wx[1]), sus_so3_dist(Rx, R));
        if (truth < floor)
            continue;
        counted++;
        lo = fmin(lo, st.residual / truth);
        hi = fmax(hi, st.residual / truth);
    }
    if (counted == 0 && failed == 0) {
        printf("NOTE %s: the first step's true error is round-off (below %.2g) at every TOL 1e-6 "
               "... 1e-12: its estimate has no truncation to be compared with\n",
               name, floor);
        return;
    }
    CHECK(failed == 0 && lo >= 0.1 && hi <= 10.0,
          "%s: the first step's estimate over its true local error in [%.3g, %.3g] "
          "(%d of TOL 1e-6, 1e-8, 1e-10, 1e-12 above round-off): within [0.1, 10]",
          name, lo, hi, counted);
}

/* The order rule of step_taylor_adaptive.c, recomputed here: the smallest even p >= -ln(TOL)/2 + 3
 * in [6, 20] (Jorba and Zou's -ln(TOL)/2 + 1, shifted by the step's fixed cost). */
static void order_rule(void)
{
    const sus_tol_ops *ops = adaptive()->tol;
    int ok = 1;
    for (double tol = 0.5; tol > 1e-16; tol *= 0.3) {
        int p = 6;
        while (p < 20 && p < -0.5 * log(tol) + 3.0)
            p += 2;
        ok &= ops->order(tol) == p;
    }
    CHECK(ok && ops->order(1e-10) == 16 && ops->order(1e-4) == 8 && ops->order(DBL_EPSILON) == 20,
          "the order is the smallest even p >= -ln(TOL)/2 + 3 in [6, 20] (1e-10: %d)",
          ops->order(1e-10));
}

int main(void)
{
    if (!adaptive()) {
        CHECK(0, "a tolerance-driven method is registered");
        return check_summary("test_taylor_adaptive");
    }
    order_rule();
    slow_transient();
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        char err[256];
        body_get(k, &b);
        if (sus_model_init(&m, b.I, err, sizeof err) != 0) {
            CHECK(0, "%s: %s", b.name, err);
            continue;
        }
        const double s = check_body_time(&m, b.w0), tol = rejecting_tol(&m, b.w0, b.name);
        rejection(&m, b.w0, b.name, tol);
        rescaled_retry(&m, b.w0, b.name, tol);
        vanishing_rows(&m, b.w0, b.name, s);
        fast_steady_rotation(&m, b.w0, b.name);
        rows_and_structure(&m, b.w0, b.name, s);
        dense_accuracy(&m, b.w0, b.name, s);
        estimate_vs_truth(&m, b.w0, b.name);
        step_budget(&m, b.w0, b.name, s);
    }
    return check_summary("test_taylor_adaptive");
}
