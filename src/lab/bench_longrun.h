/* make bench's long runs to T = 1e4: the structure errors of our preserving methods and of the
 * rk8pd peer at matched accuracy, our explicit own-attitude methods against rk8pd (w, q) at
 * equal attitude error there, and the cost of the fastest of them from T = 1e4 to T = 1e6. */
#ifndef SUS_LAB_BENCH_LONGRUN_H
#define SUS_LAB_BENCH_LONGRUN_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

/* b->LR: our preserving methods at the step that reached attitude 1e-10 at t = 50 (matched
 * accuracy), the peer (rk8pd through the driver from hstart 1e-3, on both attitude formulations)
 * at the tolerance that did, sampled 1000 times over [0, T_LONG]. */
void sus_lab_bench_long_runs(sus_lab_bench *b);

/* b->EQ: each explicit own-attitude method of ours at its first step (or TOL) whose run to
 * T_LONG ends within LONG_LEVEL of the reference (b->R_long), against rk8pd (w, q) and, for
 * information, rk8pd on the reduced problem, each at its loosest tolerance that does too. Then
 * b->growth: the row fastest against its peer, run again to T_GROWTH. */
void sus_lab_bench_equal_error_runs(sus_lab_bench *b);

/* The row of b->EQ that is fastest against its peer (the target's), or -1. */
int sus_lab_bench_best_equal_error(const sus_lab_bench *b);

/* The seconds of a growth run over those of the same run to T_LONG (NAN when none ran). */
double sus_lab_bench_growth_ratio(const sus_lab_bench *b);

#ifdef __cplusplus
}
#endif

#endif
