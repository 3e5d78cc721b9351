/* Every "ours" row of data/bench.csv names the suslov command that reproduces it; make bench
 * re-runs the fastest preserving row at each attitude and each w level with that command and
 * compares its errors (the w error only for a w-only row). */
#ifndef SUS_EXP_BENCH_REPRODUCE_H
#define SUS_EXP_BENCH_REPRODUCE_H

#include "bench.h"
#include "bench_floor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The suslov arguments of point j of series s of ours, into buf. */
void sus_exp_bench_suslov_args(const sus_exp_bench_series *s, int j, char *buf, size_t len);

typedef struct {
    int tried, ok;
    int nfailed;
    sus_exp_bench_best failed[2 * SUS_EXP_BENCH_NLEVELS]; /* the rows not reproduced */
} sus_exp_bench_reproduced;

/* Re-runs the rows with the program suslov (a path) and compares: the same code path, so they
 * must agree to the digits the CSV carries (%.17g: exactly). */
void sus_exp_bench_check_reproduce(const sus_exp_bench *b, const char *suslov,
                                   sus_exp_bench_reproduced *out);

#ifdef __cplusplus
}
#endif

#endif
