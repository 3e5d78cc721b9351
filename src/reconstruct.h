/* Discrete reconstruction, step 3 of Algorithm (algo): R_{k+1} = R_k cay(eps w^_k), and the
 * symmetric variant cayley-mid (our extension): R_{k+1} = R_k cay(eps (w^_k + w^_{k+1})/2). */
#ifndef SUSLOV_RECONSTRUCT_H
#define SUSLOV_RECONSTRUCT_H

typedef enum { SUSLOV_RECON_CAYLEY = 0, SUSLOV_RECON_CAYLEY_MID = 1 } suslov_recon;

void suslov_reconstruct(suslov_recon kind, double eps, const double R[3][3], const double w[3],
                        const double w_next[3], double R_next[3][3]);
int suslov_recon_by_name(const char *name, suslov_recon *kind);
const char *suslov_recon_name(suslov_recon kind);

#endif
