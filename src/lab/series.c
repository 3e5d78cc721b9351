#include "series.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>
#include <stdlib.h>

#define SERIES_FIELDS 7

int sus_lab_series_init(sus_lab_series *s, long steps, long every)
{
    s->n = 0;
    s->cap = (size_t)(steps / every) + 2;
    double *block = malloc(SERIES_FIELDS * s->cap * sizeof(double));
    double **fields[SERIES_FIELDS] = {&s->t,      &s->w1,     &s->w2, &s->w3,
                                      &s->lambda, &s->energy, &s->mu};
    for (int i = 0; i < SERIES_FIELDS; i++)
        *fields[i] = block ? block + (size_t)i * s->cap : NULL;
    return block ? 0 : -1;
}

void sus_lab_series_free(sus_lab_series *s)
{
    free(s->t);
    s->t = NULL;
    s->n = s->cap = 0;
}

typedef struct {
    sus_lab_series *s;
    const sus_model *m;
} rec_ctx;

static int record(void *vctx, const sus_row *row)
{
    rec_ctx *c = vctx;
    sus_lab_series *s = c->s;
    if (s->n == s->cap)
        return 1;
    double W[3][3], V[3][3], xi[3], P[3][3];
    sus_so3_hat(row->w, W);
    sus_mat3_mul(V, row->R, W);
    sus_mat3_mul_at(P, row->R, V);
    sus_so3_vee(P, xi);
    const size_t i = s->n++;
    s->t[i] = row->t;
    s->w1[i] = row->w[0];
    s->w2[i] = row->w[1];
    s->w3[i] = row->w[2];
    s->lambda[i] = row->lambda;
    s->energy[i] = sus_energy(c->m, row->w);
    s->mu[i] = xi[2];
    return 0;
}

int sus_lab_series_run(sus_lab_series *s, const sus_run_config *cfg, const double w0[2],
                       sus_run_report *report)
{
    rec_ctx c = {s, cfg->model};
    s->n = 0;
    return sus_run(cfg, w0, record, &c, report);
}

void sus_lab_series_exact(sus_lab_series *s, const sus_exact *ex, double dt, size_t n)
{
    s->n = n < s->cap ? n : s->cap;
    for (size_t i = 0; i < s->n; i++) {
        double w[2];
        s->t[i] = (double)i * dt;
        sus_exact_omega(ex, s->t[i], w);
        s->w1[i] = w[0];
        s->w2[i] = w[1];
        s->w3[i] = 0.0;
        s->lambda[i] = sus_lagmult_c(ex->model, w, sus_exact_c(ex, s->t[i]));
        s->energy[i] = sus_energy(ex->model, w);
        s->mu[i] = 0.0;
    }
}

static const double *field_of(const sus_lab_series *s, size_t field)
{
    return *(double *const *)((const char *)s + field);
}

double sus_lab_series_maxdiff(const sus_lab_series *a, const sus_lab_series *b, size_t field)
{
    const double *x = field_of(a, field), *y = field_of(b, field);
    double d = 0.0;
    for (size_t i = 0; i < a->n && i < b->n; i++)
        d = fmax(d, fabs(x[i] - y[i]));
    return d;
}

double sus_lab_series_maxdrift(const sus_lab_series *s, size_t field)
{
    const double *x = field_of(s, field);
    double d = 0.0;
    for (size_t i = 0; i < s->n; i++)
        d = fmax(d, fabs(x[i] - x[0]));
    return d;
}
