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

typedef struct {
    int status;              /* SUSLOV_STEP_* of the first failed step, or SUSLOV_STEP_OK */
    long step;               /* index k+1 of the step that failed */
    double t;                /* its time t_{k+1} */
    suslov_step_stats stats; /* of the failed step */
    long newton_iterations;  /* total over the run */
    int max_iterations;      /* per step */
} suslov_run_report;

/* R_0 = I, w_0 = (w0, 0), lambda_0 = lambda(w_0) from (LagMult): (taualg) needs w^{-1}, so
 * row 0 carries the continuous multiplier for every method.
 * Returns 0, 1 when a step failed (see report), or -1 when emit asked to stop. */
int suslov_run(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit, void *ctx,
               suslov_run_report *report);

#endif
