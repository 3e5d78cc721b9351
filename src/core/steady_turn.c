#include "steady_turn.h"

#include "quaternion.h"
#include "so3.h"

#include <math.h>
#include <string.h>

/* Double-double numbers, hi + lo with |lo| <= ulp(hi) / 2, by error-free transformations (Dekker;
 * fma gives a product's rounding error exactly). */
typedef struct {
    double hi, lo;
} dd;

static dd renorm(double hi, double lo) /* Fast2Sum, |hi| >= |lo| */
{
    const double s = hi + lo;
    return (dd){s, lo - (s - hi)};
}

static dd dd_add(dd a, dd b)
{
    const double s = a.hi + b.hi, v = s - a.hi, e = (a.hi - (s - v)) + (b.hi - v);
    return renorm(s, e + a.lo + b.lo);
}

static dd dd_mul(dd a, dd b)
{
    const double p = a.hi * b.hi;
    return renorm(p, fma(a.hi, b.hi, -p) + (a.hi * b.lo + a.lo * b.hi));
}

static dd dd_of(double x) { return (dd){x, 0.0}; }

/* a / b: the quotient of the high parts, corrected by the remainder. */
static dd dd_div(dd a, dd b)
{
    const double q = a.hi / b.hi;
    const dd r = dd_add(a, dd_mul(b, dd_of(-q)));
    return renorm(q, r.hi / b.hi);
}

/* sqrt(a), a > 0: the root of the high part, corrected by one Newton step. */
static dd dd_sqrt(dd a)
{
    const double y = sqrt(a.hi);
    const dd r = dd_add(a, dd_mul(dd_of(y), dd_of(-y)));
    return renorm(y, r.hi / (2.0 * y));
}

/* <I_m x, x>, x = (x0, x1), I_m symmetric: I11 x0^2 + 2 I12 x0 x1 + I22 x1^2. */
static dd dd_form(const sus_model *m, const double x[2])
{
    const dd a = dd_mul(dd_mul(dd_of(m->I[0][0]), dd_of(x[0])), dd_of(x[0]));
    const dd b = dd_mul(dd_mul(dd_of(2.0 * m->I[1][0]), dd_of(x[0])), dd_of(x[1]));
    const dd c = dd_mul(dd_mul(dd_of(m->I[1][1]), dd_of(x[1])), dd_of(x[1]));
    return dd_add(dd_add(a, b), c);
}

/* x / 2^k with k the exponent of its larger entry: the forms below then neither over- nor
 * underflow, and the scaling is exact. 0 for x = 0. */
static int scaled(const double x[2], double y[2])
{
    const double m = fmax(fabs(x[0]), fabs(x[1]));
    const int k = m > 0.0 ? ilogb(m) : 0;
    y[0] = ldexp(x[0], -k);
    y[1] = ldexp(x[1], -k);
    return k;
}

/* The speed is homogeneous of degree 1 in w0 and of degree 0 in d: both are scaled near 1. */
void sus_steady_speed(const sus_exact *ex, double speed[2])
{
    const double *b = ex->model->b, jb[2] = {-b[1], b[0]};
    double w[2], d[2];
    const int k = scaled(ex->w0, w);
    scaled(ex->fixed ? w : jb, d);
    dd s2 = dd_add(dd_mul(dd_of(d[0]), dd_of(d[0])), dd_mul(dd_of(d[1]), dd_of(d[1])));
    if (!ex->fixed)
        s2 = dd_div(dd_mul(dd_form(ex->model, w), s2), dd_form(ex->model, d));
    const dd s = s2.hi > 0.0 ? dd_sqrt(s2) : dd_of(0.0);
    speed[0] = ldexp(s.hi, k);
    speed[1] = ldexp(s.lo, k);
}

/* Half the angle (tau + tau_lo) |w_inf| reduced to [-pi, pi]: the product in two parts (fma gives
 * the first's rounding error exactly), the multiple of 2 pi (as hi + lo) taken off the high part by
 * fma, which is exact there. */
static double half_angle(const double speed[2], double tau, double tau_lo)
{
    const double two_pi = 6.283185307179586, two_pi_lo = 2.4492935982947064e-16;
    const double p = tau * speed[0];
    const double e = fma(tau, speed[0], -p) + (tau * speed[1] + tau_lo * speed[0]);
    const double k = nearbyint(0.5 * p / two_pi);
    return fma(-k, two_pi, 0.5 * p) - k * two_pi_lo + 0.5 * e;
}

void sus_steady_turn(const double w_inf[2], const double speed[2], double t0, double t, double q[4])
{
    const dd tau = renorm(t, -t0); /* t - t0 exactly: t >= t0 >= 0 */
    const double n = hypot(w_inf[0], w_inf[1]);
    double s, c, p[4];
    sus_so3_sincos(half_angle(speed, tau.hi, tau.lo), &s, &c);
    const double f = n > 0.0 ? s / n : 0.5 * tau.hi; /* sin(tau |w_inf| / 2) / |w_inf| */
    const double dq[4] = {c, f * w_inf[0], f * w_inf[1], 0.0};
    sus_quat_mul(p, q, dq);
    memcpy(q, p, sizeof p);
}
