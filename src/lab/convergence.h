/* The convergence sweep behind the order claims and the convergence figure: for eps = 2^-j,
 * j = 0..SUS_LAB_CONV_NJ-1, the local errors (one step from exact data, largest over a set of
 * t_k) and the global errors at T of every DSP, in w, lambda and on SO(3) with both
 * reconstructions, for every method of the registry; plus the accuracy of the reference attitude
 * (refattitude.h) against Magnus4. */
#ifndef SUS_LAB_CONVERGENCE_H
#define SUS_LAB_CONVERGENCE_H

#include "exact.h"
#include "reconstruct.h"

#ifdef __cplusplus
extern "C" {
#endif

/* eps_j = 2^(SUS_LAB_CONV_J0 - j), j = 0 .. SUS_LAB_CONV_NJ - 1: from 8 down to 2^-10. The paper's
 * methods are fitted over eps <= 2^-2 (orderfit.h); the steps above let a method of high order
 * show its slope before it reaches round-off. */
#define SUS_LAB_CONV_J0 3
#define SUS_LAB_CONV_NJ 14

/* One method's errors at eps = 2^-j. */
typedef struct {
    double loc_w[SUS_LAB_CONV_NJ];
    double loc_lambda[SUS_LAB_CONV_NJ];
    double loc_so3[SUS_RECON_COUNT][SUS_LAB_CONV_NJ];
    double glob_w[SUS_LAB_CONV_NJ];
    double glob_lambda[SUS_LAB_CONV_NJ];
    double glob_so3[SUS_RECON_COUNT][SUS_LAB_CONV_NJ];
} sus_lab_conv_method;

typedef struct {
    double eps[SUS_LAB_CONV_NJ];
    double glob_eps[SUS_LAB_CONV_NJ]; /* the step T/N actually used for the global errors, N =
                                         round(T/eps) */
    int nmethod;
    sus_lab_conv_method *m; /* [nmethod], in the order of the registry (src/methods/registry.h) */
    double R_T[3][3];       /* reference R(T) */
    double ref_local_err;   /* max |Phi_ref - Phi_magnus4| over the local increments */
    double ref_global_err;  /* |R_ref(T) - R_magnus4(T)| */
} sus_lab_convergence;

/* Runs every registered method. A step that fails (an implicit step at a large eps) leaves NaN
 * at that point, which the order fit refuses inside its window. Returns 0, or -1 (with a message
 * on stderr) when memory runs out; free with sus_lab_convergence_free either way. */
int sus_lab_convergence_run(sus_lab_convergence *c, const sus_exact *ex, const double *tk, int ntk,
                            double T);
void sus_lab_convergence_free(sus_lab_convergence *c);

#ifdef __cplusplus
}
#endif

#endif
