#include "reconstruct.h"

#include "mat3.h"
#include "so3.h"

#include <string.h>

void suslov_attitude_identity(suslov_attitude *a)
{
    mat3_identity(a->hi);
    memset(a->lo, 0, sizeof a->lo);
}

void suslov_attitude_get(const suslov_attitude *a, double R[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = a->hi[i][j] + a->lo[i][j];
}

/* (algo), step 3, with tau = cay as in (caypart). */
void suslov_reconstruct(suslov_recon kind, double eps, suslov_attitude *a, const double w[3],
                        const double w_next[3])
{
    double xi[3], D[3][3], R[3][3], dR[3][3];
    for (int i = 0; i < 3; i++)
        xi[i] = kind == SUSLOV_RECON_CAYLEY ? eps * w[i] : 0.5 * eps * (w[i] + w_next[i]);
    so3_cay_minus_identity(xi, D);
    suslov_attitude_get(a, R);
    mat3_mul(dR, R, D);
    /* Kahan: hi + lo + dR, keeping what the addition to hi rounds away in lo. */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double y = dR[i][j] + a->lo[i][j];
            const double t = a->hi[i][j] + y;
            a->lo[i][j] = y - (t - a->hi[i][j]);
            a->hi[i][j] = t;
        }
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
