#define _POSIX_C_SOURCE 200809L
#include "bench_reproduce.h"

#include "bench_longrun.h"
#include "so3.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define T_END SUS_LAB_BENCH_T_END

void sus_lab_bench_suslov_args_to(const sus_lab_bench_series *s, int j, double T, char *buf,
                                  size_t len)
{
    const char *method = s->me->type->name;
    if (s->tol_driven) {
        snprintf(buf, len, "--method %s --tol %.17g --time %.17g --every-time %.17g", method,
                 s->param[j], T, T);
        return;
    }
    const int n = snprintf(buf, len, "--method %s", method);
    if (n < 0 || (size_t)n >= len)
        return;
    if (!sus_lab_bench_own_attitude(s->me)) /* else suslov warns that it ignores it */
        snprintf(buf + n, len - (size_t)n, " --reconstruct %s", SUS_RECON_NAMES[s->recon]);
    const long N = T == T_END ? s->steps[j] : lround(T / s->param[j]);
    snprintf(buf + strlen(buf), len - strlen(buf), " --eps %.17g --steps %ld",
             T == T_END ? s->param[j] : T / (double)N, N);
}

void sus_lab_bench_suslov_args(const sus_lab_bench_series *s, int j, char *buf, size_t len)
{
    sus_lab_bench_suslov_args_to(s, j, T_END, buf, len);
}

/* The 16 numbers of the last line a command prints into v; returns 0, or -1. */
static int last_row_of(const char *cmd, double v[16])
{
    char line[4096], last[4096] = "";
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    while (fgets(line, sizeof line, p))
        memcpy(last, line, sizeof last);
    if (pclose(p) != 0)
        return -1;
    char *q = last;
    for (int i = 0; i < 16; i++) {
        char *end;
        v[i] = strtod(q, &end);
        if (end == q)
            return -1;
        q = end + (*end == ',');
    }
    return 0;
}

/* Runs `suslov ARGS` (one row: the last, by --every N, or --every-time T for a --tol run) for
 * point j of s to T, and reads where it ends. Returns 0, or -1 when it failed. */
static int rerun(const char *suslov, const sus_lab_bench_series *s, int j, double T, double w[2],
                 double R[3][3])
{
    char args[256], cmd[4096];
    double v[16];
    sus_lab_bench_suslov_args_to(s, j, T, args, sizeof args);
    snprintf(cmd, sizeof cmd, "%.3000s %.255s", suslov, args);
    if (!s->tol_driven)
        snprintf(cmd + strlen(cmd), sizeof cmd - strlen(cmd), " --every %ld",
                 T == T_END ? s->steps[j] : lround(T / s->param[j]));
    if (last_row_of(cmd, v) != 0)
        return -1;
    w[0] = v[2];
    w[1] = v[3];
    for (int i = 0; i < 9; i++)
        R[i / 3][i % 3] = v[7 + i];
    return 0;
}

/* Whether suslov's run of point j of s to t = 50 ends with the errors the bench recorded. */
static int same_errors(const sus_lab_bench *b, const char *suslov, const sus_lab_bench_series *s,
                       int j)
{
    double w[2], R[3][3];
    if (rerun(suslov, s, j, T_END, w, R) != 0)
        return 0;
    const double dw = fabs(hypot(w[0] - b->pb.w_T[0], w[1] - b->pb.w_T[1]) - s->err_w[j]);
    const double dR = s->w_only ? 0.0 : fabs(sus_so3_dist(b->pb.R_T, R) - s->err_R[j]);
    return dw <= 1e-15 * fmax(1.0, s->err_w[j] * 1e6) && dR <= 1e-15 * fmax(1.0, s->err_R[j] * 1e6);
}

/* Whether suslov's run of point j of s to T ends where the bench's did (R_end): the same code
 * path, and rows printed to 17 digits, which read back exactly, so the same matrix entries. (Not
 * sus_so3_dist: |R R^T - I| of one matrix is its orthogonality defect, a few u, not 0.) */
static int same_end(const char *suslov, const sus_lab_bench_series *s, int j, double T,
                    const double R_end[3][3])
{
    double w[2], R[3][3], d = 0.0;
    if (rerun(suslov, s, j, T, w, R) != 0)
        return 0;
    for (int i = 0; i < 9; i++)
        d = fmax(d, fabs(R[i / 3][i % 3] - R_end[i / 3][i % 3]));
    return d == 0.0;
}

static void count(sus_lab_bench_reproduced *out, int ok, int series, int point, double T)
{
    out->tried++;
    if (ok)
        out->ok++;
    else
        out->failed[out->nfailed++] = (sus_lab_bench_unreproduced){series, point, T};
}

void sus_lab_bench_check_reproduce(const sus_lab_bench *b, const char *suslov,
                                   sus_lab_bench_reproduced *out)
{
    *out = (sus_lab_bench_reproduced){0};
    for (int l = 0; l < 2 * SUS_LAB_BENCH_NLEVELS; l++) { /* the attitude levels, then w's */
        const sus_lab_bench_best o =
            sus_lab_bench_fastest(b, SUS_LAB_BENCH_LEVELS[l % SUS_LAB_BENCH_NLEVELS],
                                  l < SUS_LAB_BENCH_NLEVELS, sus_lab_bench_is_ours_preserving);
        if (o.series >= 0)
            count(out, same_errors(b, suslov, b->S[o.series], o.point), o.series, o.point, T_END);
    }
    const int k = sus_lab_bench_best_equal_error(b);
    if (k >= 0) {
        const sus_lab_bench_equal_error *e = &b->EQ[k];
        count(out, same_end(suslov, b->S[e->series], e->point, SUS_LAB_BENCH_T_LONG, e->R_end),
              e->series, e->point, SUS_LAB_BENCH_T_LONG);
    }
    const sus_lab_bench_growth *g = &b->growth;
    if (g->series >= 0)
        count(out, same_end(suslov, b->S[g->series], g->point, SUS_LAB_BENCH_T_GROWTH, g->R_end),
              g->series, g->point, SUS_LAB_BENCH_T_GROWTH);
}
