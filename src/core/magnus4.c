#include "magnus4.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>

/* exact.h's closed form in long double: Cholesky coordinates u = L^T w, psi' = k cos psi. */
typedef struct {
    long double l11, l21, l22, r, cb, sb, k, sigma, s0;
} exact_l;

static void exact_l_init(exact_l *e, const sus_model *m, const double w0[2])
{
    const double(*I)[3] = m->I;
    e->l11 = sqrtl(I[0][0]);
    e->l21 = I[1][0] / e->l11;
    e->l22 = sqrtl(I[1][1] - e->l21 * e->l21);
    const long double u1 = e->l11 * w0[0] + e->l21 * w0[1], u2 = e->l22 * w0[1];
    const long double v1 = m->b[0] / e->l11, v2 = (m->b[1] - e->l21 * v1) / e->l22;
    const long double vn = hypotl(v1, v2);
    e->r = hypotl(u1, u2);
    e->cb = v1 / vn;
    e->sb = v2 / vn;
    const long double C = (e->cb * u1 + e->sb * u2) / e->r, S = (e->cb * u2 - e->sb * u1) / e->r;
    e->k = e->r * vn / (e->l11 * e->l22);
    e->sigma = C > 0 ? 1 : -1;
    e->s0 = asinhl(S / C);
}

static void exact_l_omega(const exact_l *e, long double t, long double w[3])
{
    const long double s = e->s0 + e->sigma * e->k * t, x = expl(-fabsl(s));
    const long double cp = e->sigma * 2 * x / (1 + x * x), sp = e->sigma * tanhl(s);
    const long double u1 = e->r * (e->cb * cp - e->sb * sp), u2 = e->r * (e->sb * cp + e->cb * sp);
    w[1] = u2 / e->l22;
    w[0] = (u1 - e->l21 * w[1]) / e->l11;
    w[2] = 0;
}

/* R <- R Phi(t0, t1) by n steps of the scheme, all in long double. */
static void magnus4_l(const exact_l *e, long double t0, long double t1, long n, long double R[3][3])
{
    const long double h = (t1 - t0) / n, r3 = sqrtl(3.0L);
    const long double c1 = 0.5L - r3 / 6, c2 = 0.5L + r3 / 6, k2 = r3 / 12 * h * h;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = i == j;
    for (long s = 0; s < n; s++) {
        const long double t = t0 + s * h;
        long double a1[3], a2[3], om[3], Rn[3][3], E[3][3];
        exact_l_omega(e, t + c1 * h, a1);
        exact_l_omega(e, t + c2 * h, a2);
        /* Omega = h/2 (A1 + A2) + sqrt(3)/12 h^2 [A1, A2], [a^, b^] = (a x b)^ */
        om[0] = 0.5L * h * (a1[0] + a2[0]) + k2 * (a1[1] * a2[2] - a1[2] * a2[1]);
        om[1] = 0.5L * h * (a1[1] + a2[1]) + k2 * (a1[2] * a2[0] - a1[0] * a2[2]);
        om[2] = 0.5L * h * (a1[2] + a2[2]) + k2 * (a1[0] * a2[1] - a1[1] * a2[0]);
        /* Rodrigues in long double, half-angle form (no cancellation) */
        const long double th = sqrtl(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]);
        const long double a = th > 0 ? sinl(th) / th : 1, hs = th > 0 ? sinl(th / 2) / (th / 2) : 1,
                          b = hs * hs / 2;
        const long double W[3][3] = {{0, -om[2], om[1]}, {om[2], 0, -om[0]}, {-om[1], om[0], 0}};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                long double w2 = 0;
                for (int l = 0; l < 3; l++)
                    w2 += W[i][l] * W[l][j];
                E[i][j] = (i == j) + a * W[i][j] + b * w2;
            }
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Rn[i][j] = R[i][0] * E[0][j] + R[i][1] * E[1][j] + R[i][2] * E[2][j];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                R[i][j] = Rn[i][j];
    }
}

/* R <- R Phi(t0, t1): the long-double scheme from t0 with n and 2n steps, extrapolated
 * (16 Phi_2n - Phi_n) / 15 (the error of the fourth-order Magnus scheme is even in h). */
void sus_magnus4(const sus_exact *ex, double t0, double t1, long n, double R[3][3])
{
    exact_l e;
    long double A[3][3], B[3][3];
    exact_l_init(&e, ex->model, ex->w0);
    magnus4_l(&e, t0, t1, n, A);
    magnus4_l(&e, t0, t1, 2 * n, B);
    double Phi[3][3], Rn[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Phi[i][j] = (double)((16 * B[i][j] - A[i][j]) / 15);
    sus_mat3_mul(Rn, R, Phi);
    sus_mat3_copy(R, Rn);
}
