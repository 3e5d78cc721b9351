/* What the convergence figures share (src/render/convergence_plot.c). */
#ifndef SUS_PLOT_CONVERGENCE_PLOT_H
#define SUS_PLOT_CONVERGENCE_PLOT_H

#include "convergence.h"
#include "registry.h"

#include <stddef.h>

typedef struct sus_plot_conv_figure_spec sus_plot_conv_figure_spec;

typedef struct {
    sus_lab_convergence c;
    const sus_plot_conv_figure_spec *spec;
    int j0;       /* first sweep point drawn: eps[j0] <= spec->eps_plot_max */
    double o0max; /* max |O_0| over the t_k: the variational multiplier's plateau */
} sus_plot_conv_fig;

/* Where a figure's legend goes; never inside a panel, so a panel's y-range is its data's. */
enum {
    SUS_PLOT_CONV_LEGEND_ABOVE, /* one legend for the whole figure, in a strip above its panels */
    SUS_PLOT_CONV_LEGEND_PANELS /* each panel's own (its fitted slopes differ), above the panel, and
                                 * the line styles in a strip above the panels */
};
struct sus_plot_conv_figure_spec {
    const char *name;                         /* figures/NAME.*, data/NAME.csv */
    int (*select)(const sus_step_method *me); /* the registered methods it draws */
    sus_recon solid, dashed;                  /* the SO(3) curves drawn solid and dashed */
    double eps_plot_max;                      /* right end of the eps axes */
    int legend;                               /* SUS_PLOT_CONV_LEGEND_* */
    int legend_slopes; /* 1: each legend entry gives the slope fitted over the paper's window */
    void (*caption)(char *buf, size_t len, const sus_plot_conv_fig *f);
};

/* The whole program: argument check, sweep, figure, data, caption. Returns the exit status. */
int sus_plot_conv_figure_main(int argc, char **argv, const sus_plot_conv_figure_spec *spec);

#endif
