#include "exact_run.h"

#include "api_args.h"

#include "mat3.h"
#include "refattitude.h"

#include <math.h>

/* The tail switches on when the rotation angle it neglects is below u = 2^-53, one rounding of
 * R's entries: the reference integration is good to ~1e-17 (refattitude.h), so anything coarser
 * would be the largest error of the exact rows. */
#define EXACT_TAIL_TOL 0x1p-53

/* The time t_s after which replacing w(t) by the steady rotation w* changes R by at most
 * EXACT_TAIL_TOL, and w* itself.
 * With a = sigma s = sigma s0 + k t (exact.h), (cos psi, sin psi) - (0, 1) has norm at most
 * sech a + (1 - tanh a) <= 2 sech a <= 4 e^{-a} for a >= 0, and w = L^{-T} u, |u| = r, so
 * |w(t) - w*| <= 4 |L^{-1}|_F r e^{-a}. Two solutions of R' = R w^ from the same R(t_s)
 * differ by at most the integral of |w - w*| (their propagators are rotations), which is
 * <= 4 |L^{-1}|_F r e^{-a_s} / k. Setting that to the tolerance gives a_s. An equilibrium
 * (ex->fixed) is a steady rotation from t = 0. */
static double steady_time(const sus_exact *ex, double wstar[3])
{
    sus_exact_limit(ex, wstar);
    wstar[2] = 0.0;
    if (ex->fixed)
        return 0.0;
    const double linv = sqrt(1.0 / (ex->l11 * ex->l11) + 1.0 / (ex->l22 * ex->l22) +
                             pow(ex->l21 / (ex->l11 * ex->l22), 2));
    const double a_s = log(4.0 * linv * ex->r / (ex->k * EXACT_TAIL_TOL));
    const double t_s = (fmax(a_s, 0.0) - ex->sigma * ex->s0) / ex->k;
    return isfinite(t_s) ? fmax(t_s, 0.0) : INFINITY;
}

/* The power of two c with |w0 / c| in [1/2, 1) (c = 1 for a zero w0). (ContDyn)'s field is
 * homogeneous quadratic, f(c w) = c^2 f(w), so if w~(tau) solves it from w0 / c then
 * w(t) = c w~(c t) solves it from w0, and R(t) = R~(c t) with R~' = R~ w~^ (d/dt R~(c t) =
 * c R~ w~^ = R w^). The attitude is integrated in the scaled time tau = c t: there the step
 * bound of refattitude.h holds whatever |w0|, and the time to the steady rotation, hence the
 * cost, no longer grows as 1 / |w0|. A power of two keeps w0 / c and c t exact. */
static double speed_scale(const double w0[2])
{
    const double n = hypot(w0[0], w0[1]);
    if (n == 0.0 || !isfinite(n))
        return 1.0;
    int e;
    frexp(n, &e);
    return ldexp(1.0, e);
}

/* exp(theta a^) for a unit axis a, by Rodrigues' formula with 1 - cos = 2 sin^2(theta/2):
 * no product grows with theta, so any finite angle is fine (sin and cos reduce it exactly). */
static void rotation_about(const double a[3], double theta, double R[3][3])
{
    const double s = sin(theta), h = sin(0.5 * theta), c1 = 2.0 * h * h;
    const double K[3][3] = {{0, -a[2], a[1]}, {a[2], 0, -a[0]}, {-a[1], a[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double K2 = 0.0;
            for (int l = 0; l < 3; l++)
                K2 += K[i][l] * K[l][j];
            R[i][j] = (i == j) + s * K[i][j] + c1 * K2;
        }
}

/* Scaled-time reference attitude (speed_scale) with the closed-form tail beyond tau_s. */
typedef struct {
    sus_exact ex;   /* from w0 / c */
    sus_refatt ra;
    double c, tau_s, speed, axis[3];
    int steady;        /* R_s = R~(tau_s) is known */
    double R_s[3][3];
} scaled_attitude;

static void scaled_init(scaled_attitude *sa, const sus_model *m, const double w0[2])
{
    double I3[3][3], wstar[3];
    sa->c = speed_scale(w0);
    const double v0[2] = {w0[0] / sa->c, w0[1] / sa->c};
    sus_exact_init(&sa->ex, m, v0);
    sa->tau_s = steady_time(&sa->ex, wstar);
    sa->speed = sqrt(wstar[0] * wstar[0] + wstar[1] * wstar[1]);
    for (int i = 0; i < 3; i++)
        sa->axis[i] = sa->speed > 0.0 ? wstar[i] / sa->speed : 0.0;
    sa->steady = 0;
    sus_mat3_identity(I3);
    sus_refatt_init(&sa->ra, &sa->ex, 0.0, I3);
}

/* R(t) = R~(c t), the tail R~(tau) = R~(tau_s) exp((tau - tau_s) w~*^). The angle is formed in
 * long double, whose range holds the product of any two doubles. */
static void scaled_attitude_at(scaled_attitude *sa, double t, double R[3][3])
{
    const long double tau = (long double)t * sa->c;
    if (tau <= sa->tau_s) {
        sus_refatt_at(&sa->ra, (double)tau, R);
        return;
    }
    if (!sa->steady)
        sus_refatt_at(&sa->ra, sa->tau_s, sa->R_s);
    sa->steady = 1;
    long double angle = (tau - sa->tau_s) * sa->speed;
    /* beyond the double range the phase is already lost to the rounding of t; any angle is
     * as good as another, and reducing in long double keeps it finite */
    if (angle > 0x1p1000L)
        angle = fmodl(angle, 6.283185307179586476925286766559L);
    double E[3][3];
    rotation_about(sa->axis, (double)angle, E);
    sus_mat3_mul(R, sa->R_s, E);
}

double sus_exact_reference_steps(const sus_model *m, const double w0[2], double T)
{
    if (!sus_args_model_ready(m) || !sus_args_finite2(w0) || !(T >= 0.0) || !isfinite(T))
        return -1.0;
    scaled_attitude sa;
    scaled_init(&sa, m, w0);
    return fmin((double)((long double)T * sa.c), sa.tau_s) * SUS_REFATT_PRECISE_STEPS;
}

int sus_run_exact(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit,
                     void *ctx, sus_run_report *report)
{
    const char *bad = sus_args_run(cfg, w0, emit, report, 0);
    if (bad)
        return sus_args_refuse(report, bad);
    sus_exact ex;
    scaled_attitude sa;
    sus_exact_init(&ex, cfg->model, w0);
    scaled_init(&sa, cfg->model, w0);
    *report = (sus_run_report){.status = SUS_STEPPER_OK};
    int rc = SUS_RUN_OK;
    for (long k = 0; rc == SUS_RUN_OK;) {
        sus_row row = {.k = k, .t = (double)k * cfg->eps};
        sus_exact_omega(&ex, row.t, row.w);
        row.w[2] = 0.0;
        row.lambda = sus_lagmult(cfg->model, row.w);
        scaled_attitude_at(&sa, row.t, row.R);
        if (!sus_row_finite(&row)) {
            report->step = k;
            report->t = row.t;
            rc = SUS_RUN_BLOWUP;
        } else if (emit(ctx, &row)) {
            rc = SUS_RUN_STOPPED;
        }
        if (k == cfg->steps)
            break;
        /* k + every would overflow for N, K near LONG_MAX: compare with what is left. */
        k = cfg->steps - k > cfg->every ? k + cfg->every : cfg->steps;
    }
    return rc;
}
