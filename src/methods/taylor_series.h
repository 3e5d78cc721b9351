/* The Taylor recursion of (ContDyn) and of the attitude quaternion, shared by the fixed-step
 * Taylor methods (step_taylor.c) and the tolerance-driven one (step_taylor_adaptive.c), and the
 * quaternion's alone (q_row) by exact-attitude, whose w rows come from the closed form; the
 * equations are described at the top of step_taylor.c. Private to src/methods: everything here is
 * static inline, always inlined with the order p a constant, so each caller gets the unrolled
 * recursion of its own orders. */
#ifndef SUS_STEP_TAYLOR_SERIES_H
#define SUS_STEP_TAYLOR_SERIES_H

#include "model.h"
#include "taylor.h"

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Pairs of doubles (GCC/Clang vector extension): both Cauchy products below are sums of a scalar
 * times a pair, so one vector multiply-add does the work of two. */
typedef double v2d __attribute__((vector_size(16)));

typedef struct {
    v2d W[SUS_STEP_TAYLOR_MAX_ORDER + 1]; /* (w1, w2) coefficients, scaled: W_n = w_n h^n */
    v2d P[SUS_STEP_TAYLOR_MAX_ORDER + 1]; /* (q0, q3) coefficients of the attitude increment */
    v2d M[SUS_STEP_TAYLOR_MAX_ORDER + 1]; /* (q1, q2) */
} taylor_series;

/* (a, b) -> (-b, a). */
static inline v2d rot90(v2d v) { return (v2d){-v[1], v[0]}; }

/* Q_{n+1} = g sum_{j<=n} Q_j (x) (0, W_{n-j}), g = h/(2(n+1)), from Q_0..Q_n and W_0..W_n (see
 * series below: the pair sums, newest terms last, the exact zeros P_1 and M_0 left out). */
static inline __attribute__((always_inline)) void q_row(taylor_series *t, const int n,
                                                        const double g)
{
    const v2d Wn = t->W[n];
    v2d xp = {0.0, 0.0}, yp = {0.0, 0.0}, xm = {0.0, 0.0}, ym = {0.0, 0.0};
#pragma GCC unroll 32
    for (int j = n; j >= 1; j--) { /* j = n (newest Q) ... j = 1 */
        const v2d Wk = t->W[n - j];
        if (j >= 2) {
            xp += Wk[0] * t->P[j];
            yp += Wk[1] * t->P[j];
        }
        xm += Wk[0] * t->M[j];
        ym += Wk[1] * t->M[j];
    }
    xp += Wn[0] * t->P[0]; /* j = 0 (newest W) */
    yp += Wn[1] * t->P[0];
    t->M[n + 1] = g * (xp + rot90(yp));
    t->P[n + 1] = g * (rot90(ym) - xm);
}

/* The coefficients up to degree p over a step h from w; with_q also those of the increment q(t),
 * q(0) = 1. With u = A w (A = fA, the printed (ContDyn) coefficients over |I_m|) and c = I_3i w_i:
 *   W_{n+1} = h/(n+1) sum_j c_j U_{n-j};
 * with w = (x, y, 0), q (x) (0, w) splits into pairs: for P = (q0, q3), M = (q1, q2),
 *   (q (x) (0,w))_{1,2} = x P + rot90(y P),   (q (x) (0,w))_{0,3} = -x M + rot90(y M),
 * so Q_{n+1} = h/(2(n+1)) sum_j Q_j (x) (0, W_{n-j}) needs four pair sums.
 * Speed (the sums are short, so their latency, not their flops, sets the cost): W_n enters the sum
 * for W_{n+1} only through its ends, c_0 U_n + c_n U_0 = L W_n with the fixed 2x2 matrix
 * L = c_0 A + U_0 (I31, I32) (n >= 1; for n = 0 the two ends are one term); so the middle terms,
 * which use older coefficients only, are summed while W_n is still being computed, and the chain
 * from W_n to W_{n+1} is two multiply-adds. Likewise the quaternion sums add their newest terms
 * (j = 0 and j = n) last; the terms of M_0 = 0 and P_1 = 0 (q0' = -(q1 x + q2 y)/2 vanishes at
 * q = 1) are exact zeros and left out. Always inlined with p constant and fully unrolled: loops of
 * 1..p trips cost a mispredicted exit branch each (cachegrind, taylor12: 22 mispredictions and 3260
 * instructions a step rolled, 0.2 and 2430 unrolled). */
static inline __attribute__((always_inline)) void series(const sus_model *m, const int p,
                                                         const double h, const double w[2],
                                                         const int with_q, taylor_series *t)
{
    double C[SUS_STEP_TAYLOR_MAX_ORDER + 1];
    v2d U[SUS_STEP_TAYLOR_MAX_ORDER + 1];
    const v2d a0 = {m->fA[0][0], m->fA[1][0]}, a1 = {m->fA[0][1], m->fA[1][1]};
    t->W[0] = (v2d){w[0], w[1]};
    t->P[0] = (v2d){1.0, 0.0};
    t->M[0] = (v2d){0.0, 0.0};
    C[0] = sus_c_unchecked(m, w);
    U[0] = a0 * w[0] + a1 * w[1];
    const v2d l0 = C[0] * a0 + m->b[0] * U[0],
              l1 = C[0] * a1 + m->b[1] * U[0]; /* the columns of L */
#pragma GCC unroll 32 /* p is a constant here: no loop branches, coefficients in registers */
    for (int n = 0; n < p; n++) {
        const v2d Wn = t->W[n];
        const double f = h / (double)(n + 1);
        if (n == 0) {
            t->W[1] = f * (C[0] * U[0]);
        } else {
            v2d s = {0.0, 0.0};
#pragma GCC unroll 32
            for (int j = 1; j < n; j++)
                s += C[j] * U[n - j];
            /* + c_0 U_n + c_n U_0; f L is formed off the chain, so W_n meets one multiply and two
             * adds */
            t->W[n + 1] = f * s + (Wn[0] * (f * l0) + Wn[1] * (f * l1));
        }
        const v2d Wn1 = t->W[n + 1];
        C[n + 1] = m->b[0] * Wn1[0] + m->b[1] * Wn1[1];
        U[n + 1] = a0 * Wn1[0] + a1 * Wn1[1];
        if (with_q)
            q_row(t, n, 0.5 * f);
    }
}

/* sum_{n=1}^{p} X_n in two interleaved partial sums, in the order the recursion produces the
 * terms: the adds overlap the recursion, and only two wait for the last term X_p (smallest
 * first would put p/2 dependent adds after it, on the chain from one step to the next). The
 * order changes the sum by a rounding of the largest term, |X_1| u, below the rounding of
 * w + sum. */
static inline __attribute__((always_inline)) v2d tail_sum(const v2d *X, const int p)
{
    v2d a = {0.0, 0.0}, b = {0.0, 0.0};
    int n = 1;
#pragma GCC unroll 32
    for (; n + 1 <= p; n += 2) {
        a += X[n];
        b += X[n + 1];
    }
    if (n == p)
        a += X[p];
    return a + b;
}

/* w scaled onto the energy e0 (E is homogeneous of degree 2). e0 = 0 (w = 0, an equilibrium)
 * scales nothing: no 0/0. An overflowed series (a step far beyond its radius) keeps its infinite
 * energy, so the driver reports the blow-up at this step instead of scaling w onto 0. */
static inline void taylor_energy_onto(const sus_model *m, const double e0, double w[3])
{
    const double e1 = sus_energy(m, w);
    if (e1 > 0.0 && e0 > 0.0 && isfinite(e1)) {
        const double sc = sqrt(e0 / e1);
        w[0] *= sc;
        w[1] *= sc;
    }
}

/* w^{k+1} = w^k + sum_{n>=1} W_n, then scaled onto the energy e0 (E(w^k) for the fixed-step
 * methods, which keep no state; E(w_0) for the adaptive one). */
static inline __attribute__((always_inline)) void w_next_from(const sus_model *m, const int p,
                                                              const taylor_series *t,
                                                              const double e0, double w_next[3])
{
    const v2d d = tail_sum(t->W, p);
    w_next[0] = t->W[0][0] + d[0];
    w_next[1] = t->W[0][1] + d[1];
    w_next[2] = 0.0;
    taylor_energy_onto(m, e0, w_next);
}

/* The attitude increment over the whole step, dq = (q0, q1, q2, q3) = sum_{n<=p} Q_n. */
static inline __attribute__((always_inline)) void dq_from(const taylor_series *t, const int p,
                                                          double dq[4])
{
    const v2d P = tail_sum(t->P, p), M = tail_sum(t->M, p);
    dq[0] = 1.0 + P[0];
    dq[1] = M[0];
    dq[2] = M[1];
    dq[3] = P[1];
}

#ifdef __cplusplus
}
#endif

#endif
