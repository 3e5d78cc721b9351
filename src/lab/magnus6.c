#include "magnus6.h"

#include "mat3.h"
#include "quaternion.h"

#include <string.h>

/* The Gauss nodes 1/2 -+ sqrt(15)/10 and the weights of the alphas (Blanes, Casas & Ros). */
#define NODE_OFF 0.3872983346207417 /* sqrt(15) / 10 */
#define SQRT15_3 1.2909944487358056 /* sqrt(15) / 3 */

/* The Magnus vector of one step of Y' = A(t) Y, from the nodes' A1, A2, A3 as 3-vectors (on so(3)
 * the bracket [a^, b^] is (a x b)^):
 *   a1 = h A2, a2 = sqrt15 h / 3 (A3 - A1), a3 = 10 h / 3 (A3 - 2 A2 + A1),
 *   C1 = [a1, a2], C2 = -[a1, 2 a3 + C1] / 60,
 *   Omega = a1 + a3 / 12 + [-20 a1 - a3 + C1, a2 + C2] / 240. */
static void omega_left(double h, const double A[3][3], double O[3])
{
    double a1[3], a2[3], a3[3], C1[3], C2[3], x[3], y[3];
    for (int i = 0; i < 3; i++) {
        a1[i] = h * A[1][i];
        a2[i] = SQRT15_3 * h * (A[2][i] - A[0][i]);
        a3[i] = (10.0 / 3.0) * h * (A[2][i] - 2.0 * A[1][i] + A[0][i]);
    }
    sus_vec3_cross(C1, a1, a2);
    for (int i = 0; i < 3; i++)
        x[i] = 2.0 * a3[i] + C1[i];
    sus_vec3_cross(C2, a1, x);
    for (int i = 0; i < 3; i++) {
        x[i] = -20.0 * a1[i] - a3[i] + C1[i];
        y[i] = a2[i] - C2[i] * (1.0 / 60.0);
    }
    sus_vec3_cross(C2, x, y);
    for (int i = 0; i < 3; i++)
        O[i] = a1[i] + a3[i] * (1.0 / 12.0) + C2[i] * (1.0 / 240.0);
}

/* w at the nodes of successive steps, with E = e^{-|s|} advanced by a constant factor (exact_fast.h
 * evaluates w from E): along node j, s moves by ks h a step, so while s keeps its sign E is
 * multiplied by e^{-ks h} or e^{ks h}. E is taken afresh from exp every ANCHOR steps and where s
 * changes sign, so that the products' roundings (one each) stay below ANCHOR u relative: far below
 * any accuracy a bench level asks for. The prototype's cheap w; the library's one exp is dearer. */
#define ANCHOR 64

typedef struct {
    const sus_exact_fast *w;
    double h, up, down; /* up = e^{|ks| h}, down = e^{-|ks| h} */
    double E[3];
} nodes;

static double node_s(const nodes *nd, long k, int j)
{
    static const double c[3] = {0.5 - NODE_OFF, 0.5, 0.5 + NODE_OFF};
    return nd->w->s0 + nd->w->ks * (((double)k + c[j]) * nd->h);
}

/* The nodes' A = -w (the left-multiplying form, below) at step k. */
static void nodes_at(nodes *nd, long k, double A[3][3])
{
    for (int j = 0; j < 3; j++) {
        const double s = node_s(nd, k, j);
        if (k % ANCHOR == 0 || (s > 0.0) != (node_s(nd, k - 1, j) > 0.0))
            nd->E[j] = exp(-fabs(s));
        else /* |s| grows by |ks| h where s has the sign of ks, else shrinks */
            nd->E[j] *= (s > 0.0) == (nd->w->ks > 0.0) ? nd->down : nd->up;
        const double e2 = nd->E[j] * nd->E[j], d = 1.0 / (1.0 + e2);
        const double st[2] = {2.0 * nd->E[j] * d, copysign((1.0 - e2) * d, s)};
        sus_exact_fast_map(nd->w, st, A[j]);
        A[j][0] = -A[j][0];
        A[j][1] = -A[j][1];
        A[j][2] = 0.0;
    }
}

/* One step: R' = R w^ multiplies on the right, so R^T solves Y' = -w^ Y and the step is
 * exp(-Omega(-w)); as a quaternion, q <- q (x) (cos |O|/2, sin(|O|/2) O/|O|), O = -Omega(-w). */
static void step(nodes *nd, long k, double q[4])
{
    double A[3][3], O[3], p[4];
    nodes_at(nd, k, A);
    omega_left(nd->h, A, O);
    const double n = sus_vec3_norm(O);
    const double f = n > 0.0 ? -sin(0.5 * n) / n : -0.5;
    const double dq[4] = {cos(0.5 * n), f * O[0], f * O[1], f * O[2]};
    sus_quat_mul(p, q, dq);
    memcpy(q, p, sizeof p);
}

void sus_lab_magnus6(const sus_exact_fast *w, double T, long N, double q[4])
{
    const double h = T / (double)N;
    nodes nd = {w, h, exp(fabs(w->ks) * h), exp(-fabs(w->ks) * h), {0.0, 0.0, 0.0}};
    q[0] = 1.0;
    q[1] = q[2] = q[3] = 0.0;
    for (long k = 0; k < N; k++)
        step(&nd, k, q);
}
