/* A bench run read back from its bench.csv (src/render/bench_tables.c writes it): the series'
 * timed points and the per-step costs, enough to draw the bench's figures again. make bench draws
 * its figures from the file it has just written, and make figures draws the committed previews
 * from the recorded run's file, so a figure is always the drawing of a data file. */
#ifndef SUS_LAB_BENCH_LOAD_H
#define SUS_LAB_BENCH_LOAD_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

/* b (zeroed first) from DIR/bench.csv: its work rows as series (name, ours or peer, w alone or
 * reduced, parameter, steps, errors, seconds), its step rows as b->cost (names, w-step and whole
 * step, GSL's rk4, the closed form), and the peers' envelopes. Returns 0, or -1 with a message
 * on stderr (the file missing, or a row that is not the bench's) and b left empty. */
int sus_lab_bench_load(sus_lab_bench *b, const char *dir);

#ifdef __cplusplus
}
#endif

#endif
