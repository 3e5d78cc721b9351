#include "lambda_shift.h"
#include "dsp.h"

#include <math.h>
#include <string.h>

#define N SUS_LAB_SERIES_N

typedef double ser[N];

static void ser_mul(const double *a, const double *b, double *out)
{
    for (int n = 0; n < N; n++) {
        double s = 0.0;
        for (int k = 0; k <= n; k++)
            s += a[k] * b[n - k];
        out[n] = s;
    }
}

/* f(y) = c(y) fA y on a series y; f's series in out. */
static void field_series(const sus_model *m, const sus_lab_wseries *y, sus_lab_wseries *out)
{
    ser c, v0, v1;
    for (int n = 0; n < N; n++) {
        c[n] = m->b[0] * y->c[0][n] + m->b[1] * y->c[1][n];
        v0[n] = m->fA[0][0] * y->c[0][n] + m->fA[0][1] * y->c[1][n];
        v1[n] = m->fA[1][0] * y->c[0][n] + m->fA[1][1] * y->c[1][n];
    }
    ser_mul(c, v0, out->c[0]);
    ser_mul(c, v1, out->c[1]);
}

static void constant(sus_lab_wseries *s, const double w[2])
{
    memset(s, 0, sizeof *s);
    s->c[0][0] = w[0];
    s->c[1][0] = w[1];
}

/* out = w + a eps * s (a series times eps: shifted by one) */
static void w_plus_eps(const double w[2], double a, const sus_lab_wseries *s, sus_lab_wseries *out)
{
    sus_lab_wseries r;
    constant(&r, w);
    for (int i = 0; i < 2; i++)
        for (int n = 1; n < N; n++)
            r.c[i][n] += a * s->c[i][n - 1];
    *out = r;
}

/* (ContDyn): the Taylor series in eps of the exact flow from w (lambda_shift.h). */
void sus_lab_series_flow(const sus_model *m, const double w[2], sus_lab_wseries *s)
{
    sus_lab_wseries f;
    constant(s, w);
    /* y_{n+1} = [t^n] f(y) / (n + 1); [t^n] f(y) needs y_0 .. y_n only */
    for (int n = 0; n + 1 < N; n++) {
        field_series(m, s, &f);
        s->c[0][n + 1] = f.c[0][n] / (n + 1);
        s->c[1][n + 1] = f.c[1][n] / (n + 1);
    }
}

/* y <y, I_m y> on series (the eps^2/4 terms of (taudyn)) */
static void quartic_series(const sus_model *m, const sus_lab_wseries *y, sus_lab_wseries *q)
{
    const double(*I)[3] = m->I;
    ser p0, p1, a, b, s;
    for (int n = 0; n < N; n++) {
        p0[n] = I[0][0] * y->c[0][n] + I[0][1] * y->c[1][n];
        p1[n] = I[1][0] * y->c[0][n] + I[1][1] * y->c[1][n];
    }
    ser_mul(y->c[0], p0, a);
    ser_mul(y->c[1], p1, b);
    for (int n = 0; n < N; n++)
        s[n] = a[n] + b[n];
    ser_mul(y->c[0], s, q->c[0]);
    ser_mul(y->c[1], s, q->c[1]);
}

/* (Discretization) with l = I_m f(w^k): explicit Euler. */
static void euler_series(const sus_model *m, const double w[2], sus_lab_wseries *s)
{
    sus_lab_wseries f, y;
    constant(&y, w);
    field_series(m, &y, &f);
    w_plus_eps(w, 1.0, &f, s);
}

/* (Discretization) with the classical Runge-Kutta increment, stage by stage. */
static void rk4_series(const sus_model *m, const double w[2], sus_lab_wseries *s)
{
    sus_lab_wseries f, k1, k2, k3, k4, y;
    constant(&y, w);
    field_series(m, &y, &k1);
    w_plus_eps(w, 0.5, &k1, &y);
    field_series(m, &y, &k2);
    w_plus_eps(w, 0.5, &k2, &y);
    field_series(m, &y, &k3);
    w_plus_eps(w, 1.0, &k3, &y);
    field_series(m, &y, &k4);
    for (int i = 0; i < 2; i++)
        for (int n = 0; n < N; n++)
            f.c[i][n] = (k1.c[i][n] + 2.0 * k2.c[i][n] + 2.0 * k3.c[i][n] + k4.c[i][n]) / 6.0;
    w_plus_eps(w, 1.0, &f, s);
}

/* (Discretization) with the midpoint l1, l2: x = w + eps f((w + x)/2) solved for x by Picard
 * iteration on the series. */
static void midpoint_series(const sus_model *m, const double w[2], sus_lab_wseries *s)
{
    sus_lab_wseries f;
    constant(s, w);
    for (int it = 0; it < N; it++) {
        sus_lab_wseries mid;
        for (int i = 0; i < 2; i++)
            for (int n = 0; n < N; n++)
                mid.c[i][n] = 0.5 * (s->c[i][n] + (n == 0 ? w[i] : 0.0));
        field_series(m, &mid, &f);
        w_plus_eps(w, 1.0, &f, s);
    }
}

static void variational_series(const sus_model *m, const double w[2], sus_lab_wseries *s)
{
    /* (taudyn): I_m (x - w) + eps/2 T(x, w) + eps^2/4 (q(x) - q(w)) = 0 with
     * T = (x2 c(x) + w2 c(w), -x1 c(x) - w1 c(w)), solved as x = w - I_m^{-1}(...) */
    const double(*I)[3] = m->I;
    const double cw = sus_c(m, w);
    double qw[2];
    const double sw =
        w[0] * (I[0][0] * w[0] + I[0][1] * w[1]) + w[1] * (I[1][0] * w[0] + I[1][1] * w[1]);
    qw[0] = w[0] * sw;
    qw[1] = w[1] * sw;
    constant(s, w);
    for (int it = 0; it < N; it++) {
        sus_lab_wseries q, r;
        ser c, t0, t1;
        for (int n = 0; n < N; n++)
            c[n] = m->b[0] * s->c[0][n] + m->b[1] * s->c[1][n];
        ser_mul(s->c[1], c, t0);
        ser_mul(s->c[0], c, t1);
        quartic_series(m, s, &q);
        /* r = eps/2 T + eps^2/4 (q(x) - q(w)) */
        memset(&r, 0, sizeof r);
        for (int n = 0; n + 1 < N; n++) {
            r.c[0][n + 1] += 0.5 * (t0[n] + (n == 0 ? w[1] * cw : 0.0));
            r.c[1][n + 1] += 0.5 * (-t1[n] - (n == 0 ? w[0] * cw : 0.0));
        }
        for (int n = 0; n + 2 < N; n++) {
            r.c[0][n + 2] += 0.25 * (q.c[0][n] - (n == 0 ? qw[0] : 0.0));
            r.c[1][n + 2] += 0.25 * (q.c[1][n] - (n == 0 ? qw[1] : 0.0));
        }
        const double det = m->det_m;
        for (int n = 0; n < N; n++) {
            const double d0 = (I[1][1] * r.c[0][n] - I[0][1] * r.c[1][n]) / det;
            const double d1 = (-I[1][0] * r.c[0][n] + I[0][0] * r.c[1][n]) / det;
            s->c[0][n] = (n == 0 ? w[0] : 0.0) - d0;
            s->c[1][n] = (n == 0 ? w[1] : 0.0) - d1;
        }
    }
}

/* The steps whose series is derived here, by type. */
static const struct {
    const sus_stepper_type *type;
    void (*series)(const sus_model *m, const double w[2], sus_lab_wseries *s);
} SERIES[] = {{&sus_step_euler_type, euler_series},
              {&sus_step_rk4_type, rk4_series},
              {&sus_step_midpoint_type, midpoint_series},
              {&sus_step_variational_type, variational_series}};

/* (Discretization), and (taudyn) for the variational step: the series in eps of one step of the
 * method from w (lambda_shift.h). */
int sus_lab_series_step(const sus_model *m, const sus_stepper_type *st, const double w[2],
                        sus_lab_wseries *s)
{
    for (size_t i = 0; i < sizeof SERIES / sizeof SERIES[0]; i++)
        if (SERIES[i].type == st) {
            SERIES[i].series(m, w, s);
            return 0;
        }
    return -1;
}

void sus_lab_series_eval(const sus_lab_wseries *s, double eps, double out[2])
{
    for (int i = 0; i < 2; i++) {
        double acc = 0.0;
        for (int n = N - 1; n >= 0; n--)
            acc = acc * eps + s->c[i][n];
        out[i] = acc;
    }
}

/* (LagMult): the gradient of lambda(w) in w. */
void sus_lab_lagmult_grad(const sus_model *m, const double w[2], double g[2])
{
    const double h = 1e-3;
    for (int i = 0; i < 2; i++) {
        double a[2] = {w[0], w[1]}, b[2] = {w[0], w[1]};
        a[i] += h;
        b[i] -= h;
        g[i] = (sus_lagmult(m, a) - sus_lagmult(m, b)) / (2.0 * h);
    }
}

/* (RemarkLambda): l_lambda = -grad lambda(w^{k+1}) . sum_{j=p+1}^{p+nterms} e_j(w^k) eps^j. */
int sus_lab_lambda_shift(const sus_model *m, const sus_stepper_type *st, int p, int nterms,
                         double eps, const double w[2], const double x[2], double *l_lambda)
{
    sus_lab_wseries a, y;
    double g[2], d[2] = {0.0, 0.0};
    if (sus_lab_series_step(m, st, w, &a) != 0)
        return -1;
    sus_lab_series_flow(m, w, &y);
    for (int j = p + 1; j <= p + nterms && j < N; j++)
        for (int i = 0; i < 2; i++)
            d[i] += (a.c[i][j] - y.c[i][j]) * pow(eps, j);
    sus_lab_lagmult_grad(m, x, g);
    *l_lambda = -(g[0] * d[0] + g[1] * d[1]);
    return 0;
}
