#include "refattitude.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "quaternion.h"

/* The stated accuracy, 2^-51 after up to a thousand steps of about ten long-double roundings, needs
 * a significand of 64 bits at least (x87; binary128 on aarch64 and WebAssembly). Where long double
 * is double (MSVC, Apple's arm64) the reference would be no more accurate than the methods it
 * judges: refuse to build there rather than state what does not hold. */
_Static_assert(LDBL_MANT_DIG >= 64,
               "the reference attitude needs a long double of 64 bits at least");

/* a b - c d for doubles, to about one rounding of the result however much the two products
 * cancel: p = fl(c d) and e = c d - p are exact in long double (a product of doubles has 106
 * bits, the error of its rounding to 64 at most 42), and fmal rounds a b - p once. */
static long double cross_diff(double a, double b, double c, double d)
{
    const long double p = (long double)c * d, e = fmal(c, d, -p);
    return fmal(a, b, -p) - e;
}

/* The Cholesky coordinates of exact.h in long double, I_m = L L^T taken symmetric (I21 for I12,
 * as exact.h does): l11 = sqrt(I11), l21 = I21 / l11, l22 = sqrt(|I_m| / I11), v = L^{-1} b. The
 * determinant and v2's numerator I11 I32 - I21 I31 are formed without cancellation (cross_diff),
 * so a near-singular I_m costs no digits here. */
static void chol_init(sus_refatt_chol *c, const sus_model *m)
{
    const double(*I)[3] = m->I;
    const long double det = cross_diff(I[0][0], I[1][1], I[1][0], I[1][0]), sd = sqrtl(det);
    c->l11 = sqrtl(I[0][0]);
    c->l21 = I[1][0] / c->l11;
    c->l22 = sd / c->l11;
    c->v[0] = m->b[0] / c->l11;
    c->v[1] = cross_diff(I[0][0], m->b[1], I[1][0], m->b[0]) / (c->l11 * sd);
    c->g = 1.0L / sd;
}

/* w = L^{-T} u and u = L^T w. */
static void w_of_u(const sus_refatt_chol *c, const long double u[2], long double w[2])
{
    w[1] = u[1] / c->l22;
    w[0] = (u[0] - c->l21 * w[1]) / c->l11;
}

/* u1 = (I11 w1 + I21 w2) / l11 with its numerator to one rounding (cross_diff): on a near-singular
 * I_m, w along its soft axis makes l11 w1 and l21 w2 cancel to a part in 1 / |w|, and their
 * long-double roundings would then be that much larger relative to u1, to r, k and w_inf. */
static void u_of_w(const sus_refatt_chol *c, const double (*I)[3], const double w[2],
                   long double u[2])
{
    u[0] = cross_diff(I[0][0], w[0], -I[1][0], w[1]) / c->l11;
    u[1] = c->l22 * w[1];
}

/* The closed form's constants in long double, as exact.c forms them in double: C = c(w0) / (|v| r)
 * from c(w0) = I31 w1 + I32 w2 to one rounding (cross_diff), so that s0 = asinh(S / C) holds
 * however near w0 lies to the line c = 0 (the repelling rotation). */
static void closed_init(sus_refatt_closed *cf, const sus_refatt_chol *co, const sus_exact *ex)
{
    const double *b = ex->model->b, *w0 = ex->w0;
    u_of_w(co, ex->model->I, w0, cf->u0);
    const long double u1 = cf->u0[0], u2 = cf->u0[1], vn = hypotl(co->v[0], co->v[1]);
    cf->r = hypotl(u1, u2);
    cf->fixed = ex->fixed || !(cf->r > 0.0L) || !(vn > 0.0L);
    if (cf->fixed)
        return;
    cf->cb = co->v[0] / vn;
    cf->sb = co->v[1] / vn;
    const long double C = cross_diff(b[0], w0[0], -b[1], w0[1]) / (vn * cf->r),
                      S = (cf->cb * u2 - cf->sb * u1) / cf->r;
    cf->fixed = C == 0.0L;
    cf->k = cf->r * vn / (co->l11 * co->l22);
    cf->sigma = C > 0.0L ? 1.0L : -1.0L;
    cf->s0 = asinhl(S / C);
}

/* u(t) from the closed form (exact.c's omega_from_psi, in long double). */
static void closed_u(const sus_refatt_closed *cf, long double t, long double u[2])
{
    if (cf->fixed) {
        u[0] = cf->u0[0], u[1] = cf->u0[1];
        return;
    }
    const long double s = cf->s0 + cf->sigma * cf->k * t, e = expl(-fabsl(s));
    const long double cp = cf->sigma * 2.0L * e / (1.0L + e * e), sp = cf->sigma * tanhl(s);
    u[0] = cf->r * (cf->cb * cp - cf->sb * sp);
    u[1] = cf->r * (cf->sb * cp + cf->cb * sp);
}

/* (ContDyn): One Taylor step of order P in long double, in the Cholesky coordinates u = L^T w of
 * exact.h, where (ContDyn) reads u' = c J u / |L| with c = <v, u> and J u = (-u2, u1): no
 * cancellation however near-singular I_m is. With it, the Cauchy-product recursion of the
 * quaternion kinematics q' = 1/2 q (x) (0, w), w = L^{-T} u, whose sum advances q. u's own series
 * is needed only for its coefficients below order P, which feed q's: it is not summed, as every
 * step starts from u of the closed form (integrate, grid_state). Coefficients are scaled,
 * U_n = u_n h^n. P <= SUS_REFATT_ORDER is the step's order (order_for). */
static void precise_step(const sus_refatt_chol *co, long double h, int P, const long double u[2],
                         long double q[4])
{
    long double U[SUS_REFATT_ORDER][2], W[SUS_REFATT_ORDER][2], Q[SUS_REFATT_ORDER + 1][4],
        C[SUS_REFATT_ORDER];
    U[0][0] = u[0];
    U[0][1] = u[1];
    for (int i = 0; i < 4; i++)
        Q[0][i] = q[i];
    for (int n = 0; n < P; n++) {
        C[n] = co->v[0] * U[n][0] + co->v[1] * U[n][1];
        w_of_u(co, U[n], W[n]);
        long double s0 = 0, s1 = 0, t[4] = {0, 0, 0, 0};
        for (int j = 0; j <= n; j++) {
            s0 -= C[j] * U[n - j][1];
            s1 += C[j] * U[n - j][0];
            const long double *qj = Q[j], x = W[n - j][0], y = W[n - j][1];
            /* q (x) (0, x, y, 0) */
            t[0] -= qj[1] * x + qj[2] * y;
            t[1] += qj[0] * x - qj[3] * y;
            t[2] += qj[0] * y + qj[3] * x;
            t[3] += qj[1] * y - qj[2] * x;
        }
        const long double f = h / (n + 1);
        if (n + 1 < P) { /* U_P would feed only u's sum */
            U[n + 1][0] = f * co->g * s0;
            U[n + 1][1] = f * co->g * s1;
        }
        for (int i = 0; i < 4; i++)
            Q[n + 1][i] = 0.5L * f * t[i];
    }
    for (int n = P; n >= 1; n--)
        for (int i = 0; i < 4; i++)
            q[i] += Q[n][i];
}

/* R(q) for q not of unit length: ((s^2 - |v|^2) I + 2 v v^T + 2 s v^) / |q|^2, rounded once. */
static void rotation_of(const long double q[4], double R[3][3])
{
    const long double nq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const long double s = q[0], x = q[1], y = q[2], z = q[3];
    const long double Rl[3][3] = {
        {s * s + x * x - y * y - z * z, 2 * (x * y - s * z), 2 * (x * z + s * y)},
        {2 * (x * y + s * z), s * s - x * x + y * y - z * z, 2 * (y * z - s * x)},
        {2 * (x * z - s * y), 2 * (y * z + s * x), s * s - x * x - y * y + z * z}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = (double)(Rl[i][j] / nq);
}

static void no_answer(double R[3][3])
{
    const long double q[4] = {NAN, NAN, NAN, NAN};
    rotation_of(q, R);
}

/* The proved step (refattitude.h). On the disc |t - t0| <= rho about any real t0, s = s0 + sigma k
 * t (exact.h) has |Im s| <= Y = k rho, and for s = a + iy with |y| <= Y < pi/2 |sech s|^2 = 1 /
 * (sinh^2 a + cos^2 y) <= 1 / cos^2 Y, |tanh s|^2 = (sinh^2 a + sin^2 y) / (sinh^2 a + cos^2 y) <=
 * max(1, tan^2 Y), so u = r Rot(beta) sigma (sech s, tanh s) has |u| <= r g(Y), g(Y)^2 = 1 / cos^2
 * Y + max(1, tan^2 Y), and w = L^{-T} u has |w| <= M = |L^{-1}|_F r g(Y). Cauchy's estimate: the
 * n-th Taylor coefficient of u about t0 is at most r g / rho^n. And q(t0 + z) = q(t0) (x) V(z) with
 * V' = 1/2 V (x) (0, w): right multiplication by (0, a + ib), a and b real, has norm <= |a| + |b|
 * <= sqrt2 |w| on complex quaternions, so |V| <= exp(M rho / sqrt2) on the disc and the n-th
 * coefficient of q is at most |q(t0)| exp(M rho / sqrt2) / rho^n. With x = h / rho <= 1/2, the
 * tails past order P are at most 2 x^(P+1) times r g and |q(t0)| exp(M rho / sqrt2). The step is x
 * rho with the largest x that keeps both below REFATT_TAIL relative to |u| = r and |q|. At a steady
 * rotation (ex->fixed) w is the constant w0: g = 1 and M = |w0|. */
#define REFATT_TAIL 0x1p-64 /* one rounding of a long double */

/* A proved step and its disc: h = x rho, and W = max(g, exp(M rho / sqrt2)), which bounds the n-th
 * scaled terms of a step h' <= h by |q| W (h' / rho)^n (and u's by r W (h' / rho)^n). */
typedef struct {
    double h, rho, W;
} disc_step;

static disc_step step_on_disc(double rho, double M, double g)
{
    const double worst = fmax(g, exp(M * rho / sqrt(2.0)));
    const double x = fmin(0.5, pow(REFATT_TAIL / (2.0 * worst), 1.0 / (SUS_REFATT_ORDER + 1)));
    return (disc_step){x * rho, rho, worst};
}

/* |L^{-1}|_F, a bound of |L^{-T}|_2. */
static double inverse_norm(const sus_exact *ex)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    return sqrt(a * a + b * b + c * c);
}

static disc_step proved_step(const sus_exact *ex)
{
    const double half_pi = 1.5707963267948966, w0 = hypot(ex->w0[0], ex->w0[1]);
    if (ex->fixed && !(w0 > 0.0))
        return (disc_step){INFINITY, INFINITY, 1.0}; /* w = 0: q is constant */
    const double k = ex->fixed ? 0.0 : ex->k, scale = ex->fixed ? w0 : inverse_norm(ex) * ex->r;
    disc_step best = {0.0, INFINITY, 1.0};
    /* candidates: rho = 2^j sqrt2 / scale (the exponential's scale) and Y = k rho on a grid of
     * (0, pi/2) (the strip's); each is kept only where its Y is inside the strip */
    for (int i = 0; i < 48 + 63; i++) {
        const double rho =
            i < 48 ? ldexp(sqrt(2.0) / scale, i - 24) : half_pi * (i - 47) / 64.0 / k;
        const double Y = k * rho;
        if (!(Y < half_pi) || !(rho > 0.0))
            continue;
        const double c = cos(Y), t = tan(Y),
                     g = ex->fixed ? 1.0 : sqrt(1.0 / (c * c) + fmax(1.0, t * t));
        const disc_step d = step_on_disc(rho, scale * g, g);
        if (d.h > best.h)
            best = d;
    }
    return best;
}

long double sus_refatt_step(const sus_exact *ex) { return proved_step(ex).h; }

/* The order a step h <= the proved one needs: the least m with 2 W (h / rho)^(m+1) <= REFATT_TAIL,
 * the bound the proved step meets at SUS_REFATT_ORDER (or it, when rounding leaves that bound a
 * hair above). A partial step far shorter than the grid's (a row at a small --eps) needs few
 * terms; at h = 1e-250 the terms it leaves out would be long-double subnormals, each operation on
 * them a hundred times slower. */
static int order_for(const sus_refatt *ra, long double h)
{
    const double y = (double)(h / ra->rho);
    double tail = 2.0 * ra->W * y;
    int m = 0;
    while (m < SUS_REFATT_ORDER && !(tail <= REFATT_TAIL)) {
        tail *= y;
        m++;
    }
    return m;
}

/* The steady tail. With a = sigma s = sigma s0 + k t (exact.h), (cos psi, sin psi) - (0, 1) has
 * norm at most sech a + (1 - tanh a) <= 2 sech a <= 4 e^{-a} for a >= 0, and w = L^{-T} u, |u| = r,
 * so |w(t) - w*| <= 4 |L^{-1}|_F r e^{-a}. Two solutions of q' = 1/2 q (x) (0, w) from the same
 * q(t_s) differ by at most half the integral of |w - w*| (their propagators are unit quaternions),
 * which is <= 2 |L^{-1}|_F r e^{-a_s} / k. Setting that to REFATT_TAIL gives a_s; past t_s the
 * attitude is the steady rotation's, q(t) = q(t_s) (x) (cos(theta/2), sin(theta/2) w* / |w*|),
 * theta = (t - t_s) |w*|, in closed form. A motion that starts at a steady rotation (ex->fixed) is
 * in its tail from the start. */
static double steady_time(const sus_exact *ex)
{
    if (ex->fixed)
        return -INFINITY;
    const double a_s = log(2.0 * inverse_norm(ex) * ex->r / (ex->k * REFATT_TAIL));
    const double t_s = (fmax(a_s, 0.0) - ex->sigma * ex->s0) / ex->k;
    return isnan(t_s) ? INFINITY : t_s;
}

/* The steady phase in 113-bit arithmetic: its angle (t - t_s) |w*| grows without bound, so the
 * speed |w*| must be good to far below a long double's rounding for R(t) to stay within 2^-53 at
 * large t (in long double, 20 roundings of |w*| on a near-singular I_m reach 2^-51 after 300
 * radians). GCC and clang have __float128 on x86-64; where long double is binary128 already
 * (WebAssembly, aarch64) it is used. */
#if defined(__SIZEOF_FLOAT128__) && __LDBL_MANT_DIG__ < 113
typedef __float128 quad;
#else
typedef long double quad;
#endif

/* sqrt to 113 bits: one Newton step from the long-double root doubles its 64 bits. */
static quad quad_sqrt(quad x)
{
    const long double y = sqrtl((long double)x);
    if (!(y > 0.0L) || !isfinite(y))
        return y;
    return ((quad)y + x / y) / 2;
}

/* w*: psi -> pi/2 in exact.h puts it along +J b, J b = (-b2, b1) (L^{-T} J L^{-1} = J / |L|), on
 * the energy of w0: |w*| = |b| sqrt(<I_m w0, w0> / <I_m Jb, Jb>). Products of doubles are exact in
 * 113 bits, so the two quadratic forms lose nothing to a near-singular I_m. The axis w* / |w*|
 * needs no more than long double: an error in it does not grow with t. */
/* |d|^2, exact in 113 bits. */
static quad norm2_q(const double d[2]) { return (quad)d[0] * d[0] + (quad)d[1] * d[1]; }

static quad steady_speed(const sus_exact *ex, const double d[2])
{
    const double(*I)[3] = ex->model->I;
    const quad nd = norm2_q(d);
    if (ex->fixed)
        return quad_sqrt(nd);
    const quad w0 = ex->w0[0], w1 = ex->w0[1],
               e0 = I[0][0] * w0 * w0 + 2 * I[1][0] * w0 * w1 + I[1][1] * w1 * w1;
    const quad ed =
        I[0][0] * (quad)d[0] * d[0] + 2 * I[1][0] * (quad)d[0] * d[1] + I[1][1] * (quad)d[1] * d[1];
    return quad_sqrt(e0 * nd / ed);
}

/* w*'s direction, not normalised: w0 for a motion that stays there, else J b. */
static void steady_direction(const sus_exact *ex, double d[2])
{
    const double *b = ex->model->b;
    d[0] = ex->fixed ? ex->w0[0] : -b[1];
    d[1] = ex->fixed ? ex->w0[1] : b[0];
}

static void steady_rotation(sus_refatt *ra)
{
    double d[2];
    steady_direction(ra->ex, d);
    const quad speed = steady_speed(ra->ex, d);
    const long double n = sqrtl((long double)norm2_q(d));
    ra->axis[0] = n > 0 ? d[0] / n : 1.0L;
    ra->axis[1] = n > 0 ? d[1] / n : 0.0L;
    ra->speed[0] = (long double)speed;
    ra->speed[1] = (long double)(speed - ra->speed[0]);
}

/* q (x) (cos(theta/2), sin(theta/2) a), theta = tau |w*|, a the axis (0 on the third): the steady
 * rotation over tau. Half the angle is formed and reduced modulo 2 pi (to 128 bits, hi + lo) in
 * 113 bits; beyond 2^100 the phase is lost to the rounding of t already, and any angle will do. */
static void steady_advance(const sus_refatt *ra, quad tau, long double p[4])
{
    const quad two_pi = (quad)0xc90fdaa22168c235p-61L - (quad)0xece675d1fc8f8cbbp-127L;
    quad half = tau * ((quad)ra->speed[0] + ra->speed[1]) / 2;
    if (half < 0x1p100)
        half -= two_pi * (quad)(long double)floorl((long double)(half / two_pi));
    const long double h = half < 0x1p100 ? (long double)half : 0.0L, c = cosl(h), sn = sinl(h);
    const long double x = sn * ra->axis[0], y = sn * ra->axis[1];
    const long double *q = ra->q_s;
    p[0] = q[0] * c - q[1] * x - q[2] * y;
    p[1] = q[1] * c + q[0] * x - q[3] * y;
    p[2] = q[2] * c + q[3] * x + q[0] * y;
    p[3] = q[3] * c - q[2] * x + q[1] * y;
}

/* From t to t1 in equal steps of at most h. A stretch of 2^62 steps or more (or an infinite one)
 * cannot be run in any useful time, and its step count would not convert to an integer (undefined
 * behaviour): it gives no answer, a non-finite attitude. Callers check the cost first
 * (sus_exact_reference_steps). */
static void integrate(sus_refatt *ra, double t1)
{
    const long double steps = ceill(((long double)t1 - ra->t) / ra->h);
    if (!(steps < 0x1p62L)) {
        ra->q[0] = ra->q[1] = ra->q[2] = ra->q[3] = NAN;
        return;
    }
    const long n = (long)steps;
    const long double h = n > 0 ? ((long double)t1 - ra->t) / n : 0.0L;
    const int order = order_for(ra, h);
    for (long k = 0; k < n; k++) {
        precise_step(&ra->chol, h, order, ra->u, ra->q);
        closed_u(&ra->closed, ra->t + (k + 1) * h, ra->u); /* u's own series is not carried on */
    }
    ra->t = t1;
}

void sus_refatt_init(sus_refatt *ra, const sus_exact *ex, double t0, const double R0[3][3])
{
    double q[4];
    ra->ex = ex;
    chol_init(&ra->chol, ex->model);
    closed_init(&ra->closed, &ra->chol, ex);
    const disc_step d = proved_step(ex);
    ra->h = d.h;
    ra->rho = d.rho;
    ra->W = d.W;
    ra->t = t0;
    ra->t0 = t0;
    ra->grid = 0.0;
    /* u(t0): L^T w0 itself at t0 = 0 (the closed form there, an ulp off, would be 3e-15 in R(50));
     * else the closed form in long double. Not L^T of the double closed form w(t0): that w carries
     * a few roundings of r |L^{-1}|, which L^T turns into a few roundings of r |L| |L^{-1}| in u,
     * whose size is r: on a near-singular I_m, far above u's own rounding (test_refattitude). */
    if (t0 == 0.0)
        memcpy(ra->u, ra->closed.u0, sizeof ra->u);
    else
        closed_u(&ra->closed, t0, ra->u);
    sus_quat_from_rotation(R0, q);
    for (int i = 0; i < 4; i++)
        ra->q[i] = q[i];
    ra->t_s = fmax(steady_time(ex), t0);
    ra->steady = 0;
    steady_rotation(ra);
}

/* The tail from q(t_s), ra->q_s. */
static void tail_at(const sus_refatt *ra, double t1, double R[3][3])
{
    long double q[4];
    steady_advance(ra, (quad)t1 - ra->t_s, q);
    rotation_of(q, R);
}

void sus_refatt_advance(sus_refatt *ra, double t1, double R[3][3])
{
    if (isnan(t1)) {
        no_answer(R);
        return;
    }
    if (!ra->steady && t1 > ra->t) {
        integrate(ra, fmin(t1, ra->t_s));
        if (t1 > ra->t_s) {
            memcpy(ra->q_s, ra->q, sizeof ra->q_s);
            ra->steady = 1;
        }
    }
    if (!ra->steady) {
        rotation_of(ra->q, R);
        return;
    }
    ra->t = fmax(t1, ra->t);
    tail_at(ra, ra->t, R);
}

/* q(t1) for t0 <= t1 <= t_s, along the grid t0 + j h (sus_refatt_at); -1 for no answer. */
static int grid_state(sus_refatt *ra, double t1, long double q[4])
{
    const long double span = (long double)t1 - ra->t0, whole = floorl(span / ra->h);
    if (!(whole < 0x1p62L))
        return -1;
    for (; ra->grid < whole; ra->grid++) {
        precise_step(&ra->chol, ra->h, order_for(ra, ra->h), ra->u, ra->q);
        closed_u(&ra->closed, ra->t0 + (ra->grid + 1) * ra->h, ra->u);
    }
    memcpy(q, ra->q, sizeof ra->q);
    const long double rest = span - ra->grid * ra->h;
    if (rest > 0.0L)
        precise_step(&ra->chol, rest, order_for(ra, rest), ra->u, q);
    return 0;
}

void sus_refatt_at(sus_refatt *ra, double t1, double R[3][3])
{
    long double q[4];
    if (!(t1 > ra->t_s)) {
        if (grid_state(ra, t1, q) != 0)
            no_answer(R);
        else
            rotation_of(q, R);
        return;
    }
    if (!ra->steady && grid_state(ra, ra->t_s, ra->q_s) != 0) {
        no_answer(R);
        return;
    }
    ra->steady = 1;
    tail_at(ra, t1, R);
}

void sus_refatt_precise(const sus_model *m, const double w0[2], double T, double w[2],
                        double R[3][3])
{
    sus_exact ex;
    sus_refatt ra;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    long double wl[2];
    sus_exact_init(&ex, m, w0);
    sus_refatt_init(&ra, &ex, 0.0, I3);
    sus_refatt_advance(&ra, T, R);
    if (ra.steady) {
        wl[0] = (ra.speed[0] + ra.speed[1]) * ra.axis[0];
        wl[1] = (ra.speed[0] + ra.speed[1]) * ra.axis[1];
    } else {
        w_of_u(&ra.chol, ra.u, wl);
    }
    w[0] = (double)wl[0];
    w[1] = (double)wl[1];
}

void sus_refatt_increment(const sus_exact *ex, double t0, double t1, double Phi[3][3])
{
    sus_refatt ra;
    const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_refatt_init(&ra, ex, t0, I3);
    sus_refatt_advance(&ra, t1, Phi);
}
