/* The composition methods as steppers: the midpoint DSP (Discretization) composed with the
 * weights of src/methods/composition_coeffs.c (the engine is src/methods/composition.c). One
 * stepper per table; apply is the w-step, apply_full advances (w, R) with the reconstruction after
 * every substep. */
#include "composition.h"

#define COMPOSITION_STEPPER(ID, NAME, ORDER, STAGES, TABLE)                                        \
    static int ID##_apply(const sus_model *m, double eps, const double w[3], double w_next[3],     \
                          double *lambda_next, sus_stepper_stats *st)                              \
    {                                                                                              \
        return sus_step_composition_apply(&TABLE, m, eps, w, w_next, lambda_next, st);             \
    }                                                                                              \
    static int ID##_apply_full(const sus_model *m, double eps, sus_recon recon, sus_attitude *att, \
                               const double w[3], double w_next[3], double *lambda_next,           \
                               sus_stepper_stats *st)                                              \
    {                                                                                              \
        return sus_step_composition_apply_full(&TABLE, m, eps, recon, att, w, w_next, lambda_next, \
                                               st);                                                \
    }                                                                                              \
    static const sus_step_ops ID##_step = {.apply = ID##_apply, .apply_full = ID##_apply_full};    \
    const sus_stepper_type sus_step_##ID##_type = {.name = NAME,                                   \
                                                   .step = &ID##_step,                             \
                                                   .desc = {.order = ORDER,                        \
                                                            .lambda_order = ORDER,                 \
                                                            .implicit = 1,                         \
                                                            .conserves_energy = 1,                 \
                                                            .attitude = SUS_ATTITUDE_QUAT,         \
                                                            .follows_recon = 1,                    \
                                                            .substeps = STAGES,                    \
                                                            .source = __FILE__}};

/* lambda_{k+1} = lambda(w^{k+1}) from (LagMult), as for the midpoint DSP: its order is p. Every
 * substep is a midpoint step, so E is conserved; STAGES = 2 half - 1 of the table (a unit test
 * checks it). No stability function: the composed linear map prod (1 + g_i z/2) / (1 - g_i z/2)
 * has a pole at z = 2/g_i for each negative weight, where a backward substep's linear step
 * equation is singular, and predicts neither the return near the rotation nor the Newton failures
 * from the energy ellipse (figures/stability). */
COMPOSITION_STEPPER(comp4_s5, "comp4-s5", 4, 5, sus_step_comp_suzuki4)
COMPOSITION_STEPPER(comp6_kl, "comp6-kl", 6, 9, sus_step_comp_kahan_li6)
COMPOSITION_STEPPER(comp8_kl, "comp8-kl", 8, 17, sus_step_comp_kahan_li8)
COMPOSITION_STEPPER(comp10_ss, "comp10-ss", 10, 35, sus_step_comp_sofroniou10)
