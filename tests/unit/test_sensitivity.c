/* The regularity that src/lab/sensitivity.c records (det_min: the smallest det J / det I_m over a
 * run's steps, J the upper-left block of (REGLOC) for the midpoint DSP and of (RegCond) for the
 * variational integrator) against the same determinant computed here from the printed equations,
 * step by step along the same run.
 *
 * The block is J = I_m + E, E the eps-dependent part of d/dw^{k+1} of the step equation:
 *   midpoint DSP, (Discretization) with l = (-m2 c(m), m1 c(m)) at m = (w^k + w^{k+1}) / 2:
 *     E = -(eps / 2) dl/dm;
 *   (taudyn), with c(x) = I_3i x_i and s(x) = x^T I_m x:
 *     E = (eps / 2) d/dx (x2 c(x), -x1 c(x)) + (eps^2 / 4) (s(x) Id + x ((I_m + I_m^T) x)^T).
 * For 2 x 2 matrices det(I_m + E) = det I_m + tr(adj(I_m) E) + det E exactly, so
 *   det J / det I_m = 1 + tr(adj(I_m) E) / det I_m + det E / det I_m,
 * whose first-order term is -(eps / 2) div f(m) for the midpoint DSP (f = I_m^{-1} l, the field of
 * (ContDyn)): nonzero on a transient, so the smallest ratio is not the 1 of eps = 0.
 *
 * Expected to agree within the round-off of a 2 x 2 determinant, u (|J11 J22| + |J12 J21|), taken
 * at a point that may be one Newton correction off the root: newton.h accepts a root whose
 * residual is within 1000 u of its scale, a point off by 1000 u cond(J) relative, which moves det J
 * by as much relative to its terms; a factor 10 on that covers the few roundings of E's entries.
 * Every body of the family (its own w0), eps = 2^-3 and 1 in the paper's time (the ledger's range
 * eps <= 1), both methods. */
#include "check_body.h"
#include "dsp.h"
#include "sensitivity.h"

#include <math.h>

#define TOL_FACTOR (10.0 * 1000.0 * SUS_U)

/* E of the block at the step w -> x (see the top of the file), from I as printed. */
static void block_e(const double I[9], int var, double eps, const double w[2], const double x[2],
                    double E[2][2])
{
    if (!var) {
        const double m0 = 0.5 * (w[0] + x[0]), m1 = 0.5 * (w[1] + x[1]);
        const double c = I[6] * m0 + I[7] * m1, h = -0.5 * eps; /* eps times d m / d x = 1/2 */
        E[0][0] = h * (-m1 * I[6]);
        E[0][1] = h * (-c - m1 * I[7]);
        E[1][0] = h * (c + m0 * I[6]);
        E[1][1] = h * (m0 * I[7]);
        return;
    }
    const double c = I[6] * x[0] + I[7] * x[1], h = 0.5 * eps, q = 0.25 * eps * eps;
    const double p0 = I[0] * x[0] + I[1] * x[1], p1 = I[3] * x[0] + I[4] * x[1];
    const double s = x[0] * p0 + x[1] * p1;
    const double g0 = p0 + I[0] * x[0] + I[3] * x[1], g1 = p1 + I[1] * x[0] + I[4] * x[1];
    E[0][0] = h * (x[1] * I[6]) + q * (s + x[0] * g0);
    E[0][1] = h * (c + x[1] * I[7]) + q * (x[0] * g1);
    E[1][0] = h * (-c - x[0] * I[6]) + q * (x[1] * g0);
    E[1][1] = h * (-x[0] * I[7]) + q * (s + x[1] * g1);
}

/* det J / det I_m at the step w -> x, and in *tol its round-off bound (top of the file). */
static double ratio_at(const double I[9], int var, double eps, const double w[2], const double x[2],
                       double *tol)
{
    double E[2][2];
    block_e(I, var, eps, w, x, E);
    const double dm = I[0] * I[4] - I[1] * I[3];
    const double first = I[4] * E[0][0] - I[1] * E[1][0] - I[3] * E[0][1] + I[0] * E[1][1];
    const double second = E[0][0] * E[1][1] - E[0][1] * E[1][0];
    const double J[2][2] = {{I[0] + E[0][0], I[1] + E[0][1]}, {I[3] + E[1][0], I[4] + E[1][1]}};
    const double terms = fabs(J[0][0] * J[1][1]) + fabs(J[0][1] * J[1][0]);
    const double detj = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    const double f2 = J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1];
    *tol = TOL_FACTOR * (terms / fabs(dm)) * (f2 / fabs(detj));
    return 1.0 + first / dm + second / dm;
}

/* The run of sus_lab_sens_run_one again, its steps by the stepper's own apply, and the smallest
 * ratio over them; *tol the largest bound over the steps. NAN when a step fails. */
static double reference_min(const body *b, const sus_model *m, const sus_stepper_type *st,
                            double eps, long N, double *tol)
{
    double w[3] = {b->w0[0], b->w0[1], 0.0}, x[3], lam, lo = INFINITY;
    *tol = 0.0;
    for (long k = 0; k < N; k++) {
        sus_stepper_stats s;
        if (st->step->apply(m, eps, w, x, &lam, &s) != SUS_STEPPER_OK)
            return NAN;
        double t;
        lo = fmin(lo, ratio_at(b->I, st == sus_step_variational, eps, w, x, &t));
        *tol = fmax(*tol, t);
        w[0] = x[0], w[1] = x[1];
    }
    return lo;
}

static void check_case(const body *b, const sus_model *m, const sus_exact *ex, int var, double e)
{
    const sus_stepper_type *st = var ? sus_step_variational : sus_step_midpoint;
    const double eps = e * check_body_time(m, b->w0);
    sus_lab_sens_run r;
    sus_lab_sens_run_one(ex, st, eps, &r);
    double tol;
    const double ref = reference_min(b, m, st, eps, r.steps, &tol);
    CHECK(!r.failed && isfinite(ref) && fabs(r.det_min - ref) <= tol,
          "%s, %s, eps = %g (paper's time), %ld steps: det_min %.17g, from the printed block "
          "%.17g (|difference| %.3g, bound %.3g)",
          b->name, st->name, e, r.steps, r.det_min, ref, fabs(r.det_min - ref), tol);
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        for (int var = 0; var <= 1; var++) {
            check_case(&b, &m, &ex, var, 0.125);
            check_case(&b, &m, &ex, var, 1.0);
        }
    }
    /* An explicit step has no block: its det_min is the 1 of eps = 0. */
    body b;
    sus_model m;
    sus_exact ex;
    if (check_body_exact(0, &b, &m, &ex) == 0) {
        sus_lab_sens_run r;
        sus_lab_sens_run_one(&ex, sus_step_euler, 0.125, &r);
        CHECK(r.det_min == 1.0, "euler: det_min %.17g, 1 without a block", r.det_min);
    }
    return check_summary("test_sensitivity");
}
