#include "series.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>
#include <stdlib.h>

#define SERIES_FIELDS 7

int suslov_series_init(suslov_series *s, long steps, long every)
{
    s->n = 0;
    s->cap = (size_t)(steps / every) + 2;
    double *block = malloc(SERIES_FIELDS * s->cap * sizeof(double));
    double **fields[SERIES_FIELDS] = {&s->t, &s->w1, &s->w2, &s->w3, &s->lambda, &s->energy, &s->mu};
    for (int i = 0; i < SERIES_FIELDS; i++)
        *fields[i] = block ? block + (size_t)i * s->cap : NULL;
    return block ? 0 : -1;
}

void suslov_series_free(suslov_series *s)
{
    free(s->t);
    s->t = NULL;
    s->n = s->cap = 0;
}

typedef struct {
    suslov_series *s;
    const suslov_model *m;
} rec_ctx;

static int record(void *vctx, const suslov_row *row)
{
    rec_ctx *c = vctx;
    suslov_series *s = c->s;
    if (s->n == s->cap)
        return 1;
    double W[3][3], V[3][3], xi[3], P[3][3];
    so3_hat(row->w, W);
    mat3_mul(V, row->R, W);
    mat3_mul_at(P, row->R, V);
    so3_vee(P, xi);
    const size_t i = s->n++;
    s->t[i] = row->t;
    s->w1[i] = row->w[0];
    s->w2[i] = row->w[1];
    s->w3[i] = row->w[2];
    s->lambda[i] = row->lambda;
    s->energy[i] = suslov_energy(c->m, row->w);
    s->mu[i] = xi[2];
    return 0;
}

int suslov_series_run(suslov_series *s, const suslov_run_config *cfg, const double w0[2],
                      suslov_run_report *report)
{
    rec_ctx c = {s, cfg->model};
    s->n = 0;
    return suslov_run(cfg, w0, record, &c, report);
}

void suslov_series_exact(suslov_series *s, const suslov_exact *ex, double dt, size_t n)
{
    s->n = n < s->cap ? n : s->cap;
    for (size_t i = 0; i < s->n; i++) {
        double w[2];
        s->t[i] = (double)i * dt;
        suslov_exact_omega(ex, s->t[i], w);
        s->w1[i] = w[0];
        s->w2[i] = w[1];
        s->w3[i] = 0.0;
        s->lambda[i] = suslov_lagmult(ex->model, w);
        s->energy[i] = suslov_energy(ex->model, w);
        s->mu[i] = 0.0;
    }
}

static const double *field_of(const suslov_series *s, size_t field)
{
    return *(double *const *)((const char *)s + field);
}

double suslov_series_maxdiff(const suslov_series *a, const suslov_series *b, size_t field)
{
    const double *x = field_of(a, field), *y = field_of(b, field);
    double d = 0.0;
    for (size_t i = 0; i < a->n && i < b->n; i++)
        d = fmax(d, fabs(x[i] - y[i]));
    return d;
}

double suslov_series_maxdrift(const suslov_series *s, size_t field)
{
    const double *x = field_of(s, field);
    double d = 0.0;
    for (size_t i = 0; i < s->n; i++)
        d = fmax(d, fabs(x[i] - x[0]));
    return d;
}
