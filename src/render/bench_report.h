/* make bench's report on stdout: the per-step costs, then the targets as PASS/MISS lines (never a
 * failing test: the machine is shared and noisy) and the CHECK lines of the bench's own checks. */
#ifndef SUS_PLOT_BENCH_REPORT_H
#define SUS_PLOT_BENCH_REPORT_H

#include "bench.h"
#include "bench_longrun.h"
#include "bench_reproduce.h"

/* What was run and how it was timed; differ: the points whose timed runs ended with another
 * error than recorded; with_odeint: whether the Boost.Odeint peers are in. */
void sus_plot_bench_header(const sus_lab_bench *b, int differ, int with_odeint);
/* The per-step cost table, then "Targets:" and the per-step and per-level targets. */
void sus_plot_bench_costs_and_targets(const sus_lab_bench *b);
/* The long runs' structure errors. */
void sus_plot_bench_long_runs(const sus_lab_bench *b);
/* The runs to T = 1e4 at equal error (b->EQ) and the target line of the best of them; the cost
 * of that run to T = 1e6 against T = 1e4 (b->growth). */
void sus_plot_bench_equal_error(const sus_lab_bench *b);
void sus_plot_bench_growth(const sus_lab_bench *b);
/* The rows suslov did not reproduce, and the CHECK line; suslov is the program's path. */
void sus_plot_bench_reproduced(const sus_lab_bench *b, const sus_lab_bench_reproduced *r,
                               const char *suslov);

#endif
