/* make bench's long runs to T = 1e4: the structure errors of our preserving methods and of the
 * rk8pd peer at matched accuracy, and our explicit own-attitude methods against rk8pd (w, q) at
 * equal attitude error there. */
#ifndef SUS_EXP_BENCH_LONGRUN_H
#define SUS_EXP_BENCH_LONGRUN_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

/* b->LR: our preserving methods at the step that reached attitude 1e-10 at t = 50 (matched
 * accuracy), the peer (rk8pd through the driver from hstart 1e-3, on both attitude formulations)
 * at the tolerance that did, sampled 1000 times over [0, T_LONG]. */
void sus_exp_bench_long_runs(sus_exp_bench *b);

/* One of ours at T = 1e4 against the loosest rk8pd (w, q) tolerance (four a decade) that reaches
 * the same attitude error there (peer_sec = INFINITY when none down to 1e-15 does). */
typedef struct {
    int series, point;
    double sec, err;
    double peer_sec, peer_err, peer_tol;
} sus_exp_bench_equal_error;

/* Each explicit own-attitude method of ours at the step (or TOL) that reached attitude 1e-10 at
 * t = 50, run to T_LONG, into out (b->nseries at most); returns how many. */
int sus_exp_bench_equal_error_runs(const sus_exp_bench *b, sus_exp_bench_equal_error *out);

#ifdef __cplusplus
}
#endif

#endif
