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

int suslov_peer_open(suslov_peer *p, const suslov_model *m, const gsl_odeiv2_step_type *type, size_t dim,
                     suslov_peer_api api, double tol, double hstart)
{
    *p = (suslov_peer){.type = type, .api = api, .dim = dim, .tol = tol, .hstart = hstart};
    int (*rhs)(double, const double[], double[], void *) = dim == 11 ? suslov_peer_rhs_wR
                                                         : dim == 6  ? suslov_peer_rhs_wq
                                                                     : suslov_peer_rhs_w;
    p->sys = (gsl_odeiv2_system){rhs, NULL, dim, (void *)m};
    if (api == SUSLOV_PEER_DRIVER) {
        p->d = gsl_odeiv2_driver_alloc_y_new(&p->sys, type, hstart, tol, tol);
        if (p->d)
            gsl_odeiv2_driver_set_nmax(p->d, SUSLOV_PEER_MAX_STEPS);
        return p->d ? 0 : -1;
    }
    p->s = gsl_odeiv2_step_alloc(type, dim);
    p->c = gsl_odeiv2_control_y_new(tol, tol);
    p->e = gsl_odeiv2_evolve_alloc(dim);
    if (p->s && p->c && p->e)
        return 0;
    suslov_peer_close(p);
    return -1;
}

static int evolve_run(suslov_peer *p, double T, double *y, long *steps)
{
    double t = 0.0, h = p->hstart;
    gsl_odeiv2_evolve_reset(p->e);
    gsl_odeiv2_step_reset(p->s);
    int status = GSL_SUCCESS;
    while (t < T && status == GSL_SUCCESS)
        status = p->e->count < SUSLOV_PEER_MAX_STEPS
                   ? gsl_odeiv2_evolve_apply(p->e, p->c, p->s, &p->sys, &t, T, &h, y)
                   : GSL_EMAXITER;
    *steps = (long)p->e->count;
    return status;
}

int suslov_peer_run(suslov_peer *p, const double w0[2], double T, double *y, long *steps)
{
    suslov_peer_initial(p->dim, w0, y);
    if (p->api == SUSLOV_PEER_EVOLVE)
        return evolve_run(p, T, y, steps);
    double t = 0.0;
    gsl_odeiv2_driver_reset_hstart(p->d, p->hstart); /* resets the evolve and step objects too */
    const int status = gsl_odeiv2_driver_apply(p->d, &t, T, y);
    *steps = (long)p->d->e->count;
    return status;
}

void suslov_peer_close(suslov_peer *p)
{
    if (p->d)
        gsl_odeiv2_driver_free(p->d);
    if (p->e)
        gsl_odeiv2_evolve_free(p->e);
    if (p->c)
        gsl_odeiv2_control_free(p->c);
    if (p->s)
        gsl_odeiv2_step_free(p->s);
    *p = (suslov_peer){0};
}
