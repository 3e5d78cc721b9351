/* A reading of the paper's midpoint DSP for Figure 2: its implicit equation (Discretization)
 * with the midpoint l1, l2 solved not by Newton but by a fixed number n of fixed-point sweeps
 *     x <- w^k + eps I_m^{-1} (l1, l2)(w^k, x),   x_0 = w^k.
 * One sweep is explicit Euler, two are the explicit midpoint rule (RK2), and as n grows the
 * sweeps converge (for small eps) to the Newton solution, which conserves E exactly. */
#ifndef SUS_LAB_MIDPOINT_SWEEPS_H
#define SUS_LAB_MIDPOINT_SWEEPS_H

#include "model.h"
#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The most sweeps a stepper type is made for (Figure 2's readings run 1 to 8). */
#define SUS_LAB_MAX_SWEEPS 8

void sus_lab_midpoint_sweeps(const sus_model *m, double eps, int n, const double w[2], double x[2]);

/* N steps from w0; energy[k] = E(w_k) for k = 0..N (caller's array, N+1 long), and w_N. */
void sus_lab_midpoint_sweeps_run(const sus_model *m, double eps, int n, const double w0[2], long N,
                                 double *energy, double wN[2]);

/* The reading as a stepper for the driver (the suslov command's --sweeps, the browser's page):
 * w^{k+1} from n sweeps, lambda_{k+1} = lambda(w^{k+1}) from (LagMult) as the midpoint DSP
 * has it, R by the requested reconstruction. NULL unless 1 <= n <= SUS_LAB_MAX_SWEEPS. */
const sus_stepper_type *sus_lab_midpoint_sweeps_type(int n);

#ifdef __cplusplus
}
#endif

#endif
