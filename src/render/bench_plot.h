/* make bench's figures: work_precision (seconds per run against the w and the attitude error at
 * t = 50, our methods in colour over the peers in grey, the peers' lower envelopes in black, solid
 * on the full problem and dashed on the reduced one, the target levels dotted), work_precision_best
 * (the attitude again, with only the series of ours that make our lower envelope), and step_cost
 * (the cost of one step of every method, GSL's rk4 and the closed form). Drawn from what
 * sus_lab_bench_load reads back of a run (bench_load.h). */
#ifndef SUS_PLOT_BENCH_PLOT_H
#define SUS_PLOT_BENCH_PLOT_H

#include "bench.h"

/* FIGDIR/work_precision.{pdf,png}, FIGDIR/work_precision_best.{pdf,png} and
 * FIGDIR/step_cost.{pdf,png}. Returns 0, or -1 with a
 * message on stderr. */
int sus_plot_bench_figures(const sus_lab_bench *b, const char *figdir);

#endif
