#include "peers.h"

#include "mat3.h"
#include "quaternion.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <string.h>

int suslov_peer_rhs_wR(double t, const double y[], double f[], void *params)
{
    (void)t;
    double W[3][3];
    const double w[3] = {y[0], y[1], 0.0};
    suslov_contdyn(params, y, f);
    so3_hat(w, W);
    mat3_mul(*(double(*)[3][3])(f + 2), *(const double(*)[3][3])(y + 2), W);
    return GSL_SUCCESS;
}

int suslov_peer_rhs_wq(double t, const double y[], double f[], void *params)
{
    (void)t;
    const double w[3] = {y[0], y[1], 0.0};
    double dq[4];
    suslov_contdyn(params, y, f);
    quat_mul_pure(dq, y + 2, w);
    for (int i = 0; i < 4; i++)
        f[2 + i] = 0.5 * dq[i];
    return GSL_SUCCESS;
}

int suslov_peer_rhs_w(double t, const double y[], double f[], void *params)
{
    (void)t;
    suslov_contdyn(params, y, f);
    return GSL_SUCCESS;
}

void suslov_peer_initial(size_t dim, const double w0[2], double *y)
{
    memset(y, 0, dim * sizeof *y);
    y[0] = w0[0];
    y[1] = w0[1];
    if (dim == 11)
        y[2] = y[6] = y[10] = 1.0;
    else if (dim == 6)
        y[2] = 1.0;
}

void suslov_peer_attitude(size_t dim, const double *y, double R[3][3])
{
    if (dim == 11)
        memcpy(R, y + 2, 9 * sizeof(double));
    else
        quat_rotation(y + 2, R);
}
