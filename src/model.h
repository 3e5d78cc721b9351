/* The reduced Suslov problem of Section 5.2: the differential part (ContDyn), the multiplier
 * (LagMult) and the reduced energy, for an inertia tensor given by rows as printed. Only the
 * block I_m = (I_ij), i,j in {1,2}, and the third row (I31, I32) enter, exactly as in (RGB2). */
#ifndef SUSLOV_MODEL_H
#define SUSLOV_MODEL_H

#include <stddef.h>

typedef struct {
    double I[3][3];  /* the inertia tensor, rows as printed */
    double det_m;    /* |I_m| */
    double b[2];     /* (I31, I32): c(w) = I_3i w_i drives the motion */
} suslov_model;

/* The paper's body: I = [[1,0.1,0.2],[0.1,1,0.2],[0.2,0.1,1]] and w(0) = (0.4, 0.5). */
extern const double SUSLOV_PAPER_INERTIA[9];
extern const double SUSLOV_PAPER_OMEGA0[2];

/* Returns 0, or -1 with a one-line reason in err when an entry is not finite or I_m is not
 * symmetric positive definite. */
int suslov_model_init(suslov_model *m, const double I[9], char *err, size_t errlen);

double suslov_c(const suslov_model *m, const double w[2]);
void suslov_contdyn(const suslov_model *m, const double w[2], double f[2]);
void suslov_contdyn_jacobian(const suslov_model *m, const double w[2], double J[2][2]);
double suslov_lagmult(const suslov_model *m, const double w[2]);
double suslov_lagmult_o0(const suslov_model *m, const double w[2]);
double suslov_energy(const suslov_model *m, const double w[2]);

#endif
