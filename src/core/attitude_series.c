#include "attitude_series.h"

#include "quaternion.h"
#include "steady_turn.h"

#include <math.h>
#include <string.h>

#define ENVELOPE_TERMS 5 /* as the Taylor steps' envelope (step_exact_attitude.c) */

/* E(t)^dir, formed as one exponential: e^{-dir sigma s}. */
static double variable(const sus_exact_fast *f, int dir, double t)
{
    if (f->fixed || !(f->ks != 0.0))
        return 1.0;
    const double sigma = f->ks > 0.0 ? 1.0 : -1.0;
    return exp(-dir * sigma * (f->s0 + f->ks * t));
}

double sus_att_series_E(const sus_exact_fast *f, double t) { return variable(f, 1, t); }

static double quat_norm(const double q[4])
{
    return sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
}

/* The coefficients are formed in the frame (e_w, e_1, e_3) of the steady rotation: e_w = w_inf /
 * |w_inf|, e_1 = e_3 x e_w, both in the body's plane, and e_3 the constrained axis. There w_inf x
 * turns (x1, x3) by a right angle, multiplication by i |w_inf| of z = x1 + i x3, so (k n - w_inf
 * x)^{-1} divides e_w's component by k n and z by k n - i |w_inf|: a few products a degree, none
 * of them on the chain from one degree to the next. */
typedef struct {
    double aw, a1; /* 2 M e1 in the frame (its e_3 component is 0) */
    double beta;   /* 2 |w_inf|: 2 w_inf = beta e_w */
    double speed;  /* |w_inf| */
} frame_terms;

/* P_n from U_n, V_n: S = U (x) 2 M e1 + V (x) 2 w_inf, then the scalar and e_w parts over k n and
 * z over k n - i |w_inf| (the top of attitude_series.h), each times -1/2. */
static void solve_degree(const frame_terms *c, double kn, const double u[4], const double v[4],
                         double P[4])
{
    const double S0 = -(u[1] * c->aw + u[2] * c->a1) - v[1] * c->beta;
    const double Sw = u[0] * c->aw - u[3] * c->a1 + v[0] * c->beta;
    const double S1 = u[0] * c->a1 + u[3] * c->aw + v[3] * c->beta;
    const double S3 = u[1] * c->a1 - u[2] * c->aw - v[2] * c->beta;
    const double inv = -0.5 / kn, den = -0.5 / (kn * kn + c->speed * c->speed);
    const double cr = kn * den, ci = c->speed * den;
    P[0] = S0 * inv;
    P[1] = Sw * inv;
    P[2] = S1 * cr - S3 * ci;
    P[3] = S1 * ci + S3 * cr;
}

/* The terms past degree n estimated from the last ENVELOPE_TERMS sizes T[n - j] = |P_{n-j}| E^{n-j}
 * projected at a per degree; infinity when a >= 1. */
static double tail_estimate(const double *T, int n, double a)
{
    if (!(a < 1.0))
        return INFINITY;
    double B = 0.0, an = 1.0;
    for (int j = 0; j < ENVELOPE_TERMS; j++) {
        an *= a;
        const double x = T[n - j] * an;
        B = x > B ? x : B; /* the sizes are finite (checked as they come) */
    }
    return B / (1.0 - a);
}

/* The frame's terms of f's motion about the limit wlim. */
static frame_terms frame_of(const sus_exact_fast *f, const double wlim[2], double ew[2])
{
    const double speed = hypot(wlim[0], wlim[1]);
    ew[0] = wlim[0] / speed, ew[1] = wlim[1] / speed;
    const double a0 = 2.0 * f->M[0][0], a1 = 2.0 * f->M[1][0];
    return (frame_terms){a0 * ew[0] + a1 * ew[1], a1 * ew[0] - a0 * ew[1], 2.0 * speed, speed};
}

/* The coefficients, in the frame, to the degree at which twice the estimate at E meets budget;
 * returns that, or -1 (sus_att_series_build). alpha's growth is bounded by e^(alpha / n) <=
 * 1 / (1 - alpha / n) for n > alpha, a division where e^x would be a call. */
static double coefficients(sus_att_series *s, const frame_terms *c, double k, double alpha,
                           double E, double budget)
{
    double U[2][4] = {{0}}, V[2][4] = {{0}}, T[SUS_ATT_SERIES_MAX + 1], mass = 1.0, En = 1.0;
    const double zero[4] = {0.0, 0.0, 0.0, 0.0};
    memcpy(s->P[0], (const double[4]){1.0, 0.0, 0.0, 0.0}, sizeof s->P[0]);
    T[0] = 1.0;
    for (int n = 1; n <= SUS_ATT_SERIES_MAX; n++) {
        double *u = U[n % 2], *v = V[n % 2];
        const double *p2 = n >= 2 ? s->P[n - 2] : zero;
        for (int i = 0; i < 4; i++) { /* U_n, V_n over U_{n-2}, V_{n-2}, which they replace */
            u[i] = s->P[n - 1][i] - u[i];
            v[i] = -p2[i] - v[i];
        }
        solve_degree(c, k * n, u, v, s->P[n]);
        En *= E;
        T[n] = quat_norm(s->P[n]) * En;
        mass += T[n];
        if (!isfinite(T[n]) || mass > SUS_ATT_SERIES_MASS)
            return -1.0;
        if (n < ENVELOPE_TERMS || !(n > alpha))
            continue;
        const double a = E / (1.0 - alpha / n);
        if (!(2.0 * T[n] * a < budget * (1.0 - a))) /* the estimate's first term alone is over */
            continue;
        const double est = 2.0 * tail_estimate(T, n, a);
        if (est <= budget) {
            s->n = n;
            s->mass = mass;
            return est;
        }
    }
    return -1.0;
}

/* P(E) in the body's frame: Horner's rule in the series' frame to the degree past which the terms,
 * at most mass (E / Xmax)^j each (Xmax the variable's largest value), sum below u / 4, then the
 * vector part turned back. */
static void sum_at(const sus_att_series *s, double E, double p[4])
{
    const double r = E / s->Xmax, cut = ceil(log(0.25 * SUS_U * (1.0 - r) / s->mass) / log(r));
    const int n = r < 1.0 && cut < s->n ? (int)cut : s->n;
    double x[4];
    memcpy(x, s->P[n], sizeof x);
    for (int m = n - 1; m >= 0; m--)
        for (int i = 0; i < 4; i++)
            x[i] = x[i] * E + s->P[m][i];
    p[0] = x[0];
    p[1] = x[1] * s->ew[0] - x[2] * s->ew[1];
    p[2] = x[1] * s->ew[1] + x[2] * s->ew[0];
    p[3] = x[3];
}

double sus_att_series_build(sus_att_series *s, const sus_exact_fast *f, double ta, double tb,
                            const double qa[4], double budget)
{
    const double Ea = sus_att_series_E(f, ta), k = fabs(f->ks);
    s->dir = Ea < 1.0 ? 1 : -1;
    /* the variable's largest value on [ta, tb]: at ta past the inflection, at tb before it */
    const double X = s->dir > 0 ? Ea : variable(f, -1, tb);
    if (!(X < 1.0) || !(tb >= ta))
        return -1.0;
    s->wlim[0] = s->dir * f->winf[0], s->wlim[1] = s->dir * f->winf[1];
    const frame_terms c = frame_of(f, s->wlim, s->ew);
    const double alpha = (hypot(f->M[0][0], f->M[1][0]) + hypot(f->M[0][1], f->M[1][1])) / (2 * k);
    const double est = coefficients(s, &c, s->dir * k, alpha, X, budget);
    if (est < 0.0)
        return est;
    double p[4], pinv[4];
    s->ta = ta;
    s->Xmax = X;
    sum_at(s, variable(f, s->dir, ta), p);
    const double n2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3];
    pinv[0] = p[0] / n2;
    for (int i = 1; i < 4; i++)
        pinv[i] = -p[i] / n2;
    sus_quat_mul(s->left, qa, pinv);
    return est;
}

void sus_att_series_at(const sus_att_series *s, const sus_exact_fast *f, const double speed[2],
                       double t, double q[4])
{
    double p[4], x[4];
    memcpy(x, s->left, sizeof x);
    sus_steady_turn(s->wlim, speed, s->ta, t, x);
    sum_at(s, variable(f, s->dir, t), p);
    sus_quat_mul(q, x, p);
}
