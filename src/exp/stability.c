#include "stability.h"

#include "newton.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <math.h>

const char *const SUS_EXP_STAB_NAMES[SUS_EXP_STAB_NCLASS] = {"good", "wrong limit", "blow-up",
                                                             "solver failure", "regularity lost"};

/* Continuation of the implicit step in eps from 0 (where the root is the trivial one) to eps: the
 * physical branch. Returns 0 with w^{k+1} of that root in x, or -1 when a continuation step
 * fails or the Jacobian's determinant changes sign (a fold). */
static int continue_root(const sus_model *m, const sus_stepper_type *st, double eps, const double w[2],
                         double x[2])
{
    const int n = st->unknowns;
    double prev[SUS_MAX_UNKNOWNS], cur[SUS_MAX_UNKNOWNS], guess[SUS_MAX_UNKNOWNS];
    st->guess(m, 0.0, w, cur); /* the root at eps = 0 */
    for (int i = 0; i < n; i++)
        prev[i] = cur[i];
    for (int j = 1; j <= SUS_EXP_STAB_CONTINUATION_STEPS; j++) {
        const double e = eps * j / SUS_EXP_STAB_CONTINUATION_STEPS;
        if (j == 1)
            st->guess(m, e, w, guess);
        else
            for (int i = 0; i < n; i++) /* linear extrapolation */
                guess[i] = 2.0 * cur[i] - prev[i];
        sus_stepper_stats s;
        if (sus_step_newton_solve(st->residual, n, m, e, w, guess, &s) != SUS_STEPPER_OK || !(s.det > 0.0))
            return -1;
        for (int i = 0; i < n; i++) {
            prev[i] = cur[i];
            cur[i] = guess[i];
        }
    }
    st->result(m, eps, w, cur, x);
    return 0;
}

void sus_exp_stability_run(const sus_exact *ex, const sus_stepper_type *st, double eps, long N,
                          int check_branch, sus_exp_stab_result *res)
{
    const sus_model *m = ex->model;
    double w[3] = {ex->w0[0], ex->w0[1], 0.0}, winf[2];
    const double r0 = hypot(w[0], w[1]);
    sus_exact_limit(ex, winf);
    *res = (sus_exp_stab_result){SUS_EXP_STAB_GOOD, 0, NAN};
    for (long k = 1; k <= N; k++) {
        double x[3], lam;
        sus_stepper_stats s;
        const int status = st->apply(m, eps, w, x, &lam, &s);
        res->step = k;
        if (status == SUS_STEPPER_SINGULAR || (st->unknowns && status == SUS_STEPPER_OK && !(s.det > 0.0))) {
            res->cls = SUS_EXP_STAB_REGULARITY;
            return;
        }
        if (status != SUS_STEPPER_OK) {
            res->cls = SUS_EXP_STAB_SOLVER;
            return;
        }
        if (!isfinite(x[0]) || !isfinite(x[1]) || hypot(x[0], x[1]) > SUS_EXP_STAB_BLOWUP_FACTOR * r0) {
            res->cls = SUS_EXP_STAB_BLOWUP;
            return;
        }
        if (check_branch && st->unknowns) {
            double xc[2];
            if (continue_root(m, st, eps, w, xc) != 0) {
                res->cls = SUS_EXP_STAB_REGULARITY;
                return;
            }
            if (hypot(xc[0] - x[0], xc[1] - x[1]) > 1e-8 * (hypot(x[0], x[1]) + r0)) {
                res->cls = SUS_EXP_STAB_SOLVER;
                return;
            }
        }
        w[0] = x[0];
        w[1] = x[1];
    }
    res->step = 0;
    res->final_err = hypot(w[0] - winf[0], w[1] - winf[1]) / hypot(winf[0], winf[1]);
    res->cls = res->final_err <= SUS_EXP_STAB_GOOD_TOL ? SUS_EXP_STAB_GOOD : SUS_EXP_STAB_WRONG_LIMIT;
}

void sus_exp_ellipse_point(const sus_exact *ref, double theta, double w[2])
{
    const double u1 = ref->r * cos(theta), u2 = ref->r * sin(theta);
    w[1] = u2 / ref->l22;
    w[0] = (u1 - ref->l21 * w[1]) / ref->l11;
}

/* Does a start 1e-6 off the attracting rotation return to the line c(w) = 0 at step h? */
static int returns(const sus_exact *ex, const sus_stepper_type *st, double h)
{
    const double theta = atan2(ex->sb, ex->cb) + 0.5 * 3.14159265358979323846 + 1e-6; /* psi = pi/2 + 1e-6 */
    double w[3] = {0.0, 0.0, 0.0};
    sus_exp_ellipse_point(ex, theta, w);
    const double c0 = fabs(sus_c(ex->model, w)), eps = h / ex->k;
    for (int k = 0; k < 4000; k++) {
        double x[3], lam;
        sus_stepper_stats s;
        if (st->apply(ex->model, eps, w, x, &lam, &s) != SUS_STEPPER_OK || !isfinite(x[0]) || !isfinite(x[1]))
            return 0;
        w[0] = x[0];
        w[1] = x[1];
    }
    return fabs(sus_c(ex->model, w)) < c0;
}

double sus_exp_stability_limit(const sus_exact *ex, const sus_stepper_type *st, double lo, double hi)
{
    if (!returns(ex, st, lo))
        return NAN;
    if (returns(ex, st, hi))
        return INFINITY;
    while (hi - lo > 1e-4 * lo) {
        const double mid = 0.5 * (lo + hi);
        if (returns(ex, st, mid))
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

long sus_exp_stability_steps(double h)
{
    return (long)fmin(40000.0, fmax(40.0 / h, 10.0 * h) + 50.0);
}

void sus_exp_stability_map(const sus_exact *paper, const sus_stepper_type *st, const double *hs, int nh,
                          int nangle, sus_exp_stab_result *results)
{
    for (int i = 0; i < nh; i++)
        for (int a = 0; a < nangle; a++) {
            double w0[2];
            sus_exact ex;
            sus_exp_ellipse_point(paper, 2.0 * 3.14159265358979323846 * a / nangle + SUS_EXP_STAB_ANGLE0, w0);
            sus_exact_init(&ex, paper->model, w0);
            sus_exp_stability_run(&ex, st, hs[i] / paper->k, sus_exp_stability_steps(hs[i]),
                                 hs[i] >= SUS_EXP_STAB_BRANCH_H, &results[i * nangle + a]);
        }
}

/* |R(-h)| - 1, whose first positive zero is the linear limit. */
static double excess(double h, void *params)
{
    double (*R)(double) = *(double (**)(double))params;
    return fabs(R(-h)) - 1.0;
}

double sus_exp_linear_limit(const sus_step_method *me, double h_max)
{
    if (!me->type->stability)
        return NAN;
    /* Scan for the first sign change of |R(-h)| - 1 (a fine geometric grid: a stability
     * interval is never narrower than a grid cell, 1% of h), then bracket it with Brent. */
    double (*R)(double) = me->type->stability;
    gsl_function F = {excess, &R};
    double lo = 1e-3;
    if (excess(lo, &R) > 0.0)
        return NAN;
    for (double hi = lo * 1.01; hi <= h_max * 1.01; lo = hi, hi *= 1.01) {
        if (excess(hi, &R) <= 0.0)
            continue;
        gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
        double root = NAN;
        if (s && gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS)
            for (int it = 0; it < 100; it++) {
                gsl_root_fsolver_iterate(s);
                root = gsl_root_fsolver_root(s);
                const double lo_s = gsl_root_fsolver_x_lower(s), hi_s = gsl_root_fsolver_x_upper(s);
                if (gsl_root_test_interval(lo_s, hi_s, 0.0, 1e-14) == GSL_SUCCESS)
                    break;
            }
        if (s)
            gsl_root_fsolver_free(s);
        return root;
    }
    return INFINITY;
}
