#include "reconstruct.h"

#include "mat3.h"
#include "quaternion.h"
#include "so3.h"

#include <math.h>
#include <string.h>

/* Where an argument is NULL or kind is not a sus_recon, what can be written is NaN
 * (reconstruct.h). */
static void nan_fill(double M[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            M[i][j] = NAN;
}

static int bad_kind(sus_recon kind) { return (int)kind < 0 || (int)kind >= SUS_RECON_COUNT; }

void sus_attitude_identity(sus_attitude *a)
{
    if (!a)
        return;
    sus_mat3_identity(a->hi);
    memset(a->lo, 0, sizeof a->lo);
    a->q[0] = 1.0;
    a->q[1] = a->q[2] = a->q[3] = 0.0;
    a->has_q = 1;
    a->r_stale = 0;
}

void sus_attitude_get(const sus_attitude *a, double R[3][3])
{
    if (!R)
        return;
    if (!a) {
        nan_fill(R);
        return;
    }
    if (a->r_stale) {
        sus_quat_unit_rotation(a->q, R);
        return;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = a->hi[i][j] + a->lo[i][j];
}

void sus_quat_of_attitude(const sus_attitude *a, double q[4])
{
    if (a->has_q) {
        memcpy(q, a->q, sizeof a->q);
        return;
    }
    double R[3][3];
    sus_attitude_get(a, R);
    sus_quat_from_rotation(R, q);
}

/* The matrix is built only when asked for (sus_attitude_get): a method that carries q builds
 * no matrix on the steps whose rows nobody reads. */
void sus_quat_to_attitude(const double q[4], sus_attitude *a)
{
    sus_quat_unit(q, a->q);
    a->has_q = 1;
    a->r_stale = 1;
}

/* The argument xi of tau in (algo), step 3: eps w^k for cayley (first order), the midpoint
 * eps (w^k + w^{k+1}) / 2 for the symmetric reconstructions (second order). */
static void recon_arg(sus_recon kind, double eps, const double w[3], const double w_next[3],
                      double xi[3])
{
    for (int i = 0; i < 3; i++)
        xi[i] = kind == SUS_RECON_CAYLEY ? eps * w[i] : 0.5 * eps * (w[i] + w_next[i]);
}

/* (algo), step 3, with tau = cay as in (caypart), or tau = exp (Rodrigues) for exp-mid. */
void sus_reconstruct(sus_recon kind, double eps, sus_attitude *a, const double w[3],
                     const double w_next[3])
{
    double xi[3], D[3][3];
    if (!a)
        return;
    if (!w || !w_next || bad_kind(kind)) {
        nan_fill(D);
        sus_attitude_increment(a, D);
        return;
    }
    recon_arg(kind, eps, w, w_next, xi);
    if (kind == SUS_RECON_EXP_MID)
        sus_so3_exp_minus_identity(xi, D);
    else
        sus_so3_cay_minus_identity(xi, D);
    sus_attitude_increment(a, D);
}

/* (algo), step 3, on a quaternion of R_k (reconstruct.h). */
void sus_reconstruct_quat(sus_recon kind, double eps, double q[4], const double w[3],
                          const double w_next[3])
{
    double xi[3], dq[4], p[4];
    if (!q)
        return;
    if (!w || !w_next || bad_kind(kind)) {
        q[0] = q[1] = q[2] = q[3] = NAN;
        return;
    }
    recon_arg(kind, eps, w, w_next, xi);
    if (kind == SUS_RECON_EXP_MID) {
        const double th = sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
        double half_sin;
        sus_so3_sincos(0.5 * th, &half_sin, &dq[0]); /* so3_trig.c: the same bits in every build */
        const double s = th > 0.0 ? half_sin / th : 0.5; /* sin(th/2)/th */
        for (int i = 0; i < 3; i++)
            dq[1 + i] = s * xi[i];
    } else {
        dq[0] = 1.0;
        for (int i = 0; i < 3; i++)
            dq[1 + i] = 0.5 * xi[i];
        const double n = 1.0 / sqrt(1.0 + dq[1] * dq[1] + dq[2] * dq[2] + dq[3] * dq[3]);
        for (int i = 0; i < 4; i++)
            dq[i] *= n;
    }
    sus_quat_mul(p, q, dq);
    for (int i = 0; i < 4; i++)
        q[i] = p[i];
}

void sus_attitude_increment(sus_attitude *a, const double D[3][3])
{
    double R[3][3], dR[3][3];
    static const double NAN_D[3][3] = {{NAN, NAN, NAN}, {NAN, NAN, NAN}, {NAN, NAN, NAN}};
    if (!a)
        return;
    if (!D)
        D = NAN_D;
    sus_attitude_get(a, R);
    if (a->r_stale) { /* the matrix from here on */
        memcpy(a->hi, R, sizeof R);
        memset(a->lo, 0, sizeof a->lo);
        a->r_stale = 0;
    }
    a->has_q = 0;
    sus_mat3_mul(dR, R, D);
    /* Kahan: hi + lo + dR, keeping what the addition to hi rounds away in lo. */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double y = dR[i][j] + a->lo[i][j];
            const double t = a->hi[i][j] + y;
            a->lo[i][j] = y - (t - a->hi[i][j]);
            a->hi[i][j] = t;
        }
}

const char *const SUS_RECON_NAMES[SUS_RECON_COUNT] = {"cayley", "cayley-mid", "exp-mid"};
const char *const SUS_RECON_ABOUT[SUS_RECON_COUNT] = {
    "R_{k+1} = R_k cay(H w_k^), (algo)",
    "R_{k+1} = R_k cay(H (w_k^ + w_{k+1}^)/2) (extension)",
    "R_{k+1} = R_k exp(H (w_k^ + w_{k+1}^)/2), Rodrigues (extension)",
};

int sus_recon_by_name(const char *name, sus_recon *kind)
{
    if (!name || !kind)
        return -1;
    for (int k = 0; k < SUS_RECON_COUNT; k++)
        if (strcmp(name, SUS_RECON_NAMES[k]) == 0) {
            *kind = (sus_recon)k;
            return 0;
        }
    return -1;
}
