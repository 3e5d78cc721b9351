/* The exact solution on the same grid and with the same row format as the integrators:
 * closed-form w(t_k) and lambda(w(t_k)), and the reference R(t_k) (refattitude.h). */
#ifndef SUS_EXACT_RUN_H
#define SUS_EXACT_RUN_H

#include "driver.h"
#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The number of reference Taylor steps (refattitude.h) the run sus_run_exact(cfg, w0) costs: the
 * steps to the tail or to T = steps eps, whichever is first, over the proved step, plus one partial
 * step for each row written before the tail (a row is one partial step from the grid point before
 * it). The steps to the tail scale as 1 / |w0|, as the step does, so that part does not depend on
 * |w0|; it grows without bound as the body's I31, I32 or w0's distance from an equilibrium go to
 * zero (the approach slows while the rotation does not). A caller checks it before the run; -1
 * for the arguments sus_run_exact refuses. */
double sus_exact_reference_steps(const sus_run_config *cfg, const double w0[2]);

/* The reference attitude's steady turn (refattitude.h) keeps the stated accuracy, 2^-51 in every
 * entry, while its angle is below 2^60 radians: its 113-bit rounding reaches 2^-53 there.
 * sus_run_exact refuses a run whose angle bound (sus_exact_turn_angle) is beyond. */
#define SUS_EXACT_MAX_ANGLE 0x1p60

/* T |w_inf|, w_inf the steady rotation the motion from w0 tends to (sus_exact_limit): a bound on
 * the angle the attitude's steady tail turns by up to time T, which a method must form to within
 * its accuracy. -1 for a model sus_model_init did not make, a non-finite w0, or T not finite and
 * >= 0. */
double sus_exact_turn_angle(const sus_model *m, const double w0[2], double T);

/* Rows at t_k = k eps for k = 0, K, 2K, ..., N. R(t) comes from the reference integration
 * (refattitude.h) up to the time t_s after which w(t) is the steady rotation w* to within a
 * total rotation angle of 2^-64, and from the closed form R(t_s) exp((t - t_s) w*^) beyond
 * (exact_run.c): the cost is O(1) in T for large T. Returns a sus_run_status (driver.h): _OK,
 * _STOPPED or _BLOWUP (report->step, t), or _BAD_ARGUMENT, also for a run whose angle
 * sus_exact_turn_angle(model, w0, N eps) exceeds SUS_EXACT_MAX_ANGLE. */
int sus_run_exact(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit, void *ctx,
                  sus_run_report *report);

#ifdef __cplusplus
}
#endif

#endif
