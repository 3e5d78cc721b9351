/* PropoCons1: a (p, s) integrator of (LdAeqs) generates an (l, s) integrator of the reduced
 * equations, l the order of the left-trivialized velocity (Definition UnredConsis, 2). The reduced
 * variable is that same velocity xi = vee(R^T V), so the claim holds by the definition: what a
 * measurement can show is only that the reduced order is l and not min(r, l), for integrators
 * whose r and l differ: one with the table on xi alone, and one whose velocity comes from the
 * table on (R, V) (its stages read R), both with a first-order attitude. Local errors from exact
 * data at t_k, as in claims.c. */
#include "claims_propocons1.h"

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

static const double TKP[] = {0.0, 3.0, 7.0, 12.0, 20.0};
#define NTKP 5
#define NJP 11 /* eps = 2^-j, j = 0 .. 10 */
#define ORDER_TOL 0.1 /* an order is an integer: a tenth of the gap (as in claims.c) */

typedef struct {
    const char *id;
    const sus_butcher *tab;
    int cayley;     /* 1: the table on xi with R_{k+1} = R_k cay(eps xi_k^); 2: the table on (R, V) for
                     * the velocity, the same attitude */
    int r, l;       /* what theory gives: the table's order for both, or r = 1 (TeoL) and l = the table's */
} integrator;

static double fit(const double *eps, const double *err, double size)
{
    sus_exp_order_fit f;
    if (sus_exp_fit_order(eps, err, NJP, SUS_EXP_FIT_EPS_MAX, SUS_EXP_FIT_FLOOR_REL * size, &f) != 0)
        return NAN;
    return f.slope - 1.0;
}

void propocons1_claims(const sus_model *m, const sus_exact *ex)
{
    const integrator list[] = {
        {"heun2", &SUS_BUTCHER_HEUN2, 0, 2, 2},
        {"kutta3", &SUS_BUTCHER_KUTTA3, 0, 3, 3},
        {"rk4-xi-cayley", &SUS_BUTCHER_RK4, 1, 1, 4},
        {"rk4-rv-cayley", &SUS_BUTCHER_RK4, 2, 1, 4},
    };
    char err[256];
    sus_unreduced u;
    if (sus_unreduced_init(&u, m, err, sizeof err) != 0)
        ledger_die(err);
    for (size_t n = 0; n < sizeof list / sizeof list[0]; n++) {
        const integrator *it = &list[n];
        double eps[NJP], eR[NJP] = {0}, exi[NJP] = {0}, el[NJP] = {0};
        for (int j = 0; j < NJP; j++)
            eps[j] = ldexp(1.0, -j);
        for (int t = 0; t < NTKP; t++) {
            double Rk[3][3], I3[3][3], wk[3] = {0.0, 0.0, 0.0}, W[3][3];
            sus_refatt ra;
            sus_mat3_identity(I3);
            sus_refatt_init(&ra, ex, 0.0, I3);
            sus_refatt_advance(&ra, TKP[t], Rk);
            sus_exact_omega(ex, TKP[t], wk);
            sus_so3_hat(wk, W);
            for (int j = 0; j < NJP; j++) {
                sus_exp_local_ref ref;
                double R[3][3], V[3][3], Rx[3][3], xi[3];
                sus_exp_local_ref_init(&ref, ex, TKP[t], eps[j]);
                sus_mat3_copy(R, Rk);
                sus_mat3_mul(V, Rk, W);
                if (it->cayley == 2)
                    sus_unreduced_rk_recayley(&u, it->tab, eps[j], R, V);
                else if (it->cayley)
                    sus_unreduced_rk_cayley(&u, it->tab, eps[j], R, V);
                else
                    sus_unreduced_rk(&u, it->tab, eps[j], R, V);
                sus_mat3_mul(Rx, Rk, ref.Phi);
                eR[j] = fmax(eR[j], sus_so3_dist(Rx, R));
                sus_unreduced_xi(R, V, xi);
                const double d[3] = {ref.w_exact[0] - xi[0], ref.w_exact[1] - xi[1], ref.w_exact[2] - xi[2]};
                exi[j] = fmax(exi[j], sus_vec3_norm(d));
                el[j] = fmax(el[j], fabs(ref.lambda_exact - sus_lagmult(m, xi)));
            }
        }
        const double r = fit(eps, eR, SUS_EXP_SIZE_R), l = fit(eps, exi, SUS_EXP_SIZE_W),
                     s = fit(eps, el, SUS_EXP_SIZE_LAMBDA);
        char id[64], q[256];
        snprintf(id, sizeof id, "propocons1-r-%s", it->id);
        snprintf(q, sizeof q, "r: local slope of (MetMat) dist(R(t_k+eps), R_{k+1}) minus 1, %s on (LdAeqs)",
                 it->id);
        ledger_add(id, "Def. UnredConsis (extension)", q, r, it->r, ORDER_TOL, LEDGER_EXTENSION);
        snprintf(id, sizeof id, "propocons1-reduced-%s", it->id);
        snprintf(q, sizeof q,
                 "order of xi_k = vee(R_k^T V_k) (= l, left-trivialized velocity: PropoCons1 holds by Def. "
                 "UnredConsis 2), %s; r = %.2f, min(r, l) = %d; l = %d",
                 it->id, r, it->r < it->l ? it->r : it->l, it->l);
        ledger_add(id, "PropoCons1", q, l, it->l, ORDER_TOL, LEDGER_REPRODUCED);
        snprintf(id, sizeof id, "propocons1-lambda-%s", it->id);
        snprintf(q, sizeof q, "s of lambda(xi_{k+1}) (LagMult), %s: it carries over with l = %d", it->id,
                 it->l);
        ledger_add(id, "PropoCons1", q, s, it->l, ORDER_TOL, LEDGER_REPRODUCED);
        if (it->r != it->l) {
            /* the reduced order is l, not min(r, l); PropoCons1 itself holds by definition (the
             * reduced variable is the velocity whose order is l), so this shows only that */
            snprintf(id, sizeof id, "propocons1-not-min-%s", it->id);
            snprintf(q, sizeof q,
                     "reduced order minus r for %s (r = %.2f): the reduced order is l, not min(r, l) "
                     "(PropoCons1 holds by Def. UnredConsis 2); l - r = %d expected",
                     it->id, r, it->l - it->r);
            ledger_add_bound(id, "PropoCons1", q, l - r, 1.5, 1, LEDGER_REPRODUCED);
        }
    }
}
