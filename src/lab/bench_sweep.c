#include "bench_sweep.h"

#include "bench_runs.h"

#include <stdio.h>
#include <stdlib.h>

#define T_END SUS_LAB_BENCH_T_END
#define PEER_TOL SUS_LAB_BENCH_PEER_TOL
#define MAXPTS SUS_LAB_BENCH_MAXPTS
#define MAX_STEPS 2000000L /* caps euler's sweep: 2e6 steps of T/N is ~0.1 s a point */
#define FINE_N 40          /* the Taylor methods: every N up to here */

/* The N grid of our methods: the Taylor methods at every N from 2 to FINE_N, then by factors
 * ~sqrt 2; the other high-order ones from N = 4 by factors ~sqrt 2, the paper's low-order DSPs
 * from N = 50 by factors of 4. */
static double next_N(double Nd, int fine, int high)
{
    return fine && Nd < FINE_N ? Nd + 1.0 : Nd * (high ? 1.4142135623730951 : 4.0);
}

/* A sweep stops once the errors are below SWEEP_FLOOR, ten times below the finest target level,
 * or once they are below ROUNDOFF_ZONE and 1.4 times as many steps no longer halve them (which
 * any method of order >= 2 does while truncation dominates): more steps then only add round-off
 * (the compositions' floor is above 1e-15). Not for a tolerance-driven method, whose steps need
 * not grow with accuracy (exact-attitude's series in E takes the rest of a run in one step
 * whatever TOL): it is swept over the peers' whole TOL grid, as they are. */
#define SWEEP_FLOOR 1e-15
#define ROUNDOFF_ZONE 1e-12

static double worst_err(const sus_lab_bench_series *s, int i)
{
    return fmax(s->err_w[i], s->w_only ? 0.0 : s->err_R[i]);
}

/* One of our runs that takes longer than this is far slower than our fastest and the best peer's
 * runs at every level, so it can be the fastest at no level: our sweep stops there (the slow
 * implicit methods' finest steps cost more bench time than everything else they do). A peer's
 * sweep is never cut this way: a burst of load in that one run could cut away a peer's fastest
 * point. */
#define OURS_SLOW_RUN 1e-2

static int sweep_done(const sus_lab_bench_series *s)
{
    const int i = s->n - 1;
    if (s->ours && s->last_run > OURS_SLOW_RUN)
        return 1;
    const double e = worst_err(s, i);
    if (e < SWEEP_FLOOR)
        return 1;
    if (e > ROUNDOFF_ZONE || s->tol_driven)
        return 0;
    for (int j = i - 1; j >= 0; j--)
        if ((double)s->steps[j] * 1.4 <= (double)s->steps[i])
            return e > 0.5 * worst_err(s, j);
    return 0;
}

/* The run of N steps a series of ours times: the whole step or the w-step alone. */
static void *whole_run(const sus_lab_bench *b, const sus_lab_bench_series *s, long N)
{
    sus_lab_bench_dsp_run *r = sus_lab_bench_calloc(1, sizeof *r);
    *r = (sus_lab_bench_dsp_run){&b->pb, s->me->type, s->recon, N, T_END, {0}, {0}, 0.0};
    return r;
}

static void *w_alone_run(const sus_lab_bench *b, const sus_lab_bench_series *s, long N)
{
    sus_lab_bench_w_run *r = sus_lab_bench_calloc(1, sizeof *r);
    *r = (sus_lab_bench_w_run){&b->pb, s->me->type, N, T_END, {0}, 0.0, 0};
    return r;
}

/* Series s over the N grid from N0 (next_N's fine and high), each point the run make gives. */
static void sweep_steps(sus_lab_bench *b, sus_lab_bench_series *s, double N0, int fine, int high,
                        const sus_lab_bench_run_ops *ops,
                        void *(*make)(const sus_lab_bench *, const sus_lab_bench_series *, long))
{
    long prevN = 0;
    for (double Nd = N0; Nd <= (double)MAX_STEPS && s->n < MAXPTS; Nd = next_N(Nd, fine, high)) {
        const long N = lround(Nd);
        if (N == prevN)
            continue;
        prevN = N;
        void *r = make(b, s, N);
        if (!sus_lab_bench_record(b, s, T_END / (double)N, ops, r)) {
            ops->release(r);
            continue;
        }
        s->steps[s->n - 1] = N;
        if (sweep_done(s))
            break;
    }
}

static void sweep_ours(sus_lab_bench *b, const sus_step_method *me, sus_recon recon)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    sus_step_method_label(me->type, recon, s->name, sizeof s->name);
    const int fine = sus_lab_bench_own_attitude(me), high = me->type->desc.order > 4;
    s->ours = 1;
    s->me = me;
    s->recon = recon;
    s->preserves = sus_lab_bench_keeps_structure(me);
    sweep_steps(b, s,
                fine   ? 2.0
                : high ? 4.0
                       : 50.0,
                fine, high, &SUS_LAB_BENCH_DSP_OPS, whole_run);
}

/* A Taylor method's w alone (its w-step does not depend on the attitude series, so the row's
 * suslov_args reproduce its w error), on the same N grid as sweep_ours. */
static void sweep_ours_w(sus_lab_bench *b, const sus_step_method *me)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    snprintf(s->name, sizeof s->name, "%s (w only)", me->type->name);
    s->ours = 1;
    s->preserves = 1; /* E and w3 = 0, all there is without an attitude */
    s->w_only = 1;
    s->me = me;
    s->recon = me->recon;
    sweep_steps(b, s, 2.0, 1, 1, &SUS_LAB_BENCH_W_OPS, w_alone_run);
}

/* A tolerance-driven method of ours on the peers' TOL grid (each run to T_END through the
 * driver). */
static void sweep_ours_tol(sus_lab_bench *b, const sus_step_method *me)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    sus_step_method_label(me->type, me->recon, s->name, sizeof s->name);
    s->ours = 1;
    s->tol_driven = 1;
    s->me = me;
    s->recon = me->recon;
    s->preserves = sus_lab_bench_keeps_structure(me);
    for (int j = 0; s->n < MAXPTS && PEER_TOL(j) >= SUS_LAB_BENCH_PEER_TOL_MIN; j++) {
        sus_lab_bench_tol_run *r = sus_lab_bench_calloc(1, sizeof *r);
        *r = (sus_lab_bench_tol_run){.pb = &b->pb, .st = me->type, .tol = PEER_TOL(j), .T = T_END};
        if (!sus_lab_bench_record(b, s, PEER_TOL(j), &SUS_LAB_BENCH_TOL_OPS, r)) {
            free(r);
            continue;
        }
        s->steps[s->n - 1] = r->last.k;
        if (sweep_done(s))
            break;
    }
}

const char *sus_lab_bench_dim_name(size_t dim)
{
    return dim == 11 ? "(w,R)" : dim == 6 ? "(w,q)" : dim == 4 ? "reduced (q)" : "(w)";
}

/* A GSL peer's series, on the full problem or on the reduced one (dim 4), with abs = tol and
 * rel = rel_factor tol: 1 (GSL's y control, abs = rel) or 0 (absolute error alone). */
static void sweep_gsl_control(sus_lab_bench *b, const gsl_odeiv2_step_type *type, size_t dim,
                              sus_lab_peer_api api, double hstart, double rel_factor)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    snprintf(s->name, sizeof s->name, "GSL %s %s %s%s h0 %g", type->name,
             sus_lab_bench_dim_name(dim), api == SUS_LAB_PEER_DRIVER ? "driver" : "evolve",
             rel_factor > 0.0 ? (dim == 4 ? " abs=rel" : "") : " abs", hstart);
    s->w_only = dim == 2;
    s->reduced = dim == 4;
    s->type = type;
    s->dim = dim;
    s->api = api;
    s->hstart = hstart;
    s->rel = rel_factor;
    for (int j = 0; j < MAXPTS && PEER_TOL(j) >= SUS_LAB_BENCH_PEER_TOL_MIN; j++) {
        sus_lab_bench_peer_run *g = sus_lab_bench_calloc(1, sizeof *g);
        *g = (sus_lab_bench_peer_run){.pb = &b->pb, .T = T_END};
        const double tol = PEER_TOL(j);
        if ((dim == 4 ? sus_lab_peer_open_reduced(&g->p, &b->pb.red, type, api, tol,
                                                  rel_factor * tol, hstart)
                      : sus_lab_peer_open(&g->p, &b->pb.model, type, dim, api, tol,
                                          rel_factor * tol, hstart)) != 0)
            sus_lab_bench_die("GSL allocation failed");
        if (!sus_lab_bench_record(b, s, PEER_TOL(j), &SUS_LAB_BENCH_PEER_OPS, g)) {
            SUS_LAB_BENCH_PEER_OPS.release(g);
            continue;
        }
        s->steps[s->n - 1] = g->steps;
    }
}

static void sweep_gsl(sus_lab_bench *b, const gsl_odeiv2_step_type *type, size_t dim,
                      sus_lab_peer_api api, double hstart)
{
    sweep_gsl_control(b, type, dim, api, hstart, 1.0);
}

/* The reduced problem: rk8pd and rkck through either API, under either error control, from a
 * small and a large initial step (the step controller forgets hstart within a few steps: the
 * full problem's four initial steps differ by a few per cent at most). */
static void sweep_reduced(sus_lab_bench *b)
{
    const gsl_odeiv2_step_type *types[2] = {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkck};
    const double hstarts[2] = {1e-2, 1.0}, rel[2] = {1.0, 0.0};
    for (int k = 0; k < 2; k++)
        for (int api = 0; api < 2; api++)
            for (int c = 0; c < 2; c++)
                for (int h = 0; h < 2; h++)
                    sweep_gsl_control(b, types[k], 4, (sus_lab_peer_api)api, hstarts[h], rel[c]);
}

static void *magnus6_run(const sus_lab_bench *b, const sus_lab_bench_series *s, long N)
{
    (void)s;
    sus_lab_bench_magnus6_run *r = sus_lab_bench_calloc(1, sizeof *r);
    *r = (sus_lab_bench_magnus6_run){&b->pb, N, T_END, {0}};
    return r;
}

/* Magnus6 along the closed-form w (magnus6.h), on the Taylor methods' N grid: the prototype's
 * proposal for the loose levels, a peer on the reduced problem. */
static void sweep_magnus6(sus_lab_bench *b)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    snprintf(s->name, sizeof s->name, "Magnus6 reduced (q) fixed step");
    s->reduced = 1;
    s->fixed_peer = 1;
    s->dim = 4;
    sweep_steps(b, s, 2.0, 1, 1, &SUS_LAB_BENCH_MAGNUS6_OPS, magnus6_run);
}

static void sweep_methods(sus_lab_bench *b)
{
    for (int m = 0; m < sus_step_method_count(); m++) {
        const sus_step_method *me = sus_step_method_get(m);
        sweep_ours(b, me, me->recon);
        if (sus_lab_bench_own_attitude(me))
            sweep_ours_w(b, me);
        /* the symmetric Cayley reconstruction beside the default one, where it differs */
        else if (me->type->desc.order >= 2 && me->recon != SUS_RECON_CAYLEY_MID)
            sweep_ours(b, me, SUS_RECON_CAYLEY_MID);
    }
    for (int m = sus_step_method_count(); m < sus_step_method_count_all(); m++)
        sweep_ours_tol(b, sus_step_method_get(m));
}

void sus_lab_bench_sweep_all(sus_lab_bench *b, sus_lab_bench_more_peers more, void *ctx)
{
    sus_lab_bench_progress(b, "sweeping");
    sweep_methods(b);
    /* the two found fastest, in every configuration a user might pick */
    const gsl_odeiv2_step_type *tuned[2] = {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkck};
    const double hstarts[4] = {1e-3, 1e-2, 0.1, 1.0};
    const size_t dims[3] = {11, 6, 2};
    for (int d = 0; d < 3; d++) {
        for (int k = 0; k < 2; k++)
            for (int api = 0; api < 2; api++)
                for (int h = 0; h < 4; h++)
                    sweep_gsl(b, tuned[k], dims[d], (sus_lab_peer_api)api, hstarts[h]);
        /* the absolute error alone, which wins on the reduced problem at the tight levels: the
         * two tuned steppers through either API, from the largest initial step */
        for (int k = 0; k < 2 && dims[d] != 2; k++)
            for (int api = 0; api < 2; api++)
                sweep_gsl_control(b, tuned[k], dims[d], (sus_lab_peer_api)api, 1.0, 0.0);
        sweep_gsl(b, gsl_odeiv2_step_rkf45, dims[d], SUS_LAB_PEER_DRIVER, 1e-3);
        sweep_gsl(b, gsl_odeiv2_step_msadams, dims[d], SUS_LAB_PEER_DRIVER, 1e-3);
        if (more)
            more(b, dims[d], ctx);
    }
    sweep_reduced(b);
    sweep_magnus6(b);
    if (more)
        more(b, 4, ctx);
}
