/* make bench's sweeps: each method of ours over its grid of steps N (or, tolerance-driven, over
 * the peers' tolerances), and each peer configuration over its tolerances, every point that
 * runs and stays below error 1 kept for timing (sus_lab_bench_record).
 *
 * The grids: a user of a fixed-step method picks N, a user of an adaptive peer picks tol. The
 * Taylor methods are swept at every N up to a fine limit (their cost per step is large and their
 * error falls like N^-p, so a factor sqrt 2 in N would skip up to two decades of error), and the
 * peers at four tolerances a decade, 10^(-3 - j/4): both grids are finer than one point per
 * decade of error, and the peers' is never coarser than before (each decade point is still in
 * it). */
#ifndef SUS_LAB_BENCH_SWEEP_H
#define SUS_LAB_BENCH_SWEEP_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Peers defined outside the library (make bench's Boost.Odeint ones), swept on formulation dim
 * (11, 6, 2, or 4: the reduced problem) after the GSL ones of that formulation. */
typedef void (*sus_lab_bench_more_peers)(sus_lab_bench *b, size_t dim, void *ctx);

/* Every registered method, then the GSL peers: rk8pd and rkck in every configuration a user might
 * pick (driver or evolve loop, initial step 1e-3, 1e-2, 0.1, 1), rkf45 and msadams through the
 * driver from 1e-3; on (w, R), (w, q) and w alone, each followed by more(b, dim, ctx) when set.
 * Then the reduced problem: rk8pd and rkck, driver or evolve, abs = rel or abs alone, initial
 * step 1e-2 or 1, followed by more(b, 4, ctx). */
void sus_lab_bench_sweep_all(sus_lab_bench *b, sus_lab_bench_more_peers more, void *ctx);

/* "(w,R)", "(w,q)", "(w)" or "reduced (q)": the formulation of dim 11, 6, 2 or 4, for a peer's
 * name. */
const char *sus_lab_bench_dim_name(size_t dim);

#ifdef __cplusplus
}
#endif

#endif
