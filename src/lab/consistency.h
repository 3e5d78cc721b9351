/* Consistency experiments as the paper defines them (Definitions UnredConsis, RedConsis):
 * one step from exact data at t_k, compared with the exact solution at t_k + eps; and the
 * global errors a user sees after N steps. */
#ifndef SUS_LAB_CONSISTENCY_H
#define SUS_LAB_CONSISTENCY_H

#include "exact.h"
#include "reconstruct.h"
#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double tk, eps;
    double w_k[3];       /* exact w(t_k) */
    double w_exact[3];   /* exact w(t_k + eps) */
    double lambda_exact; /* lambda(t_k + eps) from (LagMult) */
    double Phi[3][3];    /* R(t_k)^{-1} R(t_k + eps), the reference attitude */
} sus_lab_local_ref;

typedef struct {
    double w;                    /* |w(t_k + eps) - w^{k+1}| (Killing metric = Euclidean on R^3) */
    double lambda;               /* |lambda(t_k + eps) - lambda_{k+1}| */
    double lambda_signed;        /* lambda(t_k + eps) - lambda_{k+1} (PropoFinal's O_0 limit) */
    double so3[SUS_RECON_COUNT]; /* (MetMat) distance of R_{k+1} per sus_recon */
    sus_stepper_stats stats;
} sus_lab_local_err;

/* The exact data of one step: w(t_k), w(t_k + eps), lambda(t_k + eps) and R(t_k)^{-1} R(t_k + eps).
 */
void sus_lab_local_ref_init(sus_lab_local_ref *ref, const sus_exact *ex, double tk, double eps);

/* Since (MetMat) is invariant under R -> R_k R, R_k = I without loss of generality.
 * Returns the step status (SUS_STEPPER_*). */
int sus_lab_local_errors(const sus_model *m, const sus_stepper_type *stepper,
                         const sus_lab_local_ref *ref, sus_lab_local_err *err);

typedef struct {
    double w, lambda, so3;
} sus_lab_global_err;

/* N steps of eps = T/N from w0 with R_0 = I, compared at T with the exact w(T) and the
 * reference R_ref = R(T). Returns 0, or 1 when a step failed. */
int sus_lab_global_errors(const sus_exact *ex, const sus_stepper_type *stepper, sus_recon recon,
                          double T, long N, const double R_ref[3][3], sus_lab_global_err *err);

#ifdef __cplusplus
}
#endif

#endif
