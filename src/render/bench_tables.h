/* make bench's data files, each written all-or-nothing: bench.csv (every timed point, the
 * per-step costs and the long runs, with the suslov arguments that reproduce each row of ours),
 * bench.tex (the numbers the companion text quotes) and what_to_use.tsv (at each level the fastest
 * of ours and of the peers; README, the companion). */
#ifndef SUS_PLOT_BENCH_TABLES_H
#define SUS_PLOT_BENCH_TABLES_H

#include "bench.h"

/* DATADIR/bench.csv, DATADIR/bench.tex and DATADIR/what_to_use.tsv. Returns 0, or -1 with a
 * message on stderr. */
int sus_plot_bench_tables(const sus_exp_bench *b, const char *datadir);

#endif
