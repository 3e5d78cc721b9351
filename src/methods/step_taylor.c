/* Taylor-series methods of high order (anchor: Jorba & Zou, "A software package for the
 * numerical integration of ODEs by means of high-order Taylor methods", Exp. Math. 14 (2005)).
 *
 * w: (ContDyn) is quadratic, w' = c(w) A w with c(w) = I_3i w_i and A = fA (the printed
 * coefficients over |I_m|), so the Taylor coefficients of w(t_k + t) = sum w_n t^n follow from
 * the Cauchy product  w_{n+1} = 1/(n+1) sum_{j<=n} c_j A w_{n-j},  c_j = I_3i (w_j)_i,
 * for any inertia. The coefficients are carried scaled, W_n = w_n h^n, so that the sum is
 * w(t_k + h) = sum W_n and no power of h over- or underflows.
 *
 * R: the attitude increment over the step is the quaternion dq(h) with dq(0) = 1 and
 * q' = 1/2 q (x) (0, w) (equivalent to R' = R w^, the reconstruction equation of (algo) in
 * continuous time), whose coefficients come from a second Cauchy product with those of w:
 *   Q_{n+1} = h/(2(n+1)) sum_{j<=n} Q_j (x) (0, W_{n-j}).
 * The attitude is carried as a unit quaternion: q_{k+1} = q_k (x) dq, R_{k+1} = R(q_{k+1}/|q_{k+1}|)
 * (quaternion.h), so R is orthogonal to one rounding at every step, however long the run.
 *
 * Structure: w3 = 0 exactly (only w1, w2 are computed). E = 1/2 <I_m w, w> is restored after
 * each step by scaling w^{k+1} onto the energy of w^k (E is homogeneous of degree 2, so the
 * scaling is exact up to round-off and changes w by O(h^{p+1}), within the truncation error).
 * The Taylor method ignores the requested reconstruction: its attitude is part of the series. */
#include "taylor.h"

#include "quaternion.h"
#include "reconstruct.h"

#include <math.h>

/* Pairs of doubles (GCC/Clang vector extension): both Cauchy products below are sums of a scalar
 * times a pair, so one vector multiply-add does the work of two. */
typedef double v2d __attribute__((vector_size(16)));

typedef struct {
    v2d W[SUS_STEP_TAYLOR_MAX_ORDER + 1];  /* (w1, w2) coefficients, scaled: W_n = w_n h^n */
    v2d P[SUS_STEP_TAYLOR_MAX_ORDER + 1];  /* (q0, q3) coefficients of the attitude increment */
    v2d M[SUS_STEP_TAYLOR_MAX_ORDER + 1];  /* (q1, q2) */
} taylor_series;

/* (a, b) -> (-b, a). */
static inline v2d rot90(v2d v) { return (v2d){-v[1], v[0]}; }

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
 * (j = 0 and j = n) last. Always inlined with p constant and fully unrolled: loops of 1..p trips
 * cost a mispredicted exit branch each (cachegrind, taylor12: 22 mispredictions and 3260
 * instructions a step rolled, 0.2 and 2430 unrolled). */
static inline __attribute__((always_inline)) void series(const sus_model *m, const int p,
                                                         const double h, const double w[2], const int with_q,
                                                         taylor_series *t)
{
    double C[SUS_STEP_TAYLOR_MAX_ORDER + 1];
    v2d U[SUS_STEP_TAYLOR_MAX_ORDER + 1];
    const v2d a0 = {m->fA[0][0], m->fA[1][0]}, a1 = {m->fA[0][1], m->fA[1][1]};
    t->W[0] = (v2d){w[0], w[1]};
    t->P[0] = (v2d){1.0, 0.0};
    t->M[0] = (v2d){0.0, 0.0};
    C[0] = m->b[0] * w[0] + m->b[1] * w[1];
    U[0] = a0 * w[0] + a1 * w[1];
    const v2d l0 = C[0] * a0 + m->b[0] * U[0], l1 = C[0] * a1 + m->b[1] * U[0]; /* the columns of L */
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
            /* + c_0 U_n + c_n U_0; f L is formed off the chain, so W_n meets one multiply and two adds */
            t->W[n + 1] = f * s + (Wn[0] * (f * l0) + Wn[1] * (f * l1));
        }
        const v2d Wn1 = t->W[n + 1];
        C[n + 1] = m->b[0] * Wn1[0] + m->b[1] * Wn1[1];
        U[n + 1] = a0 * Wn1[0] + a1 * Wn1[1];
        if (!with_q)
            continue;
        v2d xp = {0.0, 0.0}, yp = {0.0, 0.0}, xm = {0.0, 0.0}, ym = {0.0, 0.0};
#pragma GCC unroll 32
        for (int j = n; j >= 0; j--) { /* j = n (newest Q) ... j = 0 (newest W) */
            const v2d Wk = t->W[n - j];
            xp += Wk[0] * t->P[j];
            yp += Wk[1] * t->P[j];
            xm += Wk[0] * t->M[j];
            ym += Wk[1] * t->M[j];
        }
        const double g = 0.5 * f;
        t->M[n + 1] = g * (xp + rot90(yp));
        t->P[n + 1] = g * (rot90(ym) - xm);
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

/* w^{k+1} = w^k + sum_{n>=1} W_n, then scaled back onto E(w^k). */
static inline __attribute__((always_inline)) void w_next_from(const sus_model *m, const int p,
                                                              const taylor_series *t, double w_next[3])
{
    const v2d d = tail_sum(t->W, p);
    const double w[2] = {t->W[0][0], t->W[0][1]};
    w_next[0] = w[0] + d[0];
    w_next[1] = w[1] + d[1];
    w_next[2] = 0.0;
    const double e0 = sus_energy(m, w), e1 = sus_energy(m, w_next);
    /* An overflowed series (a step far beyond its radius) keeps its infinite energy, so the
     * driver reports the blow-up at this step instead of scaling w_next onto 0. */
    if (e1 > 0.0 && e0 > 0.0 && isfinite(e1)) {
        const double sc = sqrt(e0 / e1);
        w_next[0] *= sc;
        w_next[1] *= sc;
    }
}

/* The radius the series is proved to converge in, from its own first coefficient (majorant
 * series). With v = w(t) - w, (ContDyn) reads v' = f(w) + c(w) A v + c(v) A w + c(v) A v, so the
 * Taylor coefficients of |v| are bounded by those of y' = F + L y + K y^2, y(0) = 0, with
 * F = |f(w)| = |c(w)| |A w|, L = |c(w)| ||A|| + |b| |A w| and K = |b| ||A|| (model.h): a
 * polynomial with nonnegative coefficients that bounds each term. With z = y + z0, z0 = L/(2K),
 * z' = K (z^2 - beta^2), beta^2 = z0^2 - F/K >= 0 (L^2 >= 4 K F: arithmetic-geometric mean), so
 * (z - beta)/(z + beta) = g0 e^{2 beta K t}, g0 = (z0 - beta)/(z0 + beta), and z blows up at
 *     rho = ln(1/g0) / (2 beta K) = log1p(2 beta (z0 + beta) K / F) / (2 beta K)
 * (1/(K z0) as beta -> 0; infinite at an equilibrium, F = 0). The quaternion series, q' = 1/2 q
 * (x) (0, w) with |w(t)| <= |w| + y, is majorised by z' = (|w| + y) z / 2: the same radius. rho is
 * never below 1/(K |w|) (F <= K |w|^2, L <= 2 K |w|), the cheap test a step tries first. */
typedef struct {
    double K, z0, beta, F;
} taylor_majorant;

static taylor_majorant majorant_of(const sus_model *m, const double w[2])
{
    const double c = fabs(sus_c(m, w));
    const double nAw = hypot(m->fA[0][0] * w[0] + m->fA[0][1] * w[1],
                             m->fA[1][0] * w[0] + m->fA[1][1] * w[1]);
    taylor_majorant mj = {m->norm_b * m->norm_fA, 0.0, 0.0, c * nAw};
    if (mj.K > 0.0) {
        mj.z0 = (c * m->norm_fA + m->norm_b * nAw) / (2.0 * mj.K);
        mj.beta = sqrt(fmax(mj.z0 * mj.z0 - mj.F / mj.K, 0.0));
    }
    return mj;
}

static double majorant_radius(const taylor_majorant *mj)
{
    if (!(mj->F > 0.0) || !(mj->K > 0.0))
        return INFINITY; /* an equilibrium (or b = 0): the series is the constant w */
    const double rho = mj->beta > 0.0 ? log1p(2.0 * mj->beta * (mj->z0 + mj->beta) * mj->K / mj->F)
                                            / (2.0 * mj->beta * mj->K)
                                      : 1.0 / (mj->K * mj->z0);
    return rho * (1.0 - 1e-12); /* rounded down: a bound after rounding */
}

/* y(t) of the majorant, for 0 <= t < rho. */
static double majorant_value(const taylor_majorant *mj, double t)
{
    if (!(mj->F > 0.0) || !(mj->K > 0.0))
        return 0.0;
    if (!(mj->beta > 0.0))
        return mj->z0 / (1.0 - mj->K * mj->z0 * t) - mj->z0;
    const double g = (mj->z0 - mj->beta) / (mj->z0 + mj->beta) * exp(2.0 * mj->beta * mj->K * t);
    return mj->beta * (1.0 + g) / (1.0 - g) - mj->z0;
}

double sus_step_taylor_radius(const sus_model *m, const double w[2])
{
    const taylor_majorant mj = majorant_of(m, w);
    return majorant_radius(&mj);
}

/* Cauchy's estimate on a circle of radius R in (h, rho): the coefficients of y satisfy
 * y_n <= y(R) / R^n, so the tail past degree p is at most y(R) q^{p+1} / (1 - q), q = h/R; the
 * best R of a grid. */
double sus_step_taylor_tail_bound(int p, const sus_model *m, double h, const double w[2])
{
    const taylor_majorant mj = majorant_of(m, w);
    const double rho = majorant_radius(&mj);
    h = fabs(h);
    if (!(h < rho))
        return INFINITY;
    if (!isfinite(rho))
        return 0.0;
    double best = INFINITY;
    for (int i = 1; i < 400; i++) {
        const double R = h + (rho - h) * (double)i / 400.0, q = h / R;
        best = fmin(best, majorant_value(&mj, R) * pow(q, p + 1) / (1.0 - q));
    }
    return best;
}

/* A step outside the proved radius is refused, not summed: its sum, scaled onto the energy
 * ellipse, would be a finite but possibly meaningless w^{k+1}. stats: the step over the radius
 * (an upper bound of it below 1 from the cheap test) and |w|_2. */
static inline __attribute__((always_inline)) int diverged(const sus_model *m, double h, const double w[2],
                                                          sus_stepper_stats *st)
{
    const double a = sqrt(w[0] * w[0] + w[1] * w[1]);
    *st = (sus_stepper_stats){.residual = m->norm_b * m->norm_fA * a * fabs(h), .scale = a};
    if (st->residual < 1.0)
        return 0;
    st->residual = fabs(h) / sus_step_taylor_radius(m, w);
    return !(st->residual < 1.0);
}

static inline __attribute__((always_inline)) int taylor_apply(const int p, const sus_model *m, double eps,
                                                                const double w[3], double w_next[3],
                                                                double *lambda_next, sus_stepper_stats *st)
{
    taylor_series t;
    if (diverged(m, eps, w, st))
        return SUS_STEPPER_DIVERGED;
    series(m, p, eps, w, 0, &t);
    w_next_from(m, p, &t, w_next);
    *lambda_next = sus_lagmult(m, w_next);
    return SUS_STEPPER_OK;
}

static inline __attribute__((always_inline)) int taylor_apply_full(const int p, const sus_model *m,
                                                                     double eps, sus_attitude *att,
                                                                     const double w[3],
                                                                     double w_next[3], double *lambda_next,
                                                                     sus_stepper_stats *st)
{
    taylor_series t;
    if (diverged(m, eps, w, st))
        return SUS_STEPPER_DIVERGED;
    series(m, p, eps, w, 1, &t);
    const v2d P = tail_sum(t.P, p), M = tail_sum(t.M, p);
    const double dq[4] = {1.0 + P[0], M[0], M[1], P[1]};
    double q[4], q1[4];
    sus_quat_of_attitude(att, q);
    sus_quat_mul(q1, q, dq); /* R_{k+1} = R_k R(dq) */
    sus_quat_to_attitude(q1, att);
    w_next_from(m, p, &t, w_next);
    *lambda_next = sus_lagmult(m, w_next);
    return SUS_STEPPER_OK;
}

/* The step with p known only at run time (not on any hot path: the registered steppers below use
 * the inlined forms with p constant). */
int sus_step_taylor_apply_full(int p, const sus_model *m, double eps, sus_attitude *att,
                             const double w[3], double w_next[3], double *lambda_next,
                             sus_stepper_stats *st)
{
    return taylor_apply_full(p, m, eps, att, w, w_next, lambda_next, st);
}

/* The truncated exponential sum_{n<=p} z^n/n!: the energy projection scales w along itself, which
 * is transverse to the linearised motion along the energy ellipse, so it does not enter. */
double sus_step_taylor_stability(int p, double z)
{
    double r = 1.0, t = 1.0;
    for (int n = 1; n <= p; n++) {
        t *= z / (double)n;
        r += t;
    }
    return r;
}

#define TAYLOR_STEPPER(P)                                                                                 \
    static int taylor##P##_apply(const sus_model *m, double eps, const double w[3], double w_next[3],     \
                                 double *lambda_next, sus_stepper_stats *st)                              \
    {                                                                                                     \
        return taylor_apply(P, m, eps, w, w_next, lambda_next, st);                                       \
    }                                                                                                     \
    static int taylor##P##_apply_full(const sus_model *m, double eps, sus_recon recon, sus_attitude *att, \
                                      const double w[3], double w_next[3], double *lambda_next,           \
                                      sus_stepper_stats *st)                                              \
    {                                                                                                     \
        (void)recon;                                                                                      \
        return taylor_apply_full(P, m, eps, att, w, w_next, lambda_next, st);                             \
    }                                                                                                     \
    double sus_step_stab_taylor##P(double z) { return sus_step_taylor_stability(P, z); }                  \
    const sus_stepper_type sus_step_taylor##P##_type = {                                                  \
        .name = "taylor" #P, .order = P, .lambda_order = P, .apply = taylor##P##_apply,                   \
        .apply_full = taylor##P##_apply_full, .stability = sus_step_stab_taylor##P,                       \
        .conserves_energy = 1, .attitude = SUS_ATTITUDE_QUAT, .substeps = 1, .pre_asymptotic = 1,         \
        .apply_order = sus_step_taylor_apply_full, .source = __FILE__};

/* Which order is cheapest depends on the accuracy (measured at t = 50 over every N from 2 to 40,
 * orders 6 to 20, issue 11 follow-up): order 8 or 10 at attitude 1e-4..1e-6 and for w alone,
 * 12 at 1e-8, 12-16 at 1e-10, 14-20 at 1e-12 (within the timing noise of each other there);
 * orders 6, 14 and 20 were never clearly the fastest, so they are not registered. */
TAYLOR_STEPPER(8)
TAYLOR_STEPPER(10)
TAYLOR_STEPPER(12)
TAYLOR_STEPPER(16)
