/* The bodies the multi-body lines are measured on: the paper's, the seeded general family and
 * the stiff ones (tests/unit/bodies.h), each with its exact solution and the local-error
 * references of one grid scaled by the body's time 1/k: eps k = 1.16 * 2^(-j/4), j = 0 ..
 * CLAIMS_NE - 1 (13 octaves; for the paper's body eps = 8 down to 2^-10), from CLAIMS_NTK starts
 * spread over the transient, t_k k = 0, 0.45, 1, 1.75, 2.9; and the sizes and round-off floors of
 * the quantities measured there. Built once, on first use; shared by the claims files so that
 * every body is sampled alike and runs in its own time. */
#ifndef SUSLOV_CLAIMS_BODIES_H
#define SUSLOV_CLAIMS_BODIES_H

#include "bodies.h"
#include "consistency.h"
#include "exact.h"
#include "model.h"

#define CLAIMS_NE 53
#define CLAIMS_NTK 5

/* The quantities of a local order fit: w, lambda, and the attitude R on SO(3). */
enum { CLAIMS_Q_W, CLAIMS_Q_LAMBDA, CLAIMS_Q_R };

typedef struct {
    body b;
    sus_model m;
    sus_exact ex;                                 /* refers to m: never copied */
    sus_lab_local_ref ref[CLAIMS_NE][CLAIMS_NTK]; /* ref[j][t]: eps[j] from start t */
    double eps[CLAIMS_NE];
    double size_w, size_lambda; /* |w| and |lambda| along the motion */
} claims_body;

/* Body k of BODIES_COUNT, the paper's first. */
const claims_body *claims_body_get(int k);

/* 1/2 sum_ij |w_i I_ij w_j| (i, j <= 2): the size of E(w)'s terms, at which its evaluation
 * rounds. E itself where no term cancels; up to cond(I_m) E on a near-singular I_m. */
double claims_energy_terms(const sus_model *m, const double w[2]);

/* How a method rounds w (claims_bodies.c): an implicit step solves an equation in I_m's
 * coordinates; a projecting one scales w onto E0 (an explicit step that conserves E can only do
 * so by projecting). */
typedef struct {
    int implicit, projects;
    int substeps; /* base steps per step, each rounding its own terms */
} claims_rounding;

/* The size of quantity q on body d (an error as large is no expansion in eps), and the round-off
 * floor of its local error at each eps[j] for a method that rounds as k says, from the size of
 * the terms its evaluation rounds (claims_bodies.c). */
double claims_body_size(const claims_body *d, int q);
void claims_body_floors(const claims_body *d, const claims_rounding *k, int q,
                        double floor[CLAIMS_NE]);

#endif
