#include "perturbation.h"

#include "exact.h"
#include "mat3.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

int sus_lab_perturb_init(sus_lab_perturb *P, const sus_model *m, const sus_stepper_type *st,
                         double eps)
{
    memset(P, 0, sizeof *P);
    P->m = m;
    P->st = st;
    P->eps = eps;
    return sus_mat3_inverse(m->I, P->Iinv);
}

/* The standard C^infinity step: psi(u) = exp(-1/u) for u > 0, chi = psi(v) / (psi(v) + psi(1-v))
 * with v rescaled from [a, 1-a]; every derivative vanishes where chi is 0 or 1. */
double sus_lab_perturb_chi(double s, double *dchi)
{
    const double a = SUS_LAB_PERTURB_FLAT, v = (s - a) / (1.0 - 2.0 * a);
    *dchi = 0.0;
    if (v <= 0.0)
        return 0.0;
    if (v >= 1.0)
        return 1.0;
    const double A = exp(-1.0 / v), B = exp(-1.0 / (1.0 - v));
    const double Ap = A / (v * v), Bp = B / ((1.0 - v) * (1.0 - v));
    *dchi = (Ap * B + A * Bp) / ((A + B) * (A + B)) / (1.0 - 2.0 * a);
    return A / (A + B);
}

/* F(t, x): the exact flow of (ContDyn), any sign of t. */
static void flow(const sus_model *m, double t, const double x[2], double y[2])
{
    sus_exact ex;
    sus_exact_init(&ex, m, x);
    sus_exact_omega(&ex, t, y);
}

/* (TheoPer): the blend of the forward flow from x0 and the backward flow from x1 = phi(eps, x0). */
void sus_lab_perturb_curve(const sus_lab_perturb *P, double t, const double x0[2],
                           const double x1[2], double X[2], double Xdot[2])
{
    double dchi, A[2], B[2], fA[2], fB[2];
    const double chi = sus_lab_perturb_chi(t / P->eps, &dchi);
    flow(P->m, t, x0, A);
    flow(P->m, t - P->eps, x1, B);
    sus_contdyn(P->m, A, fA);
    sus_contdyn(P->m, B, fB);
    for (int i = 0; i < 2; i++) {
        X[i] = (1.0 - chi) * A[i] + chi * B[i];
        Xdot[i] = (1.0 - chi) * fA[i] + chi * fB[i] + dchi / P->eps * (B[i] - A[i]);
    }
}

static int phi(const sus_lab_perturb *P, const double x0[2], double x1[2])
{
    double w[3] = {x0[0], x0[1], 0.0}, wn[3], lam;
    sus_stepper_stats st;
    if (P->st->step->apply(P->m, P->eps, w, wn, &lam, &st) != SUS_STEPPER_OK)
        return SUS_LAB_PERTURB_STEP_FAILED;
    x1[0] = wn[0];
    x1[1] = wn[1];
    return SUS_LAB_PERTURB_OK;
}

/* r = X(t; x0) - x and Xdot. */
static int blend_residual(const sus_lab_perturb *P, double t, const double x0[2], const double x[2],
                          double r[2], double Xdot[2])
{
    double x1[2], X[2];
    const int s = phi(P, x0, x1);
    if (s != SUS_LAB_PERTURB_OK)
        return s;
    sus_lab_perturb_curve(P, t, x0, x1, X, Xdot);
    r[0] = X[0] - x[0];
    r[1] = X[1] - x[1];
    return SUS_LAB_PERTURB_OK;
}

/* The residual is evaluated to a few ulps of |x| (closed-form flow, one DSP step); 64 u |x|
 * is the round-off yardstick Newton must reach. */
#define NEWTON_TOL_U 64.0
#define SUS_STEP_NEWTON_MAXIT 12

/* (PerTh), through (Per1): eps^p d(eps, t/eps, x) = X'(t; x0) - h(x) with x0 from x = X(t; x0) by
 * Newton; the Jacobian dX/dx0 (close to dF(t)/dx0) by central differences. */
int sus_lab_perturb_field(sus_lab_perturb *P, double t, const double x[2], double g[2],
                          double x0_out[2])
{
    const double eps = P->eps, tau = t - eps * floor(t / eps);
    double dchi, x0[2], r[2], Xdot[2], f[2];
    const double chi = sus_lab_perturb_chi(tau / eps, &dchi);
    P->field_evals++;
    if (dchi == 0.0 && (chi == 0.0 || chi == 1.0)) {
        /* a flat end: X is an exact trajectory, the perturbation is 0 */
        g[0] = g[1] = 0.0;
        if (x0_out) {
            if (chi == 0.0)
                flow(P->m, -tau, x, x0_out);
            else
                x0_out[0] = x0_out[1] = NAN;
        }
        return SUS_LAB_PERTURB_OK;
    }
    flow(P->m, -tau, x, x0); /* exact when the perturbation is 0 */
    const double scale = fabs(x[0]) + fabs(x[1]), tol = NEWTON_TOL_U * SUS_U * scale;
    int it, s;
    double res = INFINITY;
    for (it = 0; it < SUS_STEP_NEWTON_MAXIT; it++) {
        if ((s = blend_residual(P, tau, x0, x, r, Xdot)) != SUS_LAB_PERTURB_OK)
            return s;
        res = fmax(fabs(r[0]), fabs(r[1]));
        if (res <= tol)
            break;
        double J[2][2];
        const double h = 1e-6 * fmax(scale, 1e-3);
        for (int j = 0; j < 2; j++) {
            double xp[2] = {x0[0], x0[1]}, xm[2] = {x0[0], x0[1]}, rp[2], rm[2], dd[2];
            xp[j] += h;
            xm[j] -= h;
            if ((s = blend_residual(P, tau, xp, x, rp, dd)) != SUS_LAB_PERTURB_OK ||
                (s = blend_residual(P, tau, xm, x, rm, dd)) != SUS_LAB_PERTURB_OK)
                return s;
            J[0][j] = (rp[0] - rm[0]) / (2.0 * h);
            J[1][j] = (rp[1] - rm[1]) / (2.0 * h);
        }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (!(fabs(det) > 0.0))
            return SUS_LAB_PERTURB_NEWTON_FAILED;
        x0[0] -= (J[1][1] * r[0] - J[0][1] * r[1]) / det;
        x0[1] -= (J[0][0] * r[1] - J[1][0] * r[0]) / det;
    }
    P->sus_lab_newton_its += it;
    P->sus_lab_newton_res = fmax(P->sus_lab_newton_res, res);
    if (!(res <= tol))
        return SUS_LAB_PERTURB_NEWTON_FAILED;
    sus_contdyn(P->m, x, f);
    g[0] = Xdot[0] - f[0];
    g[1] = Xdot[1] - f[1];
    if (x0_out) {
        x0_out[0] = x0[0];
        x0_out[1] = x0[1];
    }
    return SUS_LAB_PERTURB_OK;
}

/* ---- the period map, by rk8pd on the perturbed field ---- */

typedef struct {
    sus_lab_perturb *P;
    int status;
    double max_xi3, max_dlambda;
} ode_ctx;

/* The perturbed ODE (Eq2) of TheoPer: x' = h(x) + eps^p d(eps, t/eps, x). */
static int eq2_rhs(double t, const double y[], double dydt[], void *params)
{
    ode_ctx *c = params;
    double g[2], f[2];
    const int s = sus_lab_perturb_field(c->P, t, y, g, NULL);
    if (s != SUS_LAB_PERTURB_OK) {
        c->status = s;
        return GSL_EBADFUNC;
    }
    sus_contdyn(c->P->m, y, f);
    dydt[0] = f[0] + g[0];
    dydt[1] = f[1] + g[1];
    return GSL_SUCCESS;
}

static int integrate(gsl_odeiv2_system *sys, ode_ctx *c, double eps, double tol, double *y)
{
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(sys, gsl_odeiv2_step_rk8pd, 0.05 * eps, tol, tol);
    if (!d)
        return SUS_LAB_PERTURB_ODE_FAILED;
    double t = 0.0;
    c->P->sus_lab_newton_its = c->P->field_evals = 0;
    const int st = gsl_odeiv2_driver_apply(d, &t, eps, y);
    gsl_odeiv2_driver_free(d);
    if (c->status != SUS_LAB_PERTURB_OK)
        return c->status;
    return st == GSL_SUCCESS ? SUS_LAB_PERTURB_OK : SUS_LAB_PERTURB_ODE_FAILED;
}

/* (TheoPer): the period map of the perturbed equation from x0 (perturbation.h). */
int sus_lab_perturb_period_map(sus_lab_perturb *P, const double x0[2], double tol, double x_end[2])
{
    ode_ctx c = {P, SUS_LAB_PERTURB_OK, 0.0, 0.0};
    gsl_odeiv2_system sys = {eq2_rhs, NULL, 2, &c};
    double y[2] = {x0[0], x0[1]};
    const int s = integrate(&sys, &c, P->eps, tol, y);
    x_end[0] = y[0];
    x_end[1] = y[1];
    return s;
}

/* (TheoPer): the perturbed solution over one period from x0 (perturbation.h). */
int sus_lab_perturb_trajectory(sus_lab_perturb *P, const double x0[2], double tol, int n,
                               double (*x)[2])
{
    ode_ctx c = {P, SUS_LAB_PERTURB_OK, 0.0, 0.0};
    gsl_odeiv2_system sys = {eq2_rhs, NULL, 2, &c};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 0.05 * P->eps, tol, tol);
    if (!d)
        return SUS_LAB_PERTURB_ODE_FAILED;
    double y[2] = {x0[0], x0[1]}, t = 0.0;
    int st = GSL_SUCCESS;
    x[0][0] = y[0];
    x[0][1] = y[1];
    for (int i = 1; i <= n && st == GSL_SUCCESS; i++) {
        st = gsl_odeiv2_driver_apply(d, &t, P->eps * i / n, y);
        x[i][0] = y[0];
        x[i][1] = y[1];
    }
    gsl_odeiv2_driver_free(d);
    if (c.status != SUS_LAB_PERTURB_OK)
        return c.status;
    return st == GSL_SUCCESS ? SUS_LAB_PERTURB_OK : SUS_LAB_PERTURB_ODE_FAILED;
}

/* (PerFin2): I xi' = (I xi) x xi + lambda e3 + (I_m g, 0), lambda from <e3, xi'> = 0, i.e.
 * lambda = -<e3, I^{-1} q> / <e3, I^{-1} e3> with q the rest of the right-hand side (LagElim). */
static int perfin2_rhs(double t, const double y[], double dydt[], void *params)
{
    ode_ctx *c = params;
    const sus_lab_perturb *P = c->P;
    const double(*I)[3] = P->m->I;
    double g[2], Iw[3], q[3];
    const int s = sus_lab_perturb_field(c->P, t, y, g, NULL);
    if (s != SUS_LAB_PERTURB_OK) {
        c->status = s;
        return GSL_EBADFUNC;
    }
    sus_mat3_vec(Iw, I, y);
    sus_vec3_cross(q, Iw, y);
    q[0] += I[0][0] * g[0] + I[0][1] * g[1];
    q[1] += I[1][0] * g[0] + I[1][1] * g[1];
    const double lambda =
        -(P->Iinv[2][0] * q[0] + P->Iinv[2][1] * q[1] + P->Iinv[2][2] * q[2]) / P->Iinv[2][2];
    q[2] += lambda;
    sus_mat3_vec(dydt, P->Iinv, q);
    c->max_xi3 = fmax(c->max_xi3, fabs(y[2]));
    c->max_dlambda = fmax(c->max_dlambda, fabs(lambda - sus_lagmult(P->m, y)));
    return GSL_SUCCESS;
}

int sus_lab_perturb_perfin2(sus_lab_perturb *P, const double x0[2], double tol, double xi_end[3],
                            double *max_xi3, double *max_dlambda)
{
    ode_ctx c = {P, SUS_LAB_PERTURB_OK, 0.0, 0.0};
    gsl_odeiv2_system sys = {perfin2_rhs, NULL, 3, &c};
    double y[3] = {x0[0], x0[1], 0.0};
    const int s = integrate(&sys, &c, P->eps, tol, y);
    memcpy(xi_end, y, sizeof y);
    *max_xi3 = fmax(c.max_xi3, fabs(y[2]));
    *max_dlambda = c.max_dlambda;
    return s;
}

/* ---- sizes along one period ---- */

/* (TheoPer): the size of the perturbation over one period (perturbation.h). */
int sus_lab_perturb_sup_reduced(sus_lab_perturb *P, const double x0[2], int n, double *sup_g)
{
    double x1[2];
    const int s = phi(P, x0, x1);
    *sup_g = 0.0;
    if (s != SUS_LAB_PERTURB_OK)
        return s;
    for (int i = 0; i <= n; i++) {
        double X[2], Xd[2], f[2];
        sus_lab_perturb_curve(P, P->eps * i / n, x0, x1, X, Xd);
        sus_contdyn(P->m, X, f);
        *sup_g = fmax(*sup_g, hypot(Xd[0] - f[0], Xd[1] - f[1]));
    }
    return SUS_LAB_PERTURB_OK;
}

/* R' = R w^(t) along the closed-form w(t) from a given w. */
static int att_rhs(double t, const double y[], double dydt[], void *params)
{
    const sus_exact *ex = params;
    double w[3] = {0.0, 0.0, 0.0}, W[3][3];
    sus_exact_omega(ex, t, w);
    sus_so3_hat(w, W);
    sus_mat3_mul(*(double(*)[3][3])dydt, *(const double(*)[3][3])y, W);
    return GSL_SUCCESS;
}

/* log of a rotation near I: the axis-angle vector, angle from atan2 (accurate at small angles). */
static void so3_log(const double Q[3][3], double v[3])
{
    double a[3];
    sus_so3_vee(Q, a);
    const double sn = sus_vec3_norm(a), cs = 0.5 * (Q[0][0] + Q[1][1] + Q[2][2] - 1.0);
    const double th = atan2(sn, cs), f = sn > 0.0 ? th / sn : 1.0;
    for (int i = 0; i < 3; i++)
        v[i] = f * a[i];
}

#define SUP_MAXN 64
#define NFD 5 /* the stencil -2, -1, 0, 1, 2 (times the step hd) */

/* Attitudes along the exact flow from (R0, x) at the times t[i] (monotone), into R[i]. */
static int attitudes(const sus_model *m, const double R0[3][3], const double x[2], double t0,
                     const double *t, int n, double (*R)[3][3], double tol)
{
    sus_exact ex;
    sus_exact_init(&ex, m, x);
    gsl_odeiv2_system sys = {att_rhs, NULL, 9, &ex};
    const double h0 = n > 1 ? 0.5 * (t[1] - t[0]) : 1e-3;
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, h0, tol, tol);
    if (!d)
        return SUS_LAB_PERTURB_ODE_FAILED;
    double y[9], tt = t0;
    memcpy(y, R0, sizeof y);
    int st = GSL_SUCCESS;
    for (int i = 0; i < n && st == GSL_SUCCESS; i++) {
        if (t[i] != tt)
            st = gsl_odeiv2_driver_apply(d, &tt, t[i], y);
        memcpy(R[i], y, sizeof y);
    }
    gsl_odeiv2_driver_free(d);
    return st == GSL_SUCCESS ? SUS_LAB_PERTURB_OK : SUS_LAB_PERTURB_ODE_FAILED;
}

/* The sample times: n + 1 points spread over where chi is not flat, each with the stencil of NFD
 * points hd apart, into tA; the same times less eps into tB, descending (integrated backward
 * from 0). */
static void sample_times(double eps, int n, double hd, double *tA, double *tB)
{
    const double a = SUS_LAB_PERTURB_FLAT;
    const int np = (n + 1) * NFD;
    for (int i = 0; i <= n; i++)
        for (int k = 0; k < NFD; k++) {
            const double t = eps * (a + (1.0 - 2.0 * a) * i / n) + (k - 2) * hd;
            tA[i * NFD + k] = t;
            tB[np - 1 - (i * NFD + k)] = t - eps; /* descending: integrated backward from 0 */
        }
}

/* The method's step of (w, R) from (x0, I): R1 and x1 = w^1. */
static int method_step(const sus_lab_perturb *P, sus_recon recon, const double x0[2],
                       double R1[3][3], double x1[2])
{
    sus_attitude att;
    double w[3] = {x0[0], x0[1], 0.0}, wn[3], lam;
    sus_stepper_stats sst;
    sus_attitude_identity(&att);
    if (sus_stepper_full(P->st, P->m, P->eps, recon, &att, w, wn, &lam, &sst) != SUS_STEPPER_OK)
        return SUS_LAB_PERTURB_STEP_FAILED;
    sus_attitude_get(&att, R1);
    x1[0] = wn[0];
    x1[1] = wn[1];
    return SUS_LAB_PERTURB_OK;
}

/* The blend R_A exp(chi log(R_A^T R_B)) at the NFD stencil times of sample i, into Rk. */
static void blend(double eps, const double *tA, double (*RA)[3][3], double (*RB)[3][3], int i,
                  int np, double Rk[NFD][3][3])
{
    for (int k = 0; k < NFD; k++) {
        const int ia = i * NFD + k, ib = np - 1 - ia;
        double Q[3][3], L[3], E[3][3], dchi;
        const double chi = sus_lab_perturb_chi(tA[ia] / eps, &dchi);
        sus_mat3_mul_at(Q, RA[ia], RB[ib]);
        so3_log(Q, L);
        for (int j = 0; j < 3; j++)
            L[j] *= chi;
        sus_so3_exp(L, E);
        sus_mat3_mul(Rk[k], RA[ia], E);
    }
}

/* At the stencil's middle time t: the attitude perturbation vee(R^T R') - w, R' the central
 * difference with step hd, and the w perturbation |X' - f(X)|, each into its running sup. */
static void perturbation_at(const sus_lab_perturb *P, double t, const double x0[2],
                            const double x1[2], double Rk[NFD][3][3], double hd, double *sup_att,
                            double *sup_g)
{
    static const double cfd[NFD] = {1.0 / 12.0, -2.0 / 3.0, 0.0, 2.0 / 3.0, -1.0 / 12.0};
    double Rd[3][3] = {{0}}, P3[3][3], v[3], X[2], Xd[2], f[2];
    for (int k = 0; k < NFD; k++)
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                Rd[r][c] += cfd[k] * Rk[k][r][c] / hd;
    sus_mat3_mul_at(P3, Rk[2], Rd);
    double body[3];
    sus_so3_vee(P3, body);
    sus_lab_perturb_curve(P, t, x0, x1, X, Xd);
    v[0] = body[0] - X[0];
    v[1] = body[1] - X[1];
    v[2] = body[2];
    *sup_att = fmax(*sup_att, sus_vec3_norm(v));
    sus_contdyn(P->m, X, f);
    *sup_g = fmax(*sup_g, hypot(Xd[0] - f[0], Xd[1] - f[1]));
}

/* (Per11): the geodesic blend R = R_A exp(chi log(R_A^T R_B)) of the exact attitude from
 * (I, x0) and the exact one backward from the method's (R1, x1); its perturbation is
 * vee(R^T R') - w, with R' from a fourth-order central difference. Only the times where chi
 * is not flat are sampled: elsewhere R is an exact trajectory and the perturbation 0. */
int sus_lab_perturb_sup_so3(sus_lab_perturb *P, sus_recon recon, const double x0[2], int n,
                            double tol, double *sup_att, double *sup_g)
{
    double tA[(SUP_MAXN + 1) * NFD], tB[(SUP_MAXN + 1) * NFD];
    double RA[(SUP_MAXN + 1) * NFD][3][3], RB[(SUP_MAXN + 1) * NFD][3][3];
    if (n > SUP_MAXN)
        n = SUP_MAXN;
    /* the stencil spans a fifth of the sample spacing, so the times stay in order; its
     * truncation error hd^4 |R^(5)| / 30 is below 1e-9 of the perturbation at any eps <= 1 */
    const double eps = P->eps, a = SUS_LAB_PERTURB_FLAT, hd = 0.1 * (1.0 - 2.0 * a) * eps / n;
    const int np = (n + 1) * NFD;
    sample_times(eps, n, hd, tA, tB);
    double R1[3][3], I3[3][3], x1[2];
    int s = method_step(P, recon, x0, R1, x1);
    if (s != SUS_LAB_PERTURB_OK)
        return s;
    sus_mat3_identity(I3);
    if ((s = attitudes(P->m, I3, x0, 0.0, tA, np, RA, tol)) != SUS_LAB_PERTURB_OK ||
        (s = attitudes(P->m, R1, x1, 0.0, tB, np, RB, tol)) != SUS_LAB_PERTURB_OK)
        return s;
    *sup_att = *sup_g = 0.0;
    for (int i = 0; i <= n; i++) {
        double Rk[NFD][3][3];
        blend(eps, tA, RA, RB, i, np, Rk);
        perturbation_at(P, tA[i * NFD + 2], x0, x1, Rk, hd, sup_att, sup_g);
    }
    return SUS_LAB_PERTURB_OK;
}
