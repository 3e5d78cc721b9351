/* The model: (ContDyn) and (LagMult) against (RGB2) and against the printed formulas written out
 * again here, input validation, and the closed-form solution against GSL's rk8pd, on the paper's
 * body and on the seeded family of general bodies (tests/unit/bodies.h). */
#include "bodies.h"
#include "check.h"
#include "exact.h"
#include "model.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

/* (ContDyn) as printed, from the rows of I (not through src/core/model.c):
 *   w1' = -(I22 w2 + I12 w1)(I31 w1 + I32 w2) / |I_m|,  w2' = (I21 w2 + I11 w1)(I31 w1 + I32 w2) / |I_m|. */
static int contdyn_printed(double t, const double y[], double f[], void *p)
{
    (void)t;
    const double *I = p, det = I[0] * I[4] - I[1] * I[3], c = I[6] * y[0] + I[7] * y[1];
    f[0] = -(I[4] * y[1] + I[1] * y[0]) * c / det;
    f[1] = (I[3] * y[1] + I[0] * y[0]) * c / det;
    return GSL_SUCCESS;
}

/* (LagMult) as printed, from the rows of I. */
static double lagmult_printed(const double *I, const double w[2])
{
    const double det = I[0] * I[4] - I[1] * I[3], c = I[6] * w[0] + I[7] * w[1];
    return w[0] * (I[3] * w[0] + I[4] * w[1]) - w[1] * (I[0] * w[0] + I[1] * w[1])
         + c / det * ((I[7] * I[3] - I[6] * I[4]) * w[1] + (I[7] * I[0] - I[6] * I[1]) * w[0]);
}

/* max |w_exact(t) - w_rk8pd(t)| on t = 0, 0.5, ..., T, rk8pd on contdyn_printed of the body I. */
static double exact_vs_rk8pd(const sus_model *m, const double *I, const double w0[2], double T)
{
    sus_exact ex;
    sus_exact_init(&ex, m, w0);
    gsl_odeiv2_system sys = {contdyn_printed, NULL, 2, (void *)I};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-13, 1e-13);
    double y[2] = {w0[0], w0[1]}, t = 0.0, worst = 0.0;
    for (int i = 1; i <= (int)(2 * T); i++) {
        double w[2];
        if (gsl_odeiv2_driver_apply(d, &t, 0.5 * i, y) != GSL_SUCCESS) {
            worst = INFINITY;
            break;
        }
        sus_exact_omega(&ex, t, w);
        worst = fmax(worst, hypot(w[0] - y[0], w[1] - y[1]));
    }
    gsl_odeiv2_driver_free(d);
    return worst;
}

static void validation(void)
{
    char err[256];
    sus_model m;
    double bad[9];
    memcpy(bad, SUS_PAPER_INERTIA, sizeof bad);
    bad[3] = 0.2;
    CHECK(sus_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "symmetric"),
          "a non-symmetric I_m is rejected: %s", err);
    memcpy(bad, SUS_PAPER_INERTIA, sizeof bad);
    bad[1] = bad[3] = 2.0;
    CHECK(sus_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "positive definite"),
          "an indefinite I_m is rejected: %s", err);
    memcpy(bad, SUS_PAPER_INERTIA, sizeof bad);
    bad[7] = NAN;
    CHECK(sus_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "not finite"),
          "a NaN entry is rejected: %s", err);
}

/* Absolute values at the paper's body, by hand. */
static void paper_values(const sus_model *mp)
{
    const sus_model m = *mp;
    /* Absolute values at the paper's w0 = (0.4, 0.5), worked out by hand from the printed
     * formulas (the same arithmetic is written out in tests/cli/test_cli_values.sh):
     *   E = 1/2 (I11 w1^2 + 2 I12 w1 w2 + I22 w2^2) = 1/2 (0.16 + 0.04 + 0.25) = 0.225;
     *   c = I31 w1 + I32 w2 = 0.08 + 0.05 = 0.13, |I_m| = 1 - 0.01 = 0.99;
     *   (ContDyn) w1' = -(I22 w2 + I12 w1) c / |I_m| = -(0.54)(0.13)/0.99 = -0.0702/0.99,
     *             w2' =  (I21 w2 + I11 w1) c / |I_m| =  (0.45)(0.13)/0.99 =  0.0585/0.99;
     *   O_0 = c/|I_m| ((I32 I21 - I31 I22) w2 + (I32 I11 - I31 I12) w1)
     *       = 0.13/0.99 (-0.19 (0.5) + 0.08 (0.4)) = -0.00819/0.99;
     *   (LagMult) lambda = w1 (I21 w1 + I22 w2) - w2 (I11 w1 + I12 w2) + O_0
     *       = 0.4 (0.54) - 0.5 (0.45) - 0.00819/0.99 = -(0.00891 + 0.00819)/0.99 = -19/1100.
     * Each is a sum of a few products of size < 1: round-off a few u, so 1e-15. */
    {
        const double *w0 = SUS_PAPER_OMEGA0;
        double f[2];
        sus_contdyn(&m, w0, f);
        const double E0 = sus_energy(&m, w0), l0 = sus_lagmult(&m, w0), o0 = sus_lagmult_o0(&m, w0);
        CHECK(fabs(E0 - 0.225) < 1e-15, "E(w0) = %.17g, by hand 0.225", E0);
        CHECK(fabs(l0 + 19.0 / 1100.0) < 1e-15, "lambda(w0) = %.17g, by hand -19/1100", l0);
        CHECK(fabs(o0 + 0.00819 / 0.99) < 1e-15, "O_0(w0) = %.17g, by hand -0.00819/0.99", o0);
        CHECK(fabs(f[0] + 0.0702 / 0.99) < 1e-15 && fabs(f[1] - 0.0585 / 0.99) < 1e-15,
              "(ContDyn) at w0 = (%.17g, %.17g), by hand (-0.0702, 0.0585)/0.99", f[0], f[1]);
        /* The steady rotation: c = 0.2 w1 + 0.1 w2 = 0 gives w2 = -2 w1; on E = 0.225,
         * 2.3 w1^2 = 0.225; there lambda = w1 (0.1 w1 - 2 w1) + 2 w1 (w1 - 0.2 w1) = -0.3 w1^2
         * = -27/920 and O_0 = 0. */
        const double a = sqrt(0.225 / 2.3), winf[2] = {a, -2.0 * a};
        CHECK(fabs(sus_lagmult(&m, winf) + 27.0 / 920.0) < 1e-15 && fabs(sus_energy(&m,
            winf) - 0.225) < 1e-15,
              "lambda(w_inf) = %.17g, by hand -27/920; E(w_inf) = 0.225", sus_lagmult(&m, winf));
    }

}

/* Sample points around an ellipse off the origin, in all four quadrants. */
static void sample_w(int n, double w[2])
{
    const double a = 2.0 * M_PI * n / 24.0;
    w[0] = 0.7 * cos(a);
    w[1] = 0.4 * sin(a) + 0.1;
}

/* src/core/model.c against the printed formulas and against (RGB2), on the body's own rows I (read
 * from the test's array, not from the model): a row/column or sign slip moves these. */
static void model_vs_printed(const sus_model *m, const body *b)
{
    const double *I = b->I;
    double worst_f = 0.0, worst_l = 0.0, worst_rgb = 0.0, worst_e = 0.0, worst_jac = 0.0;
    for (int n = 0; n < 24; n++) {
        double w[2], f[2], g[2], J[2][2];
        sample_w(n, w);
        sus_contdyn(m, w, f);
        contdyn_printed(0.0, w, g, (void *)I);
        worst_f = fmax(worst_f, fabs(f[0] - g[0]) + fabs(f[1] - g[1]));
        const double lam = sus_lagmult(m, w);
        worst_l = fmax(worst_l, fabs(lam - lagmult_printed(I, w)));
        const double Iw[3] = {I[0] * w[0] + I[1] * w[1], I[3] * w[0] + I[4] * w[1],
            I[6] * w[0] + I[7] * w[1]};
        /* (RGB2): I (w1', w2', 0)
         *         = (-w2 (I_3i w_i), w1 (I_3i w_i), w2 (I_1i w_i) - w1 (I_2i w_i)) + lambda e3 */
        const double r0 = I[0] * f[0] + I[1] * f[1] + w[1] * Iw[2];
        const double r1 = I[3] * f[0] + I[4] * f[1] - w[0] * Iw[2];
        const double r2 = I[6] * f[0] + I[7] * f[1] - (w[1] * Iw[0] - w[0] * Iw[1]) - lam;
        worst_rgb = fmax(worst_rgb, fabs(r0) + fabs(r1) + fabs(r2));
        /* E = 1/2 <I_m w, w> is a first integral of (ContDyn): <grad E, f> = 0 */
        worst_e = fmax(worst_e, fabs(Iw[0] * f[0] + Iw[1] * f[1]));
        sus_contdyn_jacobian(m, w, J);
        for (int j = 0; j < 2; j++) {
            const double h = 1e-6;
            double wp[2] = {w[0], w[1]}, wm[2] = {w[0], w[1]}, fp[2], fm[2];
            wp[j] += h;
            wm[j] -= h;
            sus_contdyn(m, wp, fp);
            sus_contdyn(m, wm, fm);
            for (int i = 0; i < 2; i++)
                worst_jac = fmax(worst_jac, fabs((fp[i] - fm[i]) / (2.0 * h) - J[i][j]));
        }
    }
    /* entries below 2.5, |w| < 0.8, |I_m| > 0.3: each side a few dozen roundings of numbers < 10 */
    CHECK(worst_f < 1e-14, "%s: (ContDyn) of src/core/model.c = the printed formula; worst %.2e", b->name,
          worst_f);
    CHECK(worst_l < 1e-14, "%s: (LagMult) of src/core/model.c = the printed formula; worst %.2e", b->name,
          worst_l);
    CHECK(worst_rgb < 1e-14, "%s: (ContDyn) and (LagMult) satisfy all three rows of (RGB2); worst %.2e",
          b->name, worst_rgb);
    CHECK(worst_e < 1e-14, "%s: E is a first integral of (ContDyn); worst <grad E, f> %.2e", b->name,
          worst_e);
    /* f is quadratic: central differences are exact up to cancellation, ~u/h = 2e-10 */
    CHECK(worst_jac < 1e-9, "%s: Jacobian of (ContDyn) against central differences; worst %.2e", b->name,
          worst_jac);
}

/* The closed form against rk8pd at tolerance 1e-13 over [0, 100] (an adaptive method at that
 * tolerance over ~1500 steps keeps a global error of order 1e-12), and its limit. */
static void closed_form(const sus_model *m, const body *b)
{
    const double d = exact_vs_rk8pd(m, b->I, b->w0, 100.0);
    CHECK(d < 1e-11, "%s: closed form = rk8pd (tol 1e-13) of the printed (ContDyn) on [0, 100]; max diff "
                     "%.2e",
          b->name, d);
    sus_exact ex;
    sus_exact_init(&ex, m, b->w0);
    double wl[2], wt[2], wm[2];
    sus_exact_limit(&ex, wl);
    sus_exact_omega(&ex, 1e6, wt);
    sus_exact_omega(&ex, -1e6, wm);
    const double E0 = sus_energy(m, b->w0), c = b->I[6] * wl[0] + b->I[7] * wl[1];
    CHECK(isfinite(wt[0]) && isfinite(wt[1]) && hypot(wt[0] - wl[0], wt[1] - wl[1]) < 1e-15,
          "%s: w(1e6) is finite and equals the steady rotation (%.17g, %.17g)", b->name, wt[0], wt[1]);
    /* c and E are sums of a few products of size < 2: 4 u */
    CHECK(fabs(c) < 1e-15 && fabs(sus_energy(m, wl) - E0) < 1e-15 * fmax(1.0, E0),
          "%s: the steady rotation has I31 w1 + I32 w2 = %.1e and the initial energy", b->name, c);
    CHECK(isfinite(wm[0]) && isfinite(wm[1]) && fabs(sus_energy(m, wm) - E0) < 1e-15 * fmax(1.0, E0),
          "%s: w(-1e6) is finite (the repelling rotation) and on the energy ellipse", b->name);
}

/* The paper's body: closed form for w(0) around the ellipse (both branches sign(cos psi0)), the
 * rate k, and the steady rotations as fixed points. */
static void paper_closed_form(const sus_model *m)
{
    double ring = 0.0;
    for (int n = 0; n < 12; n++) {
        const double a = 2.0 * M_PI * (n + 0.25) / 12.0, w0[2] = {0.64 * cos(a), 0.64 * sin(a)};
        ring = fmax(ring, exact_vs_rk8pd(m, SUS_PAPER_INERTIA, w0, 100.0));
    }
    CHECK(ring < 1e-11, "closed form = rk8pd on [0, 100] for 12 w(0) around the ellipse; max diff %.2e",
          ring);
    sus_exact ex;
    double wl[2], wq[2];
    sus_exact_init(&ex, m, SUS_PAPER_OMEGA0);
    sus_exact_limit(&ex, wl);
    CHECK(ex.k > 0.145 && ex.k < 0.146, "rate of approach k = %.6f for the paper's body and w(0)", ex.k);
    /* The steady rotations are equilibria. The attracting one stays put; the repelling one,
     * known only to round-off (~1e-16), is left at the rate k: by t = 50 the departure is
     * about 1e-16 e^{50 k} ~ 1e-13, so 1e-12 bounds it. */
    sus_exact_init(&ex, m, wl);
    sus_exact_omega(&ex, 50.0, wq);
    CHECK(hypot(wq[0] - wl[0], wq[1] - wl[1]) < 1e-15, "the attracting steady rotation is a fixed point of "
                                                       "the closed form");
    const double weq[2] = {-wl[0], -wl[1]};
    sus_exact_init(&ex, m, weq);
    sus_exact_omega(&ex, 50.0, wq);
    const double dep = hypot(wq[0] - weq[0], wq[1] - weq[1]);
    CHECK(dep < 1e-12,
          "the repelling steady rotation is left only at round-off times e^{kt}: %.2e at t = 50", dep);
}

/* A body whose third row has I31 = I32 = 0: c(w) = 0 for every w, so (ContDyn) keeps w(t) = w(0). The
 * closed form must return w(0) itself (exactly: nothing is computed) at every t and as the limit. */
static void uncoupled(const body *b)
{
    double I[9];
    for (int i = 0; i < 9; i++)
        I[i] = b->I[i];
    I[6] = I[7] = 0.0;
    sus_model m;
    char err[256];
    if (sus_model_init(&m, I, err, sizeof err) != 0) {
        CHECK(0, "%s with I31 = I32 = 0 accepted: %s", b->name, err);
        return;
    }
    sus_exact ex;
    sus_exact_init(&ex, &m, b->w0);
    double w[2], wl[2];
    int same = 1;
    for (double t = 0.0; t <= 100.0; t += 12.5) {
        sus_exact_omega(&ex, t, w);
        same = same && w[0] == b->w0[0] && w[1] == b->w0[1];
    }
    sus_exact_limit(&ex, wl);
    CHECK(same && wl[0] == b->w0[0] && wl[1] == b->w0[1],
          "%s with I31 = I32 = 0: w(t) = w(0) = (%g, %g) on [0, 100] and as the limit, exactly", b->name,
          b->w0[0], b->w0[1]);
}

int main(void)
{
    gsl_set_error_handler_off();
    char err[256], about[200];
    validation();
    printf("bodies: seed %u\n", BODIES_SEED);
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        body_get(k, &b);
        body_describe(&b, about, sizeof about);
        CHECK(sus_model_init(&m, b.I, err, sizeof err) == 0, "accepted: %s", about);
        model_vs_printed(&m, &b);
        closed_form(&m, &b);
        uncoupled(&b);
        if (k == 0) {
            paper_values(&m);
            paper_closed_form(&m);
        }
    }
    return check_summary("test_model");
}
