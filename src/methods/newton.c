/* newton.h's solves for any residual, from the inner loop in newton_core.h, and the linear solve
 * and the continuation in eps they fall back on. */
#include "newton_core.h"

#include <float.h>
#include <math.h>

/* A product kept as mantissa and binary exponent, m 2^e with 0.5 <= |m| < 1 (or m = 0): det J
 * and its round-off yardstick are products of n factors of the size of J's entries, and leave the
 * range of doubles when J's entries are far from 1 (n = 4 and entries near c: once c^4 does),
 * where their ratio, all the singularity test reads, does not. */
typedef struct {
    double m;
    int e;
} wide;

static void wide_mul(wide *w, double f)
{
    int k;
    w->m = frexp(w->m * f, &k);
    w->e += k;
}

/* |a| > |b|, exactly: the exponents decide unless they are equal (a NaN: no). */
static int wide_abs_greater(wide a, wide b) { return ldexp(fabs(a.m), a.e - b.e) > fabs(b.m); }

/* The condition number of J with its rows scaled to unit 1-norm (D J, D = diag(1/r)), in the
 * max norm: kappa = |D J| |(D J)^-1| = max_i sum_j |(J^-1)_ij| r_j, unchanged by scaling any row.
 * J^-1 column by column from the factors of lu_factor; NaN or infinite for a zero pivot. */
static double equilibrated_cond(int n, const double *LU, const int *perm, const double *r)
{
    double rows[SUS_MAX_UNKNOWNS] = {0}, x[SUS_MAX_UNKNOWNS], kappa = 0.0;
    for (int j = 0; j < n; j++) {
        for (int k = 0; k < n; k++) { /* L y = P e_j */
            x[k] = perm[k] == j;
            for (int i = 0; i < k; i++)
                x[k] -= LU[k * n + i] * x[i];
        }
        for (int k = n - 1; k >= 0; k--) { /* U x = y */
            for (int i = k + 1; i < n; i++)
                x[k] -= LU[k * n + i] * x[i];
            x[k] /= LU[k * n + k];
        }
        for (int i = 0; i < n; i++)
            rows[i] += fabs(x[i]) * r[j];
    }
    for (int i = 0; i < n; i++)
        kappa = rows[i] > kappa || isnan(rows[i]) ? rows[i] : kappa;
    return kappa;
}

/* Is |det J| at or below 4 n u times the product of the row norms? As plain products of doubles
 * (in this order, as they have always been formed) where both lie in the range of doubles; else
 * as wide products, which round as the plain ones do (a power of two scales exactly) but never
 * under- or overflow: the answer is the same for J and 2^s J. *det: det J where a double holds it;
 * beyond, +-inf above the range and, below it, the least subnormal of its sign (not 0: det J > 0
 * is the test of the branch's orientation, newton_core.h). */
static int det_small(int n, const double *U, double sign, const double *r, double *det)
{
    double d = sign, p = 1.0;
    for (int k = 0; k < n; k++)
        d *= U[k * n + k], p *= r[k];
    const double bound = 4.0 * n * SUS_U * p;
    *det = d;
    if (in_range(d) && in_range(bound))
        return !(fabs(d) > bound);
    wide wd = {0.5 * sign, 1}, wb = {0.5, 1}; /* +-1 and 1 */
    for (int k = 0; k < n; k++)
        wide_mul(&wd, U[k * n + k]), wide_mul(&wb, r[k]);
    wide_mul(&wb, 4.0 * n * SUS_U);
    const double v = ldexp(wd.m, wd.e);
    *det = v == 0.0 && wd.m != 0.0 ? copysign(DBL_TRUE_MIN, wd.m) : v;
    return !wide_abs_greater(wd, wb);
}

int sus_step_linear_singular(int n, const double *LU, const int *perm, double sign, const double *r,
                             double *det)
{
    /* The determinant test is cheap but, beyond n = 2, strict: it falls with the product of the
     * small singular values (gauss4's J on a near-singular I_m has two, one from each block I_m).
     * Where it fails, the condition number decides: the solve's relative error is about
     * 4 n u kappa, and J is singular to working precision only where that reaches 1. */
    return det_small(n, LU, sign, r, det) &&
           !(4.0 * n * SUS_U * equilibrated_cond(n, LU, perm, r) < 1.0);
}

/* n = 2 by the closed form (newton_core.h: the (REGLOC) block); larger n by newton_core.h's
 * Gaussian elimination. Written here rather than taken from GSL: the WebAssembly build of the
 * methods has no GSL, and GSL's LU, timed on an 8 x 8 system gauss4 once solved for its attitude,
 * was most of that step's cost. */
int sus_step_linear_solve(int n, double *J, const double *g, double *dx, double *det)
{
    return n == 2 ? newton_solve_2x2(J, g, dx, det) : newton_solve_lu(n, J, g, dx, det);
}

int sus_step_newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                          const double w[2], double *x, sus_stepper_stats *st)
{
    return newton_solve(G, n, m, eps, w, x, x, st, SUS_STEP_NEWTON_MAXIT);
}

/* ---- the branch: continuation in eps from the root at eps = 0 ---- */

/* |det J|^(2/n) / |J|_F^2 of an n x n J, n > 2, for J = 2^s J0 (s from the largest |J0_ij|):
 * the same ratio for J0, whose det and |J|_F^2 a double holds however J is scaled. */
static double regularity_scaled(int n, const double *J)
{
    double J0[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], g[SUS_MAX_UNKNOWNS] = {0}, dx[SUS_MAX_UNKNOWNS],
                                                    amax = 0.0, f2 = 0.0;
    for (int i = 0; i < n * n; i++)
        amax = fmax(amax, fabs(J[i]));
    const int s = ilogb(amax);
    for (int i = 0; i < n * n; i++) {
        J0[i] = ldexp(J[i], -s);
        f2 += J0[i] * J0[i];
    }
    double det;
    sus_step_linear_solve(n, J0, g, dx, &det);
    return pow(fabs(det), 2.0 / n) / f2;
}

/* |det J| / |J|_F^2 (n = 2) or |det J|^(2/n) / |J|_F^2: how far J is from singular, scale-free.
 * Where det J or |J|_F^2 leaves the range of doubles (n > 2 on a body scaled far from 1), on J
 * scaled by a power of two; elsewhere on J itself, as it always was. */
static double regularity(sus_residual_fn G, int n, const sus_model *m, double eps,
                         const double w[2], const double *x)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS],
        J1[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], dx[SUS_MAX_UNKNOWNS], det, sc, f2 = 0.0;
    G(m, eps, w, x, g, J, &sc);
    for (int i = 0; i < n * n; i++) {
        f2 += J[i] * J[i];
        J1[i] = J[i];
    }
    sus_step_linear_solve(n, J, g, dx, &det);
    if (n == 2) /* pow(|det|, 1) is |det| (a representable exact result): n = 2 skips the call */
        return fabs(det) / f2;
    if (!(fabs(det) >= DBL_MIN && fabs(det) <= DBL_MAX && f2 >= DBL_MIN && f2 <= DBL_MAX))
        return regularity_scaled(n, J1);
    return pow(fabs(det), 2.0 / n) / f2;
}

/* r at the root x for eps relative to r at eps = 0, at its root guess(0). */
static double relative_regularity(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                                  double eps, const double w[2], const double *x)
{
    double x0[SUS_MAX_UNKNOWNS];
    guess(m, 0.0, w, x0);
    return regularity(G, n, m, eps, w, x) / regularity(G, n, m, 0.0, w, x0);
}

int sus_step_newton_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                           double eps, const double w[2], double *x, sus_stepper_stats *st,
                           double *reg_min)
{
    double prev[SUS_MAX_UNKNOWNS], cur[SUS_MAX_UNKNOWNS], xp[SUS_MAX_UNKNOWNS];
    double e = 0.0, e_prev = 0.0, de = eps / BRANCH_FIRST, reg_last = 1.0;
    int its = 0;
    guess(m, 0.0, w, cur); /* the root at eps = 0 */
    for (int i = 0; i < n; i++)
        prev[i] = cur[i];
    /* Without reg_min, r is wanted only where the stages stop short: there it is computed at the
     * last accepted stage, from the same (e, cur) and the same root at 0, so the same bits. */
    const double reg0 = reg_min ? regularity(G, n, m, 0.0, w, cur) : NAN;
    if (reg_min)
        *reg_min = 1.0;
    for (int stages = 0; e != eps; stages++) {
        if (stages == BRANCH_MAX_STAGES || !(fabs(de) >= BRANCH_MIN_STAGE * fabs(eps))) {
            st->iterations = its;
            st->continued = 1;
            if (!reg_min && e != 0.0) /* e = 0: no stage accepted, r still 1 */
                reg_last = relative_regularity(G, guess, n, m, e, w, cur);
            return reg_last <= BRANCH_FOLD ? SUS_STEPPER_SINGULAR : SUS_STEPPER_NO_CONVERGENCE;
        }
        const double en = fabs(eps - e) <= fabs(de) ? eps : e + de;
        if (e == 0.0) { /* the explicit prediction: accurate for a first stage short enough */
            guess(m, en, w, xp);
            if (!within_jump(moved_by(xp, cur, n), m, w)) {
                de *= BRANCH_SHRINK; /* too long to predict: shorter, without a Newton solve */
                continue;
            }
        } else {
            for (int i = 0; i < n; i++) /* the secant through the last two roots */
                xp[i] = cur[i] + (en - e) / (e - e_prev) * (cur[i] - prev[i]);
        }
        if (stage(G, n, m, en, w, xp, st, &its, BRANCH_STAGE_ITS) != 0) {
            de *= BRANCH_SHRINK;
            continue;
        }
        for (int i = 0; i < n; i++)
            prev[i] = cur[i], cur[i] = xp[i];
        e_prev = e, e = en,
        de *= st->iterations <= BRANCH_EASY_ITS ? BRANCH_GROW_EASY : BRANCH_GROW;
        if (reg_min) {
            reg_last = regularity(G, n, m, e, w, cur) / reg0;
            *reg_min = fmin(*reg_min, reg_last);
        }
    }
    for (int i = 0; i < n; i++)
        x[i] = cur[i];
    st->iterations = its;
    st->continued = 1;
    return SUS_STEPPER_OK;
}

int sus_step_newton_solve_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                                 double eps, const double w[2], double *x, sus_stepper_stats *st)
{
    return newton_solve_branch(G, guess, n, m, eps, w, x, st);
}
