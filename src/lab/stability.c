#include "stability.h"

#include "implicit_step.h"
#include "newton.h"
#include "orderfit.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <math.h>

const char *const SUS_LAB_STAB_NAMES[SUS_LAB_STAB_NCLASS] = {"good", "wrong limit", "blow-up",
                                                             "solver failure", "regularity lost"};

/* hypot(x) > limit, for finite x. The computed hypot is within an ulp of |x|_2 <= sqrt(2) |x|_inf,
 * so below 2 |x|_inf: where 2 |x|_inf <= limit the answer is no without the call. */
static int beyond(const double x[2], double limit)
{
    const double a = fabs(x[0]), b = fabs(x[1]);
    return 2.0 * (a > b ? a : b) > limit && hypot(x[0], x[1]) > limit;
}

/* The class a step w -> x (status, stats s) ends the run with, or -1 when the run goes on. */
static int step_class(const sus_model *m, const sus_stepper_type *st, double eps, const double w[2],
                      const double x[2], int status, const sus_stepper_stats *s, double r0,
                      int check_branch)
{
    if (status == SUS_STEPPER_SINGULAR ||
        (st->equation && status == SUS_STEPPER_OK && !(s->det > 0.0)))
        return SUS_LAB_STAB_REGULARITY;
    if (status != SUS_STEPPER_OK)
        return SUS_LAB_STAB_SOLVER;
    if (!isfinite(x[0]) || !isfinite(x[1]) || beyond(x, SUS_LAB_STAB_BLOWUP_FACTOR * r0))
        return SUS_LAB_STAB_BLOWUP;
    /* A step whose root is already the continued branch (s->continued: the step ran the very call
     * sus_step_branch_root makes, sus_step_newton_branch of its own equation with these m, eps, w,
     * a function of them alone) would be compared with itself, bit for bit: nothing to check. */
    if (check_branch && st->equation && !s->continued) {
        double xc[2];
        const int rc = sus_step_branch_root(st->equation, m, eps, w, xc);
        if (rc != SUS_STEPPER_OK)
            return rc == SUS_STEPPER_SINGULAR ? SUS_LAB_STAB_REGULARITY : SUS_LAB_STAB_SOLVER;
        if (hypot(xc[0] - x[0], xc[1] - x[1]) > 1e-8 * (hypot(x[0], x[1]) + r0))
            return SUS_LAB_STAB_SOLVER;
    }
    return -1;
}

/* Where a run stops before its N steps, and why its result cannot differ from the full run's.
 * A run's result is fixed by the first step whose class (step_class) is not -1, else by w_N.
 *   - A failure (blow-up, solver, regularity) ends the run at its step: by definition the class is
 *     that of the first failing step, and no later step is looked at.
 *   - A state that repeats bit for bit, w_k = w_{k-p} with p <= SUS_LAB_STAB_CYCLE (a converged
 *     steady rotation is p = 1, a round-off cycle about it p > 1). The step and step_class are
 *     functions of (m, eps, w) alone: a fixed step keeps no state between calls, and the build
 *     rounds the same bits the same way (no fused multiply-add, no threads). So w_{k+j} =
 *     w_{k-p+j} for every j: the steps k+1 .. N only revisit states k-p .. k-1, each of which
 *     already stepped with class -1 (no failure can come), and w_N = w_{k-p+(N-k) mod p}.
 * Nothing earlier: GOOD and WRONG_LIMIT are read from w_N, and the map records |w_N - w_inf| to
 * six digits; a run that still moves can change them, so a bound that decides the class alone
 * (a contraction towards a limit, an energy that has left the ellipse) is no licence to stop.
 * The ring holds 16 states: the check costs up to 16 comparisons a step, little beside any step
 * that runs long, and large steps fall into round-off cycles longer than 8 (each skipped saves
 * thousands of costly steps; tests/unit/test_newton_branch.c checks periods to 16 and past). */
#define SUS_LAB_STAB_CYCLE 16

/* The period p <= SUS_LAB_STAB_CYCLE with w = ring[(k - p) % CYCLE], or 0. */
static int period(const double ring[][2], long k, const double w[2])
{
    for (int p = 1; p <= SUS_LAB_STAB_CYCLE && p <= k; p++) {
        const double *v = ring[(k - p) % SUS_LAB_STAB_CYCLE];
        if (v[0] == w[0] && v[1] == w[1])
            return p;
    }
    return 0;
}

void sus_lab_stability_run(const sus_exact *ex, const sus_stepper_type *st, double eps, long N,
                           int check_branch, sus_lab_stab_result *res)
{
    const sus_model *m = ex->model;
    double w[3] = {ex->w0[0], ex->w0[1], 0.0}, ring[SUS_LAB_STAB_CYCLE][2], winf[2];
    const double r0 = hypot(w[0], w[1]);
    sus_exact_limit(ex, winf);
    *res = (sus_lab_stab_result){SUS_LAB_STAB_GOOD, 0, NAN, {NAN, NAN}};
    for (long k = 1; k <= N; k++) { /* ring[j % CYCLE] holds w_j */
        double x[3], lam;
        sus_stepper_stats s;
        ring[(k - 1) % SUS_LAB_STAB_CYCLE][0] = w[0], ring[(k - 1) % SUS_LAB_STAB_CYCLE][1] = w[1];
        const int status = st->step->apply(m, eps, w, x, &lam, &s);
        res->step = k;
        res->w_fail[0] = w[0], res->w_fail[1] = w[1];
        if ((res->cls = step_class(m, st, eps, w, x, status, &s, r0, check_branch)) >= 0)
            return;
        w[0] = x[0], w[1] = x[1];
        const int p = period(ring, k, w); /* w_k = w_{k-p}: w_N = w_{k-p+(N-k) mod p} */
        if (p) {
            const double *v = ring[(k - p + (N - k) % p) % SUS_LAB_STAB_CYCLE];
            w[0] = v[0], w[1] = v[1];
            break;
        }
    }
    res->step = 0;
    res->w_fail[0] = w[0], res->w_fail[1] = w[1];
    res->final_err = hypot(w[0] - winf[0], w[1] - winf[1]) / hypot(winf[0], winf[1]);
    res->cls =
        res->final_err <= SUS_LAB_STAB_GOOD_TOL ? SUS_LAB_STAB_GOOD : SUS_LAB_STAB_WRONG_LIMIT;
}

/* Does the branch from w reach e? */
static int reaches(const sus_model *m, const sus_stepper_type *st, const double w[2], double e,
                   double *root)
{
    sus_stepper_stats s;
    const sus_step_equation *eq = st->equation;
    return sus_step_newton_branch(eq->residual, eq->guess, eq->unknowns, m, e, w, root, &s, NULL) ==
           SUS_STEPPER_OK;
}

/* |det J| of the step equation at its branch root for step e. */
static double branch_det(const sus_model *m, const sus_stepper_type *st, const double w[2],
                         double e)
{
    double root[SUS_MAX_UNKNOWNS], g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS],
        dx[SUS_MAX_UNKNOWNS], det = NAN, scale;
    if (!reaches(m, st, w, e, root))
        return NAN;
    st->equation->residual(m, e, w, root, g, J, &scale);
    sus_step_linear_solve(st->equation->unknowns, J, g, dx, &det);
    return fabs(det);
}

int sus_lab_fold(const sus_model *m, const sus_stepper_type *st, const double w[2], double eps,
                 double *e_star, double *exponent)
{
    double root[SUS_MAX_UNKNOWNS], lo = 0.0, hi = eps, s[SUS_LAB_FOLD_POINTS],
                                   d[SUS_LAB_FOLD_POINTS];
    if (!st->equation || reaches(m, st, w, eps, root))
        return -1;
    while (fabs(hi - lo) > SUS_LAB_FOLD_BISECT * fabs(eps)) {
        const double mid = 0.5 * (lo + hi);
        if (reaches(m, st, w, mid, root))
            lo = mid;
        else
            hi = mid;
    }
    *e_star = lo;
    for (int j = 0; j < SUS_LAB_FOLD_POINTS; j++) { /* e* - e = 10^-3 ... 10^-7 e*, largest first */
        s[j] = pow(10.0, -3.0 - j) * fabs(lo);
        d[j] = branch_det(m, st, w, lo - copysign(s[j], lo));
    }
    sus_lab_order_fit f;
    if (sus_lab_fit_order(s, d, SUS_LAB_FOLD_POINTS, INFINITY, 0.0, &f) != 0 ||
        f.used != SUS_LAB_FOLD_POINTS)
        return -1;
    *exponent = f.slope;
    return 0;
}

void sus_lab_ellipse_point(const sus_exact *ref, double theta, double w[2])
{
    const double u1 = ref->r * cos(theta), u2 = ref->r * sin(theta);
    w[1] = u2 / ref->l22;
    w[0] = (u1 - ref->l21 * w[1]) / ref->l11;
}

/* Does a start 1e-6 off the attracting rotation return to the line c(w) = 0 at step h? 1 when it
 * does, 0 when it does not, 2 when a step is refused as beyond its series' proved radius. */
static int returns(const sus_exact *ex, const sus_stepper_type *st, double h)
{
    const double theta =
        atan2(ex->sb, ex->cb) + 0.5 * 3.14159265358979323846 + 1e-6; /* psi = pi/2 + 1e-6 */
    double w[3] = {0.0, 0.0, 0.0};
    sus_lab_ellipse_point(ex, theta, w);
    const double c0 = fabs(sus_c(ex->model, w)), eps = h / ex->k;
    for (int k = 0; k < 4000; k++) {
        double x[3], lam;
        sus_stepper_stats s;
        const int status = st->step->apply(ex->model, eps, w, x, &lam, &s);
        if (status == SUS_STEPPER_DIVERGED)
            return 2;
        if (status != SUS_STEPPER_OK || !isfinite(x[0]) || !isfinite(x[1]))
            return 0;
        w[0] = x[0];
        w[1] = x[1];
    }
    return fabs(sus_c(ex->model, w)) < c0;
}

double sus_lab_stability_limit(const sus_exact *ex, const sus_stepper_type *st, double lo,
                               double hi, int *radius_bound)
{
    int at_hi = returns(ex, st, hi);
    *radius_bound = 0;
    if (returns(ex, st, lo) != 1)
        return NAN;
    if (at_hi == 1)
        return INFINITY;
    while (hi - lo > 1e-4 * lo) {
        const double mid = 0.5 * (lo + hi);
        const int r = returns(ex, st, mid);
        if (r == 1)
            lo = mid;
        else
            hi = mid, at_hi = r;
    }
    *radius_bound = at_hi == 2;
    return 0.5 * (lo + hi);
}

long sus_lab_stability_steps(double h)
{
    return (long)fmin(40000.0, fmax(40.0 / h, 10.0 * h) + 50.0);
}

void sus_lab_stability_map(const sus_exact *paper, const sus_stepper_type *st, const double *hs,
                           int nh, int nangle, sus_lab_stab_result *results)
{
    for (int i = 0; i < nh; i++)
        for (int a = 0; a < nangle; a++) {
            double w0[2];
            sus_exact ex;
            sus_lab_ellipse_point(
                paper, 2.0 * 3.14159265358979323846 * a / nangle + SUS_LAB_STAB_ANGLE0, w0);
            sus_exact_init(&ex, paper->model, w0);
            sus_lab_stability_run(&ex, st, hs[i] / paper->k, sus_lab_stability_steps(hs[i]),
                                  hs[i] >= SUS_LAB_STAB_BRANCH_H, &results[i * nangle + a]);
        }
}

/* |R(-h)| - 1, whose first positive zero is the linear limit. */
static double excess(double h, void *params)
{
    double (*R)(double) = *(double (**)(double))params;
    return fabs(R(-h)) - 1.0;
}

double sus_lab_linear_limit(const sus_step_method *me, double h_max)
{
    if (!me->type->desc.stability)
        return NAN;
    /* Scan for the first sign change of |R(-h)| - 1 (a fine geometric grid: a stability
     * interval is never narrower than a grid cell, 1% of h), then bracket it with Brent. */
    double (*R)(double) = me->type->desc.stability;
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
