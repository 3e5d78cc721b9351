/* The model: (ContDyn) and (LagMult) against (RGB2), input validation, and the closed-form
 * solution against GSL's rk8pd. */
#include "check.h"
#include "exact.h"
#include "model.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

static int rhs(double t, const double y[], double f[], void *p)
{
    (void)t;
    suslov_contdyn(p, y, f);
    return GSL_SUCCESS;
}

/* max |w_exact(t) - w_rk8pd(t)| on t = 0, 0.5, ..., T. */
static double exact_vs_rk8pd(const suslov_model *m, const double w0[2], double T)
{
    suslov_exact ex;
    suslov_exact_init(&ex, m, w0);
    gsl_odeiv2_system sys = {rhs, NULL, 2, (void *)m};
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-13, 1e-13);
    double y[2] = {w0[0], w0[1]}, t = 0.0, worst = 0.0;
    for (int i = 1; i <= (int)(2 * T); i++) {
        double w[2];
        if (gsl_odeiv2_driver_apply(d, &t, 0.5 * i, y) != GSL_SUCCESS) {
            worst = INFINITY;
            break;
        }
        suslov_exact_omega(&ex, t, w);
        worst = fmax(worst, hypot(w[0] - y[0], w[1] - y[1]));
    }
    gsl_odeiv2_driver_free(d);
    return worst;
}

int main(void)
{
    gsl_set_error_handler_off();
    char err[256];
    suslov_model m;
    double bad[9];

    memcpy(bad, SUSLOV_PAPER_INERTIA, sizeof bad);
    bad[3] = 0.2;
    CHECK(suslov_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "symmetric"),
          "a non-symmetric I_m is rejected: %s", err);
    memcpy(bad, SUSLOV_PAPER_INERTIA, sizeof bad);
    bad[1] = bad[3] = 2.0;
    CHECK(suslov_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "positive definite"),
          "an indefinite I_m is rejected: %s", err);
    memcpy(bad, SUSLOV_PAPER_INERTIA, sizeof bad);
    bad[7] = NAN;
    CHECK(suslov_model_init(&m, bad, err, sizeof err) != 0 && strstr(err, "not finite"),
          "a NaN entry is rejected: %s", err);
    CHECK(suslov_model_init(&m, SUSLOV_PAPER_INERTIA, err, sizeof err) == 0,
          "the paper's inertia tensor is accepted (its I_m is symmetric; I23 != I32 does not enter)");

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
        const double *w0 = SUSLOV_PAPER_OMEGA0;
        double f[2];
        suslov_contdyn(&m, w0, f);
        const double E0 = suslov_energy(&m, w0), l0 = suslov_lagmult(&m, w0), o0 = suslov_lagmult_o0(&m, w0);
        CHECK(fabs(E0 - 0.225) < 1e-15, "E(w0) = %.17g, by hand 0.225", E0);
        CHECK(fabs(l0 + 19.0 / 1100.0) < 1e-15, "lambda(w0) = %.17g, by hand -19/1100", l0);
        CHECK(fabs(o0 + 0.00819 / 0.99) < 1e-15, "O_0(w0) = %.17g, by hand -0.00819/0.99", o0);
        CHECK(fabs(f[0] + 0.0702 / 0.99) < 1e-15 && fabs(f[1] - 0.0585 / 0.99) < 1e-15,
              "(ContDyn) at w0 = (%.17g, %.17g), by hand (-0.0702, 0.0585)/0.99", f[0], f[1]);
        /* The steady rotation: c = 0.2 w1 + 0.1 w2 = 0 gives w2 = -2 w1; on E = 0.225,
         * 2.3 w1^2 = 0.225; there lambda = w1 (0.1 w1 - 2 w1) + 2 w1 (w1 - 0.2 w1) = -0.3 w1^2
         * = -27/920 and O_0 = 0. */
        const double a = sqrt(0.225 / 2.3), winf[2] = {a, -2.0 * a};
        CHECK(fabs(suslov_lagmult(&m, winf) + 27.0 / 920.0) < 1e-15 && fabs(suslov_energy(&m, winf) - 0.225) < 1e-15,
              "lambda(w_inf) = %.17g, by hand -27/920; E(w_inf) = 0.225", suslov_lagmult(&m, winf));
    }

    /* (ContDyn) and (LagMult) solve the three rows of (RGB2) with w3 = 0, w3' = 0. */
    double worst_rgb = 0.0, worst_jac = 0.0, worst_e = 0.0;
    const double (*I)[3] = m.I;
    for (int n = 0; n < 24; n++) {
        const double a = 2.0 * M_PI * n / 24.0, w[2] = {0.7 * cos(a), 0.4 * sin(a) + 0.1};
        double f[2], J[2][2];
        suslov_contdyn(&m, w, f);
        const double lam = suslov_lagmult(&m, w);
        const double Iw[3] = {I[0][0] * w[0] + I[0][1] * w[1], I[1][0] * w[0] + I[1][1] * w[1],
                              I[2][0] * w[0] + I[2][1] * w[1]};
        /* (RGB2): I (w1', w2', 0) = ((I w) x w) + lambda e3 */
        const double r0 = I[0][0] * f[0] + I[0][1] * f[1] - (-w[1] * Iw[2]);
        const double r1 = I[1][0] * f[0] + I[1][1] * f[1] - (w[0] * Iw[2]);
        const double r2 = I[2][0] * f[0] + I[2][1] * f[1] - (w[1] * Iw[0] - w[0] * Iw[1]) - lam;
        worst_rgb = fmax(worst_rgb, fabs(r0) + fabs(r1) + fabs(r2));
        /* E is a first integral of (ContDyn): <grad E, f> = 0 */
        worst_e = fmax(worst_e, fabs((I[0][0] * w[0] + I[0][1] * w[1]) * f[0] + (I[1][0] * w[0] + I[1][1] * w[1]) * f[1]));
        suslov_contdyn_jacobian(&m, w, J);
        for (int j = 0; j < 2; j++) {
            const double h = 1e-6;
            double wp[2] = {w[0], w[1]}, wm[2] = {w[0], w[1]}, fp[2], fm[2];
            wp[j] += h;
            wm[j] -= h;
            suslov_contdyn(&m, wp, fp);
            suslov_contdyn(&m, wm, fm);
            for (int i = 0; i < 2; i++)
                worst_jac = fmax(worst_jac, fabs((fp[i] - fm[i]) / (2.0 * h) - J[i][j]));
        }
    }
    CHECK(worst_rgb < 1e-15, "(ContDyn) and (LagMult) satisfy all three rows of (RGB2); worst residual %.2e", worst_rgb);
    CHECK(worst_e < 1e-15, "E = 1/2 <I_m w, w> is a first integral of (ContDyn); worst <grad E, f> %.2e", worst_e);
    /* f is quadratic: central differences are exact up to cancellation, ~u/h = 2e-10 */
    CHECK(worst_jac < 1e-9, "Jacobian of (ContDyn) against central differences; worst %.2e", worst_jac);

    /* Closed form against rk8pd at tolerance 1e-13 over [0, 100], for the paper's w(0) and for
     * w(0) around the energy ellipse (both branches sign(cos psi0) = +-1). An adaptive method
     * at tolerance 1e-13 over ~1500 steps keeps a global error of order 1e-12. */
    const double paper = exact_vs_rk8pd(&m, SUSLOV_PAPER_OMEGA0, 100.0);
    CHECK(paper < 1e-11, "closed form = rk8pd (tol 1e-13) on [0, 100] for the paper's w(0); max diff %.2e", paper);
    double ring = 0.0;
    for (int n = 0; n < 12; n++) {
        const double a = 2.0 * M_PI * (n + 0.25) / 12.0, w0[2] = {0.64 * cos(a), 0.64 * sin(a)};
        ring = fmax(ring, exact_vs_rk8pd(&m, w0, 100.0));
    }
    CHECK(ring < 1e-11, "closed form = rk8pd on [0, 100] for 12 w(0) around the ellipse; max diff %.2e", ring);

    /* The closed form at t = 1e6: finite, on the energy ellipse, at the steady rotation. */
    suslov_exact ex;
    suslov_exact_init(&ex, &m, SUSLOV_PAPER_OMEGA0);
    double wl[2], wt[2], wm[2];
    suslov_exact_limit(&ex, wl);
    suslov_exact_omega(&ex, 1e6, wt);
    suslov_exact_omega(&ex, -1e6, wm);
    const double E0 = suslov_energy(&m, SUSLOV_PAPER_OMEGA0);
    CHECK(isfinite(wt[0]) && isfinite(wt[1]) && hypot(wt[0] - wl[0], wt[1] - wl[1]) < 1e-15,
          "w(1e6) is finite and equals the steady rotation (%.17g, %.17g)", wt[0], wt[1]);
    CHECK(fabs(suslov_c(&m, wl)) < 1e-16 && fabs(suslov_energy(&m, wl) - E0) < 1e-15,
          "the steady rotation has c(w) = I_3i w_i = %.1e and the initial energy", suslov_c(&m, wl));
    CHECK(isfinite(wm[0]) && isfinite(wm[1]) && fabs(suslov_energy(&m, wm) - E0) < 1e-15,
          "w(-1e6) is finite (the repelling rotation) and on the energy ellipse");
    CHECK(ex.k > 0.145 && ex.k < 0.146, "rate of approach k = %.6f for the paper's body and w(0)", ex.k);
    /* The steady rotations are equilibria. The attracting one stays put; the repelling one,
     * known only to round-off (~1e-16), is left at the rate k: by t = 50 the departure is
     * about 1e-16 e^{50 k} ~ 1e-13, so 1e-12 bounds it. */
    double wq[2];
    suslov_exact_init(&ex, &m, wl);
    suslov_exact_omega(&ex, 50.0, wq);
    CHECK(hypot(wq[0] - wl[0], wq[1] - wl[1]) < 1e-15, "the attracting steady rotation is a fixed point of the closed form");
    const double weq[2] = {-wl[0], -wl[1]};
    suslov_exact_init(&ex, &m, weq);
    suslov_exact_omega(&ex, 50.0, wq);
    const double dep = hypot(wq[0] - weq[0], wq[1] - weq[1]);
    CHECK(dep < 1e-12, "the repelling steady rotation is left only at round-off times e^{kt}: %.2e at t = 50", dep);
    return check_summary("test_model");
}
