/* The exact run's multiplier (exact.h: c(t) in closed form, sus_lagmult_c) against (LagMult)
 * evaluated in long double at the closed-form w AND c, both formed here from the same double
 * inputs (u_ld = 2^-64, 2^-11 of a double rounding), on every test body and on near-singular
 * bodies whose steady rotation makes I31 w1 + I32 w2 cancel; and motions whose k underflows. */
#include "check.h"
#include "check_body.h"
#include "check_exact.h"
#include "exact.h"
#include "exact_run.h"

#include <float.h>
#include <math.h>

typedef struct {
    long double l11, l21, l22, det, r, vn, cb, sb, k, sigma, s0, o0c[2];
} ref_form;

/* The closed form of exact.h in long double, from the model's doubles. */
static void ref_init(ref_form *f, const sus_model *m, const double w0[2])
{
    const double(*I)[3] = m->I, *b = m->b;
    f->det = check_cross_diff_exact(I[0][0], I[1][1], I[1][0], I[1][0]);
    f->l11 = sqrtl(I[0][0]);
    f->l21 = I[1][0] / f->l11;
    f->l22 = sqrtl(f->det) / f->l11;
    const long double u1 = check_cross_diff_exact(I[0][0], w0[0], -I[1][0], w0[1]) / f->l11;
    const long double u2 = f->l22 * w0[1];
    const long double v1 = b[0] / f->l11;
    const long double v2 =
        check_cross_diff_exact(I[0][0], b[1], I[1][0], b[0]) / (f->l11 * sqrtl(f->det));
    f->vn = hypotl(v1, v2);
    f->r = hypotl(u1, u2);
    f->cb = v1 / f->vn;
    f->sb = v2 / f->vn;
    const long double C = check_cross_diff_exact(b[0], w0[0], -b[1], w0[1]) / (f->vn * f->r);
    const long double S = (v1 * u2 - v2 * u1) / (f->vn * f->r);
    f->k = f->r * f->vn / (f->l11 * f->l22);
    f->sigma = C > 0 ? 1 : -1;
    f->s0 = asinhl(S / C);
    f->o0c[0] = check_cross_diff_exact(I[2][1], I[0][0], I[2][0], I[0][1]);
    f->o0c[1] = check_cross_diff_exact(I[2][1], I[1][0], I[2][0], I[1][1]);
}

typedef struct {
    long double lambda, terms, o0, s, grad, Mf;
} ref_value;

/* w, c and (LagMult) at t; with the sizes the bound below is made of. */
static void ref_at(const ref_form *f, const sus_model *m, double t, ref_value *v)
{
    const double(*I)[3] = m->I;
    const long double s = f->s0 + f->sigma * f->k * (long double)t;
    const long double ch = f->sigma / coshl(s), th = f->sigma * tanhl(s);
    const long double u1 = f->r * (f->cb * ch - f->sb * th), u2 = f->r * (f->sb * ch + f->cb * th);
    const long double w1 = u2 / f->l22, w0 = (u1 - f->l21 * w1) / f->l11;
    const long double c = f->sigma * f->r * f->vn / coshl(s);
    const long double t1 = w0 * (I[1][0] * w0), t2 = w0 * (I[1][1] * w1);
    const long double t3 = w1 * (I[0][0] * w0), t4 = w1 * (I[0][1] * w1);
    const long double g0 = f->o0c[1] * w1, g1 = f->o0c[0] * w0;
    v->lambda = t1 + t2 - t3 - t4 + c / f->det * (g0 + g1);
    v->o0 = fabsl(c / f->det) * (fabsl(g0) + fabsl(g1));
    v->terms = fabsl(t1) + fabsl(t2) + fabsl(t3) + fabsl(t4) + v->o0;
    v->s = fabsl(s);
    const long double In = sqrtl((long double)I[0][0] * I[0][0] + 2.0L * I[1][0] * I[1][0] +
                                 (long double)I[1][1] * I[1][1]);
    v->grad = 2 * In * hypotl(w0, w1) + fabsl(c / f->det) * hypotl(f->o0c[0], f->o0c[1]);
    const long double a = 1 / f->l11, b = 1 / f->l22, d = f->l21 / (f->l11 * f->l22);
    v->Mf = f->r * sqrtl(a * a + b * b + d * d);
}

/* Bound, fixed before measuring from the rounding of each part (u = DBL_EPSILON):
 *  - (LagMult)'s sum of products at the rounded w: a few roundings of its terms, |terms|;
 *  - c(t) = sigma r |v| sech s: a few roundings of c, and s's own rounding u |s| (s = s0 + sigma k
 *    t rounded, k rounded) times tanh s: (few + |s|) u relative, on the term O_0;
 *  - w itself (exact.h, exact_fast.h) within a few u |M|_F of the closed form (M = r L^{-T}
 *    Rot(beta)), which moves lambda at fixed c by at most |grad| = 2 |I_m|_F |w| + |c| |o0c| /
 *    |I_m| times that.
 * "A few" is at most eight roundings each: 8 u. The long-double reference adds 2^-11 of that. */
static long double bound(const ref_value *v)
{
    return 8.0L * DBL_EPSILON * (v->terms + v->s * v->o0 + v->grad * v->Mf);
}

/* lambda from the library at t (c from the closed form), against the long-double value; returns
 * the error over the bound's part from the terms alone (8 u |terms|), to report. */
static double one_time(const sus_exact *ex, const ref_form *f, double t, double *worst)
{
    double w[2];
    ref_value v;
    sus_exact_omega(ex, t, w);
    const double lam = sus_lagmult_c(ex->model, w, sus_exact_c(ex, t));
    ref_at(f, ex->model, t, &v);
    const long double err = fabsl(lam - v.lambda);
    const double ratio = (double)(err / bound(&v));
    *worst = fmax(*worst, isnan(ratio) ? INFINITY : ratio);
    return (double)(err / (8.0L * DBL_EPSILON * v.terms));
}

/* Over t = 0 and 1e-3 .. 1e3 of the time scale 1 / k, and the row grid t = 1 .. 4. */
static void check_motion(const char *name, const double I9[9], const double w0[2])
{
    sus_model m;
    sus_exact ex;
    ref_form f;
    if (sus_model_init(&m, I9, NULL, 0) != 0 || sus_exact_init(&ex, &m, w0) != 0 || ex.fixed) {
        CHECK(0, "%s: a moving closed form", name);
        return;
    }
    ref_init(&f, &m, w0);
    double worst = 0.0, terms_only = 0.0;
    for (int j = -3; j <= 3; j++)
        for (int q = 1; q <= 3; q++) {
            const double r = one_time(&ex, &f, q * pow(10.0, j) / ex.k, &worst);
            terms_only = fmax(terms_only, r);
        }
    for (int t = 0; t <= 4; t++)
        terms_only = fmax(terms_only, one_time(&ex, &f, t, &worst));
    CHECK(worst <= 1.0,
          "%s: exact's lambda against (LagMult) in long double at the closed-form w "
          "and c: worst error / bound %.3g (error / 8 u |terms| alone: %.3g)",
          name, worst, terms_only);
}

static int keep_lambda(void *ctx, const sus_row *r)
{
    *(double *)ctx = r->lambda;
    return 0;
}

/* The run's rows print that lambda: on I_m = diag(1, 1e-12), I31, I32 = 8, 4, w0 = (1, 1), the
 * motion is at its steady rotation w* = a (-1, 2) by t = 1 (k = 8e6: e^{-8e6} of the way left),
 * where c(w*) = 0 and (LagMult) is -2 a^2 (I12 ... ) = 2 a^2 (1 - 1e-12) with 1/2 <I_m w*, w*> =
 * E(w0): a^2 (1 + 4e-12) = 1 + 1e-12. Bound: a few roundings of the terms, about 2 each: 8 u 4. */
static void check_rows(void)
{
    static const double I9[9] = {1, 0, 0, 0, 1e-12, 0, 8, 4, 1}, w0[2] = {1, 1};
    sus_model m;
    sus_model_init(&m, I9, NULL, 0);
    const sus_run_config cfg = {.model = &m, .eps = 1.0, .steps = 1, .every = 1};
    sus_run_report rep;
    double lam = NAN;
    const int rc = sus_run_exact(&cfg, w0, keep_lambda, &lam, &rep);
    const long double e2 = 1e-12L, a2 = (1 + e2) / (1 + 4 * e2), want = 2 * a2 * (1 - e2);
    const double err = (double)fabsl(lam - want);
    CHECK(rc == SUS_RUN_OK && err <= 32 * DBL_EPSILON,
          "exact run on diag(1, 1e-12), b = (8, 4): "
          "lambda(t = 1) = %.17g, by hand 2 a^2 (1 - 1e-12) = %.17Lg (error %.3g)",
          lam, want, err);
}

/* k underflows: the motion is fixed (exact.h), w = w0 and c = c(w0), never NaN. */
static void check_underflow(void)
{
    static const struct {
        double I31, I32, w0[2];
    } cases[] = {
        {1e-200, 0, {1e-160, 0}}, {1e-160, 0, {1e-200, 1e-200}}, {0, -1e-300, {1e-30, 1e-40}}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const double I9[9] = {1, 0, 0, 0, 1, 0, cases[i].I31, cases[i].I32, 1};
        sus_model m;
        sus_exact ex;
        sus_model_init(&m, I9, NULL, 0);
        const int rc = sus_exact_init(&ex, &m, cases[i].w0);
        double w[2];
        sus_exact_omega(&ex, 1e300, w);
        const double c = sus_exact_c(&ex, 1e300);
        CHECK(rc == 0 && ex.fixed && w[0] == cases[i].w0[0] && w[1] == cases[i].w0[1] &&
                  c == sus_c(&m, cases[i].w0),
              "k underflows (I31, I32 = %g, %g; w0 = %g, %g): fixed, w(1e300) = w0, c = c(w0) "
              "(rc %d, fixed %d, w = %g, %g)",
              cases[i].I31, cases[i].I32, cases[i].w0[0], cases[i].w0[1], rc, ex.fixed, w[0], w[1]);
    }
}

/* A start within 2^-1060 of the repelling rotation: S / C overflows, s0 must stay finite. On I =
 * 1, b = (1, 0), w0 = (+-2^-1060, -1) (k = 1, |M| = 1), the motion leaves w = (0, -1) after t ~
 * ln(2^1061) ~ 735: at t = 735 it is on its way, compared with the long-double closed form
 * (whose S / C does not overflow) within 8 u 750 |M|: s0 ~ -735 carries a few roundings of ln |C|
 * ~ 735, and w moves by |M| times s's error. */
static void check_phase_overflow(void)
{
    static const double I9[9] = {1, 0, 0, 0, 1, 0, 1, 0, 1};
    for (int sg = -1; sg <= 1; sg += 2) {
        const double w0[2] = {sg * 0x1p-1060, -1.0};
        sus_model m;
        sus_exact ex;
        ref_form f;
        sus_model_init(&m, I9, NULL, 0);
        sus_exact_init(&ex, &m, w0);
        ref_init(&f, &m, w0);
        double w[2];
        sus_exact_omega(&ex, 735.0, w);
        const long double s = f.s0 + f.sigma * f.k * 735.0L;
        const long double ch = f.sigma / coshl(s), th = f.sigma * tanhl(s);
        const long double u1 = f.r * (f.cb * ch - f.sb * th), u2 = f.r * (f.sb * ch + f.cb * th);
        const long double y = u2 / f.l22, x = (u1 - f.l21 * y) / f.l11;
        const double err = (double)hypotl(w[0] - x, w[1] - y);
        CHECK(isfinite(ex.s0) && err <= 8.0 * DBL_EPSILON * 750.0,
              "w0 = (%g, -1), 2^-1060 off a "
              "steady rotation: s0 = %.17g finite, w(735) = (%.3g, %.3g), error %.3g",
              w0[0], ex.s0, w[0], w[1], err);
    }
}

/* The tester's bodies, a near-singular family of our own, and every test body. */
int main(void)
{
    static const double sing12[9] = {1, 0, 0, 0, 1e-12, 0, 8, 4, 1};
    static const double near1[9] = {1, 0.99999999, 0, 0.99999999, 1, 0, 8, 4, 1};
    static const double w11[2] = {1, 1}, w1m[2] = {1, -1}, wq[2] = {-0.3, 2};
    check_motion("diag(1, 1e-12), b = (8, 4), w0 = (1, 1)", sing12, w11);
    check_motion("diag(1, 1e-12), b = (8, 4), w0 = (-0.3, 2)", sing12, wq);
    check_motion("I12 = 0.99999999, b = (8, 4), w0 = (1, 1)", near1, w11);
    check_motion("I12 = 0.99999999, b = (8, 4), w0 = (1, -1)", near1, w1m);
    check_motion("I12 = 0.99999999, b = (8, 4), w0 = (-0.3, 2)", near1, wq);
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        body_get(k, &b);
        check_motion(b.name, b.I, b.w0);
    }
    check_rows();
    check_underflow();
    check_phase_overflow();
    return check_summary("test_exact_lambda");
}
