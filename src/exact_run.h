/* The exact solution on the same grid and with the same row format as the integrators:
 * closed-form w(t_k) and lambda(w(t_k)), and the rk8pd reference R(t_k). */
#ifndef SUSLOV_EXACT_RUN_H
#define SUSLOV_EXACT_RUN_H

#include "driver.h"
#include "exact.h"

/* Rows at t_k = k eps for k = 0, K, 2K, ..., N. Returns 0, -1 when emit asked to stop, or a
 * positive GSL status when the reference attitude failed (report->step/t say where). */
int suslov_run_exact(const suslov_run_config *cfg, const double w0[2], suslov_emit_fn emit,
                     void *ctx, suslov_run_report *report);

#endif
