/* The bodies the local order lines are measured on: the paper's and the seeded general family
 * (tests/unit/bodies.h), each with its exact solution and the local-error references of one grid
 * scaled by the body's time 1/k: eps k = 1.16 * 2^(-j/4), j = 0 .. CLAIMS_NE - 1 (13 octaves; for
 * the paper's body eps = 8 down to 2^-10), from CLAIMS_NTK starts spread over the transient,
 * t_k k = 0, 0.45, 1, 1.75, 2.9. Built once, on first use; shared by claims_methods.c and
 * claims_propocons1.c so that every body is sampled alike. */
#ifndef SUSLOV_CLAIMS_BODIES_H
#define SUSLOV_CLAIMS_BODIES_H

#include "bodies.h"
#include "consistency.h"
#include "exact.h"
#include "model.h"

#define CLAIMS_NE 53
#define CLAIMS_NTK 5

typedef struct {
    body b;
    sus_model m;
    sus_exact ex;                                 /* refers to m: never copied */
    sus_exp_local_ref ref[CLAIMS_NE][CLAIMS_NTK]; /* ref[j][t]: eps[j] from start t */
    double eps[CLAIMS_NE];
    double size_w, size_lambda;                   /* |w| and |lambda| along the motion */
} claims_body;

/* Body k of BODIES_COUNT, the paper's first. */
const claims_body *claims_body_get(int k);

#endif
