/* make bench's state: the problem every method and peer is given (the paper's body,
 * w(0) = (0.4, 0.5), t in [0, 50]), the work-precision series, their timed points, the per-step
 * costs and the long runs. The peers get the full problem (w and the attitude, in three
 * formulations) and, apart, the reduced one (reduced.h: the attitude alone along the closed-form
 * w), so that our methods meet them on either structure. The phases fill it in order: sweeps
 * (bench_sweep.h), timing (bench_timing.h), floor analysis (bench_floor.h), long runs
 * (bench_longrun.h); the render layer prints, writes and draws it (bench_report.h,
 * bench_tables.h, bench_plot.h); bench_load.h reads a run's data back for drawing.
 * Errors: |w(50) - w_n| against the closed form, dist(R(50), R_n) (MetMat) against the precise
 * long-double reference sus_refatt_precise (good to ~1e-17, see refattitude.h). */
#ifndef SUS_LAB_BENCH_H
#define SUS_LAB_BENCH_H

#include "exact.h"
#include "model.h"
#include "peers.h"
#include "reduced.h"
#include "registry.h"

#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_LAB_BENCH_T_END 50.0
#define SUS_LAB_BENCH_T_LONG 1e4
#define SUS_LAB_BENCH_T_GROWTH 1e6
/* The accuracies the targets ask for, and the speed-up each level asks for over the best honest
 * peer on the full problem (bench.c says why); on the reduced problem, REDUCED_TARGET at every
 * level. At T_LONG and equal error, LONG_TARGET over rk8pd; the cost of a run to T_GROWTH at
 * most GROWTH_TARGET times the cost of the same run to T_LONG. */
#define SUS_LAB_BENCH_NLEVELS 6
extern const double SUS_LAB_BENCH_LEVELS[SUS_LAB_BENCH_NLEVELS];
extern const double SUS_LAB_BENCH_LEVEL_TARGET[SUS_LAB_BENCH_NLEVELS];
#define SUS_LAB_BENCH_REDUCED_TARGET 1.5
#define SUS_LAB_BENCH_LONG_LEVEL 1e-9 /* the attitude error both sides reach at T_LONG */
#define SUS_LAB_BENCH_LONG_TARGET 20.0
#define SUS_LAB_BENCH_GROWTH_TARGET 1.5
#define SUS_LAB_BENCH_IMPLICIT_TARGET 3.0 /* an implicit step over our rk4 step, at most */
/* The peers' tolerances: four a decade, 10^(-3 - j/4), down to 1e-15. */
#define SUS_LAB_BENCH_TOLS_PER_DECADE 4
#define SUS_LAB_BENCH_PEER_TOL(j) pow(10.0, -3.0 - (double)(j) / SUS_LAB_BENCH_TOLS_PER_DECADE)
#define SUS_LAB_BENCH_PEER_TOL_MIN 0.99e-15
/* Every point of every series is timed in interleaved rounds: a batch of repeats lasting at
 * least BATCH_SECONDS per round, WP_ROUNDS rounds, the median over rounds (with min and max). A
 * burst of load from elsewhere then slows one round of every point alike. */
#define SUS_LAB_BENCH_WP_ROUNDS 7
#define SUS_LAB_BENCH_BATCH_SECONDS 1e-3
/* The per-step costs: the median of ROUNDS interleaved rounds of COST_STEPS steps. */
#define SUS_LAB_BENCH_ROUNDS 11
#define SUS_LAB_BENCH_COST_STEPS 20000L /* eps = 2.5e-3 */
/* Points per series at most: the grids stop well before (about 50 N or tolerances). */
#define SUS_LAB_BENCH_MAXPTS 64

/* The bench's clock, in seconds: the CPU time of the calling thread, so that the other processes
 * of a shared machine are not counted in a run's time (their traffic in the caches and memory
 * still slows it). Every run the bench times is single-threaded and does no I/O. */
double sus_lab_bench_now(void);

/* The problem and its reference values at t = 50. */
typedef struct {
    sus_model model;
    sus_exact ex;
    sus_exact_fast red; /* w(t) for the reduced problem */
    double w_T[2], R_T[3][3];
} sus_lab_bench_problem;

/* One work-precision series: a method of ours (with a reconstruction, or its own attitude, or w
 * alone) or one configuration of a peer on the full or the reduced problem, swept over its step
 * or tolerance. */
typedef struct {
    char name[96];
    int ours;       /* 1: a registered method; 0: a peer */
    int preserves;  /* keeps E, w3 = 0 and R in SO(3) by construction */
    int w_only;     /* w alone, no attitude: counts for the w accuracies only (err_R = inf) */
    int reduced;    /* a peer given w(t) (reduced.h): counts for the attitude only (err_w = 0) */
    int tol_driven; /* ours, tolerance-driven: param is TOL, steps the accepted steps */
    int fixed_peer; /* a peer at fixed steps (Magnus6): param is the step, as for ours */
    const sus_step_method *me; /* ours: the method; NULL for a peer */
    sus_recon recon;
    const gsl_odeiv2_step_type *type; /* a GSL peer's stepper and configuration, else NULL */
    size_t dim;
    sus_lab_peer_api api;
    double hstart, rel; /* a GSL peer's initial step, and its rel tolerance over its abs one */
    int n;
    double param[SUS_LAB_BENCH_MAXPTS], err_w[SUS_LAB_BENCH_MAXPTS], err_R[SUS_LAB_BENCH_MAXPTS];
    double sec[SUS_LAB_BENCH_MAXPTS], smin[SUS_LAB_BENCH_MAXPTS], smax[SUS_LAB_BENCH_MAXPTS];
    long steps[SUS_LAB_BENCH_MAXPTS];
    /* tolerance-driven: the cost of one accepted step in a bare loop */
    double step_ns[SUS_LAB_BENCH_MAXPTS];
    double last_run; /* seconds of the last point's first run (untimed rounds: one clock reading) */
} sus_lab_bench_series;

/* What a timed run is: run it, read the state it ended in (1 when it succeeded), and free its
 * context and whatever the context holds. */
typedef struct {
    void (*run)(void *ctx);
    int (*result)(const void *ctx, double w[2], double R[3][3]);
    void (*release)(void *ctx);
} sus_lab_bench_run_ops;

/* A point of a series, timed with the others: its run, the batch of repeats a round makes, and
 * the seconds per run of each round. */
typedef struct {
    const sus_lab_bench_run_ops *ops;
    void *ctx; /* malloc'd by the sweep; owned by the point */
    sus_lab_bench_series *s;
    int i, batch;
    double t[SUS_LAB_BENCH_WP_ROUNDS];
} sus_lab_bench_point;

/* The cost of one step, n each (one per registered method): the w-step, the whole step through
 * the driver and in a bare loop, Newton iterations per step; GSL's rk4 and the closed form (as
 * exact.h and as exact_fast.h evaluates it); and the tolerance-driven runs' sums of fastest rounds
 * through the driver and in a bare loop. */
typedef struct {
    int n;
    char (*name)[40]; /* the methods' names */
    double *ns_raw, *ns_full, *ns_direct, *ns_full_min, *newton, ns_gsl_rk4, ns_exact;
    double ns_exact_one_exp;
    double tol_drv_min, tol_bare_min;
} sus_lab_bench_costs;

/* The peers' lower envelope: every peer point that no other peer point beats in both time and
 * error, by increasing time (the staircase drawn as one line). */
typedef struct {
    int n;
    double *sec, *err; /* npoints each at most */
} sus_lab_bench_envelope;

/* At T = 1e4 and equal error: one of ours at its first point (towards accuracy) whose run to
 * T = 1e4 ends within LONG_LEVEL, against the loosest rk8pd (w, q) tolerance (four a decade)
 * that does too (peer_sec = INFINITY when none down to 1e-15 does); beside it, for information,
 * rk8pd on the reduced problem likewise (red_*). Seconds are medians of interleaved rounds.
 * R_end: where our run ended. */
typedef struct {
    int series, point;
    double sec, err, R_end[3][3];
    double peer_sec, peer_err, peer_tol;
    double red_sec, red_err, red_tol;
} sus_lab_bench_equal_error;

/* The cost of ours from T = 1e4 to T = 1e6: the fastest at T = 1e4 and equal error, at the same
 * step or TOL, run to T_GROWTH (series = -1 when none ran). */
typedef struct {
    int series, point, eq;             /* eq: its row of b->EQ */
    double sec, sec_long, R_end[3][3]; /* to T_GROWTH and, timed beside it, to T_LONG */
} sus_lab_bench_growth;

/* The structure errors of a long run to T = 1e4. */
typedef struct {
    char name[64];
    double orth, energy,
        w3; /* max over the run of |R^T R - I| (||q| - 1| for (w, q)), |E - E0|, |w3| */
    /* max |E - E0| over the first half of the run (ours): equal to energy where the error was
     * made early (in the transient) and then stayed, below it where E still drifts. */
    double energy_half;
    int ours;
    size_t dim; /* a peer's formulation */
} sus_lab_bench_longrun;

typedef struct {
    sus_lab_bench_problem pb;
    sus_lab_bench_series *
        *S; /* grown one series at a time: as many as the registry and peers give */
    int nseries;
    sus_lab_bench_point *points;
    int npoints;
    sus_lab_bench_costs cost;
    /* the full problem's peers 0: w, 1: attitude; 2: the peers on the reduced problem, attitude;
     * 3: ours, attitude (the same staircase over our points) */
    sus_lab_bench_envelope env[4];
    sus_lab_bench_longrun *LR; /* nseries at most */
    int nlr;
    sus_lab_bench_equal_error *EQ; /* nseries at most */
    int neq;
    double R_long[3][3]; /* the reference R(T_LONG) */
    sus_lab_bench_growth growth;
    void (*progress)(const char *what); /* a phase's progress, for a person watching; may be NULL */
} sus_lab_bench;

/* The problem set up in b (everything else empty). Returns 0, or -1 with a message on stderr. */
int sus_lab_bench_init(sus_lab_bench *b, void (*progress)(const char *what));
void sus_lab_bench_progress(const sus_lab_bench *b, const char *what);
/* Frees what b holds (its series, tables and envelopes; the points' runs are released when they
 * are timed) and leaves b empty. */
void sus_lab_bench_free(sus_lab_bench *b);

/* The bench's tables are sized from the counts (methods, series, points); running out of memory
 * ends the bench, as does a peer that cannot allocate (the message says which). */
void *sus_lab_bench_calloc(size_t n, size_t size);
void sus_lab_bench_die(const char *what);

/* What a method is, for the bench: one predicate each, so no consumer compares names. */
int sus_lab_bench_own_attitude(const sus_step_method *me);
int sus_lab_bench_keeps_structure(const sus_step_method *me);
int sus_lab_bench_composed(const sus_step_method *me);

/* What a series' parameter is: "eps" (a step) or "tol" (peers, tolerance-driven methods). */
const char *sus_lab_bench_param_name(const sus_lab_bench_series *s);
/* A new empty series, appended to b's. */
sus_lab_bench_series *sus_lab_bench_new_series(sus_lab_bench *b);
/* The errors of a final state (w, R) against the reference; err_R = inf for a w-only series. */
void sus_lab_bench_errors(const sus_lab_bench *b, const sus_lab_bench_series *s, const double w[2],
                          const double R[3][3], double *ew, double *eR);
/* Runs ctx once and keeps it as the next point of s unless the run failed or diverged (an error
 * above 1 says nothing about speed at any accuracy the targets ask for). Returns 1 when kept;
 * otherwise the caller frees ctx. */
int sus_lab_bench_record(sus_lab_bench *b, sus_lab_bench_series *s, double param,
                         const sus_lab_bench_run_ops *ops, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
