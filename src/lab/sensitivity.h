/* Figure 2's statements away from its one setting: the midpoint DSP and the variational
 * integrator run side by side for a range of steps, on any body and from several initial states,
 * and what each of the four statements of the caption needs is measured on both runs:
 *   energy      the change (E_N - E_0) / E_0 at the end of the run, and its largest size;
 *   faster      the error |w_k - w(t_k)| at the first t_k >= t_fast;
 *   long-term   |w_N - w_inf| at the end;
 *   constraint  the unreduced constraint |<e3, vee(R_k^T R_k w^_k)>| of Algorithm (algo), with
 *               R_{k+1} = R_k cay(eps w^_k), at every step;
 * with the largest error over the run relative to |w0| ("works quite well"), and the smallest
 * determinant of the step's (REGLOC)/(RegCond) block relative to its eps -> 0 value det I_m.
 * Times are in the body's own units 1/k (exact.h): the run ends at k T = SUS_LAB_SENS_KT, Figure
 * 2's T = 200 on the paper's body, and t_fast = SUS_LAB_SENS_KT_FAST / k, Figure 2's t = 10. */
#ifndef SUS_LAB_SENSITIVITY_H
#define SUS_LAB_SENSITIVITY_H

#include "exact.h"
#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_LAB_SENS_KT 29.0
#define SUS_LAB_SENS_KT_FAST 1.45
/* the initial states: the body's own w0, then three points of its energy ellipse at the angles
 * psi0 of exact.h (psi = pi/2 is the attracting rotation, -pi/2 the unstable one) */
#define SUS_LAB_SENS_NSTATE 4
/* the failure search: eps = 2^(j/4) from 2^-3 up to 2^SUS_LAB_SENS_FAIL_MAX_EXP */
#define SUS_LAB_SENS_FAIL_MIN_EXP (-3)
#define SUS_LAB_SENS_FAIL_MAX_EXP 12

typedef struct {
    int failed;        /* a solve failed, a value stopped being finite, the block lost its sign,
                        * or the root is not the one continued from eps = 0: the run stops there
                        * and only t_fail, det_min and steps are set */
    double t_fail;     /* the time of the step that failed */
    long steps;        /* N: the run ends at N eps, at least one step and k T rounded to steps */
    double err_max;    /* max_k |w_k - w(t_k)| / |w0| */
    double err_fast;   /* |w_k - w(t_k)| at the first t_k >= t_fast */
    double limit;      /* |w_N - w_inf| */
    double denergy;    /* (E_N - E_0) / E_0 */
    double energy_max; /* max_k |E_k - E_0| / E_0 */
    double constraint; /* max_k |<e3, vee(R_k^T R_k w^_k)>| */
    double det_min;    /* min over the steps of det J / det I_m (1 for an explicit step) */
    double w_end[2];   /* w_N */
} sus_lab_sens_run;

/* Initial state s (0 .. SUS_LAB_SENS_NSTATE - 1) of the body whose exact solution from its own
 * w0 is body. */
void sus_lab_sens_state(const sus_exact *body, int s, double w0[2]);

/* One run of st with step eps; ex is the exact solution from the run's own w0 (ex->w0). */
void sus_lab_sens_run_one(const sus_exact *ex, const sus_stepper_type *st, double eps,
                          sus_lab_sens_run *r);

/* The first step eps = 2^(j/4) scale of the search at which the run fails; INFINITY when none does
 * up to 2^SUS_LAB_SENS_FAIL_MAX_EXP scale (scale: the body's time against another's, e.g. k_paper
 * / k, so that the search covers the same eps k on every body). */
double sus_lab_sens_first_failure(const sus_exact *ex, const sus_stepper_type *st, double scale);

#ifdef __cplusplus
}
#endif

#endif
