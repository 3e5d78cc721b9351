/* PropoCons1: a (p, s) integrator of (LdAeqs) generates an (l, s) integrator of the reduced
 * equations, l the order of the left-trivialized velocity (Definition UnredConsis, 2). The reduced
 * variable is that same velocity xi = vee(R^T V), so the claim holds by the definition: what a
 * measurement can show is only that the reduced order is l and not min(r, l), for integrators
 * whose r and l differ: one with the table on xi alone, and one whose velocity comes from the
 * table on (R, V) (its stages read R), both with a first-order attitude. Local errors from exact
 * data at t_k, on the paper's body and the general ones, on the grid and starts of claims_bodies.h
 * and with the window rule of claims_orders.h, as the registered methods (claims_methods.c). */
#include "claims_propocons1.h"

#include "claims_bodies.h"
#include "claims_orders.h"
#include "consistency.h"
#include "ledger.h"
#include "mat3.h"
#include "orderfit.h"
#include "refattitude.h"
#include "so3.h"
#include "unreduced.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define NE CLAIMS_NE

/* Runge-Kutta tables on (R, V): explicit steps that do not rescale the energy, one step each. */
static const claims_rounding EXPLICIT = {0, 0, 1};

typedef struct {
    const char *id;
    const sus_butcher *tab;
    int cayley; /* 1: the table on xi with R_{k+1} = R_k cay(eps xi_k^); 2: the table on (R, V) for
                 * the velocity, the same attitude */
    int r,
        l; /* what theory gives: the table's order for both, or r = 1 (TeoL) and l = the table's */
} integrator;

/* One step of the integrator from the exact state at start t (R(t_k), V = R w^) over ref's eps: the
 * errors of R, of xi = vee(R^T V) and of lambda(xi) against the exact solution at t_k + eps. */
static void step_errors(const integrator *it, const claims_body *d, sus_unreduced *u,
                        const double Rk[3][3], const sus_lab_local_ref *ref, double e[3])
{
    double W[3][3], R[3][3], V[3][3], Rx[3][3], xi[3];
    sus_so3_hat(ref->w_k, W);
    sus_mat3_copy(R, Rk);
    sus_mat3_mul(V, Rk, W);
    if (it->cayley == 2)
        sus_unreduced_rk_recayley(u, it->tab, ref->eps, R, V);
    else if (it->cayley)
        sus_unreduced_rk_cayley(u, it->tab, ref->eps, R, V);
    else
        sus_unreduced_rk(u, it->tab, ref->eps, R, V);
    sus_mat3_mul(Rx, Rk, ref->Phi);
    sus_unreduced_xi(R, V, xi);
    const double dxi[3] = {ref->w_exact[0] - xi[0], ref->w_exact[1] - xi[1],
                           ref->w_exact[2] - xi[2]};
    e[0] = sus_so3_dist(Rx, R);
    e[1] = sus_vec3_norm(dxi);
    e[2] = fabs(ref->lambda_exact - sus_lagmult(&d->m, xi));
}

/* The orders r (R), l (xi) and s (lambda) of one integrator on one body: each error the largest
 * over the starts. */
static void body_orders(const integrator *it, const claims_body *d, curve_order o[3])
{
    char err[256];
    sus_unreduced u;
    if (sus_unreduced_init(&u, &d->m, err, sizeof err) != 0)
        ledger_die(err);
    double e[3][NE] = {{0}};
    for (int t = 0; t < CLAIMS_NTK; t++) {
        double Rk[3][3], I3[3][3];
        sus_refatt ra;
        sus_mat3_identity(I3);
        sus_refatt_init(&ra, &d->ex, 0.0, I3);
        sus_refatt_advance(&ra, d->ref[0][t].tk, Rk);
        for (int j = 0; j < NE; j++) {
            double ej[3];
            step_errors(it, d, &u, Rk, &d->ref[j][t], ej);
            for (int q = 0; q < 3; q++)
                e[q][j] = fmax(e[q][j], ej[q]);
        }
    }
    static const int quantity[3] = {CLAIMS_Q_R, CLAIMS_Q_W, CLAIMS_Q_LAMBDA};
    for (int q = 0; q < 3; q++) {
        double floor[NE];
        claims_body_floors(d, &EXPLICIT, quantity[q], floor);
        o[q] = order_of_curve(d->eps, d->ex.k, e[q], NE, claims_body_size(d, quantity[q]), floor);
    }
}

/* The lines of one integrator: r, the reduced order l, s, and where r < l that the reduced order is
 * l and not min(r, l). */
static void claims_lines(const integrator *it, const order_summary sum[3], double gap)
{
    char id[64], what[320];
    snprintf(id, sizeof id, "propocons1-r-%s", it->id);
    ledger_order_line(id,
                      "$r$: local slope of the distance \\eqref{MetMat} $\\mathrm{dist}(R(t_k+"
                      "\\varepsilon), R_{k+1})$ minus 1 on \\eqref{LdAeqs}",
                      it->id, &sum[0], it->r, "\\PaperRefOr{UnredConsis}, extension",
                      LEDGER_EXTENSION);
    snprintf(id, sizeof id, "propocons1-reduced-%s", it->id);
    snprintf(what, sizeof what,
             "order of $\\xi_k = (R_k^\\top V_k)^\\vee$ ($= l$, the left-trivialized velocity: "
             "\\PaperRefOr{PropoCons1} holds by \\PaperRefOr{UnredConsis}, 2), $\\min(r, l) = %d$; "
             "$l = %d$",
             it->r < it->l ? it->r : it->l, it->l);
    ledger_order_line(id, what, it->id, &sum[1], it->l, "\\PaperRefOr{PropoCons1}",
                      LEDGER_REPRODUCED);
    snprintf(id, sizeof id, "propocons1-lambda-%s", it->id);
    snprintf(what, sizeof what,
             "$s$ of $\\lambda(\\xi_{k+1})$ \\eqref{LagMult}: it carries over with $l = %d$",
             it->l);
    ledger_order_line(id, what, it->id, &sum[2], it->l, "\\PaperRefOr{PropoCons1}",
                      LEDGER_REPRODUCED);
    if (it->r == it->l)
        return;
    /* the reduced order is l, not min(r, l); PropoCons1 itself holds by definition (the reduced
     * variable is the velocity whose order is l), so this shows only that */
    snprintf(id, sizeof id, "propocons1-not-min-%s", it->id);
    snprintf(
        what, sizeof what,
        "least over %d bodies of the reduced order minus $r$ for %s: the reduced order is $l$, "
        "not $\\min(r, l)$ (\\PaperRefOr{PropoCons1} holds by \\PaperRefOr{UnredConsis}, 2); $l "
        "- r = %d$ expected",
        BODIES_COUNT, it->id, it->l - it->r);
    ledger_add_bound(id, "\\PaperRefOr{PropoCons1}", what, gap, 1.5, 1, LEDGER_REPRODUCED);
}

void propocons1_claims(void)
{
    static const integrator list[] = {
        {"heun2", &SUS_BUTCHER_HEUN2, 0, 2, 2},
        {"kutta3", &SUS_BUTCHER_KUTTA3, 0, 3, 3},
        {"rk4-xi-cayley", &SUS_BUTCHER_RK4, 1, 1, 4},
        {"rk4-rv-cayley", &SUS_BUTCHER_RK4, 2, 1, 4},
    };
    for (size_t n = 0; n < sizeof list / sizeof list[0]; n++) {
        const integrator *it = &list[n];
        order_summary sum[3] = {order_summary_new(), order_summary_new(), order_summary_new()};
        double gap = INFINITY; /* the least l - r over the bodies */
        for (int k = 0; k < BODIES_COUNT; k++) {
            const claims_body *d = claims_body_get(k);
            curve_order o[3];
            body_orders(it, d, o);
            order_summary_add(&sum[0], o[0], it->r, d->b.name);
            order_summary_add(&sum[1], o[1], it->l, d->b.name);
            order_summary_add(&sum[2], o[2], it->l, d->b.name);
            gap = isnan(o[1].order - o[0].order) ? -INFINITY : fmin(gap, o[1].order - o[0].order);
        }
        claims_lines(it, sum, gap);
    }
}
