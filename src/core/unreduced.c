#include "unreduced.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>
#include <stdio.h>

int sus_unreduced_init(sus_unreduced *u, const sus_model *m, char *err, size_t errlen)
{
    u->m = m;
    if (sus_mat3_inverse(m->I, u->Iinv) != 0) {
        snprintf(err, errlen, "the inertia tensor is singular");
        return -1;
    }
    return 0;
}

void sus_unreduced_xi(const double R[3][3], const double V[3][3], double xi[3])
{
    double P[3][3];
    sus_mat3_mul_at(P, R, V);
    sus_so3_vee(P, xi);
}

/* (LdAeqs) left-trivialized: I xi' = (I xi) x xi + lambda(xi) e3, the velocity part of field(). */
static void xi_field(const sus_unreduced *u, const double xi[3], double d[3])
{
    double Iw[3], rhs[3];
    sus_mat3_vec(Iw, u->m->I, xi);
    sus_vec3_cross(rhs, Iw, xi);
    rhs[2] += sus_lagmult(u->m, xi);
    sus_mat3_vec(d, u->Iinv, rhs);
}

/* (LdAeqs): the vector field of the unreduced equations in the coordinates (R, V). */
static void field(const sus_unreduced *u, const double R[3][3], const double V[3][3],
                  double dR[3][3], double dV[3][3])
{
    double w[3], wdot[3], W[3][3], Wd[3][3], A[3][3], B[3][3];
    sus_unreduced_xi(R, V, w);
    xi_field(u, w, wdot);
    sus_so3_hat(w, W);
    sus_so3_hat(wdot, Wd);
    sus_mat3_mul(A, V, W);
    sus_mat3_mul(B, R, Wd);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            dR[i][j] = V[i][j];
            dV[i][j] = A[i][j] + B[i][j];
        }
}

/* The tables (Hairer, Norsett, Wanner, Solving ODEs I, Sect. II.1). */
const sus_butcher SUS_BUTCHER_RK4 = {
    "rk4",           4, 4, {{0}, {0.5}, {0, 0.5}, {0, 0, 1}}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
    {0, 0.5, 0.5, 1}};
const sus_butcher SUS_BUTCHER_KUTTA3 = {
    "kutta3", 3, 3, {{0}, {0.5}, {-1, 2}}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {0, 0.5, 1}};
const sus_butcher SUS_BUTCHER_HEUN2 = {"heun2", 2, 2, {{0}, {1}}, {0.5, 0.5}, {0, 1}};

/* (LdAeqs) stepped by an explicit Runge-Kutta table on (R, V). */
void sus_unreduced_rk(const sus_unreduced *u, const sus_butcher *tab, double eps, double R[3][3],
                      double V[3][3])
{
    double kR[4][3][3], kV[4][3][3], Rs[3][3], Vs[3][3];
    for (int s = 0; s < tab->stages; s++) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double dr = 0.0, dv = 0.0;
                for (int q = 0; q < s; q++) {
                    dr += tab->a[s][q] * kR[q][i][j];
                    dv += tab->a[s][q] * kV[q][i][j];
                }
                Rs[i][j] = R[i][j] + eps * dr;
                Vs[i][j] = V[i][j] + eps * dv;
            }
        field(u, Rs, Vs, kR[s], kV[s]);
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double dr = 0.0, dv = 0.0;
            for (int s = 0; s < tab->stages; s++) {
                dr += tab->b[s] * kR[s][i][j];
                dv += tab->b[s] * kV[s][i][j];
            }
            R[i][j] += eps * dr;
            V[i][j] += eps * dv;
        }
}

void sus_unreduced_rk4(const sus_unreduced *u, double eps, double R[3][3], double V[3][3])
{
    sus_unreduced_rk(u, &SUS_BUTCHER_RK4, eps, R, V);
}

/* (LdAeqs) with the table on xi and the first-order reconstruction R_{k+1} = R_k cay(eps xi_k^). */
void sus_unreduced_rk_cayley(const sus_unreduced *u, const sus_butcher *tab, double eps,
                             double R[3][3], double V[3][3])
{
    double xi[3], k[4][3], C[3][3], Rn[3][3], X[3][3];
    sus_unreduced_xi(R, V, xi);
    for (int s = 0; s < tab->stages; s++) {
        double y[3];
        for (int i = 0; i < 3; i++) {
            double d = 0.0;
            for (int q = 0; q < s; q++)
                d += tab->a[s][q] * k[q][i];
            y[i] = xi[i] + eps * d;
        }
        xi_field(u, y, k[s]);
    }
    const double e[3] = {eps * xi[0], eps * xi[1], eps * xi[2]};
    sus_so3_cay(e, C);
    sus_mat3_mul(Rn, R, C);
    for (int i = 0; i < 3; i++) {
        double d = 0.0;
        for (int s = 0; s < tab->stages; s++)
            d += tab->b[s] * k[s][i];
        xi[i] += eps * d;
    }
    sus_so3_hat(xi, X);
    sus_mat3_copy(R, Rn);
    sus_mat3_mul(V, Rn, X);
}

/* (LdAeqs) stepped by the table on (R, V) in 3x3 coordinates (the velocity stages read R through
 * w = vee(R^T V)); the new velocity is its left-trivialization xi_{k+1} = vee(R~^T V~) of that
 * step, the attitude the first-order R_{k+1} = R_k cay(eps xi_k^), V_{k+1} = R_{k+1} xi_{k+1}^. */
void sus_unreduced_rk_recayley(const sus_unreduced *u, const sus_butcher *tab, double eps,
                               double R[3][3], double V[3][3])
{
    double xi0[3], xi[3], Rt[3][3], Vt[3][3], C[3][3], Rn[3][3], X[3][3];
    sus_unreduced_xi(R, V, xi0);
    sus_mat3_copy(Rt, R);
    sus_mat3_copy(Vt, V);
    sus_unreduced_rk(u, tab, eps, Rt, Vt);
    sus_unreduced_xi(Rt, Vt, xi);
    const double e[3] = {eps * xi0[0], eps * xi0[1], eps * xi0[2]};
    sus_so3_cay(e, C);
    sus_mat3_mul(Rn, R, C);
    sus_so3_hat(xi, X);
    sus_mat3_copy(R, Rn);
    sus_mat3_mul(V, Rn, X);
}
