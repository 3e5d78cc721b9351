/* newton.h's solves for any residual, from the inner loop in newton_core.h, and the linear solve
 * and the continuation in eps they fall back on. */
#include "newton_core.h"

#include <math.h>

/* The product of the row 1-norms of J: an upper bound on the sum of |terms| of det J's Leibniz
 * expansion (expanding the product gives every term of it and more): the yardstick for the
 * round-off in det J, on the safe side. */
static double row_norm_product(const double *J, int n)
{
    double p = 1.0;
    for (int i = 0; i < n; i++) {
        double r = 0.0;
        for (int j = 0; j < n; j++)
            r += fabs(J[i * n + j]);
        p *= r;
    }
    return p;
}

/* n = 2 by the closed form (newton_core.h: the (REGLOC) block); larger n by Gaussian elimination
 * with partial pivoting, on the stack. Written here rather than taken from GSL: GSL's LU was most
 * of the cost of a gauss4 step (n = 8), and the WebAssembly build of the methods has no GSL. */
int sus_step_linear_solve(int n, double *J, const double *g, double *dx, double *det)
{
    if (n == 2)
        return newton_solve_2x2(J, g, dx, det);
    const double bound = 4.0 * n * SUS_U * row_norm_product(J, n);
    double b[SUS_MAX_UNKNOWNS];
    for (int i = 0; i < n; i++)
        b[i] = g[i];
    *det = 1.0;
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(J[i * n + k]) > fabs(J[p * n + k]))
                p = i;
        if (p != k) { /* a row swap changes the determinant's sign */
            for (int j = 0; j < n; j++) {
                const double t = J[k * n + j];
                J[k * n + j] = J[p * n + j];
                J[p * n + j] = t;
            }
            const double t = b[k];
            b[k] = b[p];
            b[p] = t;
            *det = -*det;
        }
        *det *= J[k * n + k];
        if (J[k * n + k] == 0.0)
            continue;
        for (int i = k + 1; i < n; i++) {
            const double f = J[i * n + k] / J[k * n + k];
            for (int j = k; j < n; j++)
                J[i * n + j] -= f * J[k * n + j];
            b[i] -= f * b[k];
        }
    }
    if (!(fabs(*det) > bound))
        return -1;
    for (int i = n - 1; i >= 0; i--) {
        double r = b[i];
        for (int j = i + 1; j < n; j++)
            r -= J[i * n + j] * dx[j];
        dx[i] = r / J[i * n + i];
    }
    return 0;
}

int sus_step_newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                          const double w[2], double *x, sus_stepper_stats *st)
{
    return newton_solve(G, n, m, eps, w, x, x, st, SUS_STEP_NEWTON_MAXIT);
}

/* ---- the branch: continuation in eps from the root at eps = 0 ---- */

/* |det J| / |J|_F^2 (n = 2) or |det J|^(2/n) / |J|_F^2: how far J is from singular, scale-free. */
static double regularity(sus_residual_fn G, int n, const sus_model *m, double eps,
                         const double w[2], const double *x)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], dx[SUS_MAX_UNKNOWNS], det,
        sc, f2 = 0.0;
    G(m, eps, w, x, g, J, &sc);
    for (int i = 0; i < n * n; i++)
        f2 += J[i] * J[i];
    sus_step_linear_solve(n, J, g, dx, &det);
    /* pow(|det|, 1) is |det| (a representable exact result): n = 2 skips the call */
    return (n == 2 ? fabs(det) : pow(fabs(det), 2.0 / n)) / f2;
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
