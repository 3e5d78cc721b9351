/* The library integrators' view of the problem (make bench, figures/longrun): (ContDyn) with the
 * attitude either as R, R' = R w^ (y = (w1, w2, R row-major), 11 unknowns), or as a quaternion,
 * q' = 1/2 q (x) (0, w) (y = (w1, w2, q), 6 unknowns), as GSL odeiv2 right-hand sides. */
#ifndef SUSLOV_PEERS_H
#define SUSLOV_PEERS_H

#include "model.h"

#include <stddef.h>

/* GSL odeiv2 right-hand sides; params is the suslov_model. */
int suslov_peer_rhs_wR(double t, const double y[], double f[], void *params);
int suslov_peer_rhs_wq(double t, const double y[], double f[], void *params);
int suslov_peer_rhs_w(double t, const double y[], double f[], void *params);
/* y(0) for dim 11, 6 or 2: w0, then R = I or q = (1, 0, 0, 0). */
void suslov_peer_initial(size_t dim, const double w0[2], double *y);
/* R of the state: the 3x3 block, or R(q/|q|). */
void suslov_peer_attitude(size_t dim, const double *y, double R[3][3]);

#endif
