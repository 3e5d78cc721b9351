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
 * The attitude is carried as a unit quaternion: q_{k+1} = q_k (x) dq, R_{k+1} =
 * R(q_{k+1}/|q_{k+1}|) (quaternion.h), so R is orthogonal to one rounding at every step, however
 * long the run.
 *
 * Structure: w3 = 0 exactly (only w1, w2 are computed). E = 1/2 <I_m w, w> is restored after
 * each step by scaling w^{k+1} onto the energy of w^k (E is homogeneous of degree 2, so the
 * scaling is exact up to round-off and changes w by O(h^{p+1}), within the truncation error).
 * The Taylor method ignores the requested reconstruction: its attitude is part of the series. */
#include "taylor.h"
#include "taylor_series.h"

#include "quaternion.h"
#include "reconstruct.h"

#include <math.h>

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
    const double nAw =
        hypot(m->fA[0][0] * w[0] + m->fA[0][1] * w[1], m->fA[1][0] * w[0] + m->fA[1][1] * w[1]);
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
    const double rho =
        mj->beta > 0.0
            ? log1p(2.0 * mj->beta * (mj->z0 + mj->beta) * mj->K / mj->F) / (2.0 * mj->beta * mj->K)
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
static inline __attribute__((always_inline)) int diverged(const sus_model *m, double h,
                                                          const double w[2], sus_stepper_stats *st)
{
    const double a = sqrt(w[0] * w[0] + w[1] * w[1]);
    *st = (sus_stepper_stats){.residual = m->norm_b * m->norm_fA * a * fabs(h), .scale = a};
    if (st->residual < 1.0)
        return 0;
    st->residual = fabs(h) / sus_step_taylor_radius(m, w);
    return !(st->residual < 1.0);
}

static inline __attribute__((always_inline)) int taylor_apply(const int p, const sus_model *m,
                                                              double eps, const double w[3],
                                                              double w_next[3], double *lambda_next,
                                                              sus_stepper_stats *st)
{
    taylor_series t;
    if (diverged(m, eps, w, st))
        return SUS_STEPPER_DIVERGED;
    series(m, p, eps, w, 0, &t);
    w_next_from(m, p, &t, sus_energy(m, w), w_next);
    *lambda_next = sus_lagmult(m, w_next);
    return SUS_STEPPER_OK;
}

static inline __attribute__((always_inline)) int
taylor_apply_full(const int p, const sus_model *m, double eps, sus_attitude *att, const double w[3],
                  double w_next[3], double *lambda_next, sus_stepper_stats *st)
{
    taylor_series t;
    if (diverged(m, eps, w, st))
        return SUS_STEPPER_DIVERGED;
    series(m, p, eps, w, 1, &t);
    double dq[4], q[4], q1[4];
    dq_from(&t, p, dq);
    sus_quat_of_attitude(att, q);
    sus_quat_mul(q1, q, dq); /* R_{k+1} = R_k R(dq) */
    sus_quat_to_attitude(q1, att);
    w_next_from(m, p, &t, sus_energy(m, w), w_next);
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

#define TAYLOR_STEPPER(P)                                                                          \
    static int taylor##P##_apply(const sus_model *m, double eps, const double w[3],                \
                                 double w_next[3], double *lambda_next, sus_stepper_stats *st)     \
    {                                                                                              \
        return taylor_apply(P, m, eps, w, w_next, lambda_next, st);                                \
    }                                                                                              \
    static int taylor##P##_apply_full(const sus_model *m, double eps, sus_recon recon,             \
                                      sus_attitude *att, const double w[3], double w_next[3],      \
                                      double *lambda_next, sus_stepper_stats *st)                  \
    {                                                                                              \
        (void)recon;                                                                               \
        return taylor_apply_full(P, m, eps, att, w, w_next, lambda_next, st);                      \
    }                                                                                              \
    double sus_step_stab_taylor##P(double z) { return sus_step_taylor_stability(P, z); }           \
    static const sus_step_ops taylor##P##_step = {.apply = taylor##P##_apply,                      \
                                                  .apply_full = taylor##P##_apply_full,            \
                                                  .apply_order = sus_step_taylor_apply_full};      \
    const sus_stepper_type sus_step_taylor##P##_type = {                                           \
        .name = "taylor" #P,                                                                       \
        .step = &taylor##P##_step,                                                                 \
        .desc = {.order = P,                                                                       \
                 .lambda_order = P,                                                                \
                 .conserves_energy = 1,                                                            \
                 .attitude = SUS_ATTITUDE_QUAT,                                                    \
                 .substeps = 1,                                                                    \
                 .pre_asymptotic = 1,                                                              \
                 .stability = sus_step_stab_taylor##P,                                             \
                 .source = __FILE__}};

/* Which order is cheapest depends on the accuracy (measured at t = 50 over every N from 2 to 40,
 * orders 6 to 20): order 8 or 10 at attitude 1e-4..1e-6 and for w alone,
 * 12 at 1e-8, 12-16 at 1e-10, 14-20 at 1e-12 (within the timing noise of each other there);
 * orders 6, 14 and 20 were never clearly the fastest, so they are not registered. */
TAYLOR_STEPPER(8)
TAYLOR_STEPPER(10)
TAYLOR_STEPPER(12)
TAYLOR_STEPPER(16)
