/* The library's guards and bounds, checked against their definitions on the seeded general bodies:
 * the model's rounded-up norms |b|_2 and ||fA||_2 (model.h: bounds, so |c(v) fA u| <= K |v| |u|)
 * the driver's finiteness checks (driver.h: every field of a row, and every step's state w, lambda
 * and the attitude as stored, looked at) and its Newton counts, a composition's Newton count; the
 * Taylor step at the top order its arrays hold; exp(w^) - I where |w|^2 underflows; Shepperd's
 * choice of branch in recovering q from R.
 * These are what the Taylor radius and the blow-up report stand on, and no value a program prints
 * moves when they are slightly off, so they are checked here directly. */
#include "check_body.h"
#include "check_exact.h"
#include "composition.h"
#include "dsp.h"
#include "driver.h"
#include "model.h"
#include "quaternion.h"
#include "so3.h"
#include "taylor.h"

#include <math.h>
#include <string.h>

/* A rounded-up bound is at least the exact value and at most a few roundings above it: 1e-13
 * relative is 450 u, far above the few ulps of a closed form of four terms. */
#define UP 1e-13

/* ||M||_2 of a 2x2 matrix from the eigenvalues of the symmetric M M^T = [[p, r], [r, q]]:
 * s^2 = (p + q + sqrt((p - q)^2 + 4 r^2)) / 2 (a different closed form from the library's). */
static double norm2_ref(double a, double b, double c, double d)
{
    const double p = a * a + b * b, q = c * c + d * d, r = a * c + b * d;
    return sqrt(0.5 * (p + q + sqrt((p - q) * (p - q) + 4.0 * r * r)));
}

/* |I_m| exact (check_exact.h) and rounded once: formed plainly it would err by cond(I_m) u on a
 * near-singular I_m, more than UP, and the reference would not be one. */
static void norm_checks(const body *bd, const sus_model *m)
{
    const double *I = bd->I, det = (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    /* (ContDyn) as f = c(w) fA w: fA = [[-I12, -I22], [I11, I21]] / |I_m| */
    const double s = norm2_ref(-I[1] / det, -I[4] / det, I[0] / det, I[3] / det);
    CHECK(m->norm_fA >= s && m->norm_fA <= s * (1.0 + UP),
          "%s: ||fA||_2 %.17g, a bound tight to %.0e of %.17g", bd->name, m->norm_fA, UP, s);
    const double nb = sqrt(I[6] * I[6] + I[7] * I[7]);
    CHECK(m->norm_b >= nb && m->norm_b <= nb * (1.0 + UP),
          "%s: |b|_2 %.17g, a bound tight to %.0e of %.17g", bd->name, m->norm_b, UP, nb);
}

/* A row with every field finite is finite; one non-finite field, whichever, makes it not. */
static void row_finite_checks(void)
{
    sus_row r = {.k = 3,
                 .t = 0.5,
                 .w = {0.1, -0.2, 0.0},
                 .lambda = 0.3,
                 .R = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    CHECK(sus_row_finite(&r), "a finite row is finite");
    double *field[15] = {&r.t, &r.w[0], &r.w[1], &r.w[2], &r.lambda};
    for (int i = 0; i < 9; i++)
        field[5 + i] = &r.R[i / 3][i % 3];
    int missed = 0;
    for (int f = 0; f < 14; f++) {
        const double keep = *field[f];
        *field[f] = f % 2 ? NAN : INFINITY;
        missed += sus_row_finite(&r) != 0;
        *field[f] = keep;
    }
    CHECK(missed == 0,
          "a row with one non-finite field (each of the 14 in turn) is not finite: %d missed",
          missed);
}

/* An I_m that is not positive definite is refused, and the message gives I11, I22 and I12 with
 * their values (distinct, so that one printed in another's place shows). */
static void posdef_message_checks(void)
{
    const double I[2][9] = {
        {-1.25, 0.375, 0.2, 0.375, 0.75, 0.1, 0.3, -0.2, 1.0},
        {1.25, 2.5, 0.2, 2.5, 0.75, 0.1, 0.3, -0.2, 1.0}}; /* I11 < 0; |I_m| < 0 */
    for (int k = 0; k < 2; k++) {
        sus_model m;
        char err[160] = "", want[128];
        snprintf(want, sizeof want, "(I11 = %.17g, I22 = %.17g, I12 = %.17g)", I[k][0], I[k][4],
                 I[k][1]);
        const int rc = sus_model_init(&m, I[k], err, sizeof err);
        CHECK(rc == -1 && strstr(err, "not positive definite") && strstr(err, want),
              "I_m not positive definite (case %d) refused with its entries: \"%s\"", k, err);
    }
}

/* A stepper that keeps w and the attitude, except that at step POISON_STEP it makes one field of
 * the state non-finite: w_next[0..2], lambda, hi[i][j] (a matrix attitude) or q[i] (a stale one).
 */
#define POISON_STEP 3
static int poison_field, poison_calls;

static int poison_full(const sus_model *m, double eps, sus_recon recon, sus_attitude *att,
                       const double w[3], double w_next[3], double *lambda_next,
                       sus_stepper_stats *st)
{
    (void)m, (void)eps, (void)recon;
    *st = (sus_stepper_stats){0};
    for (int i = 0; i < 3; i++)
        w_next[i] = w[i];
    *lambda_next = 0.25;
    att->r_stale = poison_field >= 13;
    att->has_q = att->r_stale;
    if (++poison_calls != POISON_STEP)
        return SUS_STEPPER_OK;
    const int f = poison_field;
    double *target = f < 3    ? &w_next[f]
                     : f == 3 ? lambda_next
                     : f < 13 ? &att->hi[(f - 4) / 3][(f - 4) % 3]
                              : &att->q[f - 13];
    *target = NAN;
    return SUS_STEPPER_OK;
}

static int poison_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                        double *lambda_next, sus_stepper_stats *st)
{
    sus_attitude a;
    sus_attitude_identity(&a);
    return poison_full(m, eps, SUS_RECON_CAYLEY, &a, w, w_next, lambda_next, st);
}

static const sus_step_ops poison_ops = {.apply = poison_apply, .apply_full = poison_full};
static const sus_stepper_type poison_stepper = {.name = "poison",
                                                .step = &poison_ops,
                                                .desc = {.order = 1,
                                                         .lambda_order = 1,
                                                         .attitude = SUS_ATTITUDE_MATRIX,
                                                         .substeps = 1,
                                                         .source = __FILE__}};

/* A non-finite field of the state at a step whose row is not written stops the run there. */
static void blowup_checks(const sus_model *m)
{
    const double w0[2] = {0.4, 0.5};
    int missed = 0;
    for (poison_field = 0; poison_field < 17; poison_field++) {
        const sus_run_config cfg = {.model = m,
                                    .stepper = &poison_stepper,
                                    .recon = SUS_RECON_CAYLEY,
                                    .eps = 0.125,
                                    .steps = 10,
                                    .every = 1000};
        sus_row last;
        sus_run_report rep;
        poison_calls = 0;
        const int rc = sus_run(&cfg, w0, sus_keep_last, &last, &rep);
        missed +=
            !(rc == SUS_RUN_BLOWUP && rep.step == POISON_STEP && rep.t == POISON_STEP * 0.125);
    }
    CHECK(missed == 0,
          "a non-finite w_i, lambda, R entry or q_i (each of 17 in turn) at step %d, "
          "whose row is not written, stops the run there: %d missed",
          POISON_STEP, missed);
}

/* The driver's Newton accounting: the total and the largest count per step over the run. */
static int count_apply(const sus_model *m, double eps, const double w[3], double w_next[3],
                       double *lambda_next, sus_stepper_stats *st)
{
    (void)m, (void)eps;
    for (int i = 0; i < 3; i++)
        w_next[i] = w[i];
    *lambda_next = 0.25;
    *st = (sus_stepper_stats){.iterations = 1 + poison_calls++ % 3}; /* 1, 2, 3, 1, 2, ... */
    return SUS_STEPPER_OK;
}

static void newton_count_checks(const sus_model *m)
{
    static const sus_step_ops count_ops = {.apply = count_apply};
    const sus_stepper_type counting = {
        .name = "count",
        .step = &count_ops,
        .desc = {.order = 1, .lambda_order = 1, .substeps = 1, .source = __FILE__}};
    const sus_run_config cfg = {.model = m,
                                .stepper = &counting,
                                .recon = SUS_RECON_CAYLEY,
                                .eps = 0.125,
                                .steps = 7,
                                .every = 1};
    const double w0[2] = {0.4, 0.5};
    sus_row last;
    sus_run_report rep;
    poison_calls = 0;
    const int rc = sus_run(&cfg, w0, sus_keep_last, &last, &rep);
    const long total = 1 + 2 + 3 + 1 + 2 + 3 + 1;
    CHECK(rc == SUS_RUN_OK && rep.sus_newton_iterations == total && rep.max_iterations == 3,
          "the run's Newton iterations: total %ld (13), largest %d (3)", rep.sus_newton_iterations,
          rep.max_iterations);
}

/* A composition step's Newton count is the sum of its substeps' (each a midpoint DSP step with
 * step g_i eps from the previous substep's w), its residual the worst one's, its w the last one's.
 */
static void composition_count_checks(const body *bd, const sus_model *m)
{
    const sus_step_composition *c = &sus_step_comp_suzuki4;
    double u[3] = {bd->w0[0], bd->w0[1], 0.0}, x[3], lam, wn[3];
    sus_stepper_stats st;
    long sum = 0;
    double worst = -1.0, worst_scale = 0.0;
    for (int i = 0; i < sus_step_composition_stages(c); i++) {
        sus_step_midpoint->step->apply(m, sus_step_composition_weight(c, i) * 0.25, u, x, &lam,
                                       &st);
        sum += st.iterations;
        if (st.residual > worst)
            worst = st.residual, worst_scale = st.scale;
        u[0] = x[0], u[1] = x[1], u[2] = x[2];
    }
    const double w[3] = {bd->w0[0], bd->w0[1], 0.0};
    sus_step_composition_apply(c, m, 0.25, w, wn, &lam, &st);
    CHECK(st.iterations == sum && wn[0] == u[0] && wn[1] == u[1],
          "%s: %s, Newton iterations %d (the substeps' sum %ld), w the last substep's", bd->name,
          c->name, st.iterations, sum);
    CHECK(worst > 0.0 && st.residual == worst && st.scale == worst_scale,
          "%s: %s keeps the worst substep's residual %.3g and its scale (%.3g)", bd->name, c->name,
          st.residual, worst);
}

/* exp(w^) - I = w^ + w^ w^ / 2 + O(|w|^3): where |w|^2 underflows to 0 (|w| = 1e-200), so that the
 * angle computed is 0, the result is still w^ to round-off, not a multiple of it. */
static void tiny_angle_checks(void)
{
    const double w[3] = {1e-200, -3e-200, 2e-200};
    double D[3][3], W[3][3], d = 0.0;
    sus_so3_exp_minus_identity(w, D);
    sus_so3_hat(w, W);
    for (int i = 0; i < 9; i++)
        d = fmax(d, fabs(D[i / 3][i % 3] - W[i / 3][i % 3]) / 3e-200);
    CHECK(d <= 1e-15, "exp(w^) - I at |w| = 3.7e-200 (|w|^2 underflows) is w^: %.2g of |w|", d);
}

/* Shepperd's choice in sus_quat_from_rotation: the branch of the largest of tr, R11, R22, R33
 * divides by r = 2 |q_k| >= 1; another branch can divide by a tiny |q_k| and lose all accuracy.
 * These unit q, each with one component of 1e-8 (a branch that divides by it), are recovered to
 * round-off. */
static void shepperd_checks(void)
{
    const double qs[5][4] = {
        {-0.4809013035408614, 0.8001595003259363, -0.3584392700177361, -3.3e-8},
        {0.6, -3.3e-8, 0.48, -0.64},
        {-2.1e-8, 0.36, 0.48, 0.8},
        {0.28, 0.96, 1.7e-8, 0.0},
        {0.5861363299782679, -0.5299857305050835, 0.6128289550442271, 2.6e-8}};
    double worst = 0.0;
    for (int k = 0; k < 5; k++) {
        double q[4], R[3][3], back[4], n = 0.0;
        for (int i = 0; i < 4; i++)
            n += qs[k][i] * qs[k][i];
        const double sgn = qs[k][0] < 0.0 ? -1.0 : 1.0;
        for (int i = 0; i < 4; i++)
            q[i] = sgn * qs[k][i] / sqrt(n);
        sus_quat_rotation(q, R);
        sus_quat_from_rotation(R, back);
        for (int i = 0; i < 4; i++)
            worst = fmax(worst, fabs(back[i] - q[i]));
    }
    CHECK(worst <= 1e-13, "q(R(q)) = q with one tiny component: %.2g", worst);
}

/* The Taylor step at the largest order its arrays hold agrees with a lower order where both are
 * exact to round-off: h at 1/20 of the proved radius, so the order-16 tail is below 20^-17. The
 * registered orders never index that far, so only this reaches the arrays' last entries (an
 * array one entry short shows under -fsanitize=bounds, as SAN=1 and make mutants-ops build). */
static void taylor_top_order_checks(const body *bd, const sus_model *m)
{
    const double w[3] = {bd->w0[0], bd->w0[1], 0.0}, h = sus_step_taylor_radius(m, w) / 20.0;
    double wn[2][3], lam[2], q[2][4], d = 0.0;
    for (int k = 0; k < 2; k++) {
        sus_attitude a;
        sus_stepper_stats st;
        sus_attitude_identity(&a);
        sus_step_taylor_apply_full(k ? SUS_STEP_TAYLOR_MAX_ORDER : 16, m, h, &a, w, wn[k], &lam[k],
                                   &st);
        sus_quat_of_attitude(&a, q[k]);
    }
    for (int i = 0; i < 4; i++)
        d = fmax(d, fmax(fabs(q[1][i] - q[0][i]), i < 2 ? fabs(wn[1][i] - wn[0][i]) : 0.0));
    CHECK(d <= 1e-13, "%s: Taylor order %d against order 16, w and q: %.2g", bd->name,
          SUS_STEP_TAYLOR_MAX_ORDER, d);
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body bd;
        body_get(k, &bd);
        sus_model m;
        if (check_body_model(&bd, &m) != 0)
            continue;
        norm_checks(&bd, &m);
        taylor_top_order_checks(&bd, &m);
        composition_count_checks(&bd, &m);
        if (k == 0) {
            blowup_checks(&m);
            newton_count_checks(&m);
        }
    }
    row_finite_checks();
    posdef_message_checks();
    tiny_angle_checks();
    shepperd_checks();
    return check_summary("test_guards");
}
