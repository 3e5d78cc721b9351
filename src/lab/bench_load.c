#include "bench_load.h"

#include "bench_floor.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* bench.csv's columns, as bench_tables.c writes them. */
enum {
    C_SECTION,
    C_METHOD,
    C_KIND,
    C_SOLVES,
    C_PRESERVES,
    C_PARAM,
    C_STEPS,
    C_ERR_W,
    C_ERR_R,
    C_SEC,
    C_SMIN,
    C_SMAX,
    C_NS,
    C_NEWTON,
    C_ARGS,
    NCOLS
};

#define LINE_MAX_CHARS 2048

/* Splits a CSV line in place into f[NCOLS] (a quoted field may hold commas; no field of the
 * bench's holds a quote). Returns the number of fields. */
static int split_csv(char *line, char *f[NCOLS])
{
    int n = 0, quoted = 0;
    char *out = line;
    f[n++] = out;
    for (char *p = line; *p && *p != '\n'; p++) {
        if (*p == '"')
            quoted = !quoted;
        else if (*p == ',' && !quoted) {
            *out++ = '\0';
            if (n == NCOLS)
                return NCOLS + 1;
            f[n++] = out;
        } else
            *out++ = *p;
    }
    *out = '\0';
    return n;
}

/* A number field: NAN for an empty one, -1 from ok for one that is not a number. */
static double num(const char *s, int *ok)
{
    if (!*s)
        return NAN;
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end || errno == ERANGE)
        *ok = 0;
    return v;
}

static int same_series(const sus_lab_bench_series *s, char *f[NCOLS])
{
    return strcmp(s->name, f[C_METHOD]) == 0 && s->ours == (strcmp(f[C_KIND], "ours") == 0) &&
           s->w_only == (strcmp(f[C_SOLVES], "w") == 0) &&
           s->reduced == (strcmp(f[C_SOLVES], "R given w(t)") == 0);
}

/* A work row: the next point of the last series, or the first of a new one. */
static int work_row(sus_lab_bench *b, char *f[NCOLS])
{
    sus_lab_bench_series *s = b->nseries ? b->S[b->nseries - 1] : NULL;
    if (!s || !same_series(s, f)) {
        s = sus_lab_bench_new_series(b);
        snprintf(s->name, sizeof s->name, "%s", f[C_METHOD]);
        s->ours = strcmp(f[C_KIND], "ours") == 0;
        s->w_only = strcmp(f[C_SOLVES], "w") == 0;
        s->reduced = strcmp(f[C_SOLVES], "R given w(t)") == 0;
        s->preserves = strcmp(f[C_PRESERVES], "yes") == 0;
    }
    if (s->n >= SUS_LAB_BENCH_MAXPTS)
        return -1;
    int ok = 1;
    const int j = s->n++;
    s->param[j] = num(f[C_PARAM], &ok);
    s->steps[j] = (long)num(f[C_STEPS], &ok);
    s->err_w[j] = num(f[C_ERR_W], &ok);
    s->err_R[j] = s->w_only ? INFINITY : num(f[C_ERR_R], &ok);
    s->sec[j] = num(f[C_SEC], &ok);
    s->smin[j] = num(f[C_SMIN], &ok);
    s->smax[j] = num(f[C_SMAX], &ok);
    b->npoints++;
    return ok && isfinite(s->sec[j]) ? 0 : -1;
}

static void *regrow(void *p, size_t n, size_t size)
{
    p = realloc(p, n * size);
    if (!p)
        sus_lab_bench_die("out of memory");
    return p;
}

static void grow_costs(sus_lab_bench_costs *c)
{
    const size_t n = (size_t)++c->n;
    c->name = regrow(c->name, n, sizeof *c->name);
    c->ns_raw = regrow(c->ns_raw, n, sizeof *c->ns_raw);
    c->ns_full = regrow(c->ns_full, n, sizeof *c->ns_full);
}

/* A step row: our method's w-step (a new method), then its whole step; GSL's rk4; the closed
 * form. */
static int step_row(sus_lab_bench *b, char *f[NCOLS])
{
    sus_lab_bench_costs *c = &b->cost;
    int ok = 1;
    const double ns = num(f[C_NS], &ok);
    const int ours = strcmp(f[C_KIND], "ours") == 0;
    if (ours && strcmp(f[C_SOLVES], "w") == 0) {
        grow_costs(c);
        snprintf(c->name[c->n - 1], sizeof c->name[0], "%s", f[C_METHOD]);
        c->ns_raw[c->n - 1] = c->ns_full[c->n - 1] = ns;
    } else if (ours && strcmp(f[C_SOLVES], "w+R") == 0 && c->n > 0)
        c->ns_full[c->n - 1] = ns;
    else if (strcmp(f[C_KIND], "peer") == 0)
        c->ns_gsl_rk4 = ns;
    else if (strcmp(f[C_KIND], "closed form") == 0)
        c->ns_exact = ns;
    else if (strcmp(f[C_KIND], "closed form (one exp)") != 0) /* not drawn */
        return -1;
    return ok && ns > 0.0 ? 0 : -1;
}

static int row(sus_lab_bench *b, char *line)
{
    char *f[NCOLS];
    if (split_csv(line, f) != NCOLS)
        return -1;
    if (strcmp(f[C_SECTION], "work") == 0)
        return work_row(b, f);
    if (strcmp(f[C_SECTION], "step") == 0)
        return step_row(b, f);
    return strcmp(f[C_SECTION], "longrun") == 0 ? 0 : -1;
}

int sus_lab_bench_load(sus_lab_bench *b, const char *dir)
{
    char path[4096], line[LINE_MAX_CHARS];
    *b = (sus_lab_bench){0};
    snprintf(path, sizeof path, "%s/bench.csv", dir);
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "bench: cannot read %s: %s\n", path, strerror(errno));
        return -1;
    }
    int lineno = 1, bad = !fgets(line, sizeof line, fp) || strncmp(line, "section,", 8) != 0;
    while (!bad && fgets(line, sizeof line, fp)) {
        lineno++;
        bad = row(b, line) != 0;
    }
    fclose(fp);
    if (bad || b->nseries == 0 || b->cost.n == 0) {
        fprintf(stderr, "bench: %s, line %d: not a row of the bench's data\n", path, lineno);
        sus_lab_bench_free(b);
        return -1;
    }
    sus_lab_bench_envelopes(b);
    return 0;
}
