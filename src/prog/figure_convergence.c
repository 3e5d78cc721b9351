/* Convergence of the paper's four DSPs (the registered methods that test a statement of the
 * paper): local and global errors in w, on SO(3) with Algorithm (algo) and with cayley-mid, and
 * in lambda (the variational plateau at |O_0|). Usage: figure_convergence FIGDIR DATADIR */
#include "convergence_plot.h"

#include <stdio.h>

static int paper_method(const sus_step_method *me) { return me->paper_ref != NULL; }

static void caption(char *buf, size_t len, const sus_plot_conv_fig *f)
{
    snprintf(buf, len,
             "Convergence of the paper's four DSPs (the order claims "
             "of (nolabel:proposition-5.2), (PropoFinal) and\n"
             "(TeoL)). Regenerate: make figures (src/prog/figure_convergence.c, "
             "src/render/convergence_plot.c).\n"
             "eps = 2^-j, j = 0..10; inertia as printed, w(0) = (0.4, "
             "0.5). Local errors: one step from the exact\n"
             "solution at t_k, largest over t_k in {0, 3, 7, 12, 20}; "
             "global errors at t = 10 from t = 0. Reference:\n"
             "closed-form w, lambda; R from the reference attitude "
             "along the exact w. Each panel's legend is above it.\n"
             "Legend slopes are least-squares fits over eps in [2^-10, "
             "2^-2]: a local error has slope p+1, a global\n"
             "error slope p, so the legends of (a), (c), (e) read one more than the order.\n"
             "(a), (b) w: p = 1, 2, 4, 2 (euler, midpoint, rk4, variational).\n"
             "(c), (d) the distance of (MetMat) on SO(3): solid "
             "R_{k+1} = R_k cay(eps w_k) ((algo)): order 1 for\n"
             "every method ((TeoL)), the four curves coincide "
             "locally; dashed: cayley-mid, order min(2, p).\n"
             "(e), (f) lambda: s = p with lambda(w^{k+1}); the variational "
             "(taualg) does not converge: its local error\n"
             "tends to |O_0| (up to %.4f over these t_k), as (PropoFinal) states.\n"
             "Data: data/convergence.csv. Fitted slopes with "
             "their windows: build/claims.tsv (make check).\n",
             f->o0max);
}

int main(int argc, char **argv)
{
    /* Each panel's legend above it, where it hides no curve, with each curve's fitted slope: no
     * reference slope triangles, which would need room the data do not leave in a panel whose
     * y-range is the data's. */
    const sus_plot_conv_figure_spec spec = {.name = "convergence",
                                            .select = paper_method,
                                            .solid = SUS_RECON_CAYLEY,
                                            .dashed = SUS_RECON_CAYLEY_MID,
                                            .eps_plot_max = 1.0,
                                            .legend = SUS_PLOT_CONV_LEGEND_PANELS,
                                            .legend_slopes = 1,
                                            .caption = caption};
    return sus_plot_conv_figure_main(argc, argv, &spec);
}
