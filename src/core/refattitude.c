#include "refattitude.h"

#include "quaternion.h"

#include <math.h>

/* One Taylor step of order P in long double: the Cauchy-product recursions of (ContDyn)
 * (w' = c(w) fA w) and of q' = 1/2 q (x) (0, w), with scaled coefficients (W_n = w_n h^n). */
static void precise_step(const sus_model *m, long double h, long double w[2], long double q[4])
{
    enum { P = SUS_REFATT_PRECISE_ORDER };
    long double W[P + 1][2], Q[P + 1][4], C[P + 1], U[P + 1][2];
    const long double b0 = m->b[0], b1 = m->b[1];
    /* fA in long double from the printed inertia (the double values the model holds) */
    const double (*I)[3] = m->I;
    const long double det = (long double)I[0][0] * I[1][1] - (long double)I[0][1] * I[1][0];
    const long double A00 = -(long double)I[0][1] / det, A01 = -(long double)I[1][1] / det;
    const long double A10 = (long double)I[0][0] / det, A11 = (long double)I[1][0] / det;
    W[0][0] = w[0];
    W[0][1] = w[1];
    for (int i = 0; i < 4; i++)
        Q[0][i] = q[i];
    for (int n = 0; n < P; n++) {
        C[n] = b0 * W[n][0] + b1 * W[n][1];
        U[n][0] = A00 * W[n][0] + A01 * W[n][1];
        U[n][1] = A10 * W[n][0] + A11 * W[n][1];
        long double s0 = 0, s1 = 0, t[4] = {0, 0, 0, 0};
        for (int j = 0; j <= n; j++) {
            s0 += C[j] * U[n - j][0];
            s1 += C[j] * U[n - j][1];
            const long double *qj = Q[j], x = W[n - j][0], y = W[n - j][1];
            /* q (x) (0, x, y, 0) */
            t[0] -= qj[1] * x + qj[2] * y;
            t[1] += qj[0] * x - qj[3] * y;
            t[2] += qj[0] * y + qj[3] * x;
            t[3] += qj[1] * y - qj[2] * x;
        }
        const long double f = h / (n + 1);
        W[n + 1][0] = f * s0;
        W[n + 1][1] = f * s1;
        for (int i = 0; i < 4; i++)
            Q[n + 1][i] = 0.5L * f * t[i];
    }
    for (int n = P; n >= 1; n--) {
        w[0] += W[n][0];
        w[1] += W[n][1];
        for (int i = 0; i < 4; i++)
            q[i] += Q[n][i];
    }
}

/* R(q) for q not of unit length: ((s^2 - |v|^2) I + 2 v v^T + 2 s v^) / |q|^2, rounded once. */
static void rotation_of(const long double q[4], double R[3][3])
{
    const long double nq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const long double s = q[0], x = q[1], y = q[2], z = q[3];
    const long double Rl[3][3] = {{s * s + x * x - y * y - z * z, 2 * (x * y - s * z), 2 * (x * z + s * y)},
                                  {2 * (x * y + s * z), s * s - x * x + y * y - z * z, 2 * (y * z - s * x)},
                                  {2 * (x * z - s * y), 2 * (y * z + s * x), s * s - x * x - y * y + z * z}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = (double)(Rl[i][j] / nq);
}

/* From t to t1 in equal steps of at most 1/SUSLOV_REFATT_PRECISE_STEPS. A stretch of 2^62 steps or
 * more (or an infinite one) cannot be run in any useful time, and its step count would not convert
 * to an integer (undefined behaviour): it gives no answer, a non-finite attitude. Callers check
 * the cost first (sus_exact_reference_steps). */
static void integrate(const sus_model *m, long double w[2], long double q[4], double t, double t1)
{
    const double steps = ceil((t1 - t) * SUS_REFATT_PRECISE_STEPS);
    if (!(steps < 0x1p62)) {
        q[0] = q[1] = q[2] = q[3] = NAN;
        return;
    }
    const long n = (long)steps;
    if (n <= 0)
        return;
    const long double h = ((long double)t1 - t) / n;
    for (long k = 0; k < n; k++)
        precise_step(m, h, w, q);
}

void sus_refatt_init(sus_refatt *ra, const sus_exact *ex, double t0, const double R0[3][3])
{
    double w[2], q[4];
    ra->ex = ex;
    ra->t = t0;
    ra->t0 = t0;
    ra->grid = 0.0;
    sus_exact_omega(ex, t0, w); /* w0 itself at t0 = 0 (an ulp off would be 3e-15 in R(50)) */
    sus_quat_from_rotation(R0, q);
    for (int i = 0; i < 4; i++)
        ra->q[i] = q[i];
    ra->w[0] = w[0];
    ra->w[1] = w[1];
}

void sus_refatt_advance(sus_refatt *ra, double t1, double R[3][3])
{
    if (t1 > ra->t) {
        integrate(ra->ex->model, ra->w, ra->q, ra->t, t1);
        ra->t = t1;
    }
    rotation_of(ra->q, R);
}

void sus_refatt_at(sus_refatt *ra, double t1, double R[3][3])
{
    const long double h = 1.0L / SUS_REFATT_PRECISE_STEPS, span = (long double)t1 - ra->t0;
    const double whole = floorl(span * SUS_REFATT_PRECISE_STEPS);
    if (!(whole < 0x1p62)) { /* as integrate: no useful time, no answer */
        const long double q[4] = {NAN, NAN, NAN, NAN};
        rotation_of(q, R);
        return;
    }
    for (; ra->grid < whole; ra->grid++)
        precise_step(ra->ex->model, h, ra->w, ra->q);
    long double w[2] = {ra->w[0], ra->w[1]}, q[4] = {ra->q[0], ra->q[1], ra->q[2], ra->q[3]};
    const long double rest = span - ra->grid * h;
    if (rest > 0.0L)
        precise_step(ra->ex->model, rest, w, q);
    rotation_of(q, R);
}

void sus_refatt_precise(const sus_model *m, const double w0[2], double T, double w[2], double R[3][3])
{
    long double wl[2] = {w0[0], w0[1]}, q[4] = {1, 0, 0, 0};
    integrate(m, wl, q, 0.0, T);
    rotation_of(q, R);
    w[0] = (double)wl[0];
    w[1] = (double)wl[1];
}

void sus_refatt_increment(const sus_exact *ex, double t0, double t1, double Phi[3][3])
{
    sus_refatt ra;
    double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_refatt_init(&ra, ex, t0, I3);
    sus_refatt_advance(&ra, t1, Phi);
}
