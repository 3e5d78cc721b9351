#include "refattitude.h"

#include "mat3.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <string.h>

/* R' = R w^(t), the continuous reconstruction equation, w(t) closed-form. */
static int refatt_rhs(double t, const double y[], double dydt[], void *params)
{
    const suslov_exact *ex = params;
    double w[3] = {0.0, 0.0, 0.0}, W[3][3];
    suslov_exact_omega(ex, t, w);
    so3_hat(w, W);
    mat3_mul(*(double(*)[3][3])dydt, *(const double(*)[3][3])y, W);
    return GSL_SUCCESS;
}

int suslov_refatt_init(suslov_refatt *ra, const suslov_exact *ex, double t0, const double R0[3][3],
                       double tol)
{
    ra->ex = ex;
    ra->sys = (gsl_odeiv2_system){refatt_rhs, NULL, 9, (void *)ex};
    ra->drv = gsl_odeiv2_driver_alloc_y_new(&ra->sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
    ra->t = t0;
    memcpy(ra->y, R0, sizeof ra->y);
    return ra->drv ? 0 : -1;
}

int suslov_refatt_advance(suslov_refatt *ra, double t1, double R[3][3])
{
    int status = GSL_SUCCESS;
    if (t1 > ra->t)
        status = gsl_odeiv2_driver_apply(ra->drv, &ra->t, t1, ra->y);
    memcpy(R, ra->y, sizeof ra->y);
    return status;
}

void suslov_refatt_free(suslov_refatt *ra)
{
    if (ra->drv)
        gsl_odeiv2_driver_free(ra->drv);
    ra->drv = NULL;
}

int suslov_refatt_increment(const suslov_exact *ex, double t0, double t1, double Phi[3][3])
{
    suslov_refatt ra;
    double I3[3][3];
    mat3_identity(I3);
    if (suslov_refatt_init(&ra, ex, t0, I3, SUSLOV_REFATT_TOL) != 0)
        return GSL_ENOMEM;
    const int status = suslov_refatt_advance(&ra, t1, Phi);
    suslov_refatt_free(&ra);
    return status;
}
