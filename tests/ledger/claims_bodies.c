#include "claims_bodies.h"

#include "ledger.h"
#include "orderfit.h"

#include <math.h>

#define EPS_K_MAX 1.16

static claims_body bodies[BODIES_COUNT];
static int built;

/* The sizes of w and lambda along the motion: the largest over every point a local error is
 * measured at, w(t_k) and w(t_k + eps) for every start and eps, and the steady rotation. lambda's
 * size is that of its two parts, (LagMult)'s quadratic part Q and O_0, |Q| + |O_0|: on a
 * near-singular I_m they cancel in part, and a method whose lambda error is O(1) (s = -1) errs by
 * O_0, not by lambda. */
static void body_sizes(claims_body *d)
{
    double wl[2];
    sus_exact_limit(&d->ex, wl);
    const double ol = sus_lagmult_o0(&d->m, wl);
    double sw = hypot(wl[0], wl[1]), sl = fabs(sus_lagmult(&d->m, wl) - ol) + fabs(ol);
    for (int j = 0; j < CLAIMS_NE; j++)
        for (int t = 0; t < CLAIMS_NTK; t++)
            for (int e = 0; e < 2; e++) {
                const double *w = e ? d->ref[j][t].w_exact : d->ref[j][t].w_k;
                const double o0 = sus_lagmult_o0(&d->m, w);
                sw = fmax(sw, hypot(w[0], w[1]));
                sl = fmax(sl, fabs(sus_lagmult(&d->m, w) - o0) + fabs(o0));
            }
    d->size_w = sw;
    d->size_lambda = sl;
}

double claims_energy_terms(const sus_model *m, const double w[2])
{
    const double(*I)[3] = m->I;
    const double a0 = fabs(w[0]), a1 = fabs(w[1]);
    return 0.5 * (a0 * (fabs(I[0][0]) * a0 + fabs(I[0][1]) * a1) +
                  a1 * (fabs(I[1][0]) * a0 + fabs(I[1][1]) * a1));
}

/* The size of E(w)'s terms over |grad E| = |I_m w|: how far from w the rounding of E puts the
 * energy level through w, in units of u. A step that scales w onto E0 rounds w across the ellipse
 * by this much: |w| on a round body, up to cond(I_m) |w| where w lies along I_m's soft axis. */
static double energy_rounding(const sus_model *m, const double w[2])
{
    const double(*I)[3] = m->I;
    return 2.0 * claims_energy_terms(m, w) /
           hypot(I[0][0] * w[0] + I[0][1] * w[1], I[1][0] * w[0] + I[1][1] * w[1]);
}

/* The rounding of (LagMult) at w, in units of u: Q's four products, and O_0 = c(w) ow / |I_m|
 * (ow = o0c . w) as the product of two sums, each rounded at its terms: (|c|' |ow| + |c| |ow|') /
 * |I_m|, with |c|' = |b1 w1| + |b2 w2| and |ow|' = |o0c1 w1| + |o0c2 w2| (on a near-singular I_m
 * ow cancels, so O_0 rounds far above its own size). Its gradient (Q's and O_0's,
 * (b ow + c(w) o0c) / |I_m|) in g. */
static double lagmult_terms(const sus_model *m, const double w[2], double g[2])
{
    const double(*I)[3] = m->I, *b = m->b, *o = m->o0c;
    const double a0 = fabs(w[0]), a1 = fabs(w[1]);
    const double q = a0 * (fabs(I[1][0]) * a0 + fabs(I[1][1]) * a1) +
                     a1 * (fabs(I[0][0]) * a0 + fabs(I[0][1]) * a1);
    const double c = b[0] * w[0] + b[1] * w[1], ow = o[0] * w[0] + o[1] * w[1];
    const double tc = fabs(b[0]) * a0 + fabs(b[1]) * a1, tow = fabs(o[0]) * a0 + fabs(o[1]) * a1;
    g[0] = 2.0 * I[1][0] * w[0] + (I[1][1] - I[0][0]) * w[1] + (b[0] * ow + c * o[0]) / m->det_m;
    g[1] = (I[1][1] - I[0][0]) * w[0] - 2.0 * I[0][1] * w[1] + (b[1] * ow + c * o[1]) / m->det_m;
    return q + (tc * fabs(ow) + fabs(c) * tow) / m->det_m;
}

double claims_body_size(const claims_body *d, int q)
{
    return q == CLAIMS_Q_W ? d->size_w : q == CLAIMS_Q_LAMBDA ? d->size_lambda : 1.0;
}

/* The round-off yardstick, in units of u, of quantity q in the step of ref (from w_k to the exact
 * w at t_k + eps, where the error is measured): the size of the terms each evaluation rounds,
 * carried to the quantity to first order.
 *   w: its own rounding, |w|. The field's terms, c(w) times I_m^-1's (adj I_m / |I_m|) times w,
 *      of size |c| |w| / lambda_min, taken eps times (a near-singular I_m makes them cancel:
 *      eps |c| / lambda_min <= eps k cond(I_m)^(1/2), as |c| <= k |I_m|^(1/2), exact.h). An
 *      implicit step's root errs by I_m^-1 times its residual's rounding, whose terms are
 *      I_m (x - w), |I_m|_1 |x - w|, and the same eps |c| |w|: (|I_m|_1 |x - w| + eps |c| |w|) /
 *      lambda_min. A step that scales w onto E0 rounds it across the ellipse by energy_rounding.
 *   lambda: (LagMult)'s terms (its evaluation), plus those of w carried by its gradient g: |g|
 *      times w's own and the field's or the scaling's, and g I_m^-1 (|g I_m^-1| <= |g| /
 *      lambda_min) times the implicit residual's terms.
 *   R: 1 (the entries of a rotation) plus eps times w's (through the attitude step's angle). */
static double yardstick(const claims_body *d, const claims_rounding *k, int q,
                        const sus_lab_local_ref *ref)
{
    const sus_model *m = &d->m;
    const double(*I)[3] = m->I, *w = ref->w_exact, eps = ref->eps;
    const double nw = hypot(w[0], w[1]),
                 im = fabs(I[0][0]) + fabs(I[0][1]) + fabs(I[1][0]) + fabs(I[1][1]);
    const double lmax = 0.5 * (I[0][0] + I[1][1]) + hypot(0.5 * (I[0][0] - I[1][1]), I[0][1]);
    const double lmin = m->det_m / lmax, field = eps * fabs(sus_c(m, w)) * nw;
    double other = field / lmin, res = 0.0, g[2];
    if (k->projects)
        other = fmax(other, energy_rounding(m, w));
    if (k->implicit)
        res = im * hypot(w[0] - ref->w_k[0], w[1] - ref->w_k[1]) + field;
    if (q == CLAIMS_Q_W)
        return nw + other + res / lmin;
    if (q == CLAIMS_Q_R)
        return 1.0 + eps * (nw + other + res / lmin);
    const double terms = lagmult_terms(m, w, g);
    /* g^T I_m^-1 = (g1 I22 - g2 I21, g2 I11 - g1 I12) / |I_m| */
    const double gi =
        hypot(g[0] * I[1][1] - g[1] * I[1][0], g[1] * I[0][0] - g[0] * I[0][1]) / m->det_m;
    return terms + hypot(g[0], g[1]) * (nw + other) + gi * res;
}

/* The floor of quantity q at eps[j]: the larger of 1000 u times its size (round-off of about u
 * times the quantity then moves a point by at most 0.1%) and 100 u s times the yardstick, the
 * largest over the starts (s substeps per step, each rounding once: the worst-case sum then moves
 * a point by at most 1%), the two floors of claims_window.h's analysis. */
void claims_body_floors(const claims_body *d, const claims_rounding *k, int q,
                        double floor[CLAIMS_NE])
{
    for (int j = 0; j < CLAIMS_NE; j++) {
        double y = 0.0;
        for (int t = 0; t < CLAIMS_NTK; t++)
            y = fmax(y, yardstick(d, k, q, &d->ref[j][t]));
        floor[j] =
            fmax(SUS_LAB_FIT_FLOOR_REL * claims_body_size(d, q), 100.0 * SUS_U * k->substeps * y);
    }
}

static void body_init(int k, claims_body *d)
{
    static const double TK_RATE[CLAIMS_NTK] = {0.0, 0.45, 1.0, 1.75, 2.9};
    char err[256];
    body_get(k, &d->b);
    if (sus_model_init(&d->m, d->b.I, err, sizeof err) != 0)
        ledger_die(err);
    sus_exact_init(&d->ex, &d->m, d->b.w0);
    for (int j = 0; j < CLAIMS_NE; j++) {
        d->eps[j] = EPS_K_MAX / d->ex.k * exp2(-0.25 * j);
        for (int t = 0; t < CLAIMS_NTK; t++)
            sus_lab_local_ref_init(&d->ref[j][t], &d->ex, TK_RATE[t] / d->ex.k, d->eps[j]);
    }
    body_sizes(d);
}

const claims_body *claims_body_get(int k)
{
    if (!built) {
        for (int i = 0; i < BODIES_COUNT; i++)
            body_init(i, &bodies[i]);
        built = 1;
    }
    return &bodies[k];
}
