/* PropoCons1 with integrators that can tell "the reduced order is l" from "it is min(r, l)":
 * Runge-Kutta tables on (LdAeqs) (r = l = 2, 3, 4) and RK4 on the left-trivialized velocity with
 * the first-order Cayley reconstruction (r = 1, l = 4). */
#ifndef SUSLOV_CLAIMS_PROPOCONS1_H
#define SUSLOV_CLAIMS_PROPOCONS1_H

#include "exact.h"
#include "model.h"

void propocons1_claims(const sus_model *m, const sus_exact *ex);

#endif
