/* One step of a Discrete Suslov Problem (DSP): (w^k) -> (w^{k+1}, lambda_{k+1}) with
 * (w^{k+1})_3 = 0, in the spirit of GSL's gsl_odeiv2_step_type: a stepper is a constant
 * struct with a name, the orders the paper proves, and an apply function; the driver knows
 * only this struct. Steps keep all state on the stack: no allocation per step. */
#ifndef SUSLOV_STEPPER_H
#define SUSLOV_STEPPER_H

#include "model.h"
#include "reconstruct.h"

/* SUSLOV_STEP_DIVERGED: an explicit series step beyond the radius its series is proved to
 * converge in (the step over that radius in stats.residual, |w^k|_2 in stats.scale). */
enum { SUSLOV_STEP_OK = 0, SUSLOV_STEP_NO_CONVERGENCE = 1, SUSLOV_STEP_SINGULAR = 2, SUSLOV_STEP_DIVERGED = 3 };

typedef struct {
    int iterations;   /* Newton iterations (0 for explicit steps) */
    double residual;  /* final |G|_inf of the implicit equation */
    double scale;     /* sum of |terms| of G: the round-off yardstick for residual */
    double det;       /* determinant of the 2x2 Jacobian, the (REGLOC) block */
} suslov_step_stats;

/* An implicit DSP's step equation G(x) = 0 for x = w^{k+1}, given w = w^k: the residual,
 * its Jacobian in x (the upper-left block of (REGLOC)), and scale = sum of |terms| of G,
 * the yardstick for its round-off. */
typedef void (*suslov_residual_fn)(const suslov_model *m, double eps, const double w[2],
                                   const double x[2], double g[2], double J[2][2], double *scale);

typedef struct {
    const char *name;
    int order;         /* p: local w error O(eps^{p+1}) */
    int lambda_order;  /* s, or -1 where the paper proves the multiplier inconsistent */
    /* w and w_next are 3-vectors of so(3) ~ R^3; w[2] must be 0 and the step sets
     * w_next[2] = 0, the second equation of (DSP). Returns SUSLOV_STEP_*. */
    int (*apply)(const suslov_model *m, double eps, const double w[3], double w_next[3],
                 double *lambda_next, suslov_step_stats *st);
    suslov_residual_fn residual;  /* NULL unless the step is one 2x2 implicit equation */
    /* Optional: one step of the whole state (w, R_k) -> (w^{k+1}, R_{k+1}). When set, the driver
     * calls it instead of apply followed by suslov_reconstruct, and the method advances the
     * attitude itself with the requested reconstruction (a composition reconstructs after every
     * substep). apply must still give the w-only step. */
    int (*apply_full)(const suslov_model *m, double eps, suslov_recon recon, suslov_attitude *att,
                      const double w[3], double w_next[3], double *lambda_next, suslov_step_stats *st);
} suslov_stepper_type;

/* The types by name (for the registry table, src/registry.c) and as pointers, like GSL's
 * gsl_odeiv2_step_rk4. */
extern const suslov_stepper_type suslov_euler_type, suslov_rk4_type, suslov_midpoint_type,
    suslov_variational_type;
extern const suslov_stepper_type *const suslov_step_euler;
extern const suslov_stepper_type *const suslov_step_rk4;
extern const suslov_stepper_type *const suslov_step_midpoint;
extern const suslov_stepper_type *const suslov_step_variational;

/* One step of (w, R): apply_full when the type has it, else apply and then (algo)'s
 * reconstruction of the given kind. */
int suslov_step_full(const suslov_stepper_type *st, const suslov_model *m, double eps, suslov_recon recon,
                     suslov_attitude *att, const double w[3], double w_next[3], double *lambda_next,
                     suslov_step_stats *stats);

/* Explicit midpoint (second order) prediction, the starting point of the Newton solves. */
void suslov_predict(const suslov_model *m, double eps, const double w[2], double x[2]);

#endif
