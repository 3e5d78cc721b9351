/* The driver of Algorithm (algo): it advances (R_k, w_k) -> (R_{k+1}, w_{k+1}, lambda_{k+1})
 * with any stepper and either reconstruction, and hands every K-th row to a callback. It
 * stores nothing per step, so memory does not grow with the number of steps. */
#ifndef SUSLOV_DRIVER_H
#define SUSLOV_DRIVER_H

#include "model.h"
#include "reconstruct.h"
#include "stepper.h"

typedef struct {
    const suslov_model *model;
    const suslov_stepper_type *stepper;
    suslov_recon recon;
    double eps;   /* the time step */
    long steps;   /* N */
    long every;   /* K: rows for k = 0, K, 2K, ... and always k = N */
} suslov_run_config;

typedef struct {
    long k;
    double t;
    double w[3];
    double lambda;
    double R[3][3];
} suslov_row;

/* Returns 0 to go on, non-zero to stop the run (e.g. a write error). */
typedef int (*suslov_emit_fn)(void *ctx, const suslov_row *row);

/* What every run function (suslov_run, suslov_run_exact, suslov_series_run) returns: one
 * convention, with "emit asked to stop" distinct from every failure. */
typedef enum {
    SUSLOV_RUN_STOPPED = -1,          /* emit returned non-zero (e.g. a write error) */
    SUSLOV_RUN_OK = 0,
    SUSLOV_RUN_STEP_FAILED = 1,       /* a step's solver failed: report->status, ->stats */
    SUSLOV_RUN_BLOWUP = 2             /* w, lambda or R became non-finite at report->step */
} suslov_run_status;

typedef struct {
    int status;              /* SUSLOV_STEP_* of the first failed step, or SUSLOV_STEP_OK */
    long step;               /* index k+1 of the step that failed (the row k for the exact run) */
    double t;                /* its time t_{k+1} */
    suslov_step_stats stats; /* of the failed step */
    long newton_iterations;  /* total over the run */
    int max_iterations;      /* per step */
} suslov_run_report;

/* A suslov_emit_fn that copies each row over the suslov_row ctx points to: the run's last row. */
int suslov_keep_last(void *ctx, const suslov_row *row);
/* No silent non-finite output: 1 when t, w, lambda and R of a row are all finite numbers. */
int suslov_row_finite(const suslov_row *r);

/* R_0 = I, w_0 = (w0, 0), lambda_0 = lambda(w_0) from (LagMult): (taualg) needs w^{-1}, so
 * row 0 carries the continuous multiplier for every method.
 * Returns a suslov_run_status: SUSLOV_RUN_OK, _STEP_FAILED or _BLOWUP (see report), or
 * _STOPPED. A row that is not finite is never emitted: the run stops with _BLOWUP. */
int suslov_run(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit, void *ctx,
               suslov_run_report *report);

#endif
