#include "stability_maps.h"

#include "workpool.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* What a row costs, roughly: its steps, times the substeps of each, times about ten for an
 * implicit step's Newton solves and twice that again where the branch is checked. Only the order
 * of hand-out depends on it, never a result. */
static double row_cost(const sus_lab_stab_maps *s, int job)
{
    const sus_stepper_type *st = sus_step_method_get(job / s->nh)->type;
    const double h = s->hs[job % s->nh];
    double c = (double)sus_lab_stability_steps(h) * (st->desc.substeps > 0 ? st->desc.substeps : 1);
    if (st->desc.implicit)
        c *= 10.0;
    if (st->equation && h >= SUS_LAB_STAB_BRANCH_H)
        c *= 2.0;
    return c;
}

typedef struct {
    double cost;
    int job;
} costed;

/* Longest first; equal costs in job order (qsort is not stable). */
static int by_cost(const void *a, const void *b)
{
    const costed *x = a, *y = b;
    return x->cost > y->cost ? -1 : x->cost < y->cost ? 1 : (x->job > y->job) - (x->job < y->job);
}

static void run_row(int job, void *result, void *vctx)
{
    const sus_lab_stab_maps *s = vctx;
    const sus_stepper_type *st = sus_step_method_get(job / s->nh)->type;
    sus_lab_stability_map(s->paper, st, &s->hs[job % s->nh], 1, s->nangle, result);
}

static void row_done(int job, void *vctx)
{
    const sus_lab_stab_maps *s = vctx;
    if (s->done)
        s->done(job / s->nh, job % s->nh, s->ctx);
}

int sus_lab_stability_maps(const sus_lab_stab_maps *s, sus_lab_stab_result *results, char *err,
                           size_t errlen)
{
    const int njobs = sus_step_method_count() * s->nh;
    int *order = malloc((size_t)njobs * sizeof *order);
    costed *c = malloc((size_t)njobs * sizeof *c);
    if (!order || !c) {
        free(order), free(c);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int j = 0; j < njobs; j++)
        c[j] = (costed){row_cost(s, j), j};
    qsort(c, (size_t)njobs, sizeof *c, by_cost);
    for (int j = 0; j < njobs; j++)
        order[j] = c[j].job;
    free(c);
    const sus_sys_pool pool = {njobs,    order,      (size_t)s->nangle * sizeof *results,
                               results,  s->workers, run_row,
                               row_done, (void *)s};
    const int rc = sus_sys_pool_run(&pool, err, errlen);
    free(order);
    return rc;
}

void sus_lab_stability_onsets(const sus_lab_stab_result *map, const double *hs, int nh, int nangle,
                              sus_lab_stab_onsets *o)
{
    for (int c = 0; c < SUS_LAB_STAB_NCLASS; c++) {
        o->first_h[c] = INFINITY;
        o->starts[c] = 0;
    }
    for (int a = 0; a < nangle; a++) {
        int seen[SUS_LAB_STAB_NCLASS] = {0};
        for (int i = 0; i < nh; i++) {
            const int c = map[i * nangle + a].cls;
            o->first_h[c] = fmin(o->first_h[c], hs[i]);
            seen[c] = 1;
        }
        for (int c = 0; c < SUS_LAB_STAB_NCLASS; c++)
            o->starts[c] += seen[c];
    }
}
