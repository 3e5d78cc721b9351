/* The driver of Algorithm (algo): it advances (R_k, w_k) -> (R_{k+1}, w_{k+1}, lambda_{k+1})
 * with any stepper and either reconstruction, and hands every K-th row to a callback. It
 * stores nothing per step, so memory does not grow with the number of steps. */
#ifndef SUS_DRIVER_H
#define SUS_DRIVER_H

#include "model.h"
#include "reconstruct.h"
#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const sus_model *model;
    const sus_stepper_type *stepper;
    sus_recon recon;
    double eps; /* the time step */
    long steps; /* N */
    long every; /* K: rows for k = 0, K, 2K, ... and always k = N */
} sus_run_config;

/* The run of a tolerance-driven stepper (stepper->tol set): tol in (0, 1), the run ends at
 * t_end, and rows come at t = 0, every_time, 2 every_time, ... and t_end (every_time > 0, by the
 * method's dense output; a time within 4u t_end of t_end is t_end), or at the end of every accepted
 * step (every_time = 0). A row's k is the index of the accepted step that reaches its t: the row at
 * t_{k-1} < t <= t_k, t_k the end of the k-th accepted step, has k (row 0 has 0), so rows
 * every_time apart that fall in one step share its k, and before t_k only k - 1 steps are
 * accepted. The number of steps is known only as they are taken (it grows with |w0| t_end), so
 * a run may be given a budget: after max_steps accepted steps short of t_end it stops with
 * SUS_RUN_STEP_FAILED and SUS_STEPPER_STEP_LIMIT, the rows up to there written (max_steps = 0:
 * no limit). */
typedef struct {
    const sus_model *model;
    const sus_stepper_type *stepper;
    double tol, t_end, every_time;
    long max_steps;
} sus_tol_config;

typedef struct {
    long k;
    double t;
    double w[3];
    double lambda;
    double R[3][3];
} sus_row;

/* Returns 0 to go on, non-zero to stop the run (e.g. a write error). */
typedef int (*sus_emit_fn)(void *ctx, const sus_row *row);

/* What every run function (sus_run, sus_run_tol, sus_run_exact, sus_lab_series_run) returns:
 * one convention, with "emit asked to stop" distinct from every failure. */
typedef enum {
    SUS_RUN_STOPPED = -1, /* emit returned non-zero (e.g. a write error) */
    SUS_RUN_OK = 0,
    SUS_RUN_STEP_FAILED = 1, /* a step's solver failed: report->status, ->stats */
    SUS_RUN_BLOWUP = 2,      /* w, lambda or R became non-finite at report->step */
    SUS_RUN_BAD_ARGUMENT = 3 /* refused before row 0: report->message says which argument */
} sus_run_status;

typedef struct {
    int status;              /* SUS_STEPPER_* of the first failed step, or SUS_STEPPER_OK */
    long step;               /* index k+1 of the step that failed (the row k for the exact run) */
    double t;                /* its time t_{k+1} */
    sus_stepper_stats stats; /* of the failed step */
    long sus_newton_iterations; /* total over the run */
    int max_iterations;         /* per step */
    /* SUS_RUN_BAD_ARGUMENT: which argument is wrong and why, one line (a static string); NULL
     * for every other outcome. */
    const char *message;
} sus_run_report;

/* A sus_emit_fn that copies each row over the sus_row ctx points to: the run's last row.
 * Returns 0, or -1 (stop the run) when ctx or row is NULL. */
int sus_keep_last(void *ctx, const sus_row *row);
/* No silent non-finite output: 1 when t, w, lambda and R of a row are all finite numbers
 * (0 for a NULL row). */
int sus_row_finite(const sus_row *r);

/* The arguments every run function checks before row 0, refusing with SUS_RUN_BAD_ARGUMENT and
 * report->message (nothing emitted; with a NULL report it writes nothing): cfg, w0, emit and
 * report are not NULL; cfg->model is a model sus_model_init filled and nothing changed since
 * (a NULL, uninitialised or altered one is refused); w0 is finite, and so are the energy and
 * lambda there (sus_model_start_overflow: row 0 must be finite), and lambda along the motion
 * from w0 (sus_exact_lambda_max: every row prints it). sus_run and sus_run_exact
 * also want eps finite and > 0, steps >= 0, every >= 1 and steps * eps finite; sus_run a
 * fixed-step stepper (stepper->tol NULL) with apply or apply_full, and a recon among
 * sus_recon's values. sus_run_exact ignores cfg->stepper and cfg->recon. */

/* R_0 = I, w_0 = (w0, 0), lambda_0 = lambda(w_0) from (LagMult): (taualg) needs w^{-1}, so
 * row 0 carries the continuous multiplier for every method.
 * Returns a sus_run_status: SUS_RUN_OK, _STEP_FAILED or _BLOWUP (see report), _STOPPED, or
 * _BAD_ARGUMENT (above). A row that is not finite is never emitted: the run stops with _BLOWUP. */
int sus_run(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
            sus_run_report *report);
/* The same for a tolerance-driven stepper (sus_run refuses one with SUS_RUN_BAD_ARGUMENT, as it
 * has no tolerance): report->step is the step that failed, report->t the time it started from.
 * It refuses with SUS_RUN_BAD_ARGUMENT (above) a stepper without tol (a fixed-step method) or
 * without its alloc, step and free (and dense, for every_time > 0); a tol not in (0, 1) (a tol
 * below the rounding of the state fails at its first step instead); a t_end or every_time that is
 * not finite and >= 0; more rows every_time apart than it can count (t_end / every_time >= 2^62);
 * max_steps < 0; and a t_end by which the steady rotation turns the body past the method's
 * max_angle (stepper.h; checked once its workspace is allocated, which may build the closed form
 * that answers it). */
int sus_run_tol(const sus_tol_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
                sus_run_report *report);

#ifdef __cplusplus
}
#endif

#endif
