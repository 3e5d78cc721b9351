/* Every "ours" row of the bench's data names the suslov command that reproduces it; make bench
 * re-runs the fastest preserving row at each attitude and each w level with that command and
 * compares its errors (the w error only for a w-only row), and the rows of the long runs (the
 * fastest at T = 1e4 and equal error, and the same run to T = 1e6), comparing where they end. */
#ifndef SUS_LAB_BENCH_REPRODUCE_H
#define SUS_LAB_BENCH_REPRODUCE_H

#include "bench.h"
#include "bench_floor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The suslov arguments of point j of series s of ours, into buf: the run to t = 50, or to T (a
 * fixed-step run then takes N = T / eps steps of T / N, as the bench's long runs do). */
void sus_lab_bench_suslov_args(const sus_lab_bench_series *s, int j, char *buf, size_t len);
void sus_lab_bench_suslov_args_to(const sus_lab_bench_series *s, int j, double T, char *buf,
                                  size_t len);

/* A row not reproduced: its series and point, and the run's end time. */
typedef struct {
    int series, point;
    double T;
} sus_lab_bench_unreproduced;

typedef struct {
    int tried, ok;
    int nfailed;
    sus_lab_bench_unreproduced failed[2 * SUS_LAB_BENCH_NLEVELS + 2];
} sus_lab_bench_reproduced;

/* Re-runs the rows with the program suslov (a path) and compares: the same code path, so they
 * must agree to the digits the CSV carries (%.17g: exactly). */
void sus_lab_bench_check_reproduce(const sus_lab_bench *b, const char *suslov,
                                   sus_lab_bench_reproduced *out);

#ifdef __cplusplus
}
#endif

#endif
