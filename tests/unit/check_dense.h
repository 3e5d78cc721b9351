/* A run's rows against the reference, for the unit tests of tolerance-driven methods: the emit
 * callback of sus_run_tol that keeps the largest distance of every row, between steps too, from
 * the closed-form w and the long-double reference attitude. */
#ifndef SUSLOV_CHECK_DENSE_H
#define SUSLOV_CHECK_DENSE_H

#include "driver.h"
#include "exact.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>

typedef struct {
    sus_exact ex;
    sus_refatt ref;
    double worst_R, worst_w;
} dense_ctx;

static inline int against_reference(void *vctx, const sus_row *r)
{
    dense_ctx *c = vctx;
    double R[3][3], w[2];
    sus_refatt_advance(&c->ref, r->t, R);
    sus_exact_omega(&c->ex, r->t, w);
    c->worst_R = fmax(c->worst_R, sus_so3_dist(R, r->R));
    c->worst_w = fmax(c->worst_w, hypot(r->w[0] - w[0], r->w[1] - w[1]));
    return 0;
}

#endif
