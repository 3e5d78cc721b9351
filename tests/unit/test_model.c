/* The model: (ContDyn) and (LagMult) against (RGB2) and against the printed formulas written out
 * again here, input validation, and the closed-form solution against GSL's rk8pd, on the paper's
 * body and on the seeded family of general bodies (tests/unit/bodies.h). */
#include "check_body.h"
#include "check_exact.h"
#include "exact.h"
#include "model.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

/* (ContDyn) as printed, from the rows of I (not through src/core/model.c), in long double with
 * |I_m| exact (check_exact.h), so that its own rounding is 2^-64 of the terms however near-singular
 * I_m is: w1' = -(I22 w2 + I12 w1)(I31 w1 + I32 w2) / |I_m|,  w2' = (I21 w2 + I11 w1)(I31 w1 + I32
 * w2) / |I_m|. */
static void contdyn_printed_l(const double *I, const double w[2], long double f[2])
{
    const long double det = check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    const long double c = (long double)I[6] * w[0] + (long double)I[7] * w[1];
    f[0] = -((long double)I[4] * w[1] + (long double)I[1] * w[0]) * c / det;
    f[1] = ((long double)I[3] * w[1] + (long double)I[0] * w[0]) * c / det;
}

/* The same, for GSL's rk8pd. */
static int contdyn_printed(double t, const double y[], double f[], void *p)
{
    (void)t;
    long double fl[2];
    contdyn_printed_l(p, y, fl);
    f[0] = (double)fl[0];
    f[1] = (double)fl[1];
    return GSL_SUCCESS;
}

/* (LagMult) as printed, from the rows of I, likewise in long double with |I_m| and O_0's
 * coefficients I32 I21 - I31 I22 and I32 I11 - I31 I12 exact; its three terms in t. */
static long double lagmult_printed_terms(const double *I, const double w[2], long double t[3])
{
    const long double det = check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    const long double c = (long double)I[6] * w[0] + (long double)I[7] * w[1];
    const long double o2 = check_cross_diff_exact(I[7], I[3], I[6], I[4]);
    const long double o1 = check_cross_diff_exact(I[7], I[0], I[6], I[1]);
    t[0] = w[0] * ((long double)I[3] * w[0] + (long double)I[4] * w[1]);
    t[1] = -w[1] * ((long double)I[0] * w[0] + (long double)I[1] * w[1]);
    t[2] = c / det * (o2 * w[1] + o1 * w[0]);
    return t[0] + t[1] + t[2];
}

static long double lagmult_printed(const double *I, const double w[2])
{
    long double t[3];
    return lagmult_printed_terms(I, w, t);
}

/* 2 E = <I_m w, w> in long double, its two terms in t. */
static long double twice_energy_printed_terms(const double *I, const double w[2], long double t[2])
{
    t[0] = w[0] * ((long double)I[0] * w[0] + (long double)I[1] * w[1]);
    t[1] = w[1] * ((long double)I[3] * w[0] + (long double)I[4] * w[1]);
    return t[0] + t[1];
}

/* max |w_exact(t) - w_rk8pd(t)| on t = 0, 0.5 s, ..., 100 s, rk8pd on contdyn_printed of the body
 * I: s the body's own time (check_body_time), so that the grid spans the same 14.5 relaxation times
 * 1/k as [0, 100] on the paper's body, whatever its k. */
static double exact_vs_rk8pd(const sus_model *m, const double *I, const double w0[2], double s)
{
    sus_exact ex;
    sus_exact_init(&ex, m, w0);
    gsl_odeiv2_system sys = {contdyn_printed, NULL, 2, (void *)I};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * s, 1e-13, 1e-13);
    double y[2] = {w0[0], w0[1]}, t = 0.0, worst = 0.0;
    for (int i = 1; i <= 200; i++) {
        double w[2];
        if (gsl_odeiv2_driver_apply(d, &t, 0.5 * s * i, y) != GSL_SUCCESS) {
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
    /* the start check of a run: no model is not an overflowing energy */
    const double w[2] = {0.4, 0.5};
    sus_model zero;
    memset(&zero, 0, sizeof zero);
    const char *says[3] = {sus_model_start_overflow(NULL, w), sus_model_start_overflow(&zero, w),
                           "no model"};
    CHECK(sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) == 0, "the paper's body");
    says[2] = sus_model_start_overflow(&m, NULL);
    int no_model = 1;
    for (int i = 0; i < 3; i++)
        no_model &= says[i] && strcmp(says[i], "no model") == 0;
    CHECK(no_model && sus_model_start_overflow(&m, w) == NULL,
          "sus_model_start_overflow: \"no model\" for a NULL or zeroed model or a NULL w, NULL at "
          "the paper's start");
}

/* What double precision cannot hold is refused by sus_model_init itself, in the words the suslov
 * command prints after "--inertia: " (tests/cli/test_cli.sh pins the same lines): the command
 * and the library share the one check. Each body with a good control: the same shape, scaled
 * into range, is accepted. */
static void extreme_bodies(void)
{
    static const struct {
        double I[9], ok[9];
        const char *says;
    } cases[] = {
        {{1e-300, 0, 0, 0, 1e-300, 0, 0, 0, 1},
         {1e-150, 0, 0, 0, 1e-150, 0, 0, 0, 1},
         "the determinant of I_m, 1e-300 * 1e-300 - 0 * 0, is not a finite normal number "
         "(entries too large or too small)"},
        {{1e308, 0, 0, 0, 1e308, 0, 0, 0, 1},
         {1e150, 0, 0, 0, 1e150, 0, 0, 0, 1},
         "the determinant of I_m, 1e+308 * 1e+308 - 0 * 0, is not a finite normal number"},
        {{1e308, 1e308, 0, -1e308, 1e308, 0, 0, 0, 1},
         {1e154, 1e153, 0, 1e153, 1e154, 0, 0, 0, 1},
         "I_m is not symmetric: I12 = 1e+308 but I21 = -1e+308"},
        {{1, 0.99999999999999989, 0, 0.99999999999999989, 1, 0, 0, 0, 1},
         {1, 0.99999999999999, 0, 0.99999999999999, 1, 0, 0, 0, 1},
         "too ill-conditioned for double precision: I11 I22 and I12 I21 agree to their rounding"},
        {{0, 0, 0, 0, 0, 0, 0, 0, 1},
         {1e-300, 0, 0, 0, 1e300, 0, 0, 0, 1},
         "I_m is zero, not positive definite"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[256] = "", err_ok[256] = "";
        sus_model m;
        const int rc = sus_model_init(&m, cases[i].I, err, sizeof err);
        const int rc_ok = sus_model_init(&m, cases[i].ok, err_ok, sizeof err_ok);
        CHECK(rc == -1 && strncmp(err, cases[i].says, strlen(cases[i].says)) == 0 && rc_ok == 0,
              "extreme body %zu refused as the CLI refuses it (\"%s\"), its control accepted (%s)",
              i, err, err_ok);
    }
}

/* lambda and E within a few percent of the largest double, where a term of their sums overflows
 * in double and the sum does not: finite, and as near the printed formulas in long double as
 * anywhere, since scaling by a power of two rounds nothing: (LagMult) within 6 u L (the bound of
 * model_vs_printed, below), E within 4 u of its terms' sizes (two products of two-term sums and
 * their sum, 3 u, and the printed side's 2^-64); at twice that w, where they overflow themselves,
 * +inf (not NaN). The body and the direction of w are those of an exact run that once ended as a
 * blow-up at step 54, lambda at 1.78e308. */
static void near_overflow(void)
{
    static const double I[9] = {2, -0.7, 0, -0.7, 0.5, 0, -3, -5, 0};
    const double d[2] = {1.3088771230301911, 1.6825184306904665}, u = SUS_U;
    sus_model m;
    sus_model_init(&m, I, NULL, 0);
    long double t[3];
    /* both quadratic in w: q(s d) = s^2 q(d), s putting lambda at 0.99 and E at 0.75 of DBL_MAX */
    const long double sl = sqrtl(0.99L * DBL_MAX / fabsl(lagmult_printed(I, d)));
    const double w[2] = {(double)(sl * d[0]), (double)(sl * d[1])}, w2[2] = {2 * w[0], 2 * w[1]};
    const long double lw = lagmult_printed_terms(I, w, t);
    const long double L = fabsl(t[0]) + fabsl(t[1]) + fabsl(t[2]);
    const double l = sus_lagmult(&m, w), l2 = sus_lagmult(&m, w2);
    CHECK(fabsl(t[2]) > DBL_MAX && fabsl(lw) < DBL_MAX && isfinite(l) &&
              fabsl(l - lw) <= 6 * u * L && isinf(l2) && (l2 > 0) == (lw > 0),
          "(LagMult) at |lambda| = %.4Lg, its last term %.4Lg past the largest double: %.17g "
          "(%.2Lg of 6 u L); at 2 w: %g",
          lw, t[2], l, fabsl(l - lw) / (6 * u * L), l2);
    const long double se = sqrtl(0.75L * DBL_MAX / (0.5L * twice_energy_printed_terms(I, d, t)));
    const double v[2] = {(double)(se * d[0]), (double)(se * d[1])}, v2[2] = {2 * v[0], 2 * v[1]};
    const long double e2p = twice_energy_printed_terms(I, v, t);
    const double e = sus_energy(&m, v), e2 = sus_energy(&m, v2);
    CHECK(e2p > DBL_MAX && isfinite(e) &&
              fabsl(e - 0.5L * e2p) <= 4 * u * (fabsl(t[0]) + fabsl(t[1])) && isinf(e2) && e2 > 0,
          "E at %.4Lg, 2 E = %.4Lg past the largest double: %.17g; at 2 w: %g", 0.5L * e2p, e2p, e,
          e2);
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
        CHECK(fabs(sus_lagmult(&m, winf) + 27.0 / 920.0) < 1e-15 &&
                  fabs(sus_energy(&m, winf) - 0.225) < 1e-15,
              "lambda(w_inf) = %.17g, by hand -27/920; E(w_inf) = 0.225", sus_lagmult(&m, winf));
    }
}

/* Sample points around an ellipse off the origin, in all four quadrants, on the grid 2^-30 (so that
 * w +- 2^-4, the Jacobian's difference steps, are doubles: the steps are exact). */
static void sample_w(int n, double w[2])
{
    const double a = 2.0 * M_PI * n / 24.0;
    w[0] = ldexp(nearbyint(ldexp(0.7 * cos(a), 30)), -30);
    w[1] = ldexp(nearbyint(ldexp(0.4 * sin(a) + 0.1, 30)), -30);
}

/* The size of the terms each formula sums at w, the yardstick of its rounding (a near-singular I_m
 * makes them large where the sums are not). With u = SUS_U (a rounding is at most u/2), the model's
 * (ContDyn) is within 5 u F_i: |I_m| (u, compensated), a division (u/2), the products and sums of
 * fA w (u) and of c (u), their product (u/2), and u for the second order; its (LagMult) within 6 u
 * L: c, 1/|I_m| and O_0's coefficients (3.5 u), the products and sums (2.5 u). The printed side
 * errs by 2^-64 of the same terms. */
typedef struct {
    double ca;    /* |I31 w1| + |I32 w2|, c(w)'s terms */
    double Ia[2]; /* |I_i1 w1| + |I_i2 w2|, i = 1, 2 */
    double F[2];  /* ca (|I12 w1| + |I22 w2|) / |I_m| and ca (|I11 w1| + |I21 w2|) / |I_m| */
    double L;     /* |w1| Ia_2 + |w2| Ia_1 + ca / |I_m| (|O_0's coefficients| |w|) */
} terms;

static terms terms_at(const double *I, const double w[2])
{
    const double det = (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    const double o1 = fabs((double)check_cross_diff_exact(I[7], I[0], I[6], I[1]));
    const double o2 = fabs((double)check_cross_diff_exact(I[7], I[3], I[6], I[4]));
    terms t;
    t.ca = fabs(I[6] * w[0]) + fabs(I[7] * w[1]);
    t.Ia[0] = fabs(I[0] * w[0]) + fabs(I[1] * w[1]);
    t.Ia[1] = fabs(I[3] * w[0]) + fabs(I[4] * w[1]);
    t.F[0] = t.ca * (fabs(I[1] * w[0]) + fabs(I[4] * w[1])) / det;
    t.F[1] = t.ca * (fabs(I[0] * w[0]) + fabs(I[3] * w[1])) / det;
    t.L = fabs(w[0]) * t.Ia[1] + fabs(w[1]) * t.Ia[0] +
          t.ca / det * (o2 * fabs(w[1]) + o1 * fabs(w[0]));
    return t;
}

/* The worst of each measure over the sample points, as a multiple of its yardstick (pass: <= 1). */
typedef struct {
    double f, l, rgb, e, jac;
} worst_ratios;

/* (ContDyn) and (LagMult) of the model against the printed ones; (RGB2)'s three rows and <grad E,
 * f>, each 0 for the exact f and lambda: within the model's error times the row's I (7 u with the
 * row's own products and sums) plus 2 u of the row's other terms, so 8 u of all of them. */
static void against_printed(const sus_model *m, const double *I, const double w[2], worst_ratios *r)
{
    const terms t = terms_at(I, w);
    const double u = SUS_U;
    double f[2];
    long double g[2];
    sus_contdyn(m, w, f);
    contdyn_printed_l(I, w, g);
    r->f = fmax(r->f,
                fmax(fabsl(f[0] - g[0]) / (5 * u * t.F[0]), fabsl(f[1] - g[1]) / (5 * u * t.F[1])));
    const double lam = sus_lagmult(m, w);
    r->l = fmax(r->l, (double)(fabsl(lam - lagmult_printed(I, w)) / (6 * u * t.L)));
    const double Iw[3] = {I[0] * w[0] + I[1] * w[1], I[3] * w[0] + I[4] * w[1],
                          I[6] * w[0] + I[7] * w[1]};
    /* (RGB2): I (w1', w2', 0)
     *         = (-w2 (I_3i w_i), w1 (I_3i w_i), w2 (I_1i w_i) - w1 (I_2i w_i)) + lambda e3 */
    const double r0 = I[0] * f[0] + I[1] * f[1] + w[1] * Iw[2];
    const double r1 = I[3] * f[0] + I[4] * f[1] - w[0] * Iw[2];
    const double r2 = I[6] * f[0] + I[7] * f[1] - (w[1] * Iw[0] - w[0] * Iw[1]) - lam;
    const double y0 = fabs(I[0]) * t.F[0] + fabs(I[1]) * t.F[1] + fabs(w[1]) * t.ca;
    const double y1 = fabs(I[3]) * t.F[0] + fabs(I[4]) * t.F[1] + fabs(w[0]) * t.ca;
    const double y2 = fabs(I[6]) * t.F[0] + fabs(I[7]) * t.F[1] + t.L;
    const double rgb = fmax(fabs(r0) / y0, fmax(fabs(r1) / y1, fabs(r2) / y2)) / (8 * u);
    r->rgb = fmax(r->rgb, rgb);
    /* E = 1/2 <I_m w, w> is a first integral of (ContDyn): <grad E, f> = 0 */
    r->e = fmax(r->e, fabs(Iw[0] * f[0] + Iw[1] * f[1]) /
                          (8 * u * (t.Ia[0] * t.F[0] + t.Ia[1] * t.F[1])));
}

/* f is quadratic, so a central difference is its derivative exactly at any step: h = 2^-4, with
 * w +- h doubles (sample_w), leaves the roundings of f at w +- h (5 u F each, over 2h) and of J (4
 * u of its terms: c, p and q (u), their products and sum (u), |I_m| and the division (1.5 u), and u
 * for the second order) plus u |J| for the difference itself. */
static void jacobian_by_differences(const sus_model *m, const double *I, const double w[2],
                                    worst_ratios *r)
{
    const double h = 0x1p-4, u = SUS_U, d = (double)check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    const double ca = fabs(I[6] * w[0]) + fabs(I[7] * w[1]);
    const double pa = fabs(I[4] * w[1]) + fabs(I[1] * w[0]),
                 qa = fabs(I[3] * w[1]) + fabs(I[0] * w[0]);
    const double JA[2][2] = {
        {fabs(I[1]) * ca + pa * fabs(I[6]), fabs(I[4]) * ca + pa * fabs(I[7])},
        {fabs(I[0]) * ca + qa * fabs(I[6]), fabs(I[3]) * ca + qa * fabs(I[7])}};
    double J[2][2];
    sus_contdyn_jacobian(m, w, J);
    for (int j = 0; j < 2; j++) {
        double wp[2] = {w[0], w[1]}, wm[2] = {w[0], w[1]}, fp[2], fm[2];
        wp[j] += h;
        wm[j] -= h;
        sus_contdyn(m, wp, fp);
        sus_contdyn(m, wm, fm);
        const terms tp = terms_at(I, wp), tm = terms_at(I, wm);
        for (int i = 0; i < 2; i++) {
            const double y =
                5 * u * (tp.F[i] + tm.F[i]) / (2 * h) + 4 * u * JA[i][j] / d + u * fabs(J[i][j]);
            r->jac = fmax(r->jac, fabs((fp[i] - fm[i]) / (2 * h) - J[i][j]) / y);
        }
    }
}

/* src/core/model.c against the printed formulas and against (RGB2), on the body's own rows I (read
 * from the test's array, not from the model): a row/column or sign slip moves these by the size of
 * the terms, far above the roundings each is held to (terms_at). */
static void model_vs_printed(const sus_model *m, const body *b)
{
    worst_ratios r = {0, 0, 0, 0, 0};
    for (int n = 0; n < 24; n++) {
        double w[2];
        sample_w(n, w);
        against_printed(m, b->I, w, &r);
        jacobian_by_differences(m, b->I, w, &r);
    }
    CHECK(r.f <= 1.0,
          "%s: (ContDyn) of src/core/model.c = the printed formula; worst %.2g of 5 u F", b->name,
          r.f);
    CHECK(r.l <= 1.0,
          "%s: (LagMult) of src/core/model.c = the printed formula; worst %.2g of 6 u L", b->name,
          r.l);
    CHECK(r.rgb <= 1.0,
          "%s: (ContDyn) and (LagMult) satisfy all three rows of (RGB2); worst %.2g of 8 u "
          "of the row's terms",
          b->name, r.rgb);
    CHECK(r.e <= 1.0,
          "%s: E is a first integral of (ContDyn); <grad E, f> worst %.2g of 8 u of its terms",
          b->name, r.e);
    CHECK(r.jac <= 1.0,
          "%s: Jacobian of (ContDyn) against central differences (exact for a quadratic); "
          "worst %.2g of its rounding",
          b->name, r.jac);
}

/* 1/2 (|I11| w1^2 + |I12 + I21| |w1 w2| + |I22| w2^2): the terms of E(w). */
static double energy_terms(const double *I, const double w[2])
{
    const double cross = fabs(I[1] + I[3]) * fabs(w[0] * w[1]);
    return 0.5 * (fabs(I[0]) * w[0] * w[0] + cross + fabs(I[4]) * w[1] * w[1]);
}

/* The steady rotation w* = L^{-T} r (-sin beta, cos beta) of exact.h, where c = <v, u> = 0 and E =
 * E0. Computed, it is off by roundings that the yardsticks count (a rounding is u/2 or less):
 *   - c(w*): its own products and sum (u ca), w1*'s back-substitution (u |I31 l21 w2*| / l11) and
 *     the direction (cos beta, sin beta) (2 u r (|v1 sin beta| + |v2 cos beta|)): 4 u of their sum;
 *   - E(w*) - E0: each E rounds 2 u of its terms, r = |L^T w0| u E0, and the back-substitution
 *     u |(I_m w*)_1 l21 w2*| / l11: 4 u of their sum. */
static void steady_rotation_checks(const sus_model *m, const body *b, const sus_exact *ex)
{
    const double *I = b->I, u = SUS_U, E0 = sus_energy(m, b->w0);
    double wl[2], wm[2];
    sus_exact_limit(ex, wl);
    sus_exact_omega(ex, -1e6, wm);
    const double c = I[6] * wl[0] + I[7] * wl[1], back = fabs(ex->l21 * wl[1]) / ex->l11;
    const double v1 = I[6] / ex->l11, v2 = (I[7] - ex->l21 * v1) / ex->l22;
    const double yc = fabs(I[6] * wl[0]) + fabs(I[7] * wl[1]) + fabs(I[6]) * back +
                      2.0 * ex->r * (fabs(v1 * ex->sb) + fabs(v2 * ex->cb));
    const double ye = energy_terms(I, wl) + energy_terms(I, b->w0) + E0 +
                      (fabs(I[0] * wl[0]) + fabs(I[1] * wl[1])) * back;
    const double de = fabs(sus_energy(m, wl) - E0), dm = fabs(sus_energy(m, wm) - E0);
    CHECK(fabs(c) <= 4 * u * yc && de <= 4 * u * ye,
          "%s: the steady rotation has I31 w1 + I32 w2 = %.1e (%.2g of 4 "
          "u of its terms) and E - E0 = %.1e (%.2g of 4 u of its terms)",
          b->name, c, fabs(c) / (4 * u * yc), de, de / (4 * u * ye));
    CHECK(
        isfinite(wm[0]) && isfinite(wm[1]) && dm <= 4 * u * ye,
        "%s: w(-1e6) is finite (the repelling rotation) and on the energy ellipse (E - E0 = %.1e)",
        b->name, dm);
}

/* |I_m|, O_0's coefficients (model.c) and the closed form's l22 and direction beta (exact.c), each
 * formed as a b - c d with sus_cross_diff, against the same differences exact (check_exact.h). The
 * compensated form rounds twice (u/2 each), so each is within u of its own size however much a b
 * and c d cancel; formed plainly they would err by u/2 of |a b| + |c d|, cond(I_m) times more on a
 * near-singular I_m (the stiff bodies "cond" and "all"). Then l11 l22 = sqrt|I_m| within 2 u
 * (|I_m|, the square root, the division by l11 and this product), and tan beta = v2 / v1 = (I11 I32
 * - I21 I31) / (I31 sqrt|I_m|) within 6 u (v2 3.5 u, v1 u, the two divisions by |v| u, and u for
 * the test's side). */
static void compensated_checks(const sus_model *m, const body *b, const sus_exact *ex)
{
    const double *I = b->I, u = SUS_U;
    const long double det = check_cross_diff_exact(I[0], I[4], I[1], I[3]);
    const long double o1 = check_cross_diff_exact(I[7], I[0], I[6], I[1]);
    const long double o2 = check_cross_diff_exact(I[7], I[3], I[6], I[4]);
    const long double x = check_cross_diff_exact(I[0], I[7], I[3], I[6]), sd = sqrtl(det);
    const double dd = (double)(fabsl(m->det_m - det) / det);
    const double d1 = (double)fabsl((m->o0c[0] - o1) / o1),
                 d2 = (double)fabsl((m->o0c[1] - o2) / o2);
    const double dl = (double)fabsl(((long double)ex->l11 * ex->l22 - sd) / sd);
    const long double sbx = (long double)ex->sb * I[6] * sd, cbx = (long double)ex->cb * x;
    const double db = (double)(fabsl(sbx - cbx) / (fabsl(sbx) + fabsl(cbx)));
    CHECK(dd <= u && d1 <= u && d2 <= u,
          "%s: |I_m| and O_0's coefficients against the exact differences: "
          "%.2g, %.2g, %.2g u (at most u)",
          b->name, dd / u, d1 / u, d2 / u);
    CHECK(dl <= 2 * u && db <= 6 * u,
          "%s: the closed form's l11 l22 against sqrt|I_m| exact: %.2g u "
          "(at most 2 u); its direction beta: %.2g u (at most 6 u)",
          b->name, dl / u, db / u);
}

/* The closed form against rk8pd at tolerance 1e-13 over [0, 100 s] (an adaptive method at that
 * tolerance over ~1500 steps keeps a global error of order 1e-12), and its limit. */
static void closed_form(const sus_model *m, const body *b)
{
    const double s = check_body_time(m, b->w0), d = exact_vs_rk8pd(m, b->I, b->w0, s);
    CHECK(d < 1e-11,
          "%s: closed form = rk8pd (tol 1e-13) of the printed (ContDyn) on [0, 100 s], s = %.3g "
          "the body's time; max diff %.2e",
          b->name, s, d);
    sus_exact ex;
    sus_exact_init(&ex, m, b->w0);
    double wl[2], wt[2];
    sus_exact_limit(&ex, wl);
    sus_exact_omega(&ex, 1e6, wt);
    CHECK(isfinite(wt[0]) && isfinite(wt[1]) && hypot(wt[0] - wl[0], wt[1] - wl[1]) < 1e-15,
          "%s: w(1e6) is finite and equals the steady rotation (%.17g, %.17g)", b->name, wt[0],
          wt[1]);
    steady_rotation_checks(m, b, &ex);
    compensated_checks(m, b, &ex);
}

/* The paper's body: closed form for w(0) around the ellipse (both branches sign(cos psi0)), the
 * rate k, and the steady rotations as fixed points. */
static void paper_closed_form(const sus_model *m)
{
    double ring = 0.0;
    for (int n = 0; n < 12; n++) {
        const double a = 2.0 * M_PI * (n + 0.25) / 12.0, w0[2] = {0.64 * cos(a), 0.64 * sin(a)};
        ring = fmax(ring, exact_vs_rk8pd(m, SUS_PAPER_INERTIA, w0, 1.0));
    }
    CHECK(ring < 1e-11,
          "closed form = rk8pd on [0, 100] for 12 w(0) around the ellipse; max diff %.2e", ring);
    sus_exact ex;
    double wl[2], wq[2];
    sus_exact_init(&ex, m, SUS_PAPER_OMEGA0);
    sus_exact_limit(&ex, wl);
    CHECK(ex.k > 0.145 && ex.k < 0.146, "rate of approach k = %.6f for the paper's body and w(0)",
          ex.k);
    /* The steady rotations are equilibria. The attracting one stays put; the repelling one,
     * known only to round-off (~1e-16), is left at the rate k: by t = 50 the departure is
     * about 1e-16 e^{50 k} ~ 1e-13, so 1e-12 bounds it. */
    sus_exact_init(&ex, m, wl);
    sus_exact_omega(&ex, 50.0, wq);
    CHECK(hypot(wq[0] - wl[0], wq[1] - wl[1]) < 1e-15,
          "the attracting steady rotation is a fixed point of the closed form");
    const double weq[2] = {-wl[0], -wl[1]};
    sus_exact_init(&ex, m, weq);
    sus_exact_omega(&ex, 50.0, wq);
    const double dep = hypot(wq[0] - weq[0], wq[1] - weq[1]);
    CHECK(dep < 1e-12,
          "the repelling steady rotation is left only at round-off times e^{kt}: %.2e at t = 50",
          dep);
}

/* A body whose third row has I31 = I32 = 0: c(w) = 0 for every w, so (ContDyn) keeps w(t) = w(0).
 * The closed form must return w(0) itself (exactly: nothing is computed) at every t and as the
 * limit. */
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
          "%s with I31 = I32 = 0: w(t) = w(0) = (%g, %g) on [0, 100] and as the limit, exactly",
          b->name, b->w0[0], b->w0[1]);
}

int main(void)
{
    gsl_set_error_handler_off();
    char err[256], about[200];
    validation();
    extreme_bodies();
    near_overflow();
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
