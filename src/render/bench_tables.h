/* make bench's data files, each written all-or-nothing: bench.csv (every timed point, the
 * per-step costs and the long runs' structure errors, with the suslov arguments that reproduce
 * each row of ours; the figures are drawn from it, bench_load.h), bench.tex (the numbers the
 * companion quotes), what_to_use.tsv (at each level the fastest of ours and of the peers, on the
 * full and on the reduced problem, and for w alone) and longruns.tsv (the runs to T = 1e4 at
 * equal error and to T = 1e6). tools/bench_summary.sh makes the docs' summary of them. */
#ifndef SUS_PLOT_BENCH_TABLES_H
#define SUS_PLOT_BENCH_TABLES_H

#include "bench.h"

/* DATADIR/bench.csv, bench.tex, what_to_use.tsv and longruns.tsv. Returns 0, or -1 with a
 * message on stderr. */
int sus_plot_bench_tables(const sus_lab_bench *b, const char *datadir);

#endif
