/* What every figure program of the paper's body does first: check its arguments (FIGDIR
 * DATADIR), turn GSL's aborting error handler off, and set up the paper's inertia and w(0). */
#ifndef SUS_PLOT_FIG_SETUP_H
#define SUS_PLOT_FIG_SETUP_H

#include "exact.h"
#include "model.h"

/* Returns 0, or the exit status after a one-line message on stderr: 2 for a wrong argument
 * count, 1 when the paper's inertia is rejected. */
int sus_plot_fig_setup_paper(int argc, const char *name, sus_model *m, sus_exact *ex);

#endif
