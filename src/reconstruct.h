/* Discrete reconstruction, step 3 of Algorithm (algo): R_{k+1} = R_k cay(eps w^_k), and the
 * symmetric variant cayley-mid (our extension): R_{k+1} = R_k cay(eps (w^_k + w^_{k+1})/2).
 *
 * The product is accumulated as R_{k+1} = R_k + R_k (cay - I) with R_k carried as an unevaluated
 * sum hi + lo (Kahan's compensated summation). In exact arithmetic this is the same map; in
 * floating point the plain product R_k cay drifts off SO(3) linearly, by ~u/2 per step
 * (1e-10 after 10^6 steps: correlated rounding once the motion is a steady rotation), while
 * the compensated sum stays near 1e-14. The claims ledger measures both. */
#ifndef SUSLOV_RECONSTRUCT_H
#define SUSLOV_RECONSTRUCT_H

typedef enum { SUSLOV_RECON_CAYLEY = 0, SUSLOV_RECON_CAYLEY_MID = 1 } suslov_recon;

typedef struct {
    double hi[3][3], lo[3][3];  /* R = hi + lo */
} suslov_attitude;

void suslov_attitude_identity(suslov_attitude *a);
void suslov_attitude_get(const suslov_attitude *a, double R[3][3]);

/* (algo), step 3: advances a from R_k to R_{k+1}. */
void suslov_reconstruct(suslov_recon kind, double eps, suslov_attitude *a, const double w[3],
                        const double w_next[3]);
int suslov_recon_by_name(const char *name, suslov_recon *kind);

#endif
