#include "newton.h"

#include <math.h>

static double inf_norm(const double *v, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++)
        r = fmax(r, fabs(v[i]));
    return r;
}

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

/* n = 2 by the closed form (the (REGLOC) block, bit for bit as it has always been solved); larger
 * n by Gaussian elimination with partial pivoting, on the stack. Written here rather than taken
 * from GSL: GSL's LU was most of the cost of a gauss4 step (n = 8), and the WebAssembly build of
 * the methods has no GSL. */
int suslov_linear_solve(int n, double *J, const double *g, double *dx, double *det)
{
    if (n == 2) {
        *det = J[0] * J[3] - J[1] * J[2];
        if (fabs(*det) <= 4.0 * SUSLOV_U * (fabs(J[0] * J[3]) + fabs(J[1] * J[2])))
            return -1;
        dx[0] = (J[3] * g[0] - J[1] * g[1]) / *det;
        dx[1] = (J[0] * g[1] - J[2] * g[0]) / *det;
        return 0;
    }
    const double bound = 4.0 * n * SUSLOV_U * row_norm_product(J, n);
    double b[SUSLOV_MAX_UNKNOWNS];
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

int suslov_newton_solve(suslov_residual_fn G, int n, const suslov_model *m, double eps, const double w[2],
                        double *x, suslov_step_stats *st)
{
    double g[SUSLOV_MAX_UNKNOWNS], J[SUSLOV_MAX_UNKNOWNS * SUSLOV_MAX_UNKNOWNS], dx[SUSLOV_MAX_UNKNOWNS];
    newton_state s = {.prev = INFINITY, .best.residual = INFINITY, .ok.residual = INFINITY};
    keep(&s.best, x, n, INFINITY, 0.0);
    st->iterations = 0;
    st->det = NAN;
    for (;;) {
        G(m, eps, w, x, g, J, &st->scale);
        st->residual = inf_norm(g, n);
        const int singular = suslov_linear_solve(n, J, g, dx, &st->det) != 0;
        const int status = decide(&s, x, n, st);
        if (status >= 0)
            return status;
        /* (REGLOC): the step is defined only where this matrix is invertible. */
        if (singular)
            return s.polishing ? SUSLOV_STEP_OK : SUSLOV_STEP_SINGULAR;
        for (int i = 0; i < n; i++)
            x[i] -= dx[i];
        st->iterations++;
        /* A correction below the spacing of doubles at x leaves x unchanged: x is the root to
         * working precision even when a large Jacobian keeps |G| above NEWTON_RTOL * scale
         * (|G| >= |J| ulp(x) there). */
        if (!s.polishing && inf_norm(dx, n) <= 2.0 * SUSLOV_U * inf_norm(x, n)) {
            fn_final(G, n, m, eps, w, x, st);
            return SUSLOV_STEP_OK;
        }
    }
}

int suslov_implicit_solve(const suslov_stepper_type *type, const suslov_model *m, double eps,
                          const double w[3], double w_next[3], suslov_step_stats *st)
{
    double x[SUSLOV_MAX_UNKNOWNS];
    type->guess(m, eps, w, x);
    const int status = suslov_newton_solve(type->residual, type->unknowns, m, eps, w, x, st);
    type->result(m, eps, w, x, w_next);
    w_next[2] = 0.0;
    return status;
}
