/* The exact solution on the same grid and with the same row format as the integrators:
 * closed-form w(t_k) and lambda(w(t_k)), and the reference R(t_k) (refattitude.h). */
#ifndef SUS_EXACT_RUN_H
#define SUS_EXACT_RUN_H

#include "driver.h"
#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Rows at t_k = k eps for k = 0, K, 2K, ..., N. R(t) comes from the reference integration
 * (refattitude.h) up to the time t_s after which w(t) is the steady rotation w* to within a
 * total rotation angle of u = 2^-53, and from the closed form R(t_s) exp((t - t_s) w*^) beyond
 * (exact_run.c): the cost is O(1) in T for large T. Returns a sus_run_status (driver.h): _OK,
 * _STOPPED or _BLOWUP (report->step, t). */
/* The number of reference Taylor steps (refattitude.h) a run to time T costs, whatever the
 * number of rows: the time to the tail over the proved step. Both scale as 1 / |w0|, so the count
 * does not depend on |w0|; it grows without bound as the body's I31, I32 or w0's distance from an
 * equilibrium go to zero (the approach slows while the rotation does not); a caller checks it
 * before the run. */
double sus_exact_reference_steps(const sus_model *m, const double w0[2], double T);

int sus_run_exact(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
                  sus_run_report *report);

#ifdef __cplusplus
}
#endif

#endif
