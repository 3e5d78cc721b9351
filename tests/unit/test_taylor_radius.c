/* A Taylor step never returns a wrong answer as a success: over a grid of steps up to 100 time
 * units, on the paper's body and on general ones, every Taylor method's step either refuses
 * (SUS_STEPPER_DIVERGED: beyond the radius 1/(K |w|) its series is proved to converge in) or
 * lands within its proved error bound of the closed-form w(eps) (src/core/exact.h, independent of
 * the series). The bound (step_taylor.c): the tail past degree p is at most |w| r^{p+1} / (1 - r),
 * r = K |w| eps; restoring E moves the sum by at most kappa times its distance to the ellipse
 * (kappa = the condition number of I_m) to first order, so (2 + kappa) tail bounds the error with
 * room for the second order; 1e-14 |w| covers the rounding of a sum of at most 17 terms of size
 * at most |w| (17 u |w|) and of the scaling. */
#include "check_body.h"
#include "check_exact.h"
#include "exact.h"
#include "taylor.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>

#define NGRID 60
#define EPS_MAX 100.0

static double condition(const sus_model *m)
{
    const double a = m->I[0][0], b = m->I[0][1], d = m->I[1][1];
    const double mid = 0.5 * (a + d), rad = hypot(0.5 * (a - d), b);
    return (mid + rad) / (mid - rad);
}

/* Returns the number of steps that ran (the others refused), or -1 at the first wrong answer. */
static int sweep(const sus_stepper_type *st, const sus_model *m, const double w0[2], double *worst)
{
    sus_exact ex;
    sus_exact_init(&ex, m, w0);
    const double w[3] = {w0[0], w0[1], 0.0}, a = hypot(w0[0], w0[1]), kappa = condition(m);
    int ran = 0;
    for (int i = 0; i < NGRID; i++) {
        const double eps =
            EPS_MAX * pow(10.0, -5.0 * (double)(NGRID - 1 - i) / (NGRID - 1)); /* 1e-3 ... 100 */
        double x[3], lam, ref[2];
        sus_stepper_stats stats;
        const int status = st->step->apply(m, eps, w, x, &lam, &stats);
        if (status == SUS_STEPPER_DIVERGED)
            continue;
        sus_exact_omega(&ex, eps, ref);
        const double err = hypot(x[0] - ref[0], x[1] - ref[1]);
        const double bound =
            (2.0 + kappa) * sus_step_taylor_tail_bound(st->desc.order, m, eps, w0) + 1e-14 * a;
        *worst = fmax(*worst, err / bound);
        /* no proof, no answer */
        if (status != SUS_STEPPER_OK || !isfinite(bound) || !(err <= bound))
            return -1;
        ran++;
    }
    return ran;
}

/* The proved radius is the blow-up time of the scalar majorant z' = K z^2 + 2 K z0 z + F, z(0) = 0,
 * with K = |b| ||fA||, 2 K z0 = |c(w)| ||fA|| + |b| |fA w|, F = |c(w)| |fA w| (step_taylor.c):
 * T = int_0^inf dz / (K z^2 + 2 K z0 z + F), here by GSL's quadrature on [0, inf) instead of the
 * closed form the step uses. */
static double majorant_integrand(double z, void *p)
{
    const double *k = p; /* K, 2 K z0, F */
    return 1.0 / ((k[0] * z + k[1]) * z + k[2]);
}

/* The majorant's coefficients K, 2 K z0 = L, F at w (step_taylor.c), from the model's norms. */
static void majorant_coeffs(const sus_model *m, const double w[2], double k[3])
{
    const double c = fabs(sus_c(m, w));
    const double nAw =
        hypot(m->fA[0][0] * w[0] + m->fA[0][1] * w[1], m->fA[1][0] * w[0] + m->fA[1][1] * w[1]);
    k[0] = m->norm_b * m->norm_fA;
    k[1] = c * m->norm_fA + m->norm_b * nAw;
    k[2] = c * nAw;
}

static double radius_by_quadrature(const sus_model *m, const double w[2])
{
    double k[3];
    majorant_coeffs(m, w, k);
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    gsl_function f = {majorant_integrand, k};
    double T = NAN, abserr;
    if (!ws || gsl_integration_qagiu(&f, 0.0, 0.0, 1e-11, 200, ws, &T, &abserr) != 0)
        T = NAN;
    gsl_integration_workspace_free(ws);
    return T;
}

/* Body k of the family and its model (a refused body is a failed check). */
static int family_model(int k, body *b, sus_model *m)
{
    body_get(k, b);
    return check_body_model(b, m);
}

/* State j = 0 .. 3 of a body: its w0 turned by atan(0.3 j) and scaled to 0.25 + j of its size and
 * more (the radius moves with both). */
static void turned_state(const body *b, int j, double w[2])
{
    const double s = 0.25 + j;
    w[0] = s * (b->w0[0] - 0.3 * j * b->w0[1]);
    w[1] = s * (b->w0[1] + 0.3 * j * b->w0[0]);
}

/* On every body of the family, at its w0 and at w0 turned and scaled: the step's radius equals
 * the quadrature's to 1e-8 (the quadrature's tolerance is 1e-11; the step rounds down by 1e-12). */
static void radius_against_quadrature(void)
{
    double worst = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        if (family_model(k, &b, &m) != 0)
            continue;
        for (int j = 0; j < 4; j++) {
            double w[2];
            turned_state(&b, j, w);
            const double r = sus_step_taylor_radius(&m, w), T = radius_by_quadrature(&m, w);
            const double d = fabs(r - T) / T;
            worst = d > worst || isnan(d) ? d : worst;
        }
    }
    CHECK(worst <= 1e-8,
          "the proved radius is the majorant's blow-up time by quadrature on %d bodies x 4 "
          "states: worst relative difference %.2g (at most 1e-8)",
          BODIES_COUNT, worst);
}

/* The radius is the majorant's blow-up time rounded down by the step's stated margin, 1e-12, and by
 * no more: against the closed form ln((z0 + b)/(z0 - b)) / (2 b K), b = sqrt(z0^2 - F/K), z0 =
 * L/(2K), evaluated in long double from the same coefficients, it lies in [1 - 1e-12 - 1e-13, 1]
 * times it (1e-13: a hundred times the rounding of the step's double formula, a few u). */
static void radius_rounded_down(void)
{
    int bad = 0, n = 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        if (family_model(k, &b, &m) != 0)
            continue;
        for (int j = 0; j < 4; j++, n++) {
            double w[2];
            turned_state(&b, j, w);
            double c[3];
            majorant_coeffs(&m, w, c);
            const long double K = c[0], z0 = c[1] / (2.0L * K), be = sqrtl(z0 * z0 - c[2] / K);
            const long double rho = logl((z0 + be) / (z0 - be)) / (2.0L * be * K);
            const double q = (double)(sus_step_taylor_radius(&m, w) / rho - 1.0L);
            lo = fmin(lo, q);
            hi = fmax(hi, q);
            bad += !(q <= 0.0 && q >= -1e-12 - 1e-13);
        }
    }
    CHECK(
        bad == 0 && n > 0,
        "the proved radius over the closed form in long double, minus 1, on %d states: "
        "in [%.3g, %.3g] (must lie in [-1e-12 - 1e-13, 0]: rounded down by the stated margin only)",
        n, lo, hi);
}

/* The tail bound (step_taylor.c) is, by its definition, the least of y(R) q^{p+1} / (1 - q),
 * q = h / R, over the grid R = h + (rho - h) i / 400, i = 1 .. 399, where y is the majorant
 * y' = K y^2 + L y + F, y(0) = 0. Here y comes from GSL's rk8pd at 1e-13 instead of the closed
 * form the step uses, and rho from the quadrature above; the two bounds agree to 1e-7 (the
 * integration's tolerance times the growth of y near rho, which the grid's last point keeps
 * below a factor 400 of its size). A bound looser or tighter than its definition fails. */
static int majorant_rhs(double t, const double y[], double dy[], void *p)
{
    (void)t;
    const double *k = p; /* K, L, F */
    dy[0] = (k[0] * y[0] + k[1]) * y[0] + k[2];
    return GSL_SUCCESS;
}

static double tail_bound_by_ode(int p, const sus_model *m, double h, const double w[2])
{
    double k[3];
    majorant_coeffs(m, w, k);
    const double rho = radius_by_quadrature(m, w);
    gsl_odeiv2_system sys = {majorant_rhs, NULL, 1, k};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-13, 1e-13);
    double t = 0.0, y[1] = {0.0}, best = INFINITY;
    for (int i = 1; d && i < 400; i++) {
        const double R = h + (rho - h) * (double)i / 400.0, q = h / R;
        if (gsl_odeiv2_driver_apply(d, &t, R, y) != GSL_SUCCESS) {
            best = NAN; /* fmin would drop a NaN: no bound from a failed integration */
            break;
        }
        best = fmin(best, y[0] * pow(q, p + 1) / (1.0 - q));
    }
    gsl_odeiv2_driver_free(d);
    return best;
}

static void tail_bound_against_ode(void)
{
    double worst = 0.0;
    int n = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        if (family_model(k, &b, &m) != 0)
            continue;
        const double rho = sus_step_taylor_radius(&m, b.w0);
        for (int j = 0; j < 5;
             j++) { /* j = 3, 4: the top orders, whose best R is the grid's last */
            const int p = j < 3 ? 8 + 4 * j : (j == 3 ? 28 : SUS_STEP_TAYLOR_MAX_ORDER);
            const double h = rho * (j < 3 ? 0.1 + 0.25 * j : 0.1);
            const double got = sus_step_taylor_tail_bound(p, &m, h, b.w0);
            const double want = tail_bound_by_ode(p, &m, h, b.w0);
            const double d = fabs(got - want) / want;
            worst = d > worst || isnan(d) ? d : worst;
            n++;
        }
    }
    CHECK(worst <= 1e-7,
          "the Taylor tail bound is its definition with the majorant integrated by rk8pd, "
          "%d cases on %d bodies: worst relative difference %.2g (at most 1e-7)",
          n, BODIES_COUNT, worst);
}

/* The majorant's double root, b = 0 in step_taylor.c: z^2 + 2 z0 z + F/K = K (z + z0)^2 when
 * |c(w)| ||fA|| = |b| |fA w|, which some direction w on the unit circle meets between w along b
 * (where the left side is larger) and w across b (where it is 0). Found by bisection on that
 * difference, then among the doubles next to the root one where z0^2 - F/K, computed as the step
 * computes it, is not positive: the step then takes its b = 0 branch. Returns 0 if none is found.
 */
static int double_root_state(const sus_model *m, double w[2])
{
    double a = atan2(m->b[1], m->b[0]), z = a + acos(-1.0) / 2.0; /* along b, across b */
    for (int i = 0; i < 200; i++) {
        const double mid = 0.5 * (a + z), u[2] = {cos(mid), sin(mid)};
        double k[3];
        majorant_coeffs(m, u, k);
        const double g = 2.0 * fabs(sus_c(m, u)) * m->norm_fA - k[1]; /* |c| ||fA|| - |b| |fA u| */
        *(g > 0.0 ? &a : &z) = mid;
    }
    for (int j = 0; j < 4000; j++) {
        const double th = a + (j % 2 ? 1 : -1) * (j / 2) * 1e-16 * fabs(a),
                     u[2] = {cos(th), sin(th)};
        double k[3];
        majorant_coeffs(m, u, k);
        const double K = k[0], z0 = k[1] / (2.0 * K);
        if (z0 * z0 - k[2] / K <= 0.0) {
            w[0] = u[0];
            w[1] = u[1];
            return 1;
        }
    }
    return 0;
}

/* At the double root, the radius 1/(K z0) against the quadrature, and the tail bound (y(t) =
 * z0/(1 - K z0 t) - z0) against the integrated majorant, as above on every body. */
static void double_root_case(void)
{
    double wr = 0.0, wt = 0.0;
    int found = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        double w[2];
        if (family_model(k, &b, &m) != 0 || !double_root_state(&m, w))
            continue;
        found++;
        const double rho = sus_step_taylor_radius(&m, w), T = radius_by_quadrature(&m, w);
        const double dr = fabs(rho - T) / T, h = 0.35 * rho;
        const double want = tail_bound_by_ode(12, &m, h, w);
        const double dt = fabs(sus_step_taylor_tail_bound(12, &m, h, w) - want) / want;
        wr = dr > wr || isnan(dr) ? dr : wr;
        wt = dt > wt || isnan(dt) ? dt : wt;
    }
    CHECK(found == BODIES_COUNT && wr <= 1e-8 && wt <= 1e-7,
          "the majorant's double root, met on %d of %d bodies: radius against quadrature %.2g "
          "(at most 1e-8), tail bound against rk8pd %.2g (at most 1e-7)",
          found, BODIES_COUNT, wr, wt);
}

/* At |w| = 3 (a state where the cheap test K |w| |h| < 1 and the radius differ most), a step just
 * inside the proved radius runs and one 1e-9 beyond it (past its 1e-12 rounding) is refused, on
 * every body. */
static void refused_beyond_radius(void)
{
    int ok = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        if (family_model(k, &b, &m) != 0)
            continue;
        const double n = hypot(b.w0[0], b.w0[1]),
                     w[3] = {3.0 * b.w0[0] / n, 3.0 * b.w0[1] / n, 0.0};
        const double rho = sus_step_taylor_radius(&m, w);
        double wn[3], lam;
        sus_stepper_stats st;
        sus_attitude a;
        sus_attitude_identity(&a);
        const int in = sus_step_taylor_apply_full(16, &m, 0.99 * rho, &a, w, wn, &lam, &st);
        const int out =
            sus_step_taylor_apply_full(16, &m, (1.0 + 1e-9) * rho, &a, w, wn, &lam, &st);
        ok += in == SUS_STEPPER_OK && out == SUS_STEPPER_DIVERGED;
    }
    CHECK(ok == BODIES_COUNT,
          "|w| = 3: a Taylor step of 0.99 times the proved radius runs and one of "
          "1 + 1e-9 times it is refused (DIVERGED) on %d of %d bodies",
          ok, BODIES_COUNT);
}

/* The top right singular vector of (ContDyn)'s matrix A = [-I12 -I22; I11 I21] / |I_m| (the
 * eigenvector of the largest eigenvalue of A^T A, in closed form) and ||A||, from the printed
 * entries. */
static double top_singular(const double I[9], double v[2])
{
    const double d =
        (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]); /* exact, rounded once */
    const double A[2][2] = {{-I[1] / d, -I[4] / d}, {I[0] / d, I[3] / d}};
    const double p = A[0][0] * A[0][0] + A[1][0] * A[1][0],
                 r = A[0][1] * A[0][1] + A[1][1] * A[1][1];
    const double q = A[0][0] * A[0][1] + A[1][0] * A[1][1];
    const double lam = 0.5 * (p + r) + hypot(0.5 * (p - r), q);
    /* (lam - r, q) and (q, lam - p) both solve it; the longer one is the better conditioned */
    const int first = fabs(lam - r) >= fabs(lam - p);
    const double x = first ? lam - r : q, y = first ? q : lam - p;
    v[0] = x / hypot(x, y);
    v[1] = y / hypot(x, y);
    return sqrt(lam);
}

/* The cheap test K |w| |h| < 1 accepts a step without the radius because rho >= 1/(K |w|) (F <= K
 * |w|^2, L <= 2 K |w|), with equality when b = (I31, I32) and w both lie along A's top right
 * singular vector: there F = K |w|^2, beta = 0 and rho = 1/(K |w|). On each body turned so (b set
 * to |b| v), at w = 3 v, the radius is 1/(K |w|) within [1 - 1e-12 - 1e-13, 1 + 1e-13] (its
 * rounding-down margin and a few u); a step of 0.99 rho runs and one of 1 + 1e-9 times rho is
 * refused, so the cheap test has no slack to give. */
static void cheap_test_tight(void)
{
    int ok = 0;
    double worst = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        double v[2];
        body_get(k, &b);
        const double nA = top_singular(b.I, v), nb = hypot(b.I[6], b.I[7]);
        b.I[6] = nb * v[0];
        b.I[7] = nb * v[1];
        if (check_body_model(&b, &m) != 0)
            continue;
        const double w[3] = {3.0 * v[0], 3.0 * v[1], 0.0}, cheap = 1.0 / (nb * nA * 3.0);
        const double rho = sus_step_taylor_radius(&m, w), d = rho / cheap - 1.0;
        worst = fabs(d) > fabs(worst) || isnan(d) ? d : worst;
        double wn[3], lam;
        sus_stepper_stats st;
        sus_attitude a;
        sus_attitude_identity(&a);
        const int in = sus_step_taylor_apply_full(16, &m, 0.99 * rho, &a, w, wn, &lam, &st);
        const int out =
            sus_step_taylor_apply_full(16, &m, (1.0 + 1e-9) * rho, &a, w, wn, &lam, &st);
        ok += in == SUS_STEPPER_OK && out == SUS_STEPPER_DIVERGED && d >= -1.1e-12 && d <= 1e-13;
    }
    CHECK(ok == BODIES_COUNT,
          "b and w along A's top singular vector (rho = 1/(K |w|)), on %d of %d bodies: radius "
          "against 1/(K |w|) %.3g (in [-1.1e-12, 1e-13]); 0.99 rho runs, (1 + 1e-9) rho is refused",
          ok, BODIES_COUNT, worst);
}

int main(void)
{
    gsl_set_error_handler_off();
    radius_against_quadrature();
    radius_rounded_down();
    double_root_case();
    refused_beyond_radius();
    cheap_test_tight();
    tail_bound_against_ode();
    /* the paper's body from its w(0) and from 1e-6 off its steady rotation c(w) = 0 (where the
     * proved radius grows like log(1/|f(w)|)), and two general bodies */
    static const double bodies[4][9] = {
        {1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0},
        {1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0},
        {1.0, 0.3, 0.5, 0.3, 0.8, -0.4, 0.6, -0.7, 1.2},
        {2.0, -0.5, 0.1, -0.5, 0.6, 0.3, -1.5, 2.5, 1.0},
    };
    static const double starts[4][2] = {
        {0.4, 0.5}, {-0.1 * 3.0 + 1e-6, 0.2 * 3.0}, {-0.3, 0.9}, {1.5, -2.0}};
    const sus_stepper_type *types[4] = {&sus_step_taylor8_type, &sus_step_taylor10_type,
                                        &sus_step_taylor12_type, &sus_step_taylor16_type};
    for (int b = 0; b < 4; b++) {
        sus_model m;
        char err[256];
        if (sus_model_init(&m, bodies[b], err, sizeof err) != 0) {
            CHECK(0, "body %d: %s", b, err);
            continue;
        }
        for (int k = 0; k < 4; k++) {
            double worst = 0.0;
            const int ran = sweep(types[k], &m, starts[b], &worst);
            CHECK(ran > 0,
                  "%s, case %d: over steps 1e-3 ... 100 every step that runs (%d of %d) is within "
                  "its proved bound (worst error / bound %.2g), the others exit DIVERGED",
                  types[k]->name, b, ran, NGRID, worst);
        }
    }
    return check_summary("test_taylor_radius");
}
