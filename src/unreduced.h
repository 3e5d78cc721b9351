/* An integrator of the unreduced equations (LdAeqs), for Proposition PropoCons1: classical
 * RK4 applied to (R, V) in the 3x3 matrix coordinates of TSO(3), with the Lagrangian
 * L(R, V) = l(vee(R^T V)) of (RedSusLag) and the multiplier of (LagMult):
 *     R' = V,   V' = V w^ + R (w')^,   w = vee(R^T V),   I w' = (I w) x w + lambda(w) e3.
 * It keeps neither R in SO(3) nor the constraint <e3, vee(R^T V)> = 0 exactly: it is the
 * negative control for the preservation measurements. */
#ifndef SUSLOV_UNREDUCED_H
#define SUSLOV_UNREDUCED_H

#include "model.h"

#include <stddef.h>

typedef struct {
    const suslov_model *m;
    double Iinv[3][3];
} suslov_unreduced;

/* Returns 0, or -1 with a reason when the full inertia tensor is singular. */
int suslov_unreduced_init(suslov_unreduced *u, const suslov_model *m, char *err, size_t errlen);
void suslov_unreduced_rk4(const suslov_unreduced *u, double eps, double R[3][3], double V[3][3]);
/* The left-trivialized velocity xi = vee(R^T V) (the reduced variable of PropoCons1). */
void suslov_unreduced_xi(const double R[3][3], const double V[3][3], double xi[3]);

#endif
