/* The DSP steppers, the Newton solves, the driver and the unreduced integrator; the step
 * equations on the paper's body and on the seeded general bodies (tests/unit/bodies.h). */
#include "check_body.h"
#include "driver.h"
#include "implicit_step.h"
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
 * Returns the first two components in g and the raw lambda solving the third; *size is the sum of
 * the third component's |terms|, the yardstick of its rounding. */
static double vso3(const sus_model *m, double eps, const double w[2], const double x[2],
                   int printed, double g[2], double *size)
{
    double Dw[3][3], Dx[3][3], pw[3], px[3];
    const double mw[2] = {-w[0], -w[1]}, ew[3] = {-eps * w[0], -eps * w[1], 0.0},
                 ex[3] = {eps * x[0], eps * x[1], 0.0};
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
        r[i] = Dw[0][i] * pw[0] + Dw[1][i] * pw[1] + Dw[2][i] * pw[2] -
               (Dx[0][i] * px[0] + Dx[1][i] * px[1] + Dx[2][i] * px[2]);
    g[0] = r[0];
    g[1] = r[1];
    *size = 0.0;
    for (int j = 0; j < 3; j++)
        *size += fabs(Dw[j][2] * pw[j]) + fabs(Dx[j][2] * px[j]);
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

/* The body's scales: its time s (check_body_time: eps k as on the paper's body) and the size of its
 * w0 against the paper's 0.64, so that the sample states and steps sit where the paper's do. */
typedef struct {
    double time, size;
} body_scale;

/* x_i on the grid h 2^-40, so that x_i +- h and +- 2h are doubles (|x_i| < 2^12 h): exact steps. */
static void onto_grid(double *x, int n, double h)
{
    for (int i = 0; i < n; i++)
        x[i] = ldexp(nearbyint(ldexp(x[i] / h, 40)), -40) * h;
}

/* The fourth-order central difference of G's column j, (8 (G(x+h) - G(x-h)) - (G(x+2h) - G(x-2h)))
 * / 12h, is dG/dx_j exactly for a polynomial of degree <= 4 (the step equations are of degree 2 or
 * 3), at any h: only the roundings of G remain, at most SUS_STEP_NEWTON_RTOL = 16 u of the
 * residual's scale each (newton.h), so 18/12h of 16 u of the largest scale, and J's own roundings:
 * 32 u of the largest scale over h bounds both (h <= |x|, where J's terms are at most the scale
 * over |x|). Returns the worst |difference - J| over that bound. */
static double jacobian_column(const sus_stepper_type *st, const sus_model *m, double eps,
                              const double w[2], const double *x, const double *J, int j, double h)
{
    enum { NX = SUS_MAX_UNKNOWNS };
    const int n = st->equation->unknowns;
    static const double k[4] = {-2.0, -1.0, 1.0, 2.0}, c[4] = {1.0, -8.0, 8.0, -1.0};
    double d[NX] = {0}, scale = 0.0, worst = 0.0;
    for (int s = 0; s < 4; s++) {
        double xs[NX], g[NX], Jt[NX * NX], sc;
        for (int i = 0; i < n; i++)
            xs[i] = x[i];
        xs[j] += k[s] * h;
        st->equation->residual(m, eps, w, xs, g, Jt, &sc);
        scale = fmax(scale, sc);
        for (int i = 0; i < n; i++)
            d[i] += c[s] * g[i];
    }
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(d[i] / (12.0 * h) - J[i * n + j]) / (32.0 * SUS_U * scale / h));
    return worst;
}

/* Analytic Jacobians of every registered implicit step equation against exact differences, at 30
 * states around the body's ellipse and steps eps k as the paper's 0.05 ... 0.35 k_paper, off the
 * root. */
static void jacobians(const sus_model *m, const char *bname, body_scale bs)
{
    enum { NX = SUS_MAX_UNKNOWNS };
    for (int s = 0; s < sus_step_method_count(); s++) {
        const sus_stepper_type *st = sus_step_method_get(s)->type;
        if (!st->equation)
            continue;
        const int n = st->equation->unknowns;
        double worst = 0.0;
        for (int k = 0; k < 30; k++) {
            const double a = 0.37 * k, eps = 0.05 * (1 + k % 7) * bs.time, r = bs.size;
            const double w[2] = {0.6 * r * cos(a), 0.5 * r * sin(a)},
                         w1[2] = {0.6 * r * cos(a + 0.1), 0.5 * r * sin(a + 0.1)};
            double x[NX], g[NX], J[NX * NX], sc, big = 0.0;
            st->equation->guess(m, eps, w, x);
            for (int i = 0; i < n; i++) {
                x[i] += 0.1 * w1[i % 2]; /* off the root */
                big = fmax(big, fabs(x[i]));
            }
            const double h = ldexp(1.0, ilogb(big) - 2); /* a power of two, |x| / 8 .. |x| / 4 */
            onto_grid(x, n, h);
            st->equation->residual(m, eps, w, x, g, J, &sc);
            for (int j = 0; j < n; j++)
                worst = fmax(worst, jacobian_column(st, m, eps, w, x, J, j, h));
        }
        CHECK(
            worst <= 1.0,
            "%s, %s: analytic Jacobian of the step equation = exact differences; worst %.2g of the "
            "roundings' bound",
            bname, st->name, worst);
    }
}

/* Each step solves its equation to round-off in a few Newton iterations at small eps: eps k as
 * 0.01 k_paper (s the body's time). */
static void newton_solves(const sus_model *m, const char *bname, const double w0[2], double time)
{
    const double eps = 0.01 * time;
    enum { NX = SUS_MAX_UNKNOWNS };
    for (int s = 0; s < sus_step_method_count(); s++) {
        const sus_stepper_type *st = sus_step_method_get(s)->type;
        const sus_step_equation *eq = st->equation;
        if (!eq)
            continue;
        const double w[3] = {w0[0], w0[1], 0.0};
        double x[NX], g[NX], J[NX * NX], sc, wn[3], wr[2], lam;
        sus_stepper_stats stats, ss;
        const int status = st->step->apply(m, eps, w, wn, &lam, &stats);
        eq->guess(m, eps, w, x);
        const int s2 = sus_step_newton_solve(eq->residual, eq->unknowns, m, eps, w, x, &ss);
        eq->residual(m, eps, w, x, g, J, &sc);
        eq->result(m, eps, w, x, wr);
        double gmax = 0.0;
        for (int i = 0; i < eq->unknowns; i++)
            gmax = fmax(gmax, fabs(g[i]));
        CHECK(status == SUS_STEPPER_OK && s2 == SUS_STEPPER_OK && gmax <= 16 * SUS_U * sc &&
                  stats.iterations <= 4 && wn[2] == 0.0 && wr[0] == wn[0] && wr[1] == wn[1],
              "%s, %s: eps = 0.01 s = %.3g step solved to |G| = "
              "%.1e (scale %.2f) in %d Newton iterations, w3 = 0",
              bname, st->name, eps, gmax, sc, stats.iterations);
    }
}

/* The terms of (taualg) at (x, w): 1/2 (|x1| |I_2i x_i| + |x2| |I_1i x_i|) and the same at w. */
static double taualg_terms(const sus_model *m, const double x[2], const double w[2])
{
    const double(*I)[3] = m->I;
    double t = 0.0;
    for (int k = 0; k < 2; k++) {
        const double *y = k ? w : x;
        t += 0.5 * (fabs(y[0]) * (fabs(I[1][0] * y[0]) + fabs(I[1][1] * y[1])) +
                    fabs(y[1]) * (fabs(I[0][0] * y[0]) + fabs(I[0][1] * y[1])));
    }
    return t;
}

/* (taudyn) and (taualg) are (VSO3) with (cayinver) as printed, after lambda -> -lambda/eps^2;
 * with the exact dcay^{-1} the multiplier gains (c(x) - c(w))/eps. Steps eps k as the paper's 0.1
 * ... 3.9 k_paper (s the body's time). Each side is a sum of a few dozen roundings of its terms:
 * the third row's over eps^2, (taualg)'s, and c's over eps for the exact form: 32 u of their sum.
 */
static void variational_is_vso3(const sus_model *m, const char *bname, const double w0[2],
                                double time)
{
    double worst_dyn = 0.0, worst_alg = 0.0, worst_full = 0.0;
    int ran = 0;
    for (int n = 0; n < 20; n++) {
        const double eps = (0.1 + 0.2 * n) * time, w[3] = {w0[0] - 0.03 * n, w0[1], 0.0};
        double x[3], lam, g[2], gd[2], J[4], sc, size, size_full;
        sus_stepper_stats stats;
        if (sus_step_variational->step->apply(m, eps, w, x, &lam, &stats) != SUS_STEPPER_OK)
            continue; /* a large step may have no solution: nothing to compare */
        ran++;
        const double raw = vso3(m, eps, w, x, 1, g, &size);
        sus_step_variational->equation->residual(m, eps, w, x, gd, J, &sc);
        /* relative to the size of the terms summed (the residual's scale): two orders of summation
         */
        worst_dyn =
            fmax(worst_dyn, (fabs(g[0] + eps * gd[0]) + fabs(g[1] + eps * gd[1])) / (eps * sc));
        const double ta = taualg_terms(m, x, w);
        worst_alg = fmax(worst_alg, fabs(-raw / (eps * eps) - lam) / (size / (eps * eps) + ta));
        const double raw_full = vso3(m, eps, w, x, 0, g, &size_full);
        const double ca = fabs(m->b[0] * x[0]) + fabs(m->b[1] * x[1]) + fabs(m->b[0] * w[0]) +
                          fabs(m->b[1] * w[1]);
        const double full = lam + (sus_c(m, x) - sus_c(m, w)) / eps;
        const double yard = size_full / (eps * eps) + ta + ca / eps;
        worst_full = fmax(worst_full, fabs(-raw_full / (eps * eps) - full) / yard);
    }
    CHECK(ran > 0 && worst_dyn < 32 * DBL_EPSILON,
          "%s: (taudyn) = -1/eps x first rows of (VSO3) with "
          "(cayinver) as printed, %d of 20 steps; worst relative to the terms' size %.2e (<= 32 u)",
          bname, ran, worst_dyn);
    CHECK(ran > 0 && worst_alg < 32 * DBL_EPSILON,
          "%s: (taualg) = -1/eps^2 x third row of (VSO3) with "
          "(cayinver) as printed; worst relative to the terms' size %.2e (<= 32 u)",
          bname, worst_alg);
    CHECK(ran > 0 && worst_full < 32 * DBL_EPSILON,
          "%s: with the exact dcay^{-1} ((3,3) = 1) the multiplier "
          "is (taualg) + (c(x) - c(w))/eps; worst relative to the terms' size %.2e (<= 32 u)",
          bname, worst_full);
}

/* 1/2 (|I11| w1^2 + |I12 + I21| |w1 w2| + |I22| w2^2): the terms of E(w). */
static double energy_terms(const sus_model *m, const double w[2])
{
    const double(*I)[3] = m->I;
    return 0.5 * (fabs(I[0][0]) * w[0] * w[0] + fabs(I[0][1] + I[1][0]) * fabs(w[0] * w[1]) +
                  fabs(I[1][1]) * w[1] * w[1]);
}

/* The midpoint DSP conserves E exactly in exact arithmetic: with G = I_m (x - w) - eps l(mid) and
 * <l(mid), mid> = 0, E(x) - E(w) = <G, mid>. So a step changes E by at most |mid|_1 times its true
 * residual, the residual Newton reports plus the rounding of G (2 u of its scale, and of eps |mid|
 * |c|'s terms, which the scale leaves out where c(mid) cancels), and each E is computed to 2 u of
 * its terms. 100 steps of eps k = 0.07 k_paper (s the body's time). */
static void midpoint_energy(const sus_model *m, const char *bname, const double w0[2], double time)
{
    const double eps = 0.7 * time, u = SUS_U;
    double w[3] = {w0[0], w0[1], 0.0}, x[3], lam, worst = 0.0, dE = 0.0;
    sus_stepper_stats st;
    int ok = 1;
    for (int k = 0; k < 100; k++) {
        ok &= sus_step_midpoint->step->apply(m, eps, w, x, &lam, &st) == SUS_STEPPER_OK;
        const double mid[2] = {0.5 * (x[0] + w[0]), 0.5 * (x[1] + w[1])};
        const double ca = fabs(m->b[0] * mid[0]) + fabs(m->b[1] * mid[1]);
        const double n1 = fabs(mid[0]) + fabs(mid[1]),
                     d = fabs(sus_energy(m, x) - sus_energy(m, w));
        const double bound = n1 * (st.residual + 2 * u * (st.scale + eps * n1 * ca)) +
                             2 * u * (energy_terms(m, x) + energy_terms(m, w));
        worst = fmax(worst, d / bound);
        dE = fmax(dE, d);
        w[0] = x[0];
        w[1] = x[1];
    }
    CHECK(ok && worst <= 1.0,
          "%s: midpoint DSP: |E(w^{k+1}) - E(w^k)| <= %.1e over 100 steps of eps = "
          "0.7 s = %.3g: %.2g of the residual's and E's roundings",
          bname, dE, eps, worst);
}

/* The unreduced integrator: its inverse inertia by cofactors over det I. With X^ = the cofactors'
 * |terms| / |det I|, each cofactor rounds u of its terms and the division u/2, det I (expanded
 * along row 1) 2 u of |A_1j| X^_j1 |det I|, and the product I^{-1} I u of |I^{-1}| |I|: to first
 * order |I^{-1} I - Id|_F <= u (3 |X^ |I||_F + 2 sqrt3 (|I| X^)_11); 4 for 2 sqrt3 covers the
 * second. */
static void unreduced_inverse(const sus_model *m, const char *bname)
{
    char err[256];
    sus_unreduced un;
    double P[3][3], I3[3][3], X[3][3], XA = 0.0, AX = 0.0;
    const double(*A)[3] = m->I;
    sus_unreduced_init(&un, m, err, sizeof err);
    sus_mat3_mul(P, un.Iinv, m->I);
    sus_mat3_identity(I3);
    const double det = fabs(sus_mat3_det(A));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            X[i][j] = (fabs(A[i1][j1] * A[i2][j2]) + fabs(A[i1][j2] * A[i2][j1])) / det;
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += X[i][k] * fabs(A[k][j]);
            XA += s * s;
        }
    for (int k = 0; k < 3; k++)
        AX += fabs(A[0][k]) * X[k][0];
    const double d = sus_so3_dist(P, I3), bound = SUS_U * (3.0 * sqrt(XA) + 4.0 * AX);
    CHECK(d <= bound, "%s: unreduced: I^{-1} I = Id to %.1e (at most %.1e, its roundings)", bname,
          d, bound);
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
     * step from this w0 meets a fold of its branch at h = eps k ~ 3.6 (src/lab/stability.h). */
    const double w_fold[2] = {0.27619224, -0.63956748};
    const sus_run_config bad = {
        m, sus_step_method_by_name("gauss4")->type, SUS_RECON_CAYLEY, 1000.0, 10, 1};
    count_ctx cb = {0, -1, 1.0};
    const int rb = sus_run(&bad, w_fold, count_rows, &cb, &rep);
    CHECK(rb == 1 && rep.status == SUS_STEPPER_SINGULAR && rep.step == 1 && rep.t == 1000.0 &&
              cb.rows == 1,
          "gauss4, w0 = (0.276, -0.640), eps = 1000: step %ld (t = %g) reported "
          "as failed (status %d, a fold %d), only row 0 emitted",
          rep.step, rep.t, rep.status, SUS_STEPPER_SINGULAR);

    /* A singular (REGLOC) block is reported as such, not iterated on. */
    double x[2] = {0.3, 0.3};
    sus_stepper_stats stats;
    const double w[2] = {0.0, 0.0};
    const int status = sus_step_newton_solve(singular_residual, 2, m, 0.1, w, x, &stats);
    CHECK(status == SUS_STEPPER_SINGULAR && stats.det == 0.0 && stats.iterations == 0,
          "Newton reports a singular (REGLOC) Jacobian (det %.1g) as SUS_STEPPER_SINGULAR",
          stats.det);
}

/* The shared hooks of the implicit steps write NaN for a NULL input, nothing for a NULL output. */
static void hooks_null(const sus_model *m)
{
    const double w0[2] = {0.4, 0.5};
    double x[2] = {0, 0}, y[2] = {0, 0};
    sus_step_predict(NULL, 0.1, w0, x);
    sus_step_predict(m, 0.1, w0, NULL);
    sus_step_result_is_x(m, 0.1, w0, NULL, y);
    sus_step_result_is_x(m, 0.1, w0, x, NULL);
    CHECK(isnan(x[0]) && isnan(x[1]) && isnan(y[0]) && isnan(y[1]),
          "sus_step_predict(NULL model), sus_step_result_is_x(NULL x): NaN");
}

/* sus_step_end (stepper.h): the clock's end of a step, and NaN outside its contract. */
static void step_end_contract(void)
{
    CHECK(sus_step_end(0.0, 1.0, 2.0) == 1.0 && sus_step_end(0.0, INFINITY, 2.0) == 2.0 &&
              sus_step_end(1.5, 1.0, 2.0) == 2.0,
          "sus_step_end: t + h, or stop when h reaches it");
    const double bad[][3] = {{NAN, 1, 2}, {0, NAN, 2}, {0, 1, NAN}, {0, -1, 2},
                             {0, 0, 2},   {-5, 1, 2},  {2, 1, 2},   {3, 1, 2}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK(isnan(sus_step_end(bad[i][0], bad[i][1], bad[i][2])),
              "sus_step_end(%g, %g, %g): NaN, outside t >= 0, h > 0, t < stop", bad[i][0],
              bad[i][1], bad[i][2]);
}

int main(void)
{
    gsl_set_error_handler_off();
    step_end_contract();
    char err[256];
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        if (sus_model_init(&m, b.I, err, sizeof err) != 0) {
            fprintf(stderr, "test_steppers: %s: %s\n", b.name, err);
            return 1;
        }
        const body_scale bs = {check_body_time(&m, b.w0), hypot(b.w0[0], b.w0[1]) / 0.64};
        jacobians(&m, b.name, bs);
        newton_solves(&m, b.name, b.w0, bs.time);
        variational_is_vso3(&m, b.name, b.w0, bs.time);
        midpoint_energy(&m, b.name, b.w0, bs.time);
        unreduced_inverse(&m, b.name);
        if (k == 0) {
            driver(&m);
            hooks_null(&m);
        }
    }
    return check_summary("test_steppers");
}
