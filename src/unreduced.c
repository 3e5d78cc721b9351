#include "unreduced.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>
#include <stdio.h>

int suslov_unreduced_init(suslov_unreduced *u, const suslov_model *m, char *err, size_t errlen)
{
    const double (*I)[3] = m->I;
    const double d = mat3_det(I);
    u->m = m;
    if (!(fabs(d) > 0.0)) {
        snprintf(err, errlen, "the inertia tensor is singular");
        return -1;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            u->Iinv[i][j] = (I[i1][j1] * I[i2][j2] - I[i1][j2] * I[i2][j1]) / d;
        }
    return 0;
}

void suslov_unreduced_xi(const double R[3][3], const double V[3][3], double xi[3])
{
    double P[3][3];
    mat3_mul_at(P, R, V);
    so3_vee(P, xi);
}

/* (LdAeqs): the vector field of the unreduced equations in the coordinates (R, V). */
static void field(const suslov_unreduced *u, const double R[3][3], const double V[3][3],
                  double dR[3][3], double dV[3][3])
{
    double w[3], Iw[3], rhs[3], wdot[3], W[3][3], Wd[3][3], A[3][3], B[3][3];
    suslov_unreduced_xi(R, V, w);
    mat3_vec(Iw, u->m->I, w);
    vec3_cross(rhs, Iw, w);
    rhs[2] += suslov_lagmult(u->m, w);
    mat3_vec(wdot, u->Iinv, rhs);
    so3_hat(w, W);
    so3_hat(wdot, Wd);
    mat3_mul(A, V, W);
    mat3_mul(B, R, Wd);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            dR[i][j] = V[i][j];
            dV[i][j] = A[i][j] + B[i][j];
        }
}

void suslov_unreduced_rk4(const suslov_unreduced *u, double eps, double R[3][3], double V[3][3])
{
    static const double a[3] = {0.5, 0.5, 1.0}, wt[4] = {1.0, 2.0, 2.0, 1.0};
    double kR[3][3], kV[3][3], Rs[3][3], Vs[3][3], sR[3][3] = {{0}}, sV[3][3] = {{0}};
    mat3_copy(Rs, R);
    mat3_copy(Vs, V);
    for (int s = 0; s < 4; s++) {
        field(u, Rs, Vs, kR, kV);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                sR[i][j] += wt[s] * kR[i][j];
                sV[i][j] += wt[s] * kV[i][j];
                if (s < 3) {
                    Rs[i][j] = R[i][j] + a[s] * eps * kR[i][j];
                    Vs[i][j] = V[i][j] + a[s] * eps * kV[i][j];
                }
            }
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[i][j] += eps / 6.0 * sR[i][j];
            V[i][j] += eps / 6.0 * sV[i][j];
        }
}
