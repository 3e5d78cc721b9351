#include "peers.h"

#include "mat3.h"
#include "quaternion.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <string.h>

int sus_lab_peer_rhs_wR(double t, const double y[], double f[], void *params)
{
    (void)t;
    double W[3][3];
    const double w[3] = {y[0], y[1], 0.0};
    sus_contdyn(params, y, f);
    sus_so3_hat(w, W);
    sus_mat3_mul(*(double(*)[3][3])(f + 2), *(const double(*)[3][3])(y + 2), W);
    return GSL_SUCCESS;
}

int sus_lab_peer_rhs_wq(double t, const double y[], double f[], void *params)
{
    (void)t;
    const double w[3] = {y[0], y[1], 0.0};
    double dq[4];
    sus_contdyn(params, y, f);
    sus_quat_mul_pure(dq, y + 2, w);
    for (int i = 0; i < 4; i++)
        f[2 + i] = 0.5 * dq[i];
    return GSL_SUCCESS;
}

int sus_lab_peer_rhs_w(double t, const double y[], double f[], void *params)
{
    (void)t;
    sus_contdyn(params, y, f);
    return GSL_SUCCESS;
}

void sus_lab_peer_initial(size_t dim, const double w0[2], double *y)
{
    memset(y, 0, dim * sizeof *y);
    if (dim == 4) { /* the reduced problem: q alone */
        y[0] = 1.0;
        return;
    }
    y[0] = w0[0];
    y[1] = w0[1];
    if (dim == 11)
        y[2] = y[6] = y[10] = 1.0;
    else if (dim == 6)
        y[2] = 1.0;
}

void sus_lab_peer_attitude(size_t dim, const double *y, double R[3][3])
{
    if (dim == 11)
        memcpy(R, y + 2, 9 * sizeof(double));
    else
        sus_quat_rotation(dim == 4 ? y : y + 2, R);
}

/* p's driver, or its step, control and evolve objects, for the system p->sys. */
static int peer_alloc(sus_lab_peer *p)
{
    if (p->api == SUS_LAB_PEER_DRIVER) {
        p->d = gsl_odeiv2_driver_alloc_y_new(&p->sys, p->type, p->hstart, p->tol, p->rel);
        if (p->d)
            gsl_odeiv2_driver_set_nmax(p->d, SUS_LAB_PEER_MAX_STEPS);
        return p->d ? 0 : -1;
    }
    p->s = gsl_odeiv2_step_alloc(p->type, p->dim);
    p->c = gsl_odeiv2_control_y_new(p->tol, p->rel);
    p->e = gsl_odeiv2_evolve_alloc(p->dim);
    if (p->s && p->c && p->e)
        return 0;
    sus_lab_peer_close(p);
    return -1;
}

int sus_lab_peer_open(sus_lab_peer *p, const sus_model *m, const gsl_odeiv2_step_type *type,
                      size_t dim, sus_lab_peer_api api, double tol, double rel, double hstart)
{
    *p = (sus_lab_peer){
        .type = type, .api = api, .dim = dim, .tol = tol, .rel = rel, .hstart = hstart};
    int (*rhs)(double, const double[], double[], void *) = dim == 11  ? sus_lab_peer_rhs_wR
                                                           : dim == 6 ? sus_lab_peer_rhs_wq
                                                                      : sus_lab_peer_rhs_w;
    p->sys = (gsl_odeiv2_system){rhs, NULL, dim, (void *)m};
    return peer_alloc(p);
}

int sus_lab_peer_open_reduced(sus_lab_peer *p, const sus_exact_fast *r,
                              const gsl_odeiv2_step_type *type, sus_lab_peer_api api, double tol,
                              double rel, double hstart)
{
    *p = (sus_lab_peer){
        .type = type, .api = api, .dim = 4, .tol = tol, .rel = rel, .hstart = hstart};
    p->sys = (gsl_odeiv2_system){sus_lab_reduced_rhs, NULL, 4, (void *)r};
    return peer_alloc(p);
}

static int evolve_run(sus_lab_peer *p, double T, double *y, long *steps)
{
    double t = 0.0, h = p->hstart;
    gsl_odeiv2_evolve_reset(p->e);
    gsl_odeiv2_step_reset(p->s);
    int status = GSL_SUCCESS;
    while (t < T && status == GSL_SUCCESS)
        status = p->e->count < SUS_LAB_PEER_MAX_STEPS
                     ? gsl_odeiv2_evolve_apply(p->e, p->c, p->s, &p->sys, &t, T, &h, y)
                     : GSL_EMAXITER;
    *steps = (long)p->e->count;
    return status;
}

int sus_lab_peer_run(sus_lab_peer *p, const double w0[2], double T, double *y, long *steps)
{
    sus_lab_peer_initial(p->dim, w0, y);
    if (p->api == SUS_LAB_PEER_EVOLVE)
        return evolve_run(p, T, y, steps);
    double t = 0.0;
    gsl_odeiv2_driver_reset_hstart(p->d, p->hstart); /* resets the evolve and step objects too */
    const int status = gsl_odeiv2_driver_apply(p->d, &t, T, y);
    *steps = (long)p->d->e->count;
    return status;
}

void sus_lab_peer_close(sus_lab_peer *p)
{
    if (p->d)
        gsl_odeiv2_driver_free(p->d);
    if (p->e)
        gsl_odeiv2_evolve_free(p->e);
    if (p->c)
        gsl_odeiv2_control_free(p->c);
    if (p->s)
        gsl_odeiv2_step_free(p->s);
    *p = (sus_lab_peer){0};
}
