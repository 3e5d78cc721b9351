/* Proposition 5.3's limit: the multiplier of the variational integrator, (38) as printed, tends
 * to lambda - O_0 as eps -> 0, on the paper's body and on every body of tests/unit/bodies.h. */
#include "claims_paper.h"

#include "claims_bodies.h"
#include "ledger.h"
#include "registry.h"
#include "dsp.h"

#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdio.h>

/* max over s of |sech'''(s)| = |sech s tanh s (5 - 6 tanh^2 s)|: 1.52443 at s = +-0.509, rounded
 * up. */
#define SECH3_MAX 1.525
/* eps_i k = k_paper 2^-(LIM_J0 + i), i < LIM_N (eps_i = 2^-(LIM_J0 + i) on the paper's body):
 * small enough that the eps^2 term is a 1e-7 part of the intercept, large enough that the
 * differences stay far above round-off. */
#define LIM_J0 10
#define LIM_N 5
/* The limit is O_0, not 0, when every body's fitted limit lies this many bounds away from 0 at
 * some t_k: a line expecting 0 would fail there by two orders of magnitude at least. */
#define LIM_NOT_ZERO 100.0

/* One body's a-priori sizes, from its closed form (src/core/exact.h): c(w(t)) = C0 sigma sech s
 * with s = s0 + sigma k t and C0 = k det L, so |c'''| <= SECH3_MAX k^3 C0 = c3. The quantity
 * fitted, y(eps) = lambda(t_k+eps) - lambda_{k+1}, has (taualg) = the mean of (LagMult)'s
 * quadratic part Q at w^k and w^{k+1} = w(t_k+eps) + O(eps^3) (p = 2), and lambda = Q + O_0 with
 * O_0 = c', so y = c'(t_k+eps) + (Q(t_k+eps) - Q(t_k))/2 + O(eps^3): its eps^2 coefficient is
 * a = c'''/2 + Q''/4. With u = L^T w = r (cos th, sin th), Q = u^T M u (M = L^-1 S L^-T, S the
 * symmetric matrix of Q) = r^2 (mean + R cos(2 th - phi)), R half the spread of M's eigenvalues;
 * th' = k cos psi gives |Q''| <= r^2 R (2 |th''| + 4 th'^2) <= (2 + sqrt 5) k^2 r^2 R. So
 * |a| <= amax = c3 / 2 + (2 + sqrt 5) k^2 r^2 R / 4, at every t_k. */
typedef struct {
    double c3, amax;
} lim_sizes;

static lim_sizes lim_sizes_of(const sus_exact *bex)
{
    const double(*I)[3] = bex->model->I, k = bex->k;
    /* Q(w) = w1 (I21 w1 + I22 w2) - w2 (I11 w1 + I12 w2), (LagMult)'s first line */
    const double s11 = I[1][0], s12 = 0.5 * (I[1][1] - I[0][0]), s22 = -I[0][1];
    /* L^-1 = [[1/l11, 0], [-l21/(l11 l22), 1/l22]] */
    const double g11 = 1.0 / bex->l11, g21 = -bex->l21 / (bex->l11 * bex->l22),
                 g22 = 1.0 / bex->l22;
    const double m11 = g11 * g11 * s11;
    const double m12 = g11 * (g21 * s11 + g22 * s12);
    const double m22 = g21 * g21 * s11 + 2.0 * g21 * g22 * s12 + g22 * g22 * s22;
    const double R = hypot(0.5 * (m11 - m22), m12);
    lim_sizes z;
    z.c3 = SECH3_MAX * k * k * k * (k * bex->l11 * bex->l22);
    z.amax = 0.5 * z.c3 + 0.25 * (2.0 + sqrt(5.0)) * k * k * bex->r * bex->r * R;
    return z;
}

/* c(w(t)) = I31 w1 + I32 w2 from the third row as printed and the closed form. */
static double c_of_t(const sus_exact *bex, double t)
{
    double w[2];
    sus_exact_omega(bex, t, w);
    return bex->model->I[2][0] * w[0] + bex->model->I[2][1] * w[1];
}

/* O_0 = I31 w1' + I32 w2' = dc(w(t))/dt (docs/explanation/conventions.md), by a central difference
 * on the closed form and never from (LagMult): the expected value must not contain the term under
 * test. Each c(w(t)) is good to delta = 32 u |I3.|_1 W (s, exp, tanh and the triangular solve:
 * about ten roundings, each at most W = lim_w_major, doubled); the quotient errs by c3 h^2 / 6
 * (truncation) + delta / h (round-off), least at h^3 = 3 delta / c3. Returns O_0 and its error
 * bound in *err. */
static double o0_closed_form(const sus_exact *bex, double c3, double W, double t, double *err)
{
    const double delta = 32.0 * SUS_U * (fabs(bex->model->I[2][0]) + fabs(bex->model->I[2][1])) * W;
    const double h = cbrt(3.0 * delta / c3), tp = t + h, tm = t - h;
    *err = c3 * h * h / 6.0 + delta / h;
    return (c_of_t(bex, tp) - c_of_t(bex, tm)) / (tp - tm); /* the step between the rounded times */
}

/* The fit's constants, from the fit itself: the intercept of the line fitted to eps^2 over
 * eps_i = eps1 2^-i, i < 5, is -(155/64) eps1 eps5 (for two points it would be -eps1 eps5), so a
 * term a eps^2 moves the intercept by (155/64) |a| eps1 eps5; and the intercept is sum w_i y_i
 * with sum |w_i| = 17/12, the factor on a rounding of the y_i. */
static void lim_fit_constants(const double *x, double *quad, double *wsum)
{
    double y[LIM_N], c0, c1, c00, c01, c11, ss;
    for (int i = 0; i < LIM_N; i++)
        y[i] = x[i] * x[i];
    gsl_fit_linear(x, 1, y, 1, LIM_N, &c0, &c1, &c00, &c01, &c11, &ss);
    *quad = fabs(c0);
    *wsum = 0.0;
    for (int i = 0; i < LIM_N; i++) {
        for (int j = 0; j < LIM_N; j++)
            y[j] = i == j;
        gsl_fit_linear(x, 1, y, 1, LIM_N, &c0, &c1, &c00, &c01, &c11, &ss);
        *wsum += fabs(c0);
    }
}

typedef struct {
    double dev, bound, limit; /* max over t_k of |c0 - O_0|, the bound, max over t_k of |c0| */
} lim_body;

/* The largest |w| on the body's energy ellipse, r / sqrt(lambda_min(I_m)): the yardstick of the
 * closed form's w = L^-T u, whose rounding is a few u r |L^-1| in every direction, so up to
 * sqrt(cond(I_m)) times |w| itself where the motion crosses the ellipse's short axis. */
static double lim_w_major(const sus_exact *bex)
{
    const double(*I)[3] = bex->model->I;
    const double lmax = 0.5 * (I[0][0] + I[1][1]) + hypot(0.5 * (I[0][0] - I[1][1]), I[0][1]);
    return bex->r * sqrt(lmax / bex->model->det_m);
}

/* One variational step of eps from w(tk): y = lambda(tk+eps) - lambda_{k+1} (as
 * sus_lab_local_errors forms it), and the bound on the Newton root's rounding from its residual,
 * |dx|_inf <= |J^-1|_inf (|G(x)| + 8 u scale) (8 u scale: the rounding of G's own evaluation). */
static double lim_step(const sus_exact *bex, double tk, double eps, double *dx)
{
    const sus_model *m = bex->model;
    double wk[3] = {0.0, 0.0, 0.0}, we[2], x[3], lam, g[2], J[4], scale;
    sus_stepper_stats st;
    sus_exact_omega(bex, tk, wk);
    sus_exact_omega(bex, tk + eps, we);
    if (sus_step_variational->step->apply(m, eps, wk, x, &lam, &st) != SUS_STEPPER_OK)
        ledger_die("variational local step");
    sus_step_variational->equation->residual(m, eps, wk, x, g, J, &scale);
    const double det = fabs(J[0] * J[3] - J[1] * J[2]);
    const double jinv = fmax(fabs(J[3]) + fabs(J[1]), fabs(J[2]) + fabs(J[0])) / det;
    *dx = jinv * (st.residual + 8.0 * SUS_U * scale);
    return sus_lagmult(m, we) - lam;
}

/* The round-off of one y_i, from the size of its terms: the Newton root's dx through (taualg)'s
 * gradient, 0.5 |grad Q(x)| <= |I_m|_1 W (|I_m|_1 = sum_{i,j<=2} |I_ij|, W = lim_w_major), and
 * 64 u times the terms of (LagMult) and (taualg) evaluated at the closed form's w (off by a few
 * u W): Q's, |I_m|_1 W^2, and O_0's, |b|_1 W |o0c|_1 W / |I_m|. On a near-singular I_m the last
 * two carry the cancellation: O_0 = c(w)' is far smaller than its terms. */
static double lim_roundoff(const sus_model *m, double W, double dx)
{
    const double(*I)[3] = m->I;
    const double im = fabs(I[0][0]) + fabs(I[0][1]) + fabs(I[1][0]) + fabs(I[1][1]);
    const double to =
        (fabs(m->b[0]) + fabs(m->b[1])) * (fabs(m->o0c[0]) + fabs(m->o0c[1])) / m->det_m;
    return im * W * dx + 64.0 * SUS_U * (im + to) * W * W;
}

/* One body in its own time: eps_i k and t_k k those of the paper's body (scale = k_paper / k, 1
 * on the paper's), so that every body is sampled at the same phase of its transient and the same
 * eps k. The bound: twice (155/64) amax eps1 eps5 (2: the eps^3 terms move the intercept by
 * 1.24 eps1 times their coefficient, a part 1.24 eps1 k ~ 2e-4 of the eps^2 term's where each
 * order brings a factor k, and amax bounds the leading term only), plus the rounding of the y_i
 * (lim_roundoff) times 17/12, plus O_0's own error. */
static lim_body lim_measure(const sus_exact *bex, double scale)
{
    double x[LIM_N], quad, wsum;
    for (int i = 0; i < LIM_N; i++)
        x[i] = scale * ldexp(1.0, -LIM_J0 - i);
    lim_fit_constants(x, &quad, &wsum);
    const lim_sizes z = lim_sizes_of(bex);
    const double W = lim_w_major(bex);
    lim_body r = {0.0, 0.0, 0.0};
    double extra = 0.0;
    for (int t = 0; t < PAPER_NTK; t++) {
        const double tk = PAPER_TK[t] * scale;
        double y[LIM_N], c0, c1, c00, c01, c11, ss, o0err, dx = 0.0;
        for (int i = 0; i < LIM_N; i++) {
            double d;
            y[i] = lim_step(bex, tk, x[i], &d);
            dx = fmax(dx, d);
        }
        gsl_fit_linear(x, 1, y, 1, LIM_N, &c0, &c1, &c00, &c01, &c11, &ss);
        const double o0 = o0_closed_form(bex, z.c3, W, tk, &o0err);
        extra = fmax(extra, wsum * lim_roundoff(bex->model, W, dx) + o0err);
        r.dev = fmax(r.dev, fabs(c0 - o0));
        r.limit = fmax(r.limit, fabs(c0));
    }
    r.bound = 2.0 * quad * z.amax + extra;
    return r;
}

/* The limit against O_0 on the paper's body and the general and stiff ones (tests/unit/bodies.h),
 * the body nearest its bound reported; and the control that the limit is not 0 on any body. */
void multiplier_limit_claims(const claims_paper *p)
{
    lim_body worst = {0.0, 1.0, 0.0};
    double far = INFINITY;
    char worst_name[16] = "", far_name[16] = "", text[640];
    for (int k = 0; k < BODIES_COUNT; k++) {
        const claims_body *d = claims_body_get(k);
        if (d->ex.fixed)
            ledger_die("a body of tests/unit/bodies.h at a steady rotation");
        const lim_body r = lim_measure(&d->ex, p->ex.k / d->ex.k);
        if (r.dev / r.bound >= worst.dev / worst.bound) {
            worst = r;
            snprintf(worst_name, sizeof worst_name, "%s", d->b.name);
        }
        if (r.limit / r.bound < far) {
            far = r.limit / r.bound;
            snprintf(far_name, sizeof far_name, "%s", d->b.name);
        }
    }
    snprintf(
        text, sizeof text,
        "max over $t_k$ of $|\\lim_{\\varepsilon \\to 0} (\\lambda(t_k+\\varepsilon) - "
        "\\lambda_{k+1}) - O_0(\\omega(t_k))|$, \\eqref{taualg} as printed, fit over "
        "$\\varepsilon \\in [2^{-14}, 2^{-10}]$ $k_\\mathrm{paper}/k$ (the body's own time); "
        "expected $O_0$ by a central difference of $c(\\omega(t))$ on the closed form, not from "
        "\\eqref{LagMult}; %d bodies (worst: %s); bound $2 (155/64) A \\varepsilon_1 "
        "\\varepsilon_5$ + round-off, $A \\ge |a|$ from the closed form: the limit is $O_0$",
        BODIES_COUNT, worst_name);
    ledger_add("lambda-limit-variational", "\\PaperRefOr{PropoFinal}, proof", text, worst.dev, 0.0,
               worst.bound, LEDGER_REPRODUCED);
    snprintf(text, sizeof text,
             "smallest over %d bodies (%s) of max over $t_k$ of $|\\lim_{\\varepsilon "
             "\\to 0} (\\lambda(t_k+\\varepsilon) - \\lambda_{k+1})|$ over "
             "the bound above: $\\ge %g$, the limit is not 0",
             BODIES_COUNT, far_name, LIM_NOT_ZERO);
    ledger_add_bound("lambda-limit-variational-not-zero", "\\PaperRefOr{PropoFinal}, proof", text,
                     far, LIM_NOT_ZERO, 1, LEDGER_REPRODUCED);
}
