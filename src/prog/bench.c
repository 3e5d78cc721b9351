/* make bench: work-precision of every registered method against library integrators, the cost of
 * one step, the long-run structure errors, and the speed targets of the benchmark, printed as
 * PASS, MISS or UNDECIDED lines (never a failing test: the machine is shared and noisy).
 * Usage: bench FIGDIR DATADIR, or bench --plot FIGDIR DATADIR
 *
 * Peers, each given the same problem (the paper's body, w(0) = (0.4, 0.5), t in [0, 50]), at
 * abs = rel tolerance 1e-3 ... 1e-15 (four a decade): GSL odeiv2 rk8pd and rkck through
 * gsl_odeiv2_driver_apply and through a gsl_odeiv2_evolve_apply loop, each from initial step
 * 1e-3, 1e-2, 0.1 and 1, and (rk8pd, rkck, attitude formulations, initial step 1) with the
 * absolute error alone, as on the reduced problem; rkf45 and msadams (driver, 1e-3); Boost.Odeint
 * runge_kutta_fehlberg78 (make_controlled) and bulirsch_stoer (integrate_adaptive) when built with
 * SUSLOV_WITH_ODEINT (make bench does). Each on three formulations: (w1, w2, R) with R' = R w^ (11
 * unknowns), (w1, w2, q) with q' = 1/2 q (x) (0, w) and R = R(q/|q|) at the end (6 unknowns), and,
 * for the w accuracies only, (w1, w2) alone (2 unknowns; our Taylor methods get the same choice,
 * "(w only)"). Every run of a configuration starts from the same state, its step size included
 * (src/lab/peers.c), and the error credited to a point is the one its timed runs end with. The
 * "best peer" at an accuracy is the fastest configuration whose timed runs reach it.
 * The reduced problem (src/lab/reduced.h: q alone along the closed-form w, 4 unknowns) goes to
 * rk8pd and rkck (driver or evolve loop, abs = rel or abs alone, initial step 1e-2 or 1) and to
 * Boost's rkf78 (abs = rel or abs alone). The attitude targets compare our fastest method with the
 * best peer on each problem; the w race is information only (the closed form gives w).
 * The phases are in src/lab/bench*.c, the report, tables and figures in src/render/bench*.c.
 * The figures are drawn from DATADIR/bench.csv once it is written; `bench --plot FIGDIR DATADIR`
 * draws them again from a run's data alone (make figures does, from the recorded run). */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"
#include "bench_floor.h"
#include "bench_load.h"
#include "bench_longrun.h"
#include "bench_plot.h"
#include "bench_report.h"
#include "bench_reproduce.h"
#include "bench_sweep.h"
#include "bench_tables.h"
#include "bench_timing.h"
#include "monoclock.h"
#ifdef SUSLOV_WITH_ODEINT
#include "bench_odeint.h"
#endif

#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef SUSLOV_WITH_ODEINT
enum { WITH_ODEINT = 1 };

/* ---- the Boost.Odeint peers (C++, src/prog/bench_odeint.cpp) ---- */

typedef struct {
    const sus_lab_bench_problem *pb;
    suslov_odeint *o;
    size_t dim;
    double T;
    double y[11];
    long steps;
} odeint_run;

static void odeint_fn(void *vctx)
{
    odeint_run *r = vctx;
    sus_lab_peer_initial(r->dim, r->pb->ex.w0, r->y);
    r->steps = suslov_odeint_run(r->o, r->T, r->y);
}

static int odeint_result(const void *vctx, double w[2], double R[3][3])
{
    const odeint_run *r = vctx;
    /* the reduced problem is given w(t): its w is the closed form's */
    memcpy(w, r->dim == 4 ? r->pb->w_T : r->y, 2 * sizeof(double));
    if (r->dim != 2)
        sus_lab_peer_attitude(r->dim, r->y, R);
    return 1;
}

static void odeint_release(void *vctx)
{
    odeint_run *r = vctx;
    suslov_odeint_close(r->o);
    free(r);
}

static const sus_lab_bench_run_ops ODEINT_OPS = {odeint_fn, odeint_result, odeint_release};

/* A Boost peer's series: stepper on formulation dim, or (dim 4) rkf78 on the reduced problem
 * with rel = rel_factor tol (1: abs = rel; 0: absolute error alone). */
static void sweep_odeint(sus_lab_bench *b, int stepper, size_t dim, double rel_factor)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    snprintf(s->name, sizeof s->name, "Boost %s %s%s",
             stepper == SUSLOV_ODEINT_RKF78 ? "rkf78" : "bulirsch-stoer",
             sus_lab_bench_dim_name(dim),
             dim != 4           ? ""
             : rel_factor > 0.0 ? " abs=rel"
                                : " abs");
    s->w_only = dim == 2;
    s->reduced = dim == 4;
    s->dim = dim;
    s->rel = rel_factor;
    for (int j = 0;
         j < SUS_LAB_BENCH_MAXPTS && SUS_LAB_BENCH_PEER_TOL(j) >= SUS_LAB_BENCH_PEER_TOL_MIN; j++) {
        const double tol = SUS_LAB_BENCH_PEER_TOL(j);
        odeint_run *r = sus_lab_bench_calloc(1, sizeof *r);
        *r = (odeint_run){&b->pb,
                          dim == 4 ? suslov_odeint_open_reduced(&b->pb.red, tol, rel_factor * tol)
                                   : suslov_odeint_open(stepper, (int)dim, tol, &b->pb.model),
                          dim,
                          SUS_LAB_BENCH_T_END,
                          {0},
                          0};
        if (!r->o)
            sus_lab_bench_die("Boost.Odeint allocation failed");
        if (!sus_lab_bench_record(b, s, tol, &ODEINT_OPS, r)) {
            odeint_release(r);
            continue;
        }
        s->steps[s->n - 1] = r->steps;
    }
}

/* On the full problem rkf78 and Bulirsch-Stoer; on the reduced one rkf78 under either control. */
static void more_peers(sus_lab_bench *b, size_t dim, void *ctx)
{
    (void)ctx;
    for (int k = 0; k < 2; k++)
        if (dim == 4)
            sweep_odeint(b, SUSLOV_ODEINT_RKF78, dim, k == 0 ? 1.0 : 0.0);
        else
            sweep_odeint(b, k, dim, 1.0);
}
#else
enum { WITH_ODEINT = 0 };
#define more_peers NULL
#endif

/* ---- main ---- */

static int progress_tty;

static void progress(const char *what)
{
    fprintf(stderr, "\rbench: %-60s", what);
    fflush(stderr);
}

/* The measurements, phase by phase, with the seconds each took into t_phase[0..4]. Returns the
 * number of points whose timed runs' errors differ from the recorded ones. */
static int measure(sus_lab_bench *b, double t_phase[5])
{
    t_phase[0] = sus_sys_now();
    sus_lab_bench_sweep_all(b, more_peers, NULL);
    t_phase[1] = sus_sys_now();
    const int differ = sus_lab_bench_time_points(b);
    t_phase[2] = sus_sys_now();
    sus_lab_bench_envelopes(b);
    sus_lab_bench_measure_step_costs(b);
    sus_lab_bench_measure_tol_costs(b);
    t_phase[3] = sus_sys_now();
    sus_lab_bench_progress(b, "long runs");
    sus_lab_bench_long_runs(b);
    sus_lab_bench_equal_error_runs(b);
    t_phase[4] = sus_sys_now();
    if (progress_tty)
        fprintf(stderr, "\r%70s\r", "");
    return differ;
}

/* The suslov program beside this one (argv0's directory). */
static const char *suslov_path(const char *argv0, char *buf, size_t len)
{
    const char *slash = strrchr(argv0, '/');
    snprintf(buf, len, "%.*ssuslov", slash ? (int)(slash - argv0 + 1) : 0, argv0);
    return buf;
}

/* The re-runs with suslov, reported; returns 1 when a row was not reproduced. */
static int check(const sus_lab_bench *b, const char *argv0)
{
    char suslov[4096];
    sus_lab_bench_reproduced rep;
    sus_lab_bench_check_reproduce(b, suslov_path(argv0, suslov, sizeof suslov), &rep);
    sus_plot_bench_reproduced(b, &rep, suslov);
    return rep.ok != rep.tried;
}

/* FIGDIR's figures drawn from DATADIR/bench.csv. Returns 0, or 1 with a message on stderr. */
static int plot(const char *figdir, const char *datadir)
{
    sus_lab_bench b;
    if (sus_lab_bench_load(&b, datadir) != 0)
        return 1;
    const int failed = sus_plot_bench_figures(&b, figdir) != 0;
    sus_lab_bench_free(&b);
    return failed;
}

/* Measures, reports, writes DATADIR's files and draws FIGDIR's figures from them. */
static int bench(const char *argv0, const char *figdir, const char *datadir)
{
    progress_tty = isatty(2);
    sus_lab_bench b;
    if (sus_lab_bench_init(&b, progress_tty ? progress : NULL) != 0)
        return 1;
    double t_phase[6];
    const int differ = measure(&b, t_phase);
    sus_plot_bench_header(&b, differ, WITH_ODEINT);
    sus_plot_bench_costs_and_targets(&b);
    sus_plot_bench_long_runs(&b);
    sus_plot_bench_equal_error(&b);
    sus_plot_bench_growth(&b);
    const int unreproduced = check(&b, argv0);
    t_phase[5] = sus_sys_now();
    printf("\nbench ran for %.1f s (sweeps %.1f, work-precision timing %.1f, step costs %.1f, "
           "long runs %.1f, reproducing %.1f)\n",
           t_phase[5] - t_phase[0], t_phase[1] - t_phase[0], t_phase[2] - t_phase[1],
           t_phase[3] - t_phase[2], t_phase[4] - t_phase[3], t_phase[5] - t_phase[4]);
    fflush(stdout);
    /* data the companion would quote as checked: none rather than wrong */
    const int failed = differ || unreproduced;
    if (failed)
        fprintf(stderr,
                "bench: a CHECK FAILED (see its line in the output above); nothing written\n");
    const int unwritten = failed || sus_plot_bench_tables(&b, datadir) != 0;
    sus_lab_bench_free(&b);
    return unwritten || plot(figdir, datadir);
}

int main(int argc, char **argv)
{
    const int replot = argc == 4 && strcmp(argv[1], "--plot") == 0;
    if (argc != 3 + replot || (!replot && argv[1][0] == '-')) {
        fprintf(stderr, "usage: bench FIGDIR DATADIR (measure, write DATADIR's files, draw "
                        "FIGDIR's figures from them)\n"
                        "       bench --plot FIGDIR DATADIR (draw FIGDIR's figures from "
                        "DATADIR/bench.csv)\n");
        return 2;
    }
    gsl_set_error_handler_off();
    return replot ? plot(argv[2], argv[3]) : bench(argv[0], argv[1], argv[2]);
}
