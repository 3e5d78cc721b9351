/* make bench's clocks: the work-precision points timed in interleaved rounds, and the cost of one
 * step of every registered method (and of GSL's rk4 and of the closed form), all in b. */
#ifndef SUS_LAB_BENCH_TIMING_H
#define SUS_LAB_BENCH_TIMING_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Times every point (median, min and max over the rounds into its series) and frees the points'
 * runs. The errors the timed runs ended with are compared with the ones recorded: the same runs,
 * so equal bit for bit. A point whose timed error differs is counted (and said on stderr) and
 * keeps the larger error, so no configuration is credited with an accuracy its timed runs did not
 * reach. Returns the number of such points. */
int sus_lab_bench_time_points(sus_lab_bench *b);

/* b->cost: the per-step costs of every fixed-step method, GSL's rk4 and the closed form. */
void sus_lab_bench_measure_step_costs(sus_lab_bench *b);

/* The per-step cost of the tolerance-driven series: the median of the bare loop's rounds at each
 * point into the series (step_ns, the floor), the sums of the fastest rounds through the driver
 * and in a bare loop into b->cost (the driver's overhead). */
void sus_lab_bench_measure_tol_costs(sus_lab_bench *b);

#ifdef __cplusplus
}
#endif

#endif
