#include "reduced.h"

#include "quaternion.h"

#include <gsl/gsl_errno.h>

int sus_lab_reduced_rhs(double t, const double y[], double f[], void *params)
{
    double w[3] = {0.0, 0.0, 0.0}, p[4];
    sus_exact_fast_omega(params, t, w);
    sus_quat_mul_pure(p, y, w);
    for (int i = 0; i < 4; i++)
        f[i] = 0.5 * p[i];
    return GSL_SUCCESS;
}
