#define _POSIX_C_SOURCE 200809L
#include "bench_longrun.h"

#include "bench_runs.h"
#include "monoclock.h"
#include "refattitude.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>

#define T_LONG SUS_EXP_BENCH_T_LONG

/* ---- the long run: structure errors at T = 1e4 ---- */

typedef struct {
    const sus_model *m;
    double e0, orth, energy, w3;
} lr_acc;

static int lr_emit(void *vctx, const sus_row *row)
{
    lr_acc *a = vctx;
    a->orth = fmax(a->orth, sus_so3_orth_defect(row->R));
    a->energy = fmax(a->energy, fabs(sus_energy(a->m, row->w) - a->e0));
    a->w3 = fmax(a->w3, fabs(row->w[2]));
    return 0;
}

static void long_run_ours(const sus_exp_bench *b, const sus_exp_bench_series *s, int j, lr_acc *a)
{
    const sus_step_method *me = s->me;
    sus_run_report rep;
    if (s->tol_driven) {
        const sus_tol_config tc = {&b->pb.model, me->type, s->param[j], T_LONG, T_LONG / 1000.0, 0};
        sus_run_tol(&tc, b->pb.ex.w0, lr_emit, a, &rep);
        return;
    }
    const double eps = s->param[j];
    const long N = lround(T_LONG / eps);
    const sus_run_config cfg = {&b->pb.model, me->type, s->recon,
                                eps,          N,        N / 1000 > 0 ? N / 1000 : 1};
    sus_run(&cfg, b->pb.ex.w0, lr_emit, a, &rep);
}

/* For (w, q) the attitude is R(q/|q|), orthogonal by construction; ||q| - 1| is its drift,
 * reported in place of |R^T R - I|. */
static void long_run_peer(const sus_exp_bench *b, const sus_exp_bench_series *s, int j, lr_acc *a)
{
    gsl_odeiv2_system sys = {s->dim == 11 ? sus_exp_peer_rhs_wR : sus_exp_peer_rhs_wq, NULL, s->dim,
                             (void *)&b->pb.model};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, s->type, s->hstart, s->param[j], s->param[j]);
    double y[11], t = 0.0;
    sus_exp_peer_initial(s->dim, b->pb.ex.w0, y);
    for (int k = 1; d && k <= 1000; k++) {
        if (gsl_odeiv2_driver_apply(d, &t, T_LONG * k / 1000.0, y) != GSL_SUCCESS)
            break;
        double R[3][3];
        sus_exp_peer_attitude(s->dim, y, R);
        const double nq = sqrt(y[2] * y[2] + y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
        const double w[3] = {y[0], y[1], 0.0};
        a->orth = fmax(a->orth, s->dim == 11 ? sus_so3_orth_defect(R) : fabs(nq - 1.0));
        a->energy = fmax(a->energy, fabs(sus_energy(a->m, w) - a->e0));
    }
    if (d)
        gsl_odeiv2_driver_free(d);
}

static int long_run_wanted(const sus_exp_bench_series *s)
{
    if (s->ours)
        return s->preserves && !s->w_only;
    return s->type == gsl_odeiv2_step_rk8pd && s->api == SUS_EXP_PEER_DRIVER && s->hstart == 1e-3 &&
           s->dim != 2;
}

/* The first point of s whose attitude error is at most 1e-10 (-1 if none). */
static int point_at_1e10(const sus_exp_bench_series *s)
{
    for (int k = 0; k < s->n; k++)
        if (s->err_R[k] <= 1e-10)
            return k;
    return -1;
}

void sus_exp_bench_long_runs(sus_exp_bench *b)
{
    const double E0 = sus_energy(&b->pb.model, b->pb.ex.w0);
    b->LR = sus_exp_bench_calloc((size_t)b->nseries, sizeof *b->LR);
    for (int i = 0; i < b->nseries; i++) {
        const sus_exp_bench_series *s = b->S[i];
        const int j = point_at_1e10(s);
        if (j < 0 || !long_run_wanted(s))
            continue;
        sus_exp_bench_longrun *L = &b->LR[b->nlr++];
        snprintf(L->name, sizeof L->name, "%.63s", s->name);
        lr_acc a = {&b->pb.model, E0, 0.0, 0.0, 0.0};
        (s->ours ? long_run_ours : long_run_peer)(b, s, j, &a);
        L->orth = a.orth;
        L->energy = a.energy;
        L->w3 = a.w3;
        L->ours = s->ours;
        L->dim = s->dim;
    }
}

/* ---- at T = 1e4 and equal error: our Taylor methods against rk8pd on (w, q) ---- */

#define EQ_REPEATS 3 /* the minimum over a few runs: each is milliseconds long */

static double min_seconds(void (*fn)(void *), void *ctx)
{
    double best = INFINITY;
    for (int r = 0; r < EQ_REPEATS; r++) {
        const double t0 = sus_sys_now();
        fn(ctx);
        best = fmin(best, sus_sys_now() - t0);
    }
    return best;
}

/* rk8pd (w, q) through the driver from hstart 1e-3: the loosest of four tolerances a decade whose
 * attitude error at T_LONG is at most e->err. */
static void rk8pd_matching(const sus_exp_bench *b, const double R_ref[3][3],
                           sus_exp_bench_equal_error *e)
{
    e->peer_sec = e->peer_err = INFINITY;
    e->peer_tol = 0.0;
    for (int j = 0; SUS_EXP_BENCH_PEER_TOL(j) >= SUS_EXP_BENCH_PEER_TOL_MIN; j++) {
        sus_exp_bench_peer_run g = {.pb = &b->pb, .T = T_LONG};
        const double tol = SUS_EXP_BENCH_PEER_TOL(j);
        if (sus_exp_peer_open(&g.p, &b->pb.model, gsl_odeiv2_step_rk8pd, 6, SUS_EXP_PEER_DRIVER,
                              tol, 1e-3) != 0)
            break;
        sus_exp_bench_peer_fn(&g);
        double R[3][3];
        sus_exp_peer_attitude(6, g.y, R);
        const double err = sus_so3_dist(R_ref, R);
        double sec = INFINITY;
        if (g.status == GSL_SUCCESS && err <= e->err)
            sec = min_seconds(sus_exp_bench_peer_fn, &g);
        sus_exp_peer_close(&g.p);
        if (isfinite(sec)) {
            e->peer_sec = sec;
            e->peer_err = err;
            e->peer_tol = tol;
            return;
        }
    }
}

/* Explicit methods only: the target is the series methods', and an implicit one needs so many
 * steps to reach 1e-10 that its T = 1e4 runs would take most of this phase. */
static int equal_error_wanted(const sus_exp_bench_series *s)
{
    return s->ours && !s->w_only && !s->me->type->implicit && sus_exp_bench_own_attitude(s->me);
}

/* Series s at point j run to T_LONG: the fastest of a few runs, and its attitude error. */
static void ours_to_t_long(const sus_exp_bench *b, const sus_exp_bench_series *s, int j,
                           const double R_ref[3][3], sus_exp_bench_equal_error *e)
{
    const sus_stepper_type *st = s->me->type;
    if (s->tol_driven) {
        sus_exp_bench_tol_run r = {.pb = &b->pb, .st = st, .tol = s->param[j], .T = T_LONG};
        e->sec = min_seconds(sus_exp_bench_tol_fn, &r);
        e->err = sus_so3_dist(R_ref, r.last.R);
    } else {
        sus_exp_bench_dsp_run r = {&b->pb, st,  s->recon, lround(T_LONG / s->param[j]),
                                   T_LONG, {0}, {0},      0.0};
        e->sec = min_seconds(sus_exp_bench_dsp_fn, &r);
        e->err = sus_so3_dist(R_ref, r.last.R);
    }
}

int sus_exp_bench_equal_error_runs(const sus_exp_bench *b, sus_exp_bench_equal_error *out)
{
    double w_ref[2], R_ref[3][3];
    sus_refatt_precise(&b->pb.model, b->pb.ex.w0, T_LONG, w_ref, R_ref);
    int n = 0;
    for (int i = 0; i < b->nseries; i++) {
        const sus_exp_bench_series *s = b->S[i];
        const int j = equal_error_wanted(s) ? point_at_1e10(s) : -1;
        if (j < 0)
            continue;
        sus_exp_bench_equal_error *e = &out[n++];
        *e = (sus_exp_bench_equal_error){.series = i, .point = j};
        ours_to_t_long(b, s, j, R_ref, e);
        rk8pd_matching(b, R_ref, e);
    }
    return n;
}
