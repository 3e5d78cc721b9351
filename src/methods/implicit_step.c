#include "implicit_step.h"

#include "newton_core.h"

#include <math.h>

int sus_step_implicit_solve(const sus_step_equation *eq, const sus_model *m, double eps,
                            const double w[3], double w_next[3], sus_stepper_stats *st)
{
    double x[SUS_MAX_UNKNOWNS];
    const int status =
        sus_step_newton_solve_branch(eq->residual, eq->guess, eq->unknowns, m, eps, w, x, st);
    eq->result(m, eps, w, x, w_next);
    w_next[2] = 0.0;
    return status;
}

int sus_step_branch_root(const sus_step_equation *eq, const sus_model *m, double eps,
                         const double w[2], double w_next[2])
{
    double root[SUS_MAX_UNKNOWNS];
    sus_stepper_stats s;
    const int rc =
        sus_step_newton_branch(eq->residual, eq->guess, eq->unknowns, m, eps, w, root, &s, NULL);
    if (rc == SUS_STEPPER_OK)
        eq->result(m, eps, w, root, w_next);
    return rc;
}

void sus_step_predict(const sus_model *m, double eps, const double w[2], double x[2])
{
    if (!x)
        return;
    if (!m || !w) {
        x[0] = x[1] = NAN;
        return;
    }
    newton_predict(m, eps, w, x);
}

void sus_step_result_is_x(const sus_model *m, double eps, const double w[2], const double *x,
                          double w_next[2])
{
    (void)m;
    (void)eps;
    (void)w;
    if (!w_next)
        return;
    if (!x) {
        w_next[0] = w_next[1] = NAN;
        return;
    }
    w_next[0] = x[0];
    w_next[1] = x[1];
}
