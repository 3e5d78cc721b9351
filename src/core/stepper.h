/* One step of a Discrete Suslov Problem (DSP): (w^k) -> (w^{k+1}, lambda_{k+1}) with
 * (w^{k+1})_3 = 0, in the spirit of GSL's gsl_odeiv2_step_type: a stepper is a constant
 * struct of small constant parts (its step functions, its implicit equation, what it says of
 * itself); the drivers know only these structs. Steps keep all state on the stack: no
 * allocation per step. */
#ifndef SUS_STEPPER_H
#define SUS_STEPPER_H

#include "model.h"
#include "reconstruct.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SUS_STEPPER_DIVERGED: an explicit series step beyond the radius its series is proved to
 * converge in (the step over that radius in stats.residual, |w^k|_2 in stats.scale). */
/* SUS_STEPPER_REJECTED: a tolerance-driven step whose own error estimate stayed above the
 * tolerance through every retry, or whose step no longer advances t (the estimate in
 * stats.residual, the tolerance in stats.scale, the last step tried in stats.det, the tries in
 * stats.iterations). SUS_STEPPER_NO_MEMORY: its workspace could not be allocated.
 * SUS_STEPPER_STEP_LIMIT: a tolerance-driven run took the most steps it was allowed
 * (sus_tol_config.max_steps) short of its final time (the last step in stats.det). */
enum {
    SUS_STEPPER_OK = 0,
    SUS_STEPPER_NO_CONVERGENCE = 1,
    SUS_STEPPER_SINGULAR = 2,
    SUS_STEPPER_DIVERGED = 3,
    SUS_STEPPER_REJECTED = 4,
    SUS_STEPPER_NO_MEMORY = 5,
    SUS_STEPPER_STEP_LIMIT = 6,
    SUS_STEPPER_BAD_ARGUMENT = 7 /* sus_stepper_full: its refusals, stated where it is declared */
};

typedef struct {
    int iterations;  /* Newton iterations (0 for explicit steps) */
    double residual; /* final |G|_inf of the implicit equation */
    double scale;    /* sum of |terms| of G: the round-off yardstick for residual */
    double det;      /* determinant of the n x n Jacobian of G; for n = 2 the (REGLOC) block */
    /* The last finite |G|_inf the solve reached (NAN if none): what a failure can name when the
     * final residual is not a finite number (the iteration overflowed). */
    double last_residual;
    /* 1 when the step's root is (or its failure that of) the branch continued in eps from eps = 0,
     * sus_step_newton_branch of its own equation (newton.h), not Newton from its prediction */
    int continued;
} sus_stepper_stats;

/* How a method advances the attitude R_k. NONE: it steps w only and the driver reconstructs R
 * as a rotation matrix with the requested reconstruction; QUAT: apply_full carries R as a unit
 * quaternion and writes back R(q/|q|). */
typedef enum { SUS_ATTITUDE_NONE = 0, SUS_ATTITUDE_MATRIX, SUS_ATTITUDE_QUAT } sus_attitude_form;

/* A stepper is four parts, each what one kind of consumer reads, each a small const struct:
 *   step      the step interface, what the fixed-step driver calls (NULL: tolerance-driven);
 *   tol       the tolerance interface, what the tolerance driver calls (NULL: fixed-step);
 *   equation  the implicit step equation, what Newton and its tests read (NULL: none of its own);
 *   desc      the self-description, what the labels, the sweeps, the order fits and the tests
 *             read; every stepper has one.
 * Exactly one of step and tol is set. No consumer compares names: what it needs is in desc. */

/* ---- the step interface ---- */

/* One step of a fixed-step method. w and w_next are 3-vectors of so(3) ~ R^3; w[2] must be 0
 * and the step sets w_next[2] = 0, the second equation of (DSP). Returns SUS_STEPPER_*. */
typedef int (*sus_apply_fn)(const sus_model *m, double eps, const double w[3], double w_next[3],
                            double *lambda_next, sus_stepper_stats *st);
/* One step of the whole state (w, R_k) -> (w^{k+1}, R_{k+1}), the method advancing the attitude
 * itself (see desc.attitude, desc.follows_recon). */
typedef int (*sus_apply_full_fn)(const sus_model *m, double eps, sus_recon recon, sus_attitude *att,
                                 const double w[3], double w_next[3], double *lambda_next,
                                 sus_stepper_stats *st);
/* The same method's whole step at another order p (a ledger control). */
typedef int (*sus_apply_order_fn)(int p, const sus_model *m, double eps, sus_attitude *att,
                                  const double w[3], double w_next[3], double *lambda_next,
                                  sus_stepper_stats *st);

typedef struct {
    sus_apply_fn apply; /* the w-step: always set */
    /* Optional: when set, the driver calls it instead of apply followed by sus_reconstruct. */
    sus_apply_full_fn apply_full;
    sus_apply_order_fn apply_order; /* optional: NULL if the method is not parametrised by p */
} sus_step_ops;

/* ---- the tolerance interface ---- */

/* A tolerance-driven method chooses its own steps, so it cannot be one map (w^k) -> (w^{k+1})
 * of a given eps: it keeps state between steps (the last step's length and series), held in a
 * workspace the driver allocates once per run (never per step). The driver knows only these
 * functions; the fixed-step sweeps over eps do not list such methods (registry.h). */
typedef struct sus_tol_work sus_tol_work;
typedef struct {
    /* A workspace for a run from w0 at tolerance tol, or NULL when out of memory. */
    sus_tol_work *(*alloc)(const sus_model *m, double tol, const double w0[2]);
    /* One accepted step of the state (*t, w, att) that ends at t_end at the latest (exactly at
     * t_end when it reaches it): a step whose own error estimate exceeds tol is retried with a
     * smaller one. Returns SUS_STEPPER_OK (stats.iterations: the rejected tries) or
     * SUS_STEPPER_REJECTED (see above), leaving the state as it was. */
    int (*step)(sus_tol_work *wk, double t_end, double *t, double w[3], double *lambda,
                sus_attitude *att, sus_stepper_stats *st);
    /* Dense output: the state at time t within the last accepted step (from its start to its
     * end), from that step's own series and with the same structure as the steps keep. t, not
     * the time into the step: a method may need t - t0 to more than a double's precision. */
    void (*dense)(const sus_tol_work *wk, double t, double w[3], double *lambda, sus_attitude *att);
    void (*free)(sus_tol_work *wk);
    int (*order)(double tol); /* the order it uses at tol */
    /* The largest angle t_end |w_inf| (sus_exact_turn_angle) over which its attitude keeps its
     * promise: sus_run_tol refuses a run beyond it. */
    double max_angle;
    /* Optional: that angle at T from the workspace, for a method whose alloc already built the
     * closed form (exact.h); NULL has the driver build it (sus_exact_turn_angle) once more. */
    double (*turn_angle)(const sus_tol_work *wk, double T);
} sus_tol_ops;

/* ---- the implicit step equation ---- */

/* The largest number of unknowns of an implicit step equation: Newton keeps its n x n Jacobian
 * on the stack. */
#define SUS_MAX_UNKNOWNS 8

/* An implicit DSP's step equation G(x) = 0 in its n unknowns x (equation->unknowns), given
 * w = w^k: the residual g[n], its Jacobian J[n*n] in x (row-major; for x = w^{k+1} the upper-left
 * block of (REGLOC)), and scale = sum of |terms| of G, the yardstick for its round-off. */
typedef void (*sus_residual_fn)(const sus_model *m, double eps, const double w[2], const double *x,
                                double *g, double *J, double *scale);
/* The starting point of Newton at eps; at eps = 0 it is the root. */
typedef void (*sus_guess_fn)(const sus_model *m, double eps, const double w[2], double *x);
/* w^{k+1} from the root x. */
typedef void (*sus_result_fn)(const sus_model *m, double eps, const double w[2], const double *x,
                              double w_next[2]);

typedef struct {
    int unknowns; /* n, 1 <= n <= SUS_MAX_UNKNOWNS */
    sus_residual_fn residual;
    sus_guess_fn guess;
    sus_result_fn result;
} sus_step_equation;

/* ---- the self-description ---- */

typedef struct {
    int order;                  /* p: local w error O(eps^{p+1}); 0 for a tolerance-driven method */
    int lambda_order;           /* s, or -1 where the paper proves the multiplier inconsistent */
    int implicit;               /* 1 when a step solves an equation (its own, or in its substeps) */
    int conserves_energy;       /* E = 1/2 <I_m w, w> exact up to round-off */
    int w_closed_form;          /* 1 when w comes from the closed form (exact.h), not from steps */
    sus_attitude_form attitude; /* what apply_full (or the tolerance step) carries */
    int follows_recon;          /* 1 when the requested reconstruction is used */
    int substeps;               /* base steps per step: the round-off accumulates per substep */
    /* Order fitting: 1 when the error constants grow with the order (a series truncated within
     * its radius), so that a slope over a few octaves of eps can fall a whole order short of p. */
    int pre_asymptotic;
    /* The linear stability function R(z) of the w-step for real z = eps * eigenvalue (the
     * transverse eigenvalue at the attracting rotation is real, -k); NULL when the step has none
     * (not a linear one-step map of f, or no single limit). */
    double (*stability)(double z);
    const char *source; /* the file that defines the step (__FILE__) */
} sus_stepper_desc;

typedef struct {
    const char *name;
    const sus_step_ops *step;          /* NULL for a tolerance-driven method */
    const sus_tol_ops *tol;            /* NULL for a fixed-step method */
    const sus_step_equation *equation; /* NULL for an explicit step, or one solved in substeps */
    sus_stepper_desc desc;
} sus_stepper_type;

/* One step of (w, R): apply_full when the type has it, else apply and then (algo)'s
 * reconstruction of the given kind. Returns SUS_STEPPER_*; SUS_STEPPER_BAD_ARGUMENT, with nothing
 * written but *stats zeroed, for a NULL pointer, a tolerance-driven or apply-less stepper, a
 * recon not among sus_recon's values, an eps that is not finite, or a w whose w[0], w[1] are not
 * finite (the model is not checked here, at every step: the run drivers check it). The steps
 * write w_next[2] = 0 and read w[0], w[1] alone; a reconstruction (algo) reads all of w, so a w[2]
 * off the constraint w3 = 0 turns R about e3 (the ledger's positive control of the constraint
 * injects one). A negative eps is a step back in time, as the methods are written (0: w
 * unchanged); the run drivers take eps > 0 only. */
int sus_stepper_full(const sus_stepper_type *st, const sus_model *m, double eps, sus_recon recon,
                     sus_attitude *att, const double w[3], double w_next[3], double *lambda_next,
                     sus_stepper_stats *stats);

/* The end of a step of at most h > 0 from t >= 0 (t < stop), the clock's own: stop when h reaches
 * it, else fl(t + h), or the double below it when that rounded up, so that a method which
 * integrates exactly h' = end - t (computed) steps no further than h (but to stop, when t + h
 * rounds there) and labels its state with the very time it reached. Why h' is that difference to
 * the bit: end >= t >= 0 are both multiples of ulp(t), so end - t is one too, and it is a double
 * while below 2^53 ulp(t), in particular whenever end <= 2t (Sterbenz). Only a step longer than t
 * (the first few of a run: each more than doubles t) or a last step to stop from below stop/2 may
 * round h', by at most u h': a rounding of the step's own length, where adding h to t in place
 * rounds by u t, which summed over N steps grows like N u t. NaN for a NaN argument, t < 0, h <= 0
 * or t >= stop. */
double sus_step_end(double t, double h, double stop);

#ifdef __cplusplus
}
#endif

#endif
