/* One data-driven ledger routine, the same for every registered method: its orders p (w), s
 * (lambda) and on SO(3) (each reconstruction), and its structure (w3 = 0, |R^T R - I|, E where it
 * conserves it), on the paper's body and on each body of the seeded family (tests/unit/bodies.h).
 * What is expected comes from tests/ledger/expected_orders.c; what kind of method it is, from
 * the fields of its stepper type (src/core/stepper.h). Nothing here knows a method by name.
 *
 * Orders. Local errors as the paper defines consistency (one step from exact data at t_k,
 * against the exact solution at t_k + eps; the largest over 5 starts t_k spread over the
 * transient, t_k k = 0, 0.45, 1, 1.75, 2.9 with k the body's rate), on a grid scaled by the
 * body's time 1/k: eps k = 1.16 * 2^(-j/4), j = 0 .. NE-1, over 13 octaves (for the paper's
 * body eps = 8 down to 2^-10). A point is a candidate when its error is finite, below the size of
 * the quantity and above its round-off floor, from the size of the terms the method's evaluation
 * rounds (claims_bodies.c: a near-singular I_m raises it by up to cond(I_m)). The window is chosen
 * from the curve by the rule of claims_window.h (the longest run of one slope, at least an octave
 * long) and kept where it is the asymptotic one (claims_orders.c: it reaches eps k < pi/10 and
 * the octave below it keeps its slope). The order is the slope minus 1 (local error
 * O(eps^{q+1})), asserted within WINDOW_ORDER_TOL of the expected one on every body with such a
 * window; on a body without one, the slope over the smallest-eps octave is a lower estimate,
 * asserted only >= expected / 2 (that cannot tell p from p - 1, and says so; the plateau lines
 * and the Taylor control of claims_highorder.c do). A body whose error is at round-off wherever
 * the method steps has no order, and the line names it.
 * The SO(3) order is TeoL's min(r, p) of the pair, r measured on the attitude's local error.
 * A curve with fewer than 3 steps taken has no order: the line fails. */
#include "claims_methods.h"

#include "claims_bodies.h"
#include "claims_orders.h"
#include "consistency.h"
#include "driver.h"
#include "expected_orders.h"
#include "ledger.h"
#include "notation.h"
#include "orderfit.h"
#include "registry.h"
#include "so3.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define U DBL_EPSILON
#define NE CLAIMS_NE
#define NTK CLAIMS_NTK
#define NQ (2 + SUS_RECON_COUNT) /* w, lambda, SO(3) with each reconstruction */

/* The size of quantity q (w, lambda, SO(3) with each reconstruction). */
static double size_of(const claims_body *d, int q)
{
    return claims_body_size(d, q < 2 ? q : CLAIMS_Q_R);
}

/* The order of quantity q's error curve, above the floors of a method that rounds as t does. */
static curve_order order_on(const claims_body *d, const sus_stepper_type *t, int q,
                            const double *err)
{
    const claims_rounding k = {t->desc.implicit, t->desc.conserves_energy && !t->desc.implicit,
                               t->desc.substeps};
    double floor[NE];
    claims_body_floors(d, &k, q < 2 ? q : CLAIMS_Q_R, floor);
    return order_of_curve(d->eps, d->ex.k, err, NE, size_of(d, q), floor);
}

/* The local error curves of one method on one body: err[q][j], the largest over the starts;
 * NaN where a step failed. */
static void local_curves(const sus_step_method *me, const claims_body *d, double err[NQ][NE])
{
    for (int j = 0; j < NE; j++) {
        for (int q = 0; q < NQ; q++)
            err[q][j] = 0.0;
        for (int t = 0; t < NTK; t++) {
            sus_lab_local_err e;
            if (sus_lab_local_errors(&d->m, me->type, &d->ref[j][t], &e) != SUS_STEPPER_OK) {
                for (int q = 0; q < NQ; q++)
                    err[q][j] = NAN;
                break;
            }
            err[0][j] = fmax(err[0][j], e.w);
            err[1][j] = fmax(err[1][j], e.lambda);
            for (int r = 0; r < SUS_RECON_COUNT; r++)
                err[2 + r][j] = fmax(err[2 + r][j], e.so3[r]);
        }
    }
}

/* p, s and the SO(3) order with each reconstruction of one method, on every body. */
static void method_orders(const sus_step_method *me, const expected_order *eo)
{
    static double err[BODIES_COUNT][NQ][NE];
    order_summary sum[NQ];
    for (int q = 0; q < NQ; q++)
        sum[q] = order_summary_new();
    for (int k = 0; k < BODIES_COUNT; k++) {
        const claims_body *d = claims_body_get(k);
        local_curves(me, d, err[k]);
        const curve_order p = order_on(d, me->type, 0, err[k][0]);
        order_summary_add(&sum[0], p, eo->p, d->b.name);
        order_summary_add(&sum[1], order_on(d, me->type, 1, err[k][1]), eo->s, d->b.name);
        for (int r = 0; r < SUS_RECON_COUNT; r++)
            order_summary_add(&sum[2 + r],
                              order_of_pair(order_on(d, me->type, 2 + r, err[k][2 + r]), p),
                              eo->so3[r], d->b.name);
    }
    char id[96], what[160];
    snprintf(id, sizeof id, "method-p-%s", me->type->name);
    const ledger_assert truth = me->paper_ref ? LEDGER_REPRODUCED : LEDGER_EXTENSION;
    ledger_order_line(id, "$p$: local $\\omega$ error slope $- 1$", me->type->name, &sum[0], eo->p,
                      eo->ref, truth);
    snprintf(id, sizeof id, "method-s-%s", me->type->name);
    ledger_order_line(id, "$s$: local $\\lambda$ error slope $- 1$", me->type->name, &sum[1], eo->s,
                      eo->ref, truth);
    for (int r = 0; r < SUS_RECON_COUNT; r++) {
        /* Proposition 5.1 is about the Cayley reconstruction of Algorithm 5.1; the symmetric ones
         * are ours */
        const int paper = r == SUS_RECON_CAYLEY && me->paper_ref;
        snprintf(id, sizeof id, "method-so3-%s-%s", SUS_RECON_NAMES[r], me->type->name);
        snprintf(what, sizeof what,
                 "$\\mathrm{SO}(3)$ order $\\min(r, p)$, $r$: "
                 "local \\eqref{MetMat} error slope $- 1$, %s",
                 SUS_RECON_NAMES[r]);
        ledger_order_line(id, what, me->type->name, &sum[2 + r], eo->so3[r],
                          paper ? "\\PaperRefOr{TeoL}" : "\\PaperRefOr{TeoL}, extension",
                          paper ? LEDGER_REPRODUCED : LEDGER_EXTENSION);
    }
}

/* ---- structure ---- */

/* eps k = STRUCT_EPS k_paper, the body's own time (eps = 0.05 on the paper's body) */
#define STRUCT_EPS 0.05
#define STRUCT_STEPS                                                                               \
    2000L /* T k = 100 k_paper: the transient and the approach to the steady rotation */

typedef struct {
    const sus_model *m;
    double e0, energy, w3, orth;
    double eterms; /* the largest 1/2 sum_ij |w_i I_ij w_j| over the rows */
} structure_ctx;

static int track(void *vctx, const sus_row *row)
{
    structure_ctx *c = vctx;
    c->eterms = fmax(c->eterms, claims_energy_terms(c->m, row->w));
    c->energy = fmax(c->energy, fabs(sus_energy(c->m, row->w) - c->e0));
    c->w3 = fmax(c->w3, fabs(row->w[2]));
    c->orth = fmax(c->orth, sus_so3_orth_defect(row->R));
    return 0;
}

typedef struct {
    double value, bound; /* the worst ratio value / bound over bodies, and that body's pair */
    const char *body;
    int failed_runs;
} structure_worst;

static void worst_add(structure_worst *s, double value, double bound, const char *bname)
{
    if (!s->body || !(value / bound <= s->value / s->bound)) {
        s->value = value;
        s->bound = bound;
        s->body = bname;
    }
}

/* Round-off bounds on |R^T R - I| by attitude form. A unit quaternion is turned into R afresh at
 * every step: one rounding per entry, a few u over 9 entries whatever N: 1e-14. (algo)'s
 * reconstruction sums R_k D_k with compensation (reconstruct.h): what remains is the rounding of
 * the computed increments, |D| <= |g_i| eps |w| per substep with |g_i| < 2 for every tabulated
 * weight, four roundings per entry: 8 u N s eps |w|, plus 16 u for the last product. */
double method_orth_bound(const sus_stepper_type *t, long steps, double eps, double size_w)
{
    if (t->desc.attitude == SUS_ATTITUDE_QUAT)
        return 1e-14;
    return 16.0 * U + 8.0 * U * (double)steps * t->desc.substeps * eps * size_w;
}

/* w3 = 0, |R^T R - I| and, where the method conserves it, E over STRUCT_STEPS steps on every body,
 * each in its own time. */
static void method_structure(const sus_step_method *me)
{
    const sus_stepper_type *t = me->type;
    const double k_paper = claims_body_get(0)->ex.k;
    structure_worst w3 = {0}, orth = {0}, en = {0};
    for (int k = 0; k < BODIES_COUNT; k++) {
        const claims_body *d = claims_body_get(k);
        const double eps = STRUCT_EPS * (k_paper / d->ex.k);
        structure_ctx c = {&d->m, sus_energy(&d->m, d->b.w0), 0, 0, 0, 0};
        const sus_run_config cfg = {&d->m, me->type, me->recon, eps, STRUCT_STEPS, 1};
        sus_run_report rep;
        if (sus_run(&cfg, d->b.w0, track, &c, &rep) != 0)
            c.energy = c.w3 = c.orth = INFINITY;
        worst_add(&w3, c.w3, 1.0, d->b.name);
        worst_add(&orth, c.orth, method_orth_bound(t, STRUCT_STEPS, eps, size_of(d, 0)), d->b.name);
        /* each substep rounds E a few times and the errors need not cancel: 8 u e per substep, e
         * the size of E's terms (claims_energy_terms); an implicit root's rounding dx = J^-1 r
         * (J ~ I_m) moves E by <I_m w, dx> ~ <w, r>, r of size u |I_m| |w|: u e again, not
         * amplified by cond(I_m) */
        worst_add(&en, c.energy, 8.0 * U * (double)STRUCT_STEPS * t->desc.substeps * c.eterms,
                  d->b.name);
    }
    char id[96], q[640];
    const char *ref = me->paper_ref ? "\\eqref{DSP}, \\PaperRefOr{algo}" : "(extension)";
    const ledger_assert truth = me->paper_ref ? LEDGER_REPRODUCED : LEDGER_EXTENSION;
    snprintf(id, sizeof id, "method-w3-%s", me->type->name);
    snprintf(q, sizeof q,
             "$\\max |\\omega_3|$ over %ld steps of $\\varepsilon k = %g\\,k_\\mathrm{paper}$, %s, "
             "the worst of %d bodies (seed %u), %s: exactly 0",
             STRUCT_STEPS, STRUCT_EPS, me->type->name, BODIES_COUNT, BODIES_SEED, w3.body);
    /* every stepper writes w3 = 0.0 (the second equation of (DSP)): a check of the code, which
     * no value of the paper's can fail, so not evidence */
    ledger_add(id, ref, q, w3.value, 0.0, 0.0, LEDGER_BY_CONSTRUCTION);
    snprintf(id, sizeof id, "method-orth-%s", me->type->name);
    char label[64];
    snprintf(q, sizeof q,
             "$\\max |R^\\top R - I|$ over %ld steps of $\\varepsilon k = %g\\,k_\\mathrm{paper}$, "
             "%s, $R$ %s, the worst of %d bodies, %s; round-off bound $%s$",
             STRUCT_STEPS, STRUCT_EPS, sus_step_method_label(t, me->recon, label, sizeof label),
             t->desc.attitude == SUS_ATTITUDE_QUAT ? "from a unit quaternion"
                                                   : "by compensated products",
             BODIES_COUNT, orth.body, notation_g(orth.bound, 2).s);
    ledger_add_bound(id, ref, q, orth.value, orth.bound, 0, truth);
    if (!t->desc.conserves_energy)
        return;
    snprintf(id, sizeof id, "method-energy-%s", me->type->name);
    snprintf(
        q, sizeof q,
        "$\\max |E - E_0|$ over %ld steps of $\\varepsilon k = %g\\,k_\\mathrm{paper}$, %s (%d "
        "substeps), the worst of %d bodies, %s; bound $8\\,u N s\\,e$, $e = \\max \\frac{1}{2} "
        "\\sum |\\omega_i I_{ij} \\omega_j|$ (the terms of $E$)",
        STRUCT_STEPS, STRUCT_EPS, me->type->name, t->desc.substeps, BODIES_COUNT, en.body);
    /* the statement it tests: Figure 1(f)'s energy kept by the midpoint rule, on every body */
    ledger_add_bound(id, me->paper_ref ? "\\PaperRefOr{Fig1}, panel (f); \\eqref{DSP}" : ref, q,
                     en.value, en.bound, 0, truth);
}

void methods_claims_of(int i)
{
    const sus_step_method *me = sus_step_method_get(i);
    const expected_order *eo = expected_order_of(me->type->name);
    if (!eo) {
        char id[96];
        snprintf(id, sizeof id, "expected-order-known-%s", me->type->name);
        ledger_add_bound(id, "\\texttt{tests/ledger/expected\\_orders.c}",
                         "the method has a stated order to test against: 1 when it does", 0.0, 1.0,
                         1, LEDGER_EXTENSION);
        return;
    }
    method_orders(me, eo);
    method_structure(me);
}
