#include "bench_floor.h"

#include "dsp.h"

#include <gsl/gsl_sort.h>
#include <stdlib.h>

int sus_lab_bench_is_peer(const sus_lab_bench_series *s) { return !s->ours && !s->reduced; }
int sus_lab_bench_is_reduced_peer(const sus_lab_bench_series *s) { return !s->ours && s->reduced; }
/* Ours with an attitude (not w alone). */
static int is_ours_attitude(const sus_lab_bench_series *s) { return s->ours && !s->w_only; }
int sus_lab_bench_is_ours_preserving(const sus_lab_bench_series *s)
{
    return s->ours && s->preserves;
}

/* The fastest point by the median of its rounds (by_min 0) or by its fastest round (by_min 1). */
static sus_lab_bench_best fastest_by(const sus_lab_bench *b, double level, int which,
                                     int (*want)(const sus_lab_bench_series *), int by_min)
{
    sus_lab_bench_best best = {INFINITY, -1, -1};
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        if (!want(s))
            continue;
        for (int j = 0; j < s->n; j++) {
            const double e = which ? s->err_R[j] : s->err_w[j], t = by_min ? s->smin[j] : s->sec[j];
            if (e <= level && t < best.sec)
                best = (sus_lab_bench_best){t, i, j};
        }
    }
    return best;
}

sus_lab_bench_best sus_lab_bench_fastest(const sus_lab_bench *b, double level, int which,
                                         int (*want)(const sus_lab_bench_series *))
{
    return fastest_by(b, level, which, want, 0);
}

/* The points (time and error) of the series that want selects into sec and err; returns how
 * many. */
static int series_points(const sus_lab_bench *b, int which,
                         int (*want)(const sus_lab_bench_series *), double *sec, double *err)
{
    int n = 0;
    for (int i = 0; i < b->nseries; i++)
        if (want(b->S[i]))
            for (int j = 0; j < b->S[i]->n; j++) {
                sec[n] = b->S[i]->sec[j];
                err[n] = which ? b->S[i]->err_R[j] : b->S[i]->err_w[j];
                n++;
            }
    return n;
}

static void build_envelope(const sus_lab_bench *b, int which,
                           int (*want)(const sus_lab_bench_series *), sus_lab_bench_envelope *e)
{
    const size_t np = (size_t)b->npoints;
    double *sec = sus_lab_bench_calloc(np, sizeof *sec),
           *err = sus_lab_bench_calloc(np, sizeof *err);
    size_t *idx = sus_lab_bench_calloc(np, sizeof *idx);
    e->sec = sus_lab_bench_calloc(np, sizeof *e->sec);
    e->err = sus_lab_bench_calloc(np, sizeof *e->err);
    const int n = series_points(b, which, want, sec, err);
    gsl_sort_index(idx, sec, 1, (size_t)n);
    e->n = 0;
    double best = INFINITY;
    for (int k = 0; k < n; k++) {
        const size_t p = idx[k];
        if (err[p] < best) {
            best = err[p];
            e->sec[e->n] = sec[p];
            e->err[e->n] = err[p];
            e->n++;
        }
    }
    free(sec);
    free(err);
    free(idx);
}

void sus_lab_bench_envelopes(sus_lab_bench *b)
{
    build_envelope(b, 0, sus_lab_bench_is_peer, &b->env[0]);
    build_envelope(b, 1, sus_lab_bench_is_peer, &b->env[1]);
    build_envelope(b, 1, sus_lab_bench_is_reduced_peer, &b->env[2]);
    build_envelope(b, 1, is_ours_attitude, &b->env[3]);
}

/* Implicit steps are left out: their Newton iterations, hence their cost, depend on the step. A
 * tolerance-driven method's steps at a TOL cost what its bare loop measured at that TOL. */
double sus_lab_bench_floor_seconds(const sus_lab_bench *b, double level, int which)
{
    double best = INFINITY;
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        const sus_step_method *me = s->ours && s->preserves ? s->me : NULL;
        if (!me || me->type->desc.implicit || (which && s->w_only))
            continue;
        const int m = s->tol_driven ? -1 : sus_step_method_index_of(me->type);
        for (int j = 0; j < s->n; j++) {
            const double ns = m < 0       ? s->step_ns[j]
                              : s->w_only ? b->cost.ns_raw[m]
                                          : b->cost.ns_full[m];
            if ((which ? s->err_R[j] : s->err_w[j]) <= level)
                best = fmin(best, (double)s->steps[j] * 1e-9 * ns);
        }
    }
    return best;
}

const char *sus_lab_bench_comparison_name(sus_lab_bench_comparison c)
{
    return c == SUS_LAB_BENCH_ATT_FULL      ? "attitude"
           : c == SUS_LAB_BENCH_ATT_REDUCED ? "attitude-reduced"
                                            : "omega";
}

sus_lab_bench_level sus_lab_bench_level_verdict(const sus_lab_bench *b, sus_lab_bench_comparison c,
                                                int l)
{
    const double level = SUS_LAB_BENCH_LEVELS[l];
    const int which = c != SUS_LAB_BENCH_W_INFO;
    int (*peer)(const sus_lab_bench_series *) =
        c == SUS_LAB_BENCH_ATT_REDUCED ? sus_lab_bench_is_reduced_peer : sus_lab_bench_is_peer;
    sus_lab_bench_level v = {fastest_by(b, level, which, sus_lab_bench_is_ours_preserving, 0),
                             fastest_by(b, level, which, peer, 0),
                             INFINITY,
                             0.0,
                             0.0,
                             c == SUS_LAB_BENCH_ATT_FULL      ? SUS_LAB_BENCH_LEVEL_TARGET[l]
                             : c == SUS_LAB_BENCH_ATT_REDUCED ? SUS_LAB_BENCH_REDUCED_TARGET
                                                              : NAN,
                             0,
                             1};
    if (v.ours.series < 0)
        return v;
    v.floor = sus_lab_bench_floor_seconds(b, level, which);
    v.ratio = v.peer.series < 0 ? INFINITY : v.peer.sec / v.ours.sec;
    const sus_lab_bench_best fo = fastest_by(b, level, which, sus_lab_bench_is_ours_preserving, 1),
                             fp = fastest_by(b, level, which, peer, 1);
    v.ratio_fast = fp.series < 0 ? INFINITY : fp.sec / fo.sec;
    v.pass = v.ratio >= v.target;
    v.decided = isnan(v.target) || v.pass == (v.ratio_fast >= v.target);
    return v;
}

const char *sus_lab_bench_level_word(const sus_lab_bench_level *v)
{
    return isnan(v->target) ? "info" : !v->decided ? "UNDECIDED" : v->pass ? "PASS" : "MISS";
}

double sus_lab_bench_rk4_speedup(const sus_lab_bench *b)
{
    return b->cost.ns_gsl_rk4 / b->cost.ns_raw[sus_step_method_index_of(sus_step_rk4)];
}

double sus_lab_bench_implicit_ratio(const sus_lab_bench *b, int m)
{
    return b->cost.ns_raw[m] / b->cost.ns_raw[sus_step_method_index_of(sus_step_rk4)];
}

int sus_lab_bench_implicit_target(const sus_step_method *me)
{
    return me->type->desc.implicit && !sus_lab_bench_composed(me);
}

int sus_lab_bench_implicit_step_pass(const sus_lab_bench *b, int m)
{
    return sus_lab_bench_implicit_ratio(b, m) <= SUS_LAB_BENCH_IMPLICIT_TARGET;
}

int sus_lab_bench_implicit_pass(const sus_lab_bench *b)
{
    int pass = 1;
    for (int m = 0; m < b->cost.n; m++)
        if (sus_lab_bench_implicit_target(sus_step_method_get(m)))
            pass &= sus_lab_bench_implicit_step_pass(b, m);
    return pass;
}
