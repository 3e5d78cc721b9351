#define _POSIX_C_SOURCE 200809L
#include "bench.h"

#include "refattitude.h"
#include "so3.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

const double SUS_LAB_BENCH_LEVELS[SUS_LAB_BENCH_NLEVELS] = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};
/* Set before the methods that use the closed form were built, from a prototype's ceilings: Magnus6
 * steps along the cheap closed-form w at the loose levels (1e-4, 1e-6; that Magnus6 is timed here
 * as a peer on the reduced problem, magnus6.h), and at the others a little below the ratios the
 * Taylor methods had already reached, as a guard. */
const double SUS_LAB_BENCH_LEVEL_TARGET[SUS_LAB_BENCH_NLEVELS] = {1.8, 2.4, 2.2, 3.0, 3.7, 4.5};

int sus_lab_bench_init(sus_lab_bench *b, void (*progress)(const char *what))
{
    char err[256];
    *b = (sus_lab_bench){.progress = progress};
    sus_lab_bench_problem *pb = &b->pb;
    if (sus_model_init(&pb->model, SUS_PAPER_INERTIA, err, sizeof err) != 0) {
        fprintf(stderr, "bench: the paper's inertia is rejected: %s\n", err);
        return -1;
    }
    sus_exact_init(&pb->ex, &pb->model, SUS_PAPER_OMEGA0);
    sus_exact_fast_init(&pb->red, &pb->ex);
    sus_exact_omega(&pb->ex, SUS_LAB_BENCH_T_END, pb->w_T);
    double w_ref[2];
    sus_refatt_precise(&pb->model, pb->ex.w0, SUS_LAB_BENCH_T_END, w_ref, pb->R_T);
    return 0;
}

void sus_lab_bench_free(sus_lab_bench *b)
{
    for (int i = 0; i < b->nseries; i++)
        free(b->S[i]);
    free(b->S);
    free(b->points);
    sus_lab_bench_costs *c = &b->cost;
    free(c->name);
    free(c->ns_raw);
    free(c->ns_full);
    free(c->ns_direct);
    free(c->ns_full_min);
    free(c->newton);
    for (int k = 0; k < 4; k++) {
        free(b->env[k].sec);
        free(b->env[k].err);
    }
    free(b->LR);
    free(b->EQ);
    *b = (sus_lab_bench){0};
}

double sus_lab_bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void sus_lab_bench_progress(const sus_lab_bench *b, const char *what)
{
    if (b->progress)
        b->progress(what);
}

void sus_lab_bench_die(const char *what)
{
    fprintf(stderr, "bench: %s\n", what);
    exit(1);
}

void *sus_lab_bench_calloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (!p)
        sus_lab_bench_die("out of memory");
    return p;
}

static void *grow(void *p, size_t n, size_t size)
{
    p = realloc(p, n * size);
    if (!p)
        sus_lab_bench_die("out of memory");
    return p;
}

/* The Taylor methods carry their own attitude (no reconstruction to choose) and have a w-step
 * that does not depend on the attitude series. */
int sus_lab_bench_own_attitude(const sus_step_method *me) { return !me->type->desc.follows_recon; }

/* Keeps E, w3 = 0 and R in SO(3) by construction, as the method's type says of itself. */
int sus_lab_bench_keeps_structure(const sus_step_method *me)
{
    return me->type->desc.conserves_energy;
}

/* A step made of several implicit substeps: the compositions. */
int sus_lab_bench_composed(const sus_step_method *me)
{
    return me->type->desc.implicit && me->type->desc.substeps > 1;
}

const char *sus_lab_bench_param_name(const sus_lab_bench_series *s)
{
    return (s->ours && !s->tol_driven) || s->fixed_peer ? "eps" : "tol";
}

sus_lab_bench_series *sus_lab_bench_new_series(sus_lab_bench *b)
{
    b->S = grow(b->S, (size_t)(b->nseries + 1), sizeof *b->S);
    b->S[b->nseries] = sus_lab_bench_calloc(1, sizeof **b->S);
    return b->S[b->nseries++];
}

void sus_lab_bench_errors(const sus_lab_bench *b, const sus_lab_bench_series *s, const double w[2],
                          const double R[3][3], double *ew, double *eR)
{
    *ew = hypot(w[0] - b->pb.w_T[0], w[1] - b->pb.w_T[1]);
    *eR = s->w_only ? INFINITY : sus_so3_dist(b->pb.R_T, R);
}

static void add_point(sus_lab_bench *b, const sus_lab_bench_run_ops *ops, void *ctx,
                      sus_lab_bench_series *s, int i)
{
    b->points = grow(b->points, (size_t)(b->npoints + 1), sizeof *b->points);
    b->points[b->npoints++] = (sus_lab_bench_point){ops, ctx, s, i, 1, {0}};
}

int sus_lab_bench_record(sus_lab_bench *b, sus_lab_bench_series *s, double param,
                         const sus_lab_bench_run_ops *ops, void *ctx)
{
    double w[2], R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, ew, eR;
    const double t0 = sus_lab_bench_now();
    ops->run(ctx);
    s->last_run = sus_lab_bench_now() - t0;
    if (s->n >= SUS_LAB_BENCH_MAXPTS || !ops->result(ctx, w, R))
        return 0;
    sus_lab_bench_errors(b, s, w, R, &ew, &eR);
    if (!(ew < 1.0 && (s->w_only || eR < 1.0)))
        return 0;
    const int i = s->n++;
    s->param[i] = param;
    s->err_w[i] = ew;
    s->err_R[i] = eR;
    add_point(b, ops, ctx, s, i);
    return 1;
}
