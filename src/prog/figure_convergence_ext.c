/* Convergence of our extensions (the registered methods that test no statement of the paper),
 * over steps up to 8 so that a method of high order shows its slope before round-off; the
 * paper's midpoint DSP is drawn as the baseline they are built from. SO(3) errors with exp-mid
 * (solid) and cayley-mid (dashed).
 * Usage: figure_convergence_ext FIGDIR DATADIR */
#include "convergence_plot.h"

#include <stdio.h>

/* The extensions, and the paper's methods that conserve E (the midpoint DSP) as the baseline. */
static int extension_or_baseline(const sus_step_method *me)
{
    return me->paper_ref == NULL || me->type->desc.conserves_energy;
}

static void caption(char *buf, size_t len, const sus_plot_conv_fig *f)
{
    (void)f;
    snprintf(buf, len,
             "Convergence of the methods we add to the paper's (compositions "
             "of the midpoint DSP, Taylor series), with\n"
             "the midpoint DSP as the baseline. Regenerate: make "
             "figures (src/prog/figure_convergence_ext.c).\n"
             "eps = 2^-j, j = -3..10 (steps up to 8); global errors "
             "at t = 10 with N = round(10/eps) steps of 10/N.\n"
             "SO(3): solid, exp-mid (the Taylor methods advance "
             "their own quaternion whatever is asked); dashed,\n"
             "cayley-mid.\n"
             "The legend (above the panels) gives no slopes: over the paper's "
             "window eps <= 2^-2 these methods are at round-off. Their\n"
             "orders are fitted in the claims ledger (tests/ledger/claims_highorder.c, "
             "at t = 50 over each method's own step\n"
             "range). No reference slope triangles: the steep curves leave no room for them.\n"
             "Data: data/convergence_ext.csv. Fitted orders: build/claims.tsv (make check).\n");
}

int main(int argc, char **argv)
{
    /* No reference slopes (the curves fill the panels' lower right, and their upper left at small
     * eps, where any legend would hide them: it goes above the panels) and no legend slopes (over
     * the paper's window these methods are at round-off, and a slope fitted to round-off means
     * nothing). */
    const sus_plot_conv_figure_spec spec = {.name = "convergence_ext",
                                            .select = extension_or_baseline,
                                            .solid = SUS_RECON_EXP_MID,
                                            .dashed = SUS_RECON_CAYLEY_MID,
                                            .eps_plot_max = 8.0,
                                            .legend = SUS_PLOT_CONV_LEGEND_ABOVE,
                                            .legend_slopes = 0,
                                            .caption = caption};
    return sus_plot_conv_figure_main(argc, argv, &spec);
}
