/* Reference attitude: R' = R w^(t) along the closed-form w(t), integrated with GSL's
 * adaptive rk8pd. Its own error is checked against an independent Magnus integrator
 * (magnus4.h) in the tests and in the claims ledger. */
#ifndef SUSLOV_REFATTITUDE_H
#define SUSLOV_REFATTITUDE_H

#include "exact.h"

#include <gsl/gsl_odeiv2.h>

/* Tolerance used wherever the reference attitude measures an integrator (abs and rel). */
#define SUSLOV_REFATT_TOL 1e-13

typedef struct {
    const suslov_exact *ex;
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *drv;
    double t;
    double y[9];
} suslov_refatt;

/* Returns 0, or -1 if GSL could not allocate the driver. */
int suslov_refatt_init(suslov_refatt *ra, const suslov_exact *ex, double t0, const double R0[3][3],
                       double tol);
/* Advances to t1 >= the current time and copies R(t1). Returns a GSL status (0 = success). */
int suslov_refatt_advance(suslov_refatt *ra, double t1, double R[3][3]);
void suslov_refatt_free(suslov_refatt *ra);

/* R(t0)^{-1} R(t1): the exact increment over one step, from the identity. */
int suslov_refatt_increment(const suslov_exact *ex, double t0, double t1, double Phi[3][3]);

#endif
