/* The DSP steppers, the Newton solves, the driver and the unreduced integrator; the step
 * equations on the paper's body and on the seeded general bodies (tests/unit/bodies.h). */
#include "bodies.h"
#include "check.h"
#include "driver.h"
#include "newton.h"
#include "mat3.h"
#include "so3.h"
#include "registry.h"
#include "unreduced.h"
#include "dsp.h"

#include <gsl/gsl_errno.h>
#include <float.h>
#include <math.h>

/* (VSO3) written with a generic dcay^{-1} matrix D(eps w) (3x3), l~_d' = eps I w, and the
 * sign convention of (PartCase): DSP = D(-eps w)^T l~'(w) - D(eps x)^T l~'(x) - lambda e3.
 * Returns the first two components in g and the raw lambda solving the third. */
static double vso3(const sus_model *m, double eps, const double w[2], const double x[2],
                   int printed, double g[2])
{
    double Dw[3][3], Dx[3][3], pw[3], px[3];
    const double mw[2] = {-w[0], -w[1]}, ew[3] = {-eps * w[0], -eps * w[1], 0.0}, ex[3] = {eps * x[0],
        eps * x[1], 0.0};
    if (printed) {
        sus_so3_cayinver_printed(eps, mw, Dw);
        sus_so3_cayinver_printed(eps, x, Dx);
    } else {
        sus_so3_dcay_inv(ew, Dw);
        sus_so3_dcay_inv(ex, Dx);
    }
    for (int i = 0; i < 3; i++) {
        pw[i] = eps * (m->I[i][0] * w[0] + m->I[i][1] * w[1]);
        px[i] = eps * (m->I[i][0] * x[0] + m->I[i][1] * x[1]);
    }
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = Dw[0][i] * pw[0] + Dw[1][i] * pw[1] + Dw[2][i] * pw[2]
             - (Dx[0][i] * px[0] + Dx[1][i] * px[1] + Dx[2][i] * px[2]);
    g[0] = r[0];
    g[1] = r[1];
    return r[2];
}

/* A step equation whose Jacobian is singular everywhere: the (REGLOC) failure path. */
static void singular_residual(const sus_model *m, double eps, const double w[2], const double *x,
                              double *g, double *J, double *scale)
{
    (void)m;
    (void)eps;
    (void)w;
    g[0] = x[0] + x[1] - 1.0;
    g[1] = 2.0 * (x[0] + x[1]) - 3.0;
    J[0] = J[1] = 1.0;
    J[2] = J[3] = 2.0;
    *scale = fabs(x[0]) + fabs(x[1]) + 3.0;
}

typedef struct {
    long rows, last_k;
    double R0_defect;
} count_ctx;

static int count_rows(void *vctx, const sus_row *row)
{
    count_ctx *c = vctx;
    if (row->k == 0) {
        double I3[3][3];
        sus_mat3_identity(I3);
        c->R0_defect = sus_so3_dist(row->R, I3);
    }
    c->rows++;
    c->last_k = row->k;
    return 0;
}

/* Analytic Jacobians of every registered 2x2 implicit step equation against central differences. */
static void jacobians(const sus_model *m, const char *bname)
{
    enum { NX = SUS_MAX_UNKNOWNS };
    for (int s = 0; s < sus_step_method_count(); s++) {
        const sus_stepper_type *st = sus_step_method_get(s)->type;
        const int n = st->unknowns;
        if (!st->residual)
            continue;
        double worst = 0.0;
        for (int k = 0; k < 30; k++) {
            const double a = 0.37 * k, eps = 0.05 * (1 + k % 7), h = 1e-6;
            const double w[2] = {0.6 * cos(a), 0.5 * sin(a)},
                         w1[2] = {0.6 * cos(a + 0.1), 0.5 * sin(a + 0.1)};
            double x[NX], g[NX], J[NX * NX], sc;
            st->guess(m, eps, w, x);
            for (int i = 0; i < n; i++)
                x[i] += 0.1 * w1[i % 2]; /* off the root */
            st->residual(m, eps, w, x, g, J, &sc);
            for (int j = 0; j < n; j++) {
                double xp[NX], xm[NX], gp[NX], gm[NX], Jt[NX * NX];
                for (int i = 0; i < n; i++)
                    xp[i] = xm[i] = x[i];
                xp[j] += h;
                xm[j] -= h;
                st->residual(m, eps, w, xp, gp, Jt, &sc);
                st->residual(m, eps, w, xm, gm, Jt, &sc);
                for (int i = 0; i < n; i++)
                    worst = fmax(worst, fabs((gp[i] - gm[i]) / (2.0 * h) - J[i * n + j]));
            }
        }
        /* G is a cubic polynomial: central differences err by O(h^2) ~ 1e-12 plus u/h ~ 1e-10 */
        CHECK(worst < 1e-8,
              "%s, %s: analytic Jacobian of the step equation = central differences; worst %.2e", bname,
              st->name, worst);
    }
}

/* Each step solves its equation to round-off in a few Newton iterations at small eps. */
static void newton_solves(const sus_model *m, const char *bname, const double w0[2])
{
    enum { NX = SUS_MAX_UNKNOWNS };
    for (int s = 0; s < sus_step_method_count(); s++) {
        const sus_stepper_type *st = sus_step_method_get(s)->type;
        if (!st->residual)
            continue;
        const double w[3] = {w0[0], w0[1], 0.0};
        double x[NX], g[NX], J[NX * NX], sc, wn[3], wr[2], lam;
        sus_stepper_stats stats, ss;
        const int status = st->apply(m, 0.01, w, wn, &lam, &stats);
        st->guess(m, 0.01, w, x);
        const int s2 = sus_step_newton_solve(st->residual, st->unknowns, m, 0.01, w, x, &ss);
        st->residual(m, 0.01, w, x, g, J, &sc);
        st->result(m, 0.01, w, x, wr);
        double gmax = 0.0;
        for (int i = 0; i < st->unknowns; i++)
            gmax = fmax(gmax, fabs(g[i]));
        CHECK(status == SUS_STEPPER_OK && s2 == SUS_STEPPER_OK && gmax <= 16 * SUS_U * sc &&
                  stats.iterations <= 4 && wn[2] == 0.0 && wr[0] == wn[0] && wr[1] == wn[1],
              "%s, %s: eps = 0.01 step solved to |G| = %.1e (scale %.2f) in %d Newton iterations, w3 = 0",
              bname, st->name, gmax, sc, stats.iterations);
    }
}

/* (taudyn) and (taualg) are (VSO3) with (cayinver) as printed, after lambda -> -lambda/eps^2;
 * with the exact dcay^{-1} the multiplier gains (c(x) - c(w))/eps. */
static void variational_is_vso3(const sus_model *m, const char *bname, const double w0[2])
{
    double worst_dyn = 0.0, worst_alg = 0.0, worst_full = 0.0;
    for (int n = 0; n < 20; n++) {
        const double eps = 0.1 + 0.2 * n, w[3] = {w0[0] - 0.03 * n, w0[1], 0.0};
        double x[3], lam, g[2], gd[2], J[4], sc;
        sus_stepper_stats stats;
        if (sus_step_variational->apply(m, eps, w, x, &lam, &stats) != SUS_STEPPER_OK)
            continue; /* a large step may have no solution: nothing to compare */
        const double raw = vso3(m, eps, w, x, 1, g);
        sus_step_variational->residual(m, eps, w, x, gd, J, &sc);
        /* relative to the size of the terms summed (the residual's scale): two orders of summation */
        worst_dyn = fmax(worst_dyn, (fabs(g[0] + eps * gd[0]) + fabs(g[1] + eps * gd[1])) / (eps * sc));
        worst_alg = fmax(worst_alg, fabs(-raw / (eps * eps) - lam));
        const double raw_full = vso3(m, eps, w, x, 0, g);
        worst_full = fmax(worst_full, fabs(-raw_full / (eps * eps) - (lam + (sus_c(m, x) - sus_c(m,
            w)) / eps)));
    }
    CHECK(worst_dyn < 32 * DBL_EPSILON, "%s: (taudyn) = -1/eps x first rows of (VSO3) with "
                                                  "(cayinver) "
          "as printed; worst relative to the terms' size %.2e (<= 32 u)",
          bname, worst_dyn);
    CHECK(worst_alg < 1e-13, "%s: (taualg) = -1/eps^2 x third row of (VSO3) with (cayinver) as printed; "
                             "worst %.2e",
          bname, worst_alg);
    CHECK(worst_full < 1e-13, "%s: with the exact dcay^{-1} ((3,3) = 1) the multiplier is (taualg) + (c(x) "
                              "- c(w))/eps; "
          "worst %.2e", bname, worst_full);
}

/* The midpoint DSP conserves E exactly in exact arithmetic: E(x) - E(w) = eps <f(mid), I_m mid> = 0. */
static void midpoint_energy(const sus_model *m, const char *bname, const double w0[2])
{
    double w[3] = {w0[0], w0[1], 0.0}, x[3], lam, dE = 0.0;
    sus_stepper_stats stats;
    for (int k = 0; k < 100; k++) {
        sus_step_midpoint->apply(m, 0.7, w, x, &lam, &stats);
        dE = fmax(dE, fabs(sus_energy(m, x) - sus_energy(m, w)));
        w[0] = x[0];
        w[1] = x[1];
    }
    /* E < 1.5 on the family: a few roundings of it */
    CHECK(dE < 1e-15 * fmax(1.0, sus_energy(m, w0)),
          "%s: midpoint DSP: |E(w^{k+1}) - E(w^k)| <= %.1e over 100 steps of eps = 0.7 (round-off)", bname,
              dE);
}

/* The unreduced integrator: its inverse inertia is right (entries below 2.5, condition < 20). */
static void unreduced_inverse(const sus_model *m, const char *bname)
{
    char err[256];
    sus_unreduced u;
    double P[3][3], I3[3][3];
    sus_unreduced_init(&u, m, err, sizeof err);
    sus_mat3_mul(P, u.Iinv, m->I);
    sus_mat3_identity(I3);
    CHECK(sus_so3_dist(P, I3) < 1e-14, "%s: unreduced: I^{-1} I = Id to %.1e", bname, sus_so3_dist(P, I3));
}

/* The driver: rows 0, K, 2K, ... and always the last one; R_0 = I; a failing step is reported. */
static void driver(const sus_model *m)
{
    const sus_run_config cfg = {m, sus_step_rk4, SUS_RECON_CAYLEY, 0.1, 1003, 100};
    count_ctx cc = {0, -1, 1.0};
    sus_run_report rep;
    const double w0[2] = {0.4, 0.5};
    const int rc = sus_run(&cfg, w0, count_rows, &cc, &rep);
    CHECK(rc == 0 && cc.rows == 12 && cc.last_k == 1003 && cc.R0_defect == 0.0,
          "driver: N = 1003, K = 100 gives %ld rows (0, 100, ..., 1000, 1003), R_0 = I", cc.rows);

    /* A failing step is reported with its index and time, never accepted: the 2-stage Gauss
     * step from this w0 meets a fold of its branch at h = eps k ~ 3.6 (src/exp/stability.h). */
    const double w_fold[2] = {0.27619224, -0.63956748};
    const sus_run_config bad = {m, sus_step_method_by_name("gauss4")->type, SUS_RECON_CAYLEY, 1000.0, 10, 1};
    count_ctx cb = {0, -1, 1.0};
    const int rb = sus_run(&bad, w_fold, count_rows, &cb, &rep);
    CHECK(rb == 1 && rep.status == SUS_STEPPER_SINGULAR && rep.step == 1 && rep.t == 1000.0 && cb.rows == 1,
          "gauss4, w0 = (0.276, -0.640), eps = 1000: step %ld (t = %g) reported as failed (status %d, a fold "
          "%d), only row 0 emitted",
          rep.step, rep.t, rep.status, SUS_STEPPER_SINGULAR);

    /* A singular (REGLOC) block is reported as such, not iterated on. */
    double x[2] = {0.3, 0.3};
    sus_stepper_stats stats;
    const double w[2] = {0.0, 0.0};
    const int status = sus_step_newton_solve(singular_residual, 2, m, 0.1, w, x, &stats);
    CHECK(status == SUS_STEPPER_SINGULAR && stats.det == 0.0 && stats.iterations == 0,
          "Newton reports a singular (REGLOC) Jacobian (det %.1g) as SUS_STEPPER_SINGULAR", stats.det);
}

int main(void)
{
    gsl_set_error_handler_off();
    char err[256];
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (sus_model_init(&m, b.I, err, sizeof err) != 0) {
            fprintf(stderr, "test_steppers: %s: %s\n", b.name, err);
            return 1;
        }
        jacobians(&m, b.name);
        newton_solves(&m, b.name, b.w0);
        variational_is_vso3(&m, b.name, b.w0);
        midpoint_energy(&m, b.name, b.w0);
        unreduced_inverse(&m, b.name);
        if (k == 0)
            driver(&m);
    }
    return check_summary("test_steppers");
}
