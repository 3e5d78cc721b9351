/* The exact run (src/core/exact_run.c): its rows, which take R(t) from the reference along its own
 * grid (sus_refatt_at), against the reference advanced over the whole stretch (sus_refatt_advance),
 * two paths through the same transient and the same closed-form tail, on every test body
 * (tests/unit/bodies.h); an equilibrium; the row grid and the error convention. The reference's
 * accuracy itself is checked against an independent Magnus integration in test_highorder.c. */
#include "check_body.h"
#include "exact_run.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"

#include <float.h>
#include <math.h>
#include <string.h>

typedef struct {
    long rows, last_k;
    double R[3][3];
} keep_ctx;

static int keep(void *vctx, const sus_row *r)
{
    keep_ctx *c = vctx;
    c->rows++;
    c->last_k = r->k;
    memcpy(c->R, r->R, sizeof c->R);
    return 0;
}

static int stop_at_first(void *vctx, const sus_row *r)
{
    (void)r;
    ((keep_ctx *)vctx)->rows++;
    return 1;
}

/* The exact run's rows against the reference advanced over the stretch, and an equilibrium, on one
 * body. */
static void tail_vs_reference(const body *b)
{
    sus_model m;
    if (check_body_model(b, &m) != 0)
        return;
    sus_exact ex;
    sus_exact_init(&ex, &m, b->w0);
    /* An equilibrium exactly: c(w) = I31 w1 + I32 w2 = 0 for w = 2^e (-I32, I31), with 2^e near
     * the steady rotation's size (sus_exact_limit's w* is one to a rounding only, and from a
     * rounding off the line the motion is not uniform to u on a near-singular I_m) */
    double wstar[2];
    sus_exact_limit(&ex, wstar);
    const int e = (int)lround(log2(hypot(wstar[0], wstar[1]) / hypot(m.b[0], m.b[1])));
    wstar[0] = ldexp(-m.b[1], e), wstar[1] = ldexp(m.b[0], e);
    const double wn = hypot(wstar[0], wstar[1]), scale = check_body_time(&m, b->w0);

    /* At t = 300, 1000, 3000 on the paper's body (in the body's own time elsewhere), all past the
     * tail's start t_s: the two paths differ in their transient steps (a grid and a partial step,
     * or equal steps over [0, t_s]) by a few long-double roundings a step, and share the tail,
     * whose angle is formed in 113 bits. Each result is rounded once to double, by at most u (u =
     * DBL_EPSILON / 2) per entry: the bound is those two roundings in the Frobenius norm of the
     * nine entries, 3 * 2u = 6u. */
    const double Ts[] = {300.0, 1000.0, 3000.0};
    for (int i = 0; i < 3; i++) {
        const double T = Ts[i] * scale;
        const sus_run_config cfg = {&m, NULL, SUS_RECON_CAYLEY, T / 4.0, 4, 1};
        keep_ctx c = {0, -1, {{0}}};
        sus_run_report rep;
        const int rc = sus_run_exact(&cfg, b->w0, keep, &c, &rep);
        double I3[3][3], R[3][3];
        sus_mat3_identity(I3);
        sus_refatt ra;
        sus_refatt_init(&ra, &ex, 0.0, I3);
        sus_refatt_advance(&ra, T, R);
        const double d = sus_mat3_dist(c.R, R), bound = 6.0 * DBL_EPSILON / 2.0;
        CHECK(rc == SUS_RUN_OK && c.rows == 5 && c.last_k == 4 && d <= bound,
              "%s: exact run to T = %g: rows 0..4, its R(T) within %.2e of "
              "the reference advanced over the stretch (bound 6u = %.2e)",
              b->name, T, d, bound);
    }

    /* An equilibrium (w0 on the steady rotation) rotates uniformly from t = 0: R(t) = exp(t w0^).
     */
    const sus_run_config cfg = {&m, NULL, SUS_RECON_CAYLEY, 12.5, 1, 1};
    keep_ctx c = {0, -1, {{0}}};
    sus_run_report rep;
    const int rc = sus_run_exact(&cfg, wstar, keep, &c, &rep);
    const double xi[3] = {12.5 * wstar[0], 12.5 * wstar[1], 0.0};
    double E[3][3];
    sus_so3_exp(xi, E);
    const double d = sus_mat3_dist(c.R, E), bound = 4.0 * DBL_EPSILON / 2.0 * (1.0 + wn * 12.5);
    CHECK(rc == SUS_RUN_OK && d <= bound,
          "%s: equilibrium w0 = w*: R(12.5) = exp(12.5 w*^) to %.1e (bound 4u(1 + |w*|T) = %.1e)",
          b->name, d, bound);
}

/* A start 1e-14 off the repelling rotation (c(w0) ~ 1e-15): it stays there until s = s0 + sigma k t
 * crosses 0, at t1 = |s0| / k (|s0| ~ 32), and at t2 = t1 + 1 / k is on its way. The closed form
 * from w0 against the closed form restarted from w(t1), well away from both rotations: both give
 * w(t2). (A time shift of the motion is a motion too, so this sees the evaluation, not s0 itself;
 * s0 is checked against asinh(S / C) with c(w0) in long double, whose rounding, 2^-64 |I32 w2|,
 * is a millionth of c(w0) here: 1e-5 covers it. With C formed from the rounded Cholesky
 * coordinates, whose terms cancel to 1e-14 of their size, s0 could be off by u / 1e-14.)
 * Each evaluation has s to a few roundings of the terms it adds, |s0| and k t: 8 u (|s0| + k t)
 * each, and w moves by at most |w| per unit of s; w(t1)'s own rounding adds u |w|. The
 * reference R from w0 against the reference restarted at t1 from R(t1): the two share the closed
 * form's w, and R(t1) is rounded once to double: 16 u per entry covers that and a few roundings
 * of each. */
static void near_repelling(const sus_model *m)
{
    const double w0[2] = {0.1, -0.20000000000001};
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_exact ex, ex1;
    double w1[2], wa[2], wb[2], R1[3][3], Ra[3][3], Rb[3][3];
    sus_exact_init(&ex, m, w0);
    const double t1 = fabs(ex.s0) / ex.k, t2 = t1 + 1.0 / ex.k;
    sus_exact_omega(&ex, t1, w1);
    sus_exact_omega(&ex, t2, wa);
    sus_exact_init(&ex1, m, w1);
    sus_exact_omega(&ex1, t2 - t1, wb);
    const double spread = fabs(ex.s0) + ex.k * t2 + fabs(ex1.s0) + ex1.k * (t2 - t1) + 1.0;
    const double dw = hypot(wa[0] - wb[0], wa[1] - wb[1]),
                 bw = 8.0 * SUS_U * spread * hypot(wa[0], wa[1]);
    sus_refatt ra, rb;
    sus_refatt_init(&ra, &ex, 0.0, I3);
    sus_refatt_advance(&ra, t1, R1);
    sus_refatt_advance(&ra, t2, Ra);
    sus_refatt_init(&rb, &ex1, 0.0, R1);
    sus_refatt_advance(&rb, t2 - t1, Rb);
    const double dR = sus_mat3_dist(Ra, Rb), bR = 16.0 * 3.0 * SUS_U;
    /* S / C = |v| (cb u2 - sb u1) / c(w0), |v| = k l11 l22 / r (exact.c) */
    const long double c = fmal(m->b[0], w0[0], (long double)m->b[1] * w0[1]),
                      u1 = ex.l11 * (long double)w0[0] + ex.l21 * (long double)w0[1],
                      u2 = ex.l22 * (long double)w0[1], vn = ex.k * ex.l11 * ex.l22 / ex.r;
    const double ds = fabs(ex.s0 - (double)asinhl(vn * (ex.cb * u2 - ex.sb * u1) / c));
    CHECK(fabs(ex.s0) > 30.0 && ds <= 1e-5 && dw <= bw && dR <= bR,
          "w0 1e-14 off the repelling rotation: s0 = %.1f, %.1e from long double's (bound 1e-5); "
          "w(%.0f) from w0 and from w(%.0f) agree to %.1e (bound %.1e), R(%.0f) to %.1e (bound "
          "16 u per entry, %.1e)",
          ex.s0, ds, t2, t1, dw, bw, t2, dR, bR);
}

/* The proved step (refattitude.h): one step of it against the same stretch in 8 steps, the
 * quaternions compared in long double before any rounding to double. The step keeps its series'
 * tail below 2^-64 and each step adds a few long-double roundings (refattitude.h: about 10 2^-64
 * a step): 9 steps, 128 2^-64 covers them. A step taken past what the strip of analyticity proves
 * (a disc reaching out of it) leaves a tail far above that, though still far below a double's
 * rounding of R. */
static void proved_step(const body *b)
{
    sus_model m;
    sus_exact ex;
    if (check_body_model(b, &m) != 0 || sus_exact_init(&ex, &m, b->w0) != 0 || ex.fixed)
        return;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double R[3][3];
    sus_refatt one, eight;
    sus_refatt_init(&one, &ex, 0.0, I3);
    sus_refatt_init(&eight, &ex, 0.0, I3);
    const double h = (double)one.h;
    eight.h = one.h / 8;
    sus_refatt_advance(&one, h, R);
    sus_refatt_advance(&eight, h, R);
    long double d = 0.0L;
    for (int i = 0; i < 4; i++)
        d = fmaxl(d, fabsl(one.q[i] - eight.q[i]));
    CHECK(d <= 128.0L * 0x1p-64L,
          "%s: one proved reference step (k h = %.3g) against 8: quaternions within %.2Lg (bound "
          "128 2^-64 = %.2Lg)",
          b->name, ex.k * h, d, 128.0L * 0x1p-64L);
}

/* |lambda| along one body's motion, sampled at s = -40 ... 40 in steps of 1/64 (s = s0 + sigma k
 * t), against sus_exact_lambda_max. The motion's (z, y) = (sech s, tanh s) = (cos phi, sin phi)
 * turns by dphi = sech s ds <= 1/64 a sample, and lambda = m + R cos 2(phi - phi0) with R <=
 * lambda_max, so the best sample is within 2 R (1/128)^2 < 2^-12 lambda_max of it (the ends,
 * s = +-40, within 4 e^-40 of phi = +-pi/2). No sample exceeds it by more than its rounding: w
 * within 16 u of its scale enters the quadratic terms twice, and the products and sums round
 * under 32 u more, so 64 u of the terms' sizes. Returns the best sample / lambda_max, or -1 for a
 * sample past it. */
static double lambda_sampled(const sus_model *m, const sus_exact *ex)
{
    const double(*I)[3] = m->I, lmax = sus_exact_lambda_max(ex);
    double best = 0.0;
    for (int j = -40 * 64; j <= 40 * 64; j++) {
        const double t = (j / 64.0 - ex->s0) / (ex->sigma * ex->k);
        double w[2];
        sus_exact_omega(ex, t, w);
        const double c = sus_exact_c(ex, t), l = fabs(sus_lagmult_c(m, w, c));
        const double terms = fabs(w[0]) * (fabs(I[1][0] * w[0]) + fabs(I[1][1] * w[1])) +
                             fabs(w[1]) * (fabs(I[0][0] * w[0]) + fabs(I[0][1] * w[1])) +
                             fabs(sus_o0_with_c(m, w, c));
        if (!(l <= lmax + 64.0 * DBL_EPSILON / 2 * terms))
            return -1.0;
        best = fmax(best, l);
    }
    return best / lmax;
}

/* (LagMult) along the motion. On every test body its largest size against samples (above). On I =
 * diag(1, 1e-300) with I31 = I32 = 1: L = diag(1, 1e-150), v = L^{-1} b = (1, 1e150), so cmax = r
 * |v| = 1e150 r and w2 reaches r / l22 = 1e150 r, while |w1| <= r; o0c = (1, -1e-300), so
 * lambda's last term c / |I_m| (w1 - 1e-300 w2) is about 1e300 cmax r = 1e450 r^2 at its peak.
 * From the paper's w0 (r = 0.4) that is past the range: refused before row 0, with the command's
 * reason. From |w0| = 1e-100 it is 1e250, but c / |I_m| alone reaches 1e350 in the transient
 * (near t = 3.5e-198): every row finite all the same. */
static void lambda_along_the_motion(void)
{
    double worst = 2.0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model mb;
        sus_exact ex;
        body_get(k, &b);
        check_body_model(&b, &mb);
        sus_exact_init(&ex, &mb, b.w0);
        worst = fmin(worst, ex.fixed ? 1.0 : lambda_sampled(&mb, &ex));
    }
    CHECK(worst >= 1.0 - 0x1p-12 && isnan(sus_exact_lambda_max(NULL)),
          "sus_exact_lambda_max on %d bodies: no sample of |lambda| along the motion above it by "
          "more than its rounding, and the best within 2^-12 below: worst best / max %.9g (-1: "
          "one above); NaN for a NULL closed form",
          BODIES_COUNT, worst);
    const double I[9] = {1, 0, 0, 0, 1e-300, 0, 1, 1, 1}, far[2] = {0.4, 0.5};
    const double near[2] = {1e-100, 1e-100};
    sus_model m;
    sus_exact ex;
    char err[256] = "";
    CHECK(sus_model_init(&m, I, err, sizeof err) == 0, "I22 = 1e-300 is a body: %s", err);
    sus_exact_init(&ex, &m, far);
    const double lfar = sus_exact_lambda_max(&ex);
    sus_run_config cfg = {&m, NULL, SUS_RECON_CAYLEY, 1e-150, 4, 1};
    keep_ctx c = {0, -1, {{0}}};
    sus_run_report rep;
    int rc = sus_run_exact(&cfg, far, keep, &c, &rep);
    CHECK(isinf(lfar) && rc == SUS_RUN_BAD_ARGUMENT && c.rows == 0 &&
              strstr(rep.message, "overflows along the motion"),
          "from w0 = (0.4, 0.5) on I = diag(1, 1e-300), I31 = I32 = 1: lambda overflows along the "
          "motion (largest %g), the run refused (rc %d, %ld rows: %s)",
          lfar, rc, c.rows, rep.message ? rep.message : "");
    sus_exact_init(&ex, &m, near);
    const double lnear = sus_exact_lambda_max(&ex);
    cfg.eps = 1e-199;
    cfg.steps = 80; /* rows every 1e-199 to 8e-198, across the transient */
    rc = sus_run_exact(&cfg, near, keep, &c, &rep);
    CHECK(lnear > 1e249 && lnear < 1e251 && rc == SUS_RUN_OK && c.rows == 81,
          "from |w0| = 1e-100 its largest is %.3g (1e250 to a factor 10): the run writes its 81 "
          "rows, all finite (rc %d, %ld)",
          lnear, rc, c.rows);
}

int main(void)
{
    lambda_along_the_motion();
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        body_get(k, &b);
        tail_vs_reference(&b);
        proved_step(&b);
    }
    sus_model m;
    char err[256];
    sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err);
    near_repelling(&m);

    /* Steps near 2^63: no k + K overflow, rows 0, K, 2K, 3K and N. */
    {
        const sus_run_config cfg = {
            &m, NULL, SUS_RECON_CAYLEY, 1e-3, 9223372036854775807L, 3074457345618258602L};
        keep_ctx c = {0, -1, {{0}}};
        sus_run_report rep;
        const int rc = sus_run_exact(&cfg, SUS_PAPER_OMEGA0, keep, &c, &rep);
        CHECK(rc == SUS_RUN_OK && c.rows == 5 && c.last_k == 9223372036854775807L,
              "N = 2^63-1, K = N/3: %ld rows, last k = %ld (no overflow, no wrap)", c.rows,
              c.last_k);
    }

    /* The error convention: emit asking to stop is SUS_RUN_STOPPED, after the first row. */
    {
        const sus_run_config cfg = {&m, NULL, SUS_RECON_CAYLEY, 0.1, 10, 1};
        keep_ctx c = {0, -1, {{0}}};
        sus_run_report rep;
        const int rc = sus_run_exact(&cfg, SUS_PAPER_OMEGA0, stop_at_first, &c, &rep);
        CHECK(rc == SUS_RUN_STOPPED && c.rows == 1 && SUS_RUN_STOPPED < 0 && SUS_RUN_OK == 0,
              "emit asking to stop gives SUS_RUN_STOPPED (%d), distinct from every failure", rc);
    }
    return check_summary("test_exact_run");
}
