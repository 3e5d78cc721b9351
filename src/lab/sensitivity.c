#include "sensitivity.h"

#include "implicit_step.h"
#include "mat3.h"
#include "reconstruct.h"
#include "so3.h"
#include "unreduced.h"

#include <math.h>

/* psi0 of the states 1 .. 3: the fastest point of the ellipse (c(w) largest), and a point early
 * and a point late on the transient, a third of the way to the unstable and to the attracting
 * rotation */
static const double STATE_PSI[SUS_LAB_SENS_NSTATE - 1] = {0.0, -1.0471975511965976,
                                                          1.0471975511965976};

void sus_lab_sens_state(const sus_exact *body, int s, double w0[2])
{
    if (s <= 0 || s >= SUS_LAB_SENS_NSTATE || body->fixed) {
        w0[0] = body->w0[0];
        w0[1] = body->w0[1];
        return;
    }
    /* u = r (cos theta, sin theta), theta = beta + psi, and w = L^{-T} u (exact.h) */
    const double th = atan2(body->sb, body->cb) + STATE_PSI[s - 1];
    const double u1 = body->r * cos(th), u2 = body->r * sin(th);
    w0[1] = u2 / body->l22;
    w0[0] = (u1 - body->l21 * w0[1]) / body->l11;
}

/* The unreduced constraint of step 6 of (algo): v = R w^, <e3, vee(R^T v)>. */
static double unreduced_constraint(const sus_attitude *a, const double w[3])
{
    double R[3][3], W[3][3], V[3][3], xi[3];
    sus_attitude_get(a, R);
    sus_so3_hat(w, W);
    sus_mat3_mul(V, R, W);
    sus_unreduced_xi(R, V, xi);
    return fabs(xi[2]);
}

/* What one step leaves, its error and energy, folded into r; returns the error. */
static double record(const sus_exact *ex, const sus_model *m, double t, double t_fast,
                     const double w[3], double e0, sus_lab_sens_run *r)
{
    double we[2];
    sus_exact_omega(ex, t, we);
    const double err = hypot(w[0] - we[0], w[1] - we[1]);
    r->err_max = fmax(r->err_max, err / hypot(ex->w0[0], ex->w0[1]));
    if (t >= t_fast && isnan(r->err_fast))
        r->err_fast = err;
    r->energy_max = fmax(r->energy_max, fabs(sus_energy(m, w) - e0) / e0);
    return err;
}

/* A step that failed: the solve did not converge, a value is not finite, the block's determinant
 * reached or passed zero, or the root is not the one continuation from eps = 0 reaches (two roots
 * of one equation are apart by O(|w|); the same root agrees to round-off times the block's
 * conditioning, far below the 1e-8 |w| that tells them apart). A step whose root is already the
 * continuation's (s->continued: the same call, bit for bit) is not continued again. */
static int step_failed(int status, const double w[3], const double x[3], const sus_stepper_stats *s,
                       const sus_model *m, const sus_stepper_type *st, double eps, double *det_min)
{
    if (status != SUS_STEPPER_OK || !isfinite(x[0]) || !isfinite(x[1]))
        return 1;
    if (!st->equation)
        return 0;
    const double ratio = s->det / m->det_m;
    *det_min = fmin(*det_min, ratio);
    double xc[2];
    if (!(ratio > 0.0))
        return 1;
    if (s->continued)
        return 0;
    if (sus_step_branch_root(st->equation, m, eps, w, xc) != SUS_STEPPER_OK)
        return 1;
    return hypot(xc[0] - x[0], xc[1] - x[1]) > 1e-8 * (hypot(x[0], x[1]) + hypot(w[0], w[1]));
}

void sus_lab_sens_run_one(const sus_exact *ex, const sus_stepper_type *st, double eps,
                          sus_lab_sens_run *r)
{
    const sus_model *m = ex->model;
    const double T = SUS_LAB_SENS_KT / ex->k, t_fast = SUS_LAB_SENS_KT_FAST / ex->k;
    const long N = (long)fmax(1.0, round(T / eps));
    double w[3] = {ex->w0[0], ex->w0[1], 0.0}, winf[2], last = 0.0;
    const double e0 = sus_energy(m, w);
    sus_attitude att;
    sus_attitude_identity(&att);
    /* det_min: the smallest ratio over the steps, which may lie above 1; 1 where no block is */
    *r = (sus_lab_sens_run){.steps = N, .err_fast = NAN, .det_min = st->equation ? INFINITY : 1.0};
    for (long k = 0; k < N; k++) {
        double x[3], lam;
        sus_stepper_stats s;
        const int status = sus_stepper_full(st, m, eps, SUS_RECON_CAYLEY, &att, w, x, &lam, &s);
        if (step_failed(status, w, x, &s, m, st, eps, &r->det_min)) {
            r->failed = 1;
            r->t_fail = (double)(k + 1) * eps;
            return;
        }
        w[0] = x[0];
        w[1] = x[1];
        w[2] = 0.0;
        last = record(ex, m, (double)(k + 1) * eps, t_fast, w, e0, r);
        r->constraint = fmax(r->constraint, unreduced_constraint(&att, w));
    }
    sus_exact_limit(ex, winf);
    r->w_end[0] = w[0];
    r->w_end[1] = w[1];
    r->limit = hypot(w[0] - winf[0], w[1] - winf[1]);
    r->denergy = (sus_energy(m, w) - e0) / e0;
    if (isnan(r->err_fast)) /* the run ended before t_fast: its last error */
        r->err_fast = last;
}

double sus_lab_sens_first_failure(const sus_exact *ex, const sus_stepper_type *st, double scale)
{
    for (int j = 4 * SUS_LAB_SENS_FAIL_MIN_EXP; j <= 4 * SUS_LAB_SENS_FAIL_MAX_EXP; j++) {
        sus_lab_sens_run r;
        const double eps = exp2(0.25 * j) * scale;
        sus_lab_sens_run_one(ex, st, eps, &r);
        if (r.failed)
            return eps;
    }
    return INFINITY;
}
