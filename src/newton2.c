#include "newton2.h"

#include <float.h>
#include <math.h>

static double inf_norm2(const double v[2])
{
    return fmax(fabs(v[0]), fabs(v[1]));
}

int newton2_solve(newton2_fn fn, const void *ctx, double x[2], suslov_step_stats *st)
{
    double g[2], J[2][2], scale = 0.0;
    int polished = 0;
    st->iterations = 0;
    st->det = NAN;
    for (;;) {
        fn(ctx, x, g, J, &scale);
        st->residual = inf_norm2(g);
        st->scale = scale;
        st->det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (!isfinite(st->residual) || !isfinite(scale))
            return SUSLOV_STEP_NO_CONVERGENCE;
        /* Once the residual is at round-off, one more correction takes x from "within the
         * tolerance" to the round-off floor; without it the tolerance, not round-off, sets a
         * bias that accumulates over many steps. */
        const int small = st->residual <= NEWTON2_RTOL * scale;
        if (small && polished)
            return SUSLOV_STEP_OK;
        polished = small;
        if (st->iterations == NEWTON2_MAXIT)
            return SUSLOV_STEP_NO_CONVERGENCE;
        /* (REGLOC): the step is defined only where this block is invertible; a determinant
         * below the round-off in its own two products is indistinguishable from zero. */
        if (fabs(st->det) <= 4.0 * DBL_EPSILON * (fabs(J[0][0] * J[1][1]) + fabs(J[0][1] * J[1][0])))
            return SUSLOV_STEP_SINGULAR;
        x[0] -= (J[1][1] * g[0] - J[0][1] * g[1]) / st->det;
        x[1] -= (J[0][0] * g[1] - J[1][0] * g[0]) / st->det;
        st->iterations++;
    }
}
