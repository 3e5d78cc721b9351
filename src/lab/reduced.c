#include "reduced.h"

#include "quaternion.h"

#include <gsl/gsl_errno.h>

int sus_lab_reduced_init(sus_lab_reduced *r, const sus_exact *ex)
{
    *r = (sus_lab_reduced){{{0.0, 0.0}, {0.0, 0.0}}, {NAN, NAN}, 0.0, 0.0};
    if (!ex || !ex->model)
        return -1;
    r->c[0] = r->c[1] = 0.0;
    if (ex->fixed) {
        r->c[0] = ex->w0[0];
        r->c[1] = ex->w0[1];
        return 0;
    }
    /* M = sigma L^{-T} r Rot(beta): the rows of w1 = u2 / l22 and w0 = (u1 - l21 w1) / l11 */
    const double a = ex->sigma * ex->r;
    r->M[1][0] = a * ex->sb / ex->l22;
    r->M[1][1] = a * ex->cb / ex->l22;
    r->M[0][0] = (a * ex->cb - ex->l21 * r->M[1][0]) / ex->l11;
    r->M[0][1] = (-a * ex->sb - ex->l21 * r->M[1][1]) / ex->l11;
    r->s0 = ex->s0;
    r->ks = ex->sigma * ex->k;
    return 0;
}

int sus_lab_reduced_rhs(double t, const double y[], double f[], void *params)
{
    double w[3] = {0.0, 0.0, 0.0}, p[4];
    sus_lab_reduced_omega(params, t, w);
    sus_quat_mul_pure(p, y, w);
    for (int i = 0; i < 4; i++)
        f[i] = 0.5 * p[i];
    return GSL_SUCCESS;
}
