/* A Taylor step never returns a wrong answer as a success: over a grid of steps up to 100 time
 * units, on the paper's body and on general ones, every Taylor method's step either refuses
 * (SUS_STEPPER_DIVERGED: beyond the radius 1/(K |w|) its series is proved to converge in) or
 * lands within its proved error bound of the closed-form w(eps) (src/core/exact.h, independent of the
 * series). The bound (step_taylor.c): the tail past degree p is at most |w| r^{p+1} / (1 - r),
 * r = K |w| eps; restoring E moves the sum by at most kappa times its distance to the ellipse
 * (kappa = the condition number of I_m) to first order, so (2 + kappa) tail bounds the error with
 * room for the second order; 1e-14 |w| covers the rounding of a sum of at most 17 terms of size
 * at most |w| (17 u |w|) and of the scaling. */
#include "bodies.h"
#include "check.h"
#include "exact.h"
#include "taylor.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
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
        const int status = st->apply(m, eps, w, x, &lam, &stats);
        if (status == SUS_STEPPER_DIVERGED)
            continue;
        sus_exact_omega(&ex, eps, ref);
        const double err = hypot(x[0] - ref[0], x[1] - ref[1]);
        const double bound = (2.0 + kappa) * sus_step_taylor_tail_bound(st->order, m, eps, w0) + 1e-14 * a;
        *worst = fmax(*worst, err / bound);
        if (status != SUS_STEPPER_OK || !isfinite(bound) || !(err <= bound)) /* no proof, no answer */
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

static double radius_by_quadrature(const sus_model *m, const double w[2])
{
    const double c = fabs(sus_c(m, w));
    const double nAw =
        hypot(m->fA[0][0] * w[0] + m->fA[0][1] * w[1], m->fA[1][0] * w[0] + m->fA[1][1] * w[1]);
    double k[3] = {m->norm_b * m->norm_fA, c * m->norm_fA + m->norm_b * nAw, c * nAw};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    gsl_function f = {majorant_integrand, k};
    double T = NAN, abserr;
    if (!ws || gsl_integration_qagiu(&f, 0.0, 0.0, 1e-11, 200, ws, &T, &abserr) != 0)
        T = NAN;
    gsl_integration_workspace_free(ws);
    return T;
}

/* On every body of the family, at its w0 and at w0 turned and scaled: the step's radius equals
 * the quadrature's to 1e-8 (the quadrature's tolerance is 1e-11; the step rounds down by 1e-12). */
static void radius_against_quadrature(void)
{
    double worst = 0.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        char err[256];
        body_get(k, &b);
        if (sus_model_init(&m, b.I, err, sizeof err) != 0) {
            CHECK(0, "%s: %s", b.name, err);
            continue;
        }
        for (int j = 0; j < 4; j++) {
            const double s = 0.25 + j;
            const double w[2] = {s * (b.w0[0] - 0.3 * j * b.w0[1]), s * (b.w0[1] + 0.3 * j * b.w0[0])};
            const double r = sus_step_taylor_radius(&m, w), T = radius_by_quadrature(&m, w);
            const double d = fabs(r - T) / T;
            worst = d > worst || isnan(d) ? d : worst;
        }
    }
    CHECK(worst <= 1e-8, "the proved radius is the majorant's blow-up time by quadrature on %d bodies x 4 "
          "states: worst relative difference %.2g (at most 1e-8)", BODIES_COUNT, worst);
}

int main(void)
{
    gsl_set_error_handler_off();
    radius_against_quadrature();
    /* the paper's body from its w(0) and from 1e-6 off its steady rotation c(w) = 0 (where the
     * proved radius grows like log(1/|f(w)|)), and two general bodies */
    static const double bodies[4][9] = {
        {1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0},
        {1.0, 0.1, 0.2, 0.1, 1.0, 0.2, 0.2, 0.1, 1.0},
        {1.0, 0.3, 0.5, 0.3, 0.8, -0.4, 0.6, -0.7, 1.2},
        {2.0, -0.5, 0.1, -0.5, 0.6, 0.3, -1.5, 2.5, 1.0},
    };
    static const double starts[4][2] = {{0.4, 0.5}, {-0.1 * 3.0 + 1e-6, 0.2 * 3.0}, {-0.3, 0.9}, {1.5, -2.0}};
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
                  "%s, case %d: over steps 1e-3 ... 100 every step that runs (%d of %d) is within its "
                  "proved bound (worst error / bound %.2g), the others exit DIVERGED",
                  types[k]->name, b, ran, NGRID, worst);
        }
    }
    return check_summary("test_taylor_radius");
}
