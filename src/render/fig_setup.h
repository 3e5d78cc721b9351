/* What every figure program of the paper's body does first: check its arguments (FIGDIR
 * DATADIR), turn GSL's aborting error handler off, and set up the paper's inertia and w(0). */
#ifndef SUS_PLOT_FIG_SETUP_H
#define SUS_PLOT_FIG_SETUP_H

#include "exact.h"
#include "model.h"
#include "series.h"

/* Returns 0, or the exit status after a one-line message on stderr: 2 for a wrong argument
 * count, 1 when the paper's inertia is rejected. */
int sus_plot_fig_setup_paper(int argc, const char *name, sus_model *m, sus_exact *ex);

/* Figures 1 and 2's pair from the paper's w(0): the midpoint DSP into mid and the variational
 * integrator into var, N steps of eps with the Cayley reconstruction, a row every `every` steps.
 * Returns 0, or the exit status after a one-line message: 1 out of memory, 3 a failed step. */
int sus_plot_fig_run_pair(const char *name, const sus_model *m, double eps, long N, int every,
                          sus_lab_series *mid, sus_lab_series *var);

#endif
