/* Integrators of the unreduced equations (LdAeqs), for Proposition PropoCons1: an explicit
 * Runge-Kutta method given by its Butcher table (classical RK4, Kutta's third-order, Heun's
 * second-order) applied to (R, V) in the 3x3 matrix coordinates of TSO(3), with the Lagrangian
 * L(R, V) = l(vee(R^T V)) of (RedSusLag) and the multiplier of (LagMult):
 *     R' = V,   V' = V w^ + R (w')^,   w = vee(R^T V),   I w' = (I w) x w + lambda(w) e3.
 * It keeps neither R in SO(3) nor the constraint <e3, vee(R^T V)> = 0 exactly: it is the
 * negative control for the preservation measurements. */
#ifndef SUS_UNREDUCED_H
#define SUS_UNREDUCED_H

#include "model.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const sus_model *m;
    double Iinv[3][3];
} sus_unreduced;

/* Returns 0, or -1 with a reason when the full inertia tensor is singular. */
int sus_unreduced_init(sus_unreduced *u, const sus_model *m, char *err, size_t errlen);
/* An explicit Runge-Kutta method: a[i][j] (j < i), weights b, nodes c. */
typedef struct {
    const char *name;
    int stages, order;
    double a[4][4], b[4], c[4];
} sus_butcher;

extern const sus_butcher SUS_BUTCHER_RK4, SUS_BUTCHER_KUTTA3, SUS_BUTCHER_HEUN2;

/* One step of the table on (R, V): r = l = the table's order (Definition UnredConsis). */
void sus_unreduced_rk(const sus_unreduced *u, const sus_butcher *tab, double eps, double R[3][3],
                      double V[3][3]);
void sus_unreduced_rk4(const sus_unreduced *u, double eps, double R[3][3], double V[3][3]);
/* An integrator with r != l: the table on the left-trivialized velocity xi = vee(R^T V) of
 * (LdAeqs), I xi' = (I xi) x xi + lambda(xi) e3 (l = the table's order), with the first-order
 * reconstruction R_{k+1} = R_k cay(eps xi_k^) (r = 1, TeoL), and V_{k+1} = R_{k+1} xi_{k+1}^. */
void sus_unreduced_rk_cayley(const sus_unreduced *u, const sus_butcher *tab, double eps,
                             double R[3][3], double V[3][3]);
/* r = 1, l = the table's order, with the velocity from (R, V): the table on (R, V) as
 * sus_unreduced_rk (its velocity stages read R), xi_{k+1} = vee(R~^T V~) of that step, then
 * R_{k+1} = R_k cay(eps xi_k^) and V_{k+1} = R_{k+1} xi_{k+1}^. */
void sus_unreduced_rk_recayley(const sus_unreduced *u, const sus_butcher *tab, double eps,
                               double R[3][3], double V[3][3]);
/* The left-trivialized velocity xi = vee(R^T V) (the reduced variable of PropoCons1). */
void sus_unreduced_xi(const double R[3][3], const double V[3][3], double xi[3]);

#ifdef __cplusplus
}
#endif

#endif
