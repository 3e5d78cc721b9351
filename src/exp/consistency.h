/* Consistency experiments as the paper defines them (Definitions UnredConsis, RedConsis):
 * one step from exact data at t_k, compared with the exact solution at t_k + eps; and the
 * global errors a user sees after N steps. */
#ifndef SUSLOV_CONSISTENCY_H
#define SUSLOV_CONSISTENCY_H

#include "exact.h"
#include "reconstruct.h"
#include "stepper.h"

typedef struct {
    double tk, eps;
    double w_k[3];        /* exact w(t_k) */
    double w_exact[3];    /* exact w(t_k + eps) */
    double lambda_exact;  /* lambda(t_k + eps) from (LagMult) */
    double Phi[3][3];     /* R(t_k)^{-1} R(t_k + eps), the reference attitude */
} suslov_local_ref;

typedef struct {
    double w;               /* |w(t_k + eps) - w^{k+1}| (Killing metric = Euclidean on R^3) */
    double lambda;          /* |lambda(t_k + eps) - lambda_{k+1}| */
    double lambda_signed;   /* lambda(t_k + eps) - lambda_{k+1} (PropoFinal's O_0 limit) */
    double so3[SUSLOV_RECON_COUNT]; /* (MetMat) distance of R_{k+1} per suslov_recon */
    suslov_step_stats stats;
} suslov_local_err;

/* The exact data of one step: w(t_k), w(t_k + eps), lambda(t_k + eps) and R(t_k)^{-1} R(t_k + eps). */
void suslov_local_ref_init(suslov_local_ref *ref, const suslov_exact *ex, double tk, double eps);

/* Since (MetMat) is invariant under R -> R_k R, R_k = I without loss of generality.
 * Returns the step status (SUSLOV_STEP_*). */
int suslov_local_errors(const suslov_model *m, const suslov_stepper_type *stepper,
                        const suslov_local_ref *ref, suslov_local_err *err);

typedef struct {
    double w, lambda, so3;
} suslov_global_err;

/* N steps of eps = T/N from w0 with R_0 = I, compared at T with the exact w(T) and the
 * reference R_ref = R(T). Returns 0, or 1 when a step failed. */
int suslov_global_errors(const suslov_exact *ex, const suslov_stepper_type *stepper,
                         suslov_recon recon, double T, long N, const double R_ref[3][3],
                         suslov_global_err *err);

#endif
