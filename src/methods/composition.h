/* Symmetric composition of a symmetric one-step map (Hairer, Lubich & Wanner, Geometric
 * Numerical Integration, 2nd ed., Section V.3): Psi_h = Phi_{g_s h} o ... o Phi_{g_1 h}, with
 * palindromic weights g_i = g_{s+1-i} and sum g_i = 1. Here Phi is the paper's midpoint DSP
 * (Discretization) with a symmetric reconstruction (cayley-mid or exp-mid), a symmetric
 * second-order map of (w, R); the weights raise it to order 4, 6, 8 or 10. Every substep is a
 * midpoint step, so E = 1/2 <I_m w, w> (a quadratic invariant of the midpoint rule), w3 = 0 and
 * R in SO(3) hold exactly, as for the midpoint DSP itself. */
#ifndef SUSLOV_COMPOSITION_H
#define SUSLOV_COMPOSITION_H

#include "stepper.h"

typedef struct {
    const char *name;    /* e.g. "Kahan-Li s=9" */
    const char *source;  /* where the weights were taken from */
    int order;           /* the order the source states (the ledger measures it) */
    int half;            /* m: the weights g_1..g_m, the middle one last; s = 2m - 1 stages */
    const double *g;
} suslov_composition;

static inline int suslov_composition_stages(const suslov_composition *c) { return 2 * c->half - 1; }
/* g_i for i = 0..s-1 from the half-sequence. */
static inline double suslov_composition_weight(const suslov_composition *c, int i)
{
    const int s = suslov_composition_stages(c);
    return c->g[i < c->half ? i : s - 1 - i];
}

/* The w-step of the composition (no attitude): s midpoint substeps. */
int suslov_composition_apply(const suslov_composition *c, const suslov_model *m, double eps,
                             const double w[3], double w_next[3], double *lambda_next,
                             suslov_step_stats *st);
/* The whole step of (w, R): every midpoint substep is followed by the reconstruction recon over
 * that substep, so that the composed map is the composition of the symmetric pair. */
int suslov_composition_apply_full(const suslov_composition *c, const suslov_model *m, double eps,
                                  suslov_recon recon, suslov_attitude *att, const double w[3],
                                  double w_next[3], double *lambda_next, suslov_step_stats *st);

/* The steppers (src/methods/step_composition.c): the midpoint DSP composed with each table. */
extern const suslov_stepper_type suslov_comp4_s5_type, suslov_comp6_kl_type, suslov_comp8_kl_type,
    suslov_comp10_ss_type;

/* The tables (src/methods/composition_coeffs.c). */
extern const suslov_composition suslov_comp_suzuki4, suslov_comp_kahan_li6, suslov_comp_kahan_li8,
    suslov_comp_sofroniou10;

#endif
