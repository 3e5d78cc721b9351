/* What the convergence figures share (src/render/convergence_plot.c). */
#ifndef SUS_PLOT_CONVERGENCE_PLOT_H
#define SUS_PLOT_CONVERGENCE_PLOT_H

#include "convergence.h"
#include "registry.h"

#include <stddef.h>

typedef struct sus_plot_conv_figure_spec sus_plot_conv_figure_spec;

typedef struct {
    sus_exp_convergence c;
    const sus_plot_conv_figure_spec *spec;
    int j0;         /* first sweep point drawn: eps[j0] <= spec->eps_plot_max */
    double o0max;   /* max |O_0| over the t_k: the variational multiplier's plateau */
} sus_plot_conv_fig;

#define SUS_PLOT_CONV_LEGEND_ABOVE (-1)
struct sus_plot_conv_figure_spec {
    const char *name;                          /* figures/NAME.*, data/NAME.csv */
    int (*select)(const sus_step_method *me);    /* the registered methods it draws */
    sus_recon solid, dashed;                /* the SO(3) curves drawn solid and dashed */
    double eps_plot_max;                       /* right end of the eps axes */
    const int *slopes_local, *slopes_global;   /* reference slope triangles for w and lambda */
    int nslopes;
    const int *slopes_so3_local, *slopes_so3_global;
    int nslopes_so3;
    int slope_j;          /* the reference slopes run from eps[slope_j + 3] to eps[slope_j] ... */
    double slope_drop;    /* ... ending this factor under the panel's top */
    int legend_corner;    /* sus_plot_legend's corner; SUS_PLOT_CONV_LEGEND_ABOVE: one legend for the
                           * whole figure, in a strip above its panels, where it hides no curve */
    int legend_slopes;    /* 1: each legend entry gives the slope fitted over the paper's window */
    void (*caption)(char *buf, size_t len, const sus_plot_conv_fig *f);
};

/* The whole program: argument check, sweep, figure, data, caption. Returns the exit status. */
int sus_plot_conv_figure_main(int argc, char **argv, const sus_plot_conv_figure_spec *spec);

#endif
