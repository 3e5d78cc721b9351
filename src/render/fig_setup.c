#include "fig_setup.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>

int sus_plot_fig_setup_paper(int argc, const char *name, sus_model *m, sus_exact *ex)
{
    if (argc != 3) {
        fprintf(stderr, "usage: figure_%s FIGDIR DATADIR\n", name);
        return 2;
    }
    gsl_set_error_handler_off();
    char err[256];
    if (sus_model_init(m, SUS_PAPER_INERTIA, err, sizeof err) != 0) {
        fprintf(stderr, "figure_%s: the paper's inertia is rejected: %s\n", name, err);
        return 1;
    }
    sus_exact_init(ex, m, SUS_PAPER_OMEGA0);
    return 0;
}
