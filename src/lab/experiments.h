/* The settings of the paper's experiments, in one place: the figure programs that draw them
 * (src/prog/figure_fig1.c, figure_fig2.c, figure_fig2_energy.c, figure_inertia.c) and the ledger
 * that measures them (tests/ledger/claims_figures.c) read the same values, so the claims are about
 * the runs the figures show. */
#ifndef SUS_LAB_EXPERIMENTS_H
#define SUS_LAB_EXPERIMENTS_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Figure 1: eps = 1e-3. The paper gives no interval: t in [0, 60] = 8.7/k covers the transient
 * to the steady rotation (e^{-8.7} ~ 2e-4, k = 0.145); rows kept every 10th step. */
#define SUS_LAB_FIG1_EPS 1e-3
#define SUS_LAB_FIG1_T_END 60.0
#define SUS_LAB_FIG1_EVERY 10

/* Figure 2: eps = 1 over [0, 200] = 29/k, every step kept; the readings of the midpoint rule's
 * implicit equation tried against it: Newton and 1 .. 8 fixed-point sweeps. */
#define SUS_LAB_FIG2_EPS 1.0
#define SUS_LAB_FIG2_T_END 200.0
#define SUS_LAB_FIG2_NSWEEP 8

/* The inertia ambiguity: exact solutions on t_k = k 0.05, t in [0, 60]. */
#define SUS_LAB_INERTIA_T_END 60.0
#define SUS_LAB_INERTIA_DT 0.05

/* N = T / eps steps (T a whole number of steps in every experiment above). */
static inline long sus_lab_experiment_steps(double t_end, double eps)
{
    return (long)llround(t_end / eps);
}

/* The printed I with its third row (I31, I32) replaced by the third column (I13, I23): the
 * inertia of a symmetric body with the printed third column. */
static inline void sus_lab_inertia_column_swap(const double I[9], double Icol[9])
{
    for (int i = 0; i < 9; i++)
        Icol[i] = I[i];
    Icol[6] = I[2];
    Icol[7] = I[5];
}

#ifdef __cplusplus
}
#endif

#endif
