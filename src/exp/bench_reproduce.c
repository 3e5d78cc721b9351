#define _POSIX_C_SOURCE 200809L
#include "bench_reproduce.h"

#include "so3.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define T_END SUS_EXP_BENCH_T_END

void sus_exp_bench_suslov_args(const sus_exp_bench_series *s, int j, char *buf, size_t len)
{
    const char *method = s->me->type->name;
    if (s->tol_driven) {
        snprintf(buf, len, "--method %s --tol %.17g --time %.17g --every-time %.17g", method,
                 s->param[j], T_END, T_END);
        return;
    }
    const int n = snprintf(buf, len, "--method %s", method);
    if (n < 0 || (size_t)n >= len)
        return;
    if (!sus_exp_bench_own_attitude(s->me)) /* else suslov warns that it ignores it */
        snprintf(buf + n, len - (size_t)n, " --reconstruct %s", SUS_RECON_NAMES[s->recon]);
    snprintf(buf + strlen(buf), len - strlen(buf), " --eps %.17g --steps %ld", s->param[j],
             s->steps[j]);
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

/* Runs `suslov ARGS --every N` and the differences of the last row's errors from the bench's. */
static int reproduce(const sus_exp_bench *b, const char *suslov, const sus_exp_bench_series *s,
                     int j, double *dw, double *dR)
{
    char args[256], cmd[4096];
    double v[16];
    sus_exp_bench_suslov_args(s, j, args, sizeof args);
    snprintf(cmd, sizeof cmd, "%.3000s %.255s", suslov, args);
    if (!s->tol_driven) /* one row: the last (a --tol run's comes from --every-time T) */
        snprintf(cmd + strlen(cmd), sizeof cmd - strlen(cmd), " --every %ld", s->steps[j]);
    if (last_row_of(cmd, v) != 0)
        return -1;
    const double R[3][3] = {{v[7], v[8], v[9]}, {v[10], v[11], v[12]}, {v[13], v[14], v[15]}};
    *dw = fabs(hypot(v[2] - b->pb.w_T[0], v[3] - b->pb.w_T[1]) - s->err_w[j]);
    *dR = s->w_only ? 0.0 : fabs(sus_so3_dist(b->pb.R_T, R) - s->err_R[j]);
    return 0;
}

void sus_exp_bench_check_reproduce(const sus_exp_bench *b, const char *suslov,
                                   sus_exp_bench_reproduced *out)
{
    *out = (sus_exp_bench_reproduced){0};
    for (int l = 0; l < 2 * SUS_EXP_BENCH_NLEVELS; l++) { /* the attitude levels, then w's */
        const sus_exp_bench_best o =
            sus_exp_bench_fastest(b, SUS_EXP_BENCH_LEVELS[l % SUS_EXP_BENCH_NLEVELS],
                                  l < SUS_EXP_BENCH_NLEVELS, sus_exp_bench_is_ours_preserving);
        if (o.series < 0)
            continue;
        const sus_exp_bench_series *s = b->S[o.series];
        double dw, dR;
        out->tried++;
        if (reproduce(b, suslov, s, o.point, &dw, &dR) == 0 &&
            dw <= 1e-15 * fmax(1.0, s->err_w[o.point] * 1e6) &&
            dR <= 1e-15 * fmax(1.0, s->err_R[o.point] * 1e6))
            out->ok++;
        else
            out->failed[out->nfailed++] = o;
    }
}
