#include "fig_setup.h"
#include "dsp.h"

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

int sus_plot_fig_run_pair(const char *name, const sus_model *m, double eps, long N, int every,
                          sus_lab_series *mid, sus_lab_series *var)
{
    if (sus_lab_series_init(mid, N, every) || sus_lab_series_init(var, N, every)) {
        fprintf(stderr, "figure_%s: out of memory\n", name);
        return 1;
    }
    sus_run_report rep;
    const sus_run_config cm = {m, sus_step_midpoint, SUS_RECON_CAYLEY, eps, N, every};
    const sus_run_config cv = {m, sus_step_variational, SUS_RECON_CAYLEY, eps, N, every};
    if (sus_lab_series_run(mid, &cm, SUS_PAPER_OMEGA0, &rep) ||
        sus_lab_series_run(var, &cv, SUS_PAPER_OMEGA0, &rep)) {
        fprintf(stderr, "figure_%s: a step failed at step %ld (t = %g)\n", name, rep.step, rep.t);
        return 3;
    }
    return 0;
}
