/* Where the integrators stop working. The Suslov field is homogeneous of degree 2, so the step
 * that matters is the dimensionless h = eps k, k the rate at which w approaches the steady
 * rotation (exact.h). A run from w0 with step eps over N steps is classified as
 *   GOOD        it ends within SUS_LAB_STAB_GOOD_TOL |w_inf| of the exact steady rotation w_inf;
 *   WRONG_LIMIT bounded, but ends elsewhere (a wrong steady rotation, a cycle, ...);
 *   BLOWUP      |w| exceeds SUS_LAB_STAB_BLOWUP_FACTOR |w0| or stops being finite;
 *   SOLVER      the step's solve failed other than at a fold, or its root is not the one the
 *               branch continued in eps from eps = 0 reaches (checked when check_branch is set),
 *               or a Taylor step's series diverges (beyond its radius of convergence);
 *   REGULARITY  the branch meets a fold (det J -> 0 as it turns back: beyond it the step equation
 *               has no root on the branch), or the (REGLOC) block is singular at the root or has
 *               changed sign from its eps -> 0 value (det I_m > 0): the discrete flow stops
 *               being defined.
 * The implicit steps solve for that branch themselves (newton.h: Newton from their prediction,
 * else continuation in eps), so SOLVER and REGULARITY measure the step equation, not where
 * Newton from one starting point happens to fail. */
#ifndef SUS_LAB_STABILITY_H
#define SUS_LAB_STABILITY_H

#include "exact.h"
#include "registry.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    SUS_LAB_STAB_GOOD,
    SUS_LAB_STAB_WRONG_LIMIT,
    SUS_LAB_STAB_BLOWUP,
    SUS_LAB_STAB_SOLVER,
    SUS_LAB_STAB_REGULARITY,
    SUS_LAB_STAB_NCLASS
};
extern const char *const SUS_LAB_STAB_NAMES[SUS_LAB_STAB_NCLASS];

#define SUS_LAB_STAB_GOOD_TOL 0.01
#define SUS_LAB_STAB_BLOWUP_FACTOR 100.0

typedef struct {
    int cls;
    long step;        /* where a failure happened (0 when none) */
    double final_err; /* |w_N - w_inf| / |w_inf| (NaN after a failure) */
    double w_fail[2]; /* the state the failed step started from (w_N after none) */
} sus_lab_stab_result;

void sus_lab_stability_run(const sus_exact *ex, const sus_stepper_type *st, double eps, long N,
                           int check_branch, sus_lab_stab_result *res);

/* The point of the energy ellipse of the paper's w(0) at angle theta in the Cholesky
 * coordinates of exact.h (theta = psi + beta), and the rate k there (the same all round). */
void sus_lab_ellipse_point(const sus_exact *ref, double theta, double w[2]);

/* The linear stability limit of an explicit stepper at the attracting steady rotation,
 * measured: the largest h for which a start 1e-6 off the rotation returns to the line of
 * steady rotations (bisection to 1e-4 relative over [lo, hi]). Returns INFINITY when it still
 * returns at hi, NAN when it does not even return at lo. *radius_bound: 1 when what ends the
 * returns there is a step refused as beyond its series' proved radius (a Taylor step), not an
 * instability: the linear limit lies beyond the steps the method takes from there. */
double sus_lab_stability_limit(const sus_exact *ex, const sus_stepper_type *st, double lo,
                               double hi, int *radius_bound);

/* The run length for step h: long enough for the exact motion (k t = 40) and for a method
 * whose contraction per step is only 1 - O(1/h) (the A-stable midpoint rule at large h). */
long sus_lab_stability_steps(double h);

/* The map: classes[i * nangle + a] for h = hs[i] and w0 at angle 2 pi a / nangle +
 * SUS_LAB_STAB_ANGLE0 on the paper's energy ellipse; the branch check runs for h >=
 * SUS_LAB_STAB_BRANCH_H. */
#define SUS_LAB_STAB_ANGLE0 0.01
#define SUS_LAB_STAB_BRANCH_H 0.05
void sus_lab_stability_map(const sus_exact *paper, const sus_stepper_type *st, const double *hs,
                           int nh, int nangle, sus_lab_stab_result *results);

/* Where the step equation's branch from w has a fold, for a step eps the continuation does not
 * reach: e_star, the largest step it reaches (bisection to SUS_LAB_FOLD_BISECT of eps), and the
 * exponent of |det J| at the branch root against e_star - e, the least-squares slope over
 * e_star - e = 10^-3 ... 10^-7 e_star (SUS_LAB_FOLD_POINTS, one a decade). At a quadratic fold
 * (two roots meet and vanish) det J ~ (e_star - e)^(1/2). Returns 0, or -1 when the branch reaches
 * eps (or the method has no step equation). Far below 10^-7 the bisection's own resolution
 * (2^-50 of eps) would enter. */
#define SUS_LAB_FOLD_BISECT 0x1p-50
#define SUS_LAB_FOLD_POINTS 5
int sus_lab_fold(const sus_model *m, const sus_stepper_type *st, const double w[2], double eps,
                 double *e_star, double *exponent);

/* The linear stability limit at the attracting rotation, where the transverse eigenvalue of Df is
 * -k: the smallest h > 0 with |R(-h)| = 1 for the method's stability function R (Euler: 2; RK4:
 * 2.7853); INFINITY when |R(-h)| <= 1 up to h_max (the midpoint rule is A-stable); NAN when the
 * method has no stability function in the registry. */
double sus_lab_linear_limit(const sus_step_method *me, double h_max);

#ifdef __cplusplus
}
#endif

#endif
