#include "claims_bodies.h"

#include "ledger.h"

#include <math.h>

#define EPS_K_MAX 1.16

static claims_body bodies[BODIES_COUNT];
static int built;

/* w and lambda at the starts and at the limit bound their sizes along the motion (E is kept, so
 * |w| moves within a factor cond(I_m)^(1/2); lambda changes with c(w) only). */
static void body_sizes(claims_body *d)
{
    double wl[2];
    sus_exact_limit(&d->ex, wl);
    double sw = hypot(wl[0], wl[1]), sl = fabs(sus_lagmult(&d->m, wl));
    for (int t = 0; t < CLAIMS_NTK; t++) {
        const double *w = d->ref[0][t].w_k;
        sw = fmax(sw, hypot(w[0], w[1]));
        sl = fmax(sl, fabs(sus_lagmult(&d->m, w)));
    }
    d->size_w = sw;
    d->size_lambda = sl;
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
            sus_exp_local_ref_init(&d->ref[j][t], &d->ex, TK_RATE[t] / d->ex.k, d->eps[j]);
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
