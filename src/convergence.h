/* The convergence sweep behind the order claims and the convergence figure: for eps = 2^-j,
 * j = 0..SUSLOV_CONV_NJ-1, the local errors (one step from exact data, largest over a set of
 * t_k) and the global errors at T of every DSP, in w, lambda and on SO(3) with both
 * reconstructions; plus the accuracy of the rk8pd reference attitude against Magnus4. */
#ifndef SUSLOV_CONVERGENCE_H
#define SUSLOV_CONVERGENCE_H

#include "exact.h"

#define SUSLOV_CONV_NJ 11
#define SUSLOV_CONV_NMETHOD 4

typedef struct {
    double eps[SUSLOV_CONV_NJ];
    double loc_w[SUSLOV_CONV_NMETHOD][SUSLOV_CONV_NJ];
    double loc_lambda[SUSLOV_CONV_NMETHOD][SUSLOV_CONV_NJ];
    double loc_so3[SUSLOV_CONV_NMETHOD][2][SUSLOV_CONV_NJ];   /* [method][suslov_recon][j] */
    double glob_w[SUSLOV_CONV_NMETHOD][SUSLOV_CONV_NJ];
    double glob_lambda[SUSLOV_CONV_NMETHOD][SUSLOV_CONV_NJ];
    double glob_so3[SUSLOV_CONV_NMETHOD][2][SUSLOV_CONV_NJ];
    double R_T[3][3];        /* reference R(T) */
    double ref_local_err;    /* max |Phi_rk8pd - Phi_magnus4| over the local increments */
    double ref_global_err;   /* |R_rk8pd(T) - R_magnus4(T)| */
} suslov_convergence;

/* Method index m is suslov_stepper_get(m). Returns 0, or -1 (with a message on stderr) when
 * a step or the reference attitude fails. */
int suslov_convergence_run(suslov_convergence *c, const suslov_exact *ex, const double *tk, int ntk,
                           double T);

#endif
