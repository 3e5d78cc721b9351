/* Symmetric composition of a symmetric one-step map (Hairer, Lubich & Wanner, Geometric
 * Numerical Integration, 2nd ed., Section V.3): Psi_h = Phi_{g_s h} o ... o Phi_{g_1 h}, with
 * palindromic weights g_i = g_{s+1-i} and sum g_i = 1. Here Phi is the paper's midpoint DSP
 * (Discretization) with a symmetric reconstruction (cayley-mid or exp-mid), a symmetric
 * second-order map of (w, R); the weights raise it to order 4, 6, 8 or 10. Every substep is a
 * midpoint step, so E = 1/2 <I_m w, w> (a quadratic invariant of the midpoint rule), w3 = 0 and
 * R in SO(3) hold exactly, as for the midpoint DSP itself. */
#ifndef SUS_STEP_COMPOSITION_H
#define SUS_STEP_COMPOSITION_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const char *name;   /* e.g. "Kahan-Li s=9" */
    const char *source; /* where the weights were taken from */
    int order;          /* the order the source states (the ledger measures it) */
    int half;           /* m: the weights g_1..g_m, the middle one last; s = 2m - 1 stages */
    const double *g;
} sus_step_composition;

static inline int sus_step_composition_stages(const sus_step_composition *c)
{
    return 2 * c->half - 1;
}
/* g_i for i = 0..s-1 from the half-sequence. */
static inline double sus_step_composition_weight(const sus_step_composition *c, int i)
{
    const int s = sus_step_composition_stages(c);
    return c->g[i < c->half ? i : s - 1 - i];
}

/* The w-step of the composition (no attitude): s midpoint substeps. */
int sus_step_composition_apply(const sus_step_composition *c, const sus_model *m, double eps,
                               const double w[3], double w_next[3], double *lambda_next,
                               sus_stepper_stats *st);
/* The whole step of (w, R): every midpoint substep is followed by the reconstruction recon over
 * that substep, so that the composed map is the composition of the symmetric pair. */
int sus_step_composition_apply_full(const sus_step_composition *c, const sus_model *m, double eps,
                                    sus_recon recon, sus_attitude *att, const double w[3],
                                    double w_next[3], double *lambda_next, sus_stepper_stats *st);

/* The steppers (src/methods/step_composition.c): the midpoint DSP composed with each table. */
extern const sus_stepper_type sus_step_comp4_s5_type, sus_step_comp6_kl_type,
    sus_step_comp8_kl_type, sus_step_comp10_ss_type;

/* The tables (src/methods/composition_coeffs.c). */
extern const sus_step_composition sus_step_comp_suzuki4, sus_step_comp_kahan_li6,
    sus_step_comp_kahan_li8, sus_step_comp_sofroniou10;

#ifdef __cplusplus
}
#endif

#endif
