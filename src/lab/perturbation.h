/* Section 6 made constructive: a one-step method phi(eps, .) of order p for (ContDyn) is the
 * period map of an eps-periodic perturbation x' = h(x) + eps^p d(eps, t/eps, x) (TheoPer).
 *
 * Construction (one of many; the theorem only says one exists). On a period t in [0, eps],
 * s = t/eps, the curve from x0 is the blend
 *     X(t; x0) = (1 - chi(s)) F(t, x0) + chi(s) F(t - eps, phi(eps, x0)),
 * F the exact flow (closed form, exact.h), chi a C^infinity weight that is 0 on [0, a] and 1 on
 * [1 - a, 1]. So X(0) = x0, X(eps) = phi(eps, x0), and the perturbation g = X' - h(X) vanishes
 * identically near both ends of the period: its eps-periodic continuation is smooth. Since
 * F(t - eps, phi) - F(t, x0) = O(eps^{p+1}), g = chi'(s)/eps O(eps^{p+1}) = O(eps^p).
 * To evaluate g at a point x (not only along one curve) the blend is inverted, x = X(t; x0),
 * for x0 by Newton: that is d(eps, t/eps, x) as a function of x.
 *
 * The same on SO(3) x R^2 (Per11): the attitude blends R_A(t) = R0 Phi(t; x0) (exact) and
 * R_B(t) = R1 Phi_1(t - eps) (exact, backward from the method's (R1, x1)) along the geodesic,
 * R = R_A exp(chi log(R_A^T R_B)); the attitude perturbation is vee(R^T R') - w. */
#ifndef SUS_LAB_PERTURBATION_H
#define SUS_LAB_PERTURBATION_H

#include "model.h"
#include "orderfit.h"
#include "reconstruct.h"
#include "stepper.h"

#include <float.h>

#ifdef __cplusplus
extern "C" {
#endif

/* chi is flat (0 or 1) on the first and last tenth of the period. */
#define SUS_LAB_PERTURB_FLAT 0.1

/* The round-off floors of the perturbation's sizes, shared by the ledger (claims_section6.c) and
 * the figure; both grow like 1/eps, so a size at eps is compared with FLOOR / eps.
 * FLOOR_G: g is chi'/eps times a difference of two flows each good to a few u |w| (|w| <= 0.8,
 * chi' < 3); a fitted point must sit 1000 times above it (orderfit.h: round-off moves no fitted
 * point by more than 0.1%).
 * FLOOR_ATT: on SO(3) the attitudes come from rk8pd at ATT_TOL and enter a difference quotient
 * over the stencil step 0.1 (1 - 2 FLAT) eps / 32 = 0.0025 eps of sus_lab_perturb_sup_so3 with 32
 * samples; 100 ATT_TOL / (0.0025 eps) keeps that noise below 1% of a fitted point. */
#define SUS_LAB_PERTURB_ATT_TOL 1e-14
#define SUS_LAB_PERTURB_FLOOR_G (1000.0 * SUS_U * SUS_LAB_SIZE_W * 3.0)
#define SUS_LAB_PERTURB_FLOOR_ATT (100.0 * SUS_LAB_PERTURB_ATT_TOL / 0.0025)

enum {
    SUS_LAB_PERTURB_OK = 0,
    SUS_LAB_PERTURB_STEP_FAILED = 1,
    SUS_LAB_PERTURB_NEWTON_FAILED = 2,
    SUS_LAB_PERTURB_ODE_FAILED = 3
};

typedef struct {
    const sus_model *m;
    const sus_stepper_type *st; /* phi: its w-step (apply) */
    double eps;
    double Iinv[3][3];                    /* the full inertia inverse, for (PerFin2) */
    long sus_lab_newton_its, field_evals; /* counters of the last period map */
    double sus_lab_newton_res;            /* largest final Newton residual seen */
} sus_lab_perturb;

/* Returns 0, or -1 when the full inertia tensor is singular. */
int sus_lab_perturb_init(sus_lab_perturb *P, const sus_model *m, const sus_stepper_type *st,
                         double eps);

/* The weight chi(s) and its derivative dchi/ds. */
double sus_lab_perturb_chi(double s, double *dchi);

/* The blended curve X(t; x0) and X'(t) for t in [0, eps], given x1 = phi(eps, x0). */
void sus_lab_perturb_curve(const sus_lab_perturb *P, double t, const double x0[2],
                           const double x1[2], double X[2], double Xdot[2]);

/* eps^p d(eps, t/eps, x): the perturbation at time t (any t: reduced mod eps) and point x,
 * with x0 such that x = X(t mod eps; x0) (may be NULL). Returns SUSLOV_PERTURB_*. */
int sus_lab_perturb_field(sus_lab_perturb *P, double t, const double x[2], double g[2],
                          double x0[2]);

/* The period map of (Eq2) from x0: rk8pd at tolerance tol (abs and rel) over [0, eps] on the
 * perturbed field, into x_end. Returns SUSLOV_PERTURB_*. */
int sus_lab_perturb_period_map(sus_lab_perturb *P, const double x0[2], double tol, double x_end[2]);

/* The solution of (Eq2) over one period from x0, sampled at t = i eps / n, i = 0 .. n, into
 * x[i][0..1] (the last one is the period map). Returns SUSLOV_PERTURB_*. */
int sus_lab_perturb_trajectory(sus_lab_perturb *P, const double x0[2], double tol, int n,
                               double (*x)[2]);

/* The same on the three-dimensional (PerFin2): I xi' = (I xi) x xi + lambda e3 + dt, with the
 * perturbing force dt = (I_m g, 0) in the constraint-free rows and lambda eliminated so that
 * <e3, xi'> = 0. Integrates from (x0, 0) over [0, eps]; returns xi(eps), the largest |xi_3| seen
 * and the largest |lambda - lambda(xi)| over the period (the multiplier shift). */
int sus_lab_perturb_perfin2(sus_lab_perturb *P, const double x0[2], double tol, double xi_end[3],
                            double *max_xi3, double *max_dlambda);

/* Along the curve from x0, sampled at n + 1 equally spaced times: the largest |g| (reduced
 * perturbation, eps^p d); and on SO(3) with reconstruction recon (R0 = I, the method's own
 * attitude step, sus_stepper_full), the largest |vee(R^T R') - w| of the geodesic blend, at n + 1
 * times where chi is not flat (n <= 64). Returns SUSLOV_PERTURB_*. */
int sus_lab_perturb_sup_reduced(sus_lab_perturb *P, const double x0[2], int n, double *sup_g);
int sus_lab_perturb_sup_so3(sus_lab_perturb *P, sus_recon recon, const double x0[2], int n,
                            double tol, double *sup_att, double *sup_g);

#ifdef __cplusplus
}
#endif

#endif
