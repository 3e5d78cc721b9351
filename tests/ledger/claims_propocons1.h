/* PropoCons1 with integrators that can tell "the reduced order is l" from "it is min(r, l)":
 * Runge-Kutta tables on (LdAeqs) (r = l = 2, 3, 4) and RK4 on the left-trivialized velocity with
 * the first-order Cayley reconstruction (r = 1, l = 4); on the paper's body and the general ones.
 */
#ifndef SUSLOV_CLAIMS_PROPOCONS1_H
#define SUSLOV_CLAIMS_PROPOCONS1_H

void propocons1_claims(void);

#endif
