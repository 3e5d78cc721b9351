#include "midpoint_sweeps.h"

void sus_lab_midpoint_sweeps(const sus_model *m, double eps, int n, const double w[2], double x[2])
{
    x[0] = w[0];
    x[1] = w[1];
    for (int j = 0; j < n; j++) {
        const double mid[2] = {0.5 * (w[0] + x[0]), 0.5 * (w[1] + x[1])};
        double f[2];
        sus_contdyn(m, mid, f); /* I_m^{-1} (l1, l2) at the midpoint */
        x[0] = w[0] + eps * f[0];
        x[1] = w[1] + eps * f[1];
    }
}

void sus_lab_midpoint_sweeps_run(const sus_model *m, double eps, int n, const double w0[2], long N,
                                 double *energy, double wN[2])
{
    double w[2] = {w0[0], w0[1]};
    energy[0] = sus_energy(m, w);
    for (long k = 0; k < N; k++) {
        double x[2];
        sus_lab_midpoint_sweeps(m, eps, n, w, x);
        w[0] = x[0];
        w[1] = x[1];
        energy[k + 1] = sus_energy(m, w);
    }
    wN[0] = w[0];
    wN[1] = w[1];
}

/* One step of the reading: (Discretization) with the midpoint l1, l2, by n sweeps. */
static int sweeps_apply(int n, const sus_model *m, double eps, const double w[3], double w_next[3],
                        double *lambda_next, sus_stepper_stats *st)
{
    sus_lab_midpoint_sweeps(m, eps, n, w, w_next);
    w_next[2] = 0.0;
    *lambda_next = sus_lagmult(m, w_next);
    *st = (sus_stepper_stats){0};
    return SUS_STEPPER_OK;
}

/* apply takes no n: one function and one type for each n. */
#define SWEEPS_TYPE(n)                                                                             \
    static int apply_##n(const sus_model *m, double eps, const double w[3], double w_next[3],      \
                         double *lambda_next, sus_stepper_stats *st)                               \
    {                                                                                              \
        return sweeps_apply(n, m, eps, w, w_next, lambda_next, st);                                \
    }                                                                                              \
    static const sus_step_ops step_##n = {.apply = apply_##n};                                     \
    static const sus_stepper_type sweeps_##n = {.name = "midpoint-sweeps" #n,                      \
                                                .step = &step_##n,                                 \
                                                .desc = {.order = (n) < 2 ? (n) : 2,               \
                                                         .lambda_order = (n) < 2 ? (n) : 2,        \
                                                         .follows_recon = 1,                       \
                                                         .substeps = 1,                            \
                                                         .source = __FILE__}};
SWEEPS_TYPE(1)
SWEEPS_TYPE(2)
SWEEPS_TYPE(3)
SWEEPS_TYPE(4)
SWEEPS_TYPE(5)
SWEEPS_TYPE(6)
SWEEPS_TYPE(7)
SWEEPS_TYPE(8)

const sus_stepper_type *sus_lab_midpoint_sweeps_type(int n)
{
    static const sus_stepper_type *const types[SUS_LAB_MAX_SWEEPS] = {
        &sweeps_1, &sweeps_2, &sweeps_3, &sweeps_4, &sweeps_5, &sweeps_6, &sweeps_7, &sweeps_8};
    return n >= 1 && n <= SUS_LAB_MAX_SWEEPS ? types[n - 1] : NULL;
}
