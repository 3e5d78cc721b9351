/* The library integrators' view of the problem (make bench, figures/longrun): (ContDyn) with the
 * attitude either as R, R' = R w^ (y = (w1, w2, R row-major), 11 unknowns), or as a quaternion,
 * q' = 1/2 q (x) (0, w) (y = (w1, w2, q), 6 unknowns), or w alone (2), as GSL odeiv2 right-hand
 * sides; and the reduced problem of reduced.h, the attitude alone along the closed-form w
 * (y = q, 4 unknowns). */
#ifndef SUS_LAB_PEERS_H
#define SUS_LAB_PEERS_H

#include "model.h"
#include "reduced.h"

#include <gsl/gsl_odeiv2.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* GSL odeiv2 right-hand sides; params is the sus_model. */
int sus_lab_peer_rhs_wR(double t, const double y[], double f[], void *params);
int sus_lab_peer_rhs_wq(double t, const double y[], double f[], void *params);
int sus_lab_peer_rhs_w(double t, const double y[], double f[], void *params);
/* y(0) for dim 11, 6 or 2: w0, then R = I or q = (1, 0, 0, 0); for dim 4 (the reduced problem)
 * q = (1, 0, 0, 0). */
void sus_lab_peer_initial(size_t dim, const double w0[2], double *y);
/* R of the state: the 3x3 block, or R(q/|q|) (q after w, or alone for dim 4). */
void sus_lab_peer_attitude(size_t dim, const double *y, double R[3][3]);

/* One configuration of an adaptive GSL peer: stepper, formulation (dim 11, 6, 2, or 4 for the
 * reduced problem), API (the driver or the evolve loop), tolerances and initial step. Every
 * sus_lab_peer_run starts from the same state, the step size included
 * (gsl_odeiv2_driver_reset keeps the step the previous run ended with; sus_lab_peer_run resets
 * it to hstart), so a repeated (timed) run gives bit for bit the result of the first. */
typedef enum { SUS_LAB_PEER_DRIVER = 0, SUS_LAB_PEER_EVOLVE = 1 } sus_lab_peer_api;

typedef struct {
    const gsl_odeiv2_step_type *type;
    sus_lab_peer_api api;
    size_t dim;
    double tol, rel, hstart; /* abs tolerance tol, rel tolerance rel (GSL's y control) */
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *d; /* the driver API */
    gsl_odeiv2_step *s;   /* the evolve API */
    gsl_odeiv2_control *c;
    gsl_odeiv2_evolve *e;
} sus_lab_peer;

/* A run that needs more steps than this has lost its way (its tolerance below what round-off
 * allows, where the step shrinks without end): it fails instead of running for hours. */
#define SUS_LAB_PEER_MAX_STEPS 200000UL

/* Returns 0, or -1 when GSL cannot allocate. Absolute tolerance tol and relative tolerance rel
 * (GSL's y control: rel = tol is abs = rel, rel = 0 the absolute error alone). */
int sus_lab_peer_open(sus_lab_peer *p, const sus_model *m, const gsl_odeiv2_step_type *type,
                      size_t dim, sus_lab_peer_api api, double tol, double rel, double hstart);
/* The reduced problem along r (which must outlive p), abs tolerance tol and rel tolerance rel. */
int sus_lab_peer_open_reduced(sus_lab_peer *p, const sus_exact_fast *r,
                              const gsl_odeiv2_step_type *type, sus_lab_peer_api api, double tol,
                              double rel, double hstart);
/* From y(0) (sus_lab_peer_initial) to t = T with the step reset to hstart; steps taken (accepted
 * and rejected) in *steps. Returns the GSL status. */
int sus_lab_peer_run(sus_lab_peer *p, const double w0[2], double T, double *y, long *steps);
void sus_lab_peer_close(sus_lab_peer *p);

#ifdef __cplusplus
}
#endif

#endif
