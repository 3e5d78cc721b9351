/* The consistency orders of the paper's methods (the general-DSP proposition, Proposition 5.1,
 * 5.3 and 4.1), and (36), on the paper's body.
 *
 * Local errors follow the paper's definition of consistency: one step from exact data at t_k,
 * compared with the exact solution at t_k + eps, for t_k in PAPER_TK; the error at eps is the
 * largest over t_k. Orders are least-squares slopes of log error against log eps. */
#include "claims_paper.h"

#include "consistency.h"
#include "dsp.h"
#include "expected_orders.h"
#include "ledger.h"
#include "mat3.h"
#include "notation.h"
#include "orderfit.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"
#include "unreduced.h"

#include <math.h>
#include <stdio.h>

#define NJ 11 /* the paper's window: eps = 2^-j, j = 0 .. 10, for the experiments in this file */

#define FIT_EPS_MAX SUS_LAB_FIT_EPS_MAX
#define FIT_FLOOR_REL SUS_LAB_FIT_FLOOR_REL
#define SIZE_W SUS_LAB_SIZE_W
#define SIZE_LAMBDA SUS_LAB_SIZE_LAMBDA
#define SIZE_R SUS_LAB_SIZE_R
/* An order is an integer; a tenth of the gap between consecutive orders tells p from p +- 1
 * unambiguously and leaves room for the O(k eps) bend over the window. */
#define ORDER_TOL 0.1

/* The window and the floor of every order line of this file, as its quantity states them. */
#define WINDOW_TEXT                                                                                \
    "fit over $\\varepsilon \\in [2^{-10}, 2^{-2}]$, errors above $1000\\,u \\times "              \
    "\\mathrm{size}$"

static double eps_of(int j) { return ldexp(1.0, -j); }

/* Order p of a local error (slope - 1) or of a global one (slope) of a quantity of the given
 * size, over eps[0..n-1] up to eps_max; SO(3) errors (size SIZE_R) also note the smallest error
 * fitted. */
static double fit_on(const double *eps, const double *err, int n, int local, double size,
                     double eps_max)
{
    const double floor = FIT_FLOOR_REL * size;
    sus_lab_order_fit f;
    for (int j = 0; j < n; j++)
        if (size == SIZE_R && eps[j] <= eps_max && err[j] > floor)
            ledger_keep_min(local ? CLAIMS_MIN_SO3_LOCAL : CLAIMS_MIN_SO3_GLOBAL, err[j]);
    if (sus_lab_fit_order(eps, err, n, eps_max, floor, &f) != 0)
        return NAN;
    return f.slope - (local ? 1.0 : 0.0);
}

/* The same over eps = 2^-j, j = 0 .. NJ-1, in the paper's window. */
static double fit(const double *err, int local, double size)
{
    double eps[NJ];
    for (int j = 0; j < NJ; j++)
        eps[j] = eps_of(j);
    return fit_on(eps, err, NJ, local, size, FIT_EPS_MAX);
}

static void order_line(const char *id, const char *ref, const char *what, double measured,
                       double expected, ledger_assert truth)
{
    char q[512];
    snprintf(q, sizeof q, "%s; " WINDOW_TEXT, what);
    ledger_add(id, ref, q, measured, expected, ORDER_TOL, truth);
}

/* ---- local errors of the four DSPs, their multipliers and the reconstructions ---- */

/* The expected orders of a registered method; a method the table does not know fails here, so
 * no expected value is ever taken from the stepper under test. */
static const expected_order *expected(const sus_stepper_type *st)
{
    const expected_order *e = expected_order_of(st->name);
    if (!e) {
        char id[64];
        snprintf(id, sizeof id, "expected-order-known-%s", st->name);
        ledger_add_bound(id, "\\texttt{tests/ledger/expected\\_orders.c}",
                         "the method has a stated order to test against: 1 when it does", 0.0, 1.0,
                         1, LEDGER_EXTENSION);
    }
    return e;
}

/* min(a, b) that stays NaN when either is: C's fmin drops a NaN, and a failed fit must fail. */
static double min_nan(double a, double b) { return isnan(a) || isnan(b) ? NAN : fmin(a, b); }

/* p and s of one of the paper's methods; returns p. */
static double reduced_orders(const sus_step_method *me, const sus_lab_convergence *conv, int s,
                             const expected_order *eo)
{
    char id[64], what[256];
    const sus_stepper_type *st = me->type;
    const sus_lab_conv_method *cm = &conv->m[s];
    const double p = fit_on(conv->eps, cm->loc_w, SUS_LAB_CONV_NJ, 1, SIZE_W, FIT_EPS_MAX);
    snprintf(id, sizeof id, "reduced-order-%s", st->name);
    snprintf(what, sizeof what,
             "$p$: local slope of $|\\omega(t_k+\\varepsilon) - \\omega^{k+1}|$ minus 1, %s",
             st->name);
    order_line(id, eo->ref, what, p, eo->p, me->paper_ref ? LEDGER_REPRODUCED : LEDGER_EXTENSION);
    if (eo->s > 0) {
        snprintf(id, sizeof id, "lambda-order-%s", st->name);
        snprintf(what, sizeof what,
                 "$s$: local slope of $|\\lambda(t_k+\\varepsilon) "
                 "- \\lambda(\\omega^{k+1})|$ minus 1, %s",
                 st->name);
        order_line(id, eo->ref, what,
                   fit_on(conv->eps, cm->loc_lambda, SUS_LAB_CONV_NJ, 1, SIZE_LAMBDA, FIT_EPS_MAX),
                   eo->s, me->paper_ref ? LEDGER_REPRODUCED : LEDGER_EXTENSION);
    }
    return p;
}

void consistency_local_claims(const claims_paper *pp)
{
    char id[64], what[256];
    double r_min = INFINITY; /* the SO(3) order r alone, smallest over the paper's methods */
    for (int s = 0; s < pp->conv.nmethod; s++) {
        const sus_step_method *me = sus_step_method_get(s);
        const sus_stepper_type *st = me->type;
        const sus_lab_conv_method *cm = &pp->conv.m[s];
        const expected_order *eo = expected(st);
        if (!eo || !me->paper_ref)
            continue; /* missing: recorded as a failure; an extension: claims_methods.c */
        const double p = reduced_orders(me, &pp->conv, s, eo);
        for (int r = 0; r < SUS_RECON_COUNT; r++) {
            /* Proposition 5.1: the unreduced order is min(r, l), r from (MetMat) on SO(3), l = p.
             */
            const double rr =
                fit_on(pp->conv.eps, cm->loc_so3[r], SUS_LAB_CONV_NJ, 1, SIZE_R, FIT_EPS_MAX);
            const int paper = r == SUS_RECON_CAYLEY && me->paper_ref;
            snprintf(id, sizeof id, "unreduced-order-%s-%s", SUS_RECON_NAMES[r], st->name);
            snprintf(what, sizeof what,
                     "$\\min(r, p)$, $r$: local slope of the distance \\eqref{MetMat} minus 1, "
                     "reconstruction %s, %s",
                     SUS_RECON_NAMES[r], st->name);
            order_line(id, paper ? "\\PaperRefOr{TeoL}" : "\\PaperRefOr{TeoL}, extension", what,
                       min_nan(rr, p), eo->so3[r], paper ? LEDGER_REPRODUCED : LEDGER_EXTENSION);
            if (paper)
                r_min = min_nan(r_min, rr);
        }
    }
    /* The Conclusions say the order "becomes zero in the unreduced setting", whatever the reduced
     * one: the order on SO(3), r, which Proposition 5.1's proof gives as 1. Tested on r itself
     * (not min(r, p), which for euler is its reduced p = 1 and so could not tell r from p).
     * Asserting the contradiction: an order below 0.5 would round to 0. An erratum: the sentence
     * contradicts the paper's own Proposition 5.1, not a result. */
    ledger_add("conclusion-unreduced-order-zero", "Conclusions (\\PaperRefOr{nolabel:section-7})",
               "the order $r$ on $\\mathrm{SO}(3)$ (local slope of the distance \\eqref{MetMat} "
               "minus 1) with $R_{k+1} = R_k \\mathrm{cay}(\\varepsilon \\omega_k)$, smallest over "
               "the paper's methods; the text says 0, \\PaperRefOr{TeoL} says 1",
               r_min, 0.0, 0.5, LEDGER_ERRATUM);
}

/* ---- the multiplier with (36) corrected ---- */

/* With the exact dcay^{-1} ((3,3) entry 1, not 0) the multiplier gains (c(x) - c(w))/eps: its
 * order against lambda at the end and at the middle of the step, on the paper's body. */
void consistency_multiplier_claims(const claims_paper *p)
{
    double full_err[NJ] = {0}, half_err[NJ] = {0};
    for (int t = 0; t < PAPER_NTK; t++) {
        double wk[2];
        sus_exact_omega(&p->ex, PAPER_TK[t], wk);
        for (int j = 0; j < NJ; j++) {
            const double eps = eps_of(j);
            double w[3] = {wk[0], wk[1], 0.0}, xn[3], lam, wm[2], we[2];
            sus_stepper_stats st;
            if (sus_step_variational->step->apply(&p->m, eps, w, xn, &lam, &st) != SUS_STEPPER_OK)
                ledger_die("variational step");
            const double full = lam + (sus_c(&p->m, xn) - sus_c(&p->m, w)) / eps;
            sus_exact_omega(&p->ex, PAPER_TK[t] + eps, we);
            sus_exact_omega(&p->ex, PAPER_TK[t] + 0.5 * eps, wm);
            full_err[j] = fmax(full_err[j], fabs(sus_lagmult(&p->m, we) - full));
            half_err[j] = fmax(half_err[j], fabs(sus_lagmult(&p->m, wm) - full));
        }
    }
    const char *ref = "\\eqref{cayinver} with its entry $(3,3) = 1$; extension";
    order_line("lambda-order-variational-exact-dcayinv", ref,
               "$s$ of \\eqref{taualg} $+ (c(\\omega^{k+1}) - c(\\omega^k))/\\varepsilon$ against "
               "$\\lambda(t_k+\\varepsilon)$: consistent, $s = 0$",
               fit(full_err, 1, SIZE_LAMBDA), 0.0, LEDGER_EXTENSION);
    order_line(
        "lambda-order-variational-exact-dcayinv-mid", ref,
        "the same multiplier against $\\lambda(t_k+\\varepsilon/2)$: $s = 1$ at the half step",
        fit(half_err, 1, SIZE_LAMBDA), 1.0, LEDGER_EXTENSION);
}

/* ---- (36) as printed against the formula for dcay^{-1} after (23) ---- */

void consistency_cayinver_claims(void)
{
    double others = 0.0, d33 = 0.0;
    for (int n = 0; n < 16; n++) {
        const double eps = 0.125 * (n + 1), w[2] = {0.4 + 0.01 * n, 0.5 - 0.02 * n};
        const double ew[3] = {eps * w[0], eps * w[1], 0.0};
        double P[3][3], D[3][3];
        sus_so3_cayinver_printed(eps, w, P);
        sus_so3_dcay_inv(ew, D);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                if (i == 2 && j == 2)
                    d33 = fmax(d33, fabs(P[i][j] - D[i][j]));
                else
                    others = fmax(others, fabs(P[i][j] - D[i][j]));
    }
    /* The paper presents (cayinver) as dcay^{-1} for w_3 = 0; entry (3,3) is printed 0 but is 1.
     * It is this entry that removes the O_0 term from (taualg) (see the extension lines above).
     * Two lines: the printed matrix is not dcay^{-1} (its (3,3) entry is off by exactly 1), and
     * every other entry is right. The entries are a few products of numbers below 2: 1e-14 is
     * about fifty roundings. A typo against the formula the paper prints two pages earlier. */
    ledger_add(
        "cayinver-equals-dcayinv", "\\eqref{cayinver} against the formula after \\eqref{caypart}",
        "max over 16 $(\\varepsilon, \\omega)$ of the difference between the entry $(3,3)$ of "
        "\\eqref{cayinver} as printed and that of $(I - \\hat{\\omega}/2 + \\omega "
        "\\omega^\\top/4)(\\varepsilon \\omega)$: 1, not 0",
        d33, 0.0, 1e-14, LEDGER_ERRATUM);
    ledger_add("cayinver-33-off-by-one", "(extension)",
               "the entry $(3,3)$ differs by exactly 1: max over 16 $(\\varepsilon, \\omega)$ of "
               "$|d_{33} - 1|$, $d_{33}$ that difference",
               fabs(d33 - 1.0), 0.0, 1e-14, LEDGER_EXTENSION);
    ledger_add("cayinver-other-entries-agree", "(extension)",
               "max over 16 $(\\varepsilon, \\omega)$ of the differences "
               "between the other eight entries of \\eqref{cayinver} as "
               "printed and those of $\\mathrm{dcay}^{-1}$: they agree",
               others, 0.0, 1e-14, LEDGER_EXTENSION);
}

/* ---- global errors at T = 10 ---- */

void consistency_global_claims(const claims_paper *pp)
{
    char id[64], what[256];
    for (int s = 0; s < pp->conv.nmethod; s++) {
        const sus_step_method *me = sus_step_method_get(s);
        const sus_stepper_type *st = me->type;
        const sus_lab_conv_method *cm = &pp->conv.m[s];
        const expected_order *eo = expected_order_of(st->name);
        if (!eo || !me->paper_ref)
            continue; /* local_claims has recorded the failure; an extension: claims_methods.c */
        snprintf(id, sizeof id, "global-order-%s", st->name);
        snprintf(what, sizeof what, "slope of the global error $|\\omega(10) - \\omega_N|$, %s",
                 st->name);
        order_line(id, eo->ref, what,
                   fit_on(pp->conv.glob_eps, cm->glob_w, SUS_LAB_CONV_NJ, 0, SIZE_W, FIT_EPS_MAX),
                   eo->p, me->paper_ref ? LEDGER_REPRODUCED : LEDGER_EXTENSION);
        for (int r = 0; r < SUS_RECON_COUNT; r++) {
            snprintf(id, sizeof id, "global-so3-order-%s-%s", SUS_RECON_NAMES[r], st->name);
            snprintf(what, sizeof what,
                     "slope of the distance \\eqref{MetMat} $\\mathrm{dist}(R(10), R_N)$, "
                     "reconstruction %s, %s",
                     SUS_RECON_NAMES[r], st->name);
            order_line(
                id, "\\PaperRefOr{TeoL}, extension", what,
                fit_on(pp->conv.glob_eps, cm->glob_so3[r], SUS_LAB_CONV_NJ, 0, SIZE_R, FIT_EPS_MAX),
                eo->so3[r], LEDGER_EXTENSION);
        }
    }
}

/* ---- Proposition 4.1: an unreduced integrator, left-trivialized, inherits its velocity order */

/* The local errors of RK4 on (LdAeqs) from exact data at t_k: of V, R, xi = vee(R^T V) and
 * lambda(xi), the largest over t_k. */
static void unreduced_errors(const claims_paper *p, sus_unreduced *u, double ev[NJ], double exi[NJ],
                             double eR[NJ], double el[NJ])
{
    for (int t = 0; t < PAPER_NTK; t++) {
        double Rk[3][3], I3[3][3], wk[3] = {0.0, 0.0, 0.0}, W[3][3];
        sus_refatt ra;
        sus_mat3_identity(I3);
        sus_refatt_init(&ra, &p->ex, 0.0, I3);
        sus_refatt_advance(&ra, PAPER_TK[t], Rk);
        sus_exact_omega(&p->ex, PAPER_TK[t], wk);
        sus_so3_hat(wk, W);
        for (int j = 0; j < NJ; j++) {
            sus_lab_local_ref ref;
            sus_lab_local_ref_init(&ref, &p->ex, PAPER_TK[t], eps_of(j));
            double R[3][3], V[3][3], Rx[3][3], Vx[3][3], We[3][3], xi[3], D[3][3];
            sus_mat3_copy(R, Rk);
            sus_mat3_mul(V, Rk, W);
            sus_unreduced_rk4(u, eps_of(j), R, V);
            sus_mat3_mul(Rx, Rk, ref.Phi); /* R(t_k + eps) */
            sus_so3_hat(ref.w_exact, We);
            sus_mat3_mul(Vx, Rx, We); /* V(t_k + eps) = R w^ */
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    D[a][b] = Vx[a][b] - V[a][b];
            ev[j] = fmax(ev[j], sus_mat3_frobenius(D));
            eR[j] = fmax(eR[j], sus_so3_dist(Rx, R));
            sus_unreduced_xi(R, V, xi);
            const double dxi[3] = {ref.w_exact[0] - xi[0], ref.w_exact[1] - xi[1],
                                   ref.w_exact[2] - xi[2]};
            exi[j] = fmax(exi[j], sus_vec3_norm(dxi));
            el[j] = fmax(el[j], fabs(ref.lambda_exact - sus_lagmult(&p->m, xi)));
        }
    }
}

void consistency_unreduced_claims(const claims_paper *p)
{
    char err[256];
    sus_unreduced u;
    if (sus_unreduced_init(&u, &p->m, err, sizeof err) != 0)
        ledger_die(err);
    double ev[NJ] = {0}, exi[NJ] = {0}, eR[NJ] = {0}, el[NJ] = {0};
    unreduced_errors(p, &u, ev, exi, eR, el);
    const double l = fit(ev, 1, SIZE_W);
    const char *ext = "\\PaperRefOr{UnredConsis}, extension";
    order_line(
        "unreduced-velocity-order-rk4", ext,
        "$l$: local slope of $|V(t_k+\\varepsilon) - V_{k+1}|$ ($3 \\times 3$ coordinates of "
        "$T\\mathrm{SO}(3)$) minus 1, RK4 on \\eqref{LdAeqs}",
        l, 4.0, LEDGER_EXTENSION);
    order_line(
        "unreduced-position-order-rk4", ext,
        "$r$: local slope of the distance \\eqref{MetMat} $\\mathrm{dist}(R(t_k+\\varepsilon), "
        "R_{k+1})$ minus 1, RK4 on \\eqref{LdAeqs}",
        fit(eR, 1, SIZE_R), 4.0, LEDGER_EXTENSION);
    order_line("reduced-from-unreduced", "\\PaperRefOr{PropoCons1}",
               "order of the left-trivialized sequence $\\xi_k = (R_k^\\top V_k)^\\vee$ of RK4 on "
               "\\eqref{LdAeqs}: it inherits $l = 4$",
               fit(exi, 1, SIZE_W), 4.0, LEDGER_REPRODUCED);
    order_line("reduced-from-unreduced-lambda", "\\PaperRefOr{PropoCons1}",
               "$s$ of $\\lambda(\\xi_{k+1})$ from the unreduced RK4: $s = 4$ carries over",
               fit(el, 1, SIZE_LAMBDA), 4.0, LEDGER_REPRODUCED);
}
