#include "newton2.h"

#include <float.h>
#include <math.h>

static double inf_norm2(const double v[2])
{
    return fmax(fabs(v[0]), fabs(v[1]));
}

/* Records the residual at the accepted x. */
static void fn_final(suslov_residual_fn G, const suslov_model *m, double eps, const double w[2],
                     const double x[2], suslov_step_stats *st)
{
    double g[2], J[2][2];
    G(m, eps, w, x, g, J, &st->scale);
    st->residual = inf_norm2(g);
}

/* (REGLOC): Newton on the step equation; the block it inverts is the upper-left one of (REGLOC),
 * and a singular block ends the step as a failure. */
int newton2_solve(suslov_residual_fn G, const suslov_model *m, double eps, const double w[2],
                  double x[2], suslov_step_stats *st)
{
    double g[2], J[2][2], scale = 0.0, x_ok[2] = {0.0, 0.0}, res_ok = INFINITY, scale_ok = 0.0;
    double prev = INFINITY, x_best[2] = {x[0], x[1]}, res_best = INFINITY;
    int polishing = 0;
    st->iterations = 0;
    st->det = NAN;
    for (;;) {
        G(m, eps, w, x, g, J, &scale);
        st->residual = inf_norm2(g);
        st->scale = scale;
        st->det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (polishing) {
            /* The polished x replaces the accepted one unless round-off made it worse. */
            if (!(st->residual <= res_ok)) {
                x[0] = x_ok[0];
                x[1] = x_ok[1];
                st->residual = res_ok;
                st->scale = scale_ok;
            }
            return SUSLOV_STEP_OK;
        }
        if (!isfinite(st->residual) || !isfinite(scale))
            return SUSLOV_STEP_NO_CONVERGENCE;
        if (st->residual < res_best) {
            res_best = st->residual;
            x_best[0] = x[0];
            x_best[1] = x[1];
        }
        /* Stagnation at the round-off floor: near a large or ill-conditioned Jacobian |G| cannot
         * fall below ~ |J| ulp(x) times a few, which may sit above NEWTON2_RTOL * scale. When
         * an iteration no longer halves |G| and |G| is within NEWTON2_STAGNATION * scale, the
         * best iterate is the root to working precision. */
        if (!polishing && st->residual > NEWTON2_RTOL * scale && st->residual <= NEWTON2_STAGNATION * scale &&
            st->residual > 0.5 * prev) {
            x[0] = x_best[0];
            x[1] = x_best[1];
            st->residual = res_best;
            return SUSLOV_STEP_OK;
        }
        prev = st->residual;
        /* Once the residual is at round-off, one more correction takes x from "within the
         * tolerance" to the round-off floor; without it the tolerance, not round-off, sets a
         * bias that accumulates over many steps. */
        if (st->residual <= NEWTON2_RTOL * scale) {
            polishing = 1;
            x_ok[0] = x[0];
            x_ok[1] = x[1];
            res_ok = st->residual;
            scale_ok = scale;
        } else if (st->iterations == NEWTON2_MAXIT) {
            return SUSLOV_STEP_NO_CONVERGENCE;
        }
        /* (REGLOC): the step is defined only where this block is invertible; a determinant
         * below the round-off in its own two products is indistinguishable from zero. */
        if (fabs(st->det) <= 4.0 * DBL_EPSILON * (fabs(J[0][0] * J[1][1]) + fabs(J[0][1] * J[1][0])))
            return polishing ? SUSLOV_STEP_OK : SUSLOV_STEP_SINGULAR;
        const double dx[2] = {(J[1][1] * g[0] - J[0][1] * g[1]) / st->det,
                              (J[0][0] * g[1] - J[1][0] * g[0]) / st->det};
        x[0] -= dx[0];
        x[1] -= dx[1];
        st->iterations++;
        /* A correction below the spacing of doubles at x leaves x unchanged: x is the root to
         * working precision even when a large Jacobian keeps |G| above NEWTON2_RTOL * scale
         * (|G| >= |J| ulp(x) there). */
        if (!polishing && inf_norm2(dx) <= 2.0 * DBL_EPSILON * inf_norm2(x)) {
            fn_final(G, m, eps, w, x, st);
            return SUSLOV_STEP_OK;
        }
    }
}

int suslov_implicit_solve(suslov_residual_fn G, const suslov_model *m, double eps, const double w[3],
                          double w_next[3], suslov_step_stats *st)
{
    suslov_predict(m, eps, w, w_next);
    const int status = newton2_solve(G, m, eps, w, w_next, st);
    w_next[2] = 0.0;
    return status;
}
