#include "reconstruct.h"

#include "mat3.h"
#include "so3.h"

#include <string.h>

/* (algo), step 3, with tau = cay as in (caypart). */
void suslov_reconstruct(suslov_recon kind, double eps, const double R[3][3], const double w[3],
                        const double w_next[3], double R_next[3][3])
{
    double xi[3], C[3][3];
    for (int i = 0; i < 3; i++)
        xi[i] = kind == SUSLOV_RECON_CAYLEY ? eps * w[i] : 0.5 * eps * (w[i] + w_next[i]);
    so3_cay(xi, C);
    mat3_mul(R_next, R, C);
}

int suslov_recon_by_name(const char *name, suslov_recon *kind)
{
    if (strcmp(name, "cayley") == 0)
        *kind = SUSLOV_RECON_CAYLEY;
    else if (strcmp(name, "cayley-mid") == 0)
        *kind = SUSLOV_RECON_CAYLEY_MID;
    else
        return -1;
    return 0;
}

const char *suslov_recon_name(suslov_recon kind)
{
    return kind == SUSLOV_RECON_CAYLEY ? "cayley" : "cayley-mid";
}
