#include "bench_tables.h"

#include "atomic_file.h"
#include "bench_floor.h"
#include "bench_longrun.h"
#include "bench_reproduce.h"
#include "dsp.h"
#include "fig_output.h"

#include <math.h>
#include <stdio.h>

#define NLEVELS SUS_LAB_BENCH_NLEVELS
#define LEVELS SUS_LAB_BENCH_LEVELS

/* ---- bench.csv ---- */

/* What a work row's run solves: w and the attitude, the attitude given w(t), or w alone. */
static const char *solves(const sus_lab_bench_series *s)
{
    return s->w_only ? "w" : s->reduced ? "R given w(t)" : "w+R";
}

static void csv_work_rows(FILE *fp, const sus_lab_bench *b)
{
    char args[256];
    for (int i = 0; i < b->nseries; i++) {
        const sus_lab_bench_series *s = b->S[i];
        for (int j = 0; j < s->n; j++) {
            args[0] = '\0';
            if (s->ours)
                sus_lab_bench_suslov_args(s, j, args, sizeof args);
            char eR[32] = ""; /* empty for a w-only row: no attitude */
            if (!s->w_only)
                snprintf(eR, sizeof eR, "%.6g", s->err_R[j]);
            fprintf(fp, "work,\"%s\",%s,%s,%s,%.17g,%ld,%.6g,%s,%.6g,%.6g,%.6g,,,%s\n", s->name,
                    s->ours ? "ours" : "peer", solves(s), s->preserves ? "yes" : "no", s->param[j],
                    s->steps[j], s->err_w[j], eR, s->sec[j], s->smin[j], s->smax[j], args);
        }
    }
}

/* The whole step's name: NAME+RECON with its default reconstruction, or the method's label when
 * it carries its own attitude. */
static const char *whole_step_name(const sus_step_method *me, char *buf, size_t len)
{
    if (!me->type->desc.follows_recon)
        return sus_step_method_label(me->type, me->recon, buf, len);
    snprintf(buf, len, "%s+%s", me->type->name, SUS_RECON_NAMES[me->recon]);
    return buf;
}

static void csv_step_rows(FILE *fp, const sus_lab_bench_costs *c)
{
    char whole[96];
    for (int m = 0; m < c->n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        fprintf(fp, "step,%s,ours,w,,,,,,,,,%.4g,%.3g,\n", me->type->name, c->ns_raw[m],
                c->newton[m]);
        fprintf(fp, "step,%s,ours,w+R,,,,,,,,,%.4g,%.3g,\n",
                whole_step_name(me, whole, sizeof whole), c->ns_full[m], c->newton[m]);
    }
    fprintf(fp, "step,gsl-rk4-driver,peer,w,,,,,,,,,%.4g,,\n", c->ns_gsl_rk4);
    fprintf(fp, "step,exact-omega,closed form,w(t),,,,,,,,,%.4g,,\n", c->ns_exact);
    fprintf(fp, "step,exact-omega-one-exp,closed form (one exp),w(t),,,,,,,,,%.4g,,\n",
            c->ns_exact_one_exp);
}

static void write_csv(FILE *fp, const sus_lab_bench *b)
{
    /* the method field is quoted: peer names such as "GSL rk8pd (w,q)" hold a comma */
    fprintf(fp, "section,method,kind,solves,preserves,parameter,steps,omega_error,attitude_error,"
                "seconds_median,seconds_min,seconds_max,ns_per_step,newton_per_step,suslov_args\n");
    csv_work_rows(fp, b);
    csv_step_rows(fp, &b->cost);
    for (int i = 0; i < b->nlr; i++)
        fprintf(fp, "longrun,\"%s\",%s,w+R,,%g,,%.3g,%.3g,,,,,,\n", b->LR[i].name,
                b->LR[i].ours ? "ours" : "peer", SUS_LAB_BENCH_T_LONG, b->LR[i].energy,
                b->LR[i].orth);
}

/* ---- bench.tex: the numbers the companion text quotes ---- */

static const char *const LVL[NLEVELS] = {"Four", "Six", "Eight", "Ten", "Twelve", "Fourteen"};

static const char *pass_word(int pass) { return pass ? "PASS" : "MISS"; }

/* \newcommand{\NAME}{ratio}, to digits decimals; \infty where no peer reached the level. */
static void tex_ratio(FILE *fp, const char *name, const char *suffix, double r, int digits)
{
    if (isinf(r))
        fprintf(fp, "\\newcommand{\\%s%s}{\\infty}\n", name, suffix);
    else
        fprintf(fp, "\\newcommand{\\%s%s}{%.*f}\n", name, suffix, digits, r);
}

/* A verdict whose ratio lies within a tenth of its target (either side) is marked: a move of the
 * target by that much, or the ratio's own move between runs, would turn it. The companion marks
 * its near-threshold verdicts by the same rule, fixed before looking. */
static const char *near_mark(const sus_lab_bench_level *v)
{
    return isfinite(v->target) && fabs(v->ratio / v->target - 1.0) <= 0.1 ? "$^\\ddagger$" : "";
}

/* Two decimals: a ratio of 1.96 must not print as "2", nor 1.30 as "1.3", beside its verdict. Each
 * attitude ratio also by the fastest rounds (sus_lab_bench_level: the verdict's second estimate).
 * The w ratios are information (no target, no verdict). */
static void tex_levels(FILE *fp, const sus_lab_bench *b)
{
    for (int l = 0; l < NLEVELS; l++) {
        const sus_lab_bench_level vR = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_FULL, l),
                                  vD = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_REDUCED, l),
                                  vw = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_W_INFO, l);
        tex_ratio(fp, "BenchRatioR", LVL[l], vR.ratio, 2);
        tex_ratio(fp, "BenchRatioFastR", LVL[l], vR.ratio_fast, 2);
        fprintf(fp, "\\newcommand{\\BenchPassR%s}{%s%s}\n", LVL[l], sus_lab_bench_level_word(&vR),
                near_mark(&vR));
        tex_ratio(fp, "BenchRatioRed", LVL[l], vD.ratio, 2);
        tex_ratio(fp, "BenchRatioFastRed", LVL[l], vD.ratio_fast, 2);
        fprintf(fp, "\\newcommand{\\BenchPassRed%s}{%s%s}\n", LVL[l], sus_lab_bench_level_word(&vD),
                near_mark(&vD));
        tex_ratio(fp, "BenchRatioW", LVL[l], vw.ratio, 2);
        fprintf(fp, "\\newcommand{\\BenchTarget%s}{%.2g}\n", LVL[l], vR.target);
    }
    fprintf(fp, "\\newcommand{\\BenchTargetRed}{%.2g}\n", SUS_LAB_BENCH_REDUCED_TARGET);
}

/* The runs to T = 1e4 at equal error and to T = 1e6: the targets' ratios and verdicts. */
static void tex_long(FILE *fp, const sus_lab_bench *b)
{
    const int k = sus_lab_bench_best_equal_error(b);
    const double r = k < 0 ? 0.0 : b->EQ[k].peer_sec / b->EQ[k].sec,
                 g = sus_lab_bench_growth_ratio(b);
    tex_ratio(fp, "BenchLongRatio", "", r, 2);
    fprintf(fp, "\\newcommand{\\BenchPassLong}{%s}\n", pass_word(r >= SUS_LAB_BENCH_LONG_TARGET));
    fprintf(fp, "\\newcommand{\\BenchLongTarget}{%g}\n", SUS_LAB_BENCH_LONG_TARGET);
    fprintf(fp, "\\newcommand{\\BenchGrowthRatio}{%.2f}\n\\newcommand{\\BenchPassGrowth}{%s}\n", g,
            pass_word(g <= SUS_LAB_BENCH_GROWTH_TARGET));
    fprintf(fp, "\\newcommand{\\BenchGrowthTarget}{%g}\n", SUS_LAB_BENCH_GROWTH_TARGET);
}

static void write_tex(FILE *fp, const sus_lab_bench *b)
{
    const sus_lab_bench_costs *c = &b->cost;
    const double speedup = sus_lab_bench_rk4_speedup(b);
    const int irk4 = sus_step_method_index_of(sus_step_rk4),
              imid = sus_step_method_index_of(sus_step_midpoint),
              ivar = sus_step_method_index_of(sus_step_variational);
    fprintf(
        fp,
        "%% Generated by make bench (src/prog/bench.c): do not edit.\n"
        "\\newcommand{\\BenchRkNs}{%.3g}\n\\newcommand{\\BenchGslRkNs}{%.3g}\n"
        "\\newcommand{\\BenchRkSpeedup}{%.3g}\n\\newcommand{\\BenchMidpointRatio}{%.3g}\n"
        "\\newcommand{\\BenchVariationalRatio}{%.3g}\n\\newcommand{\\BenchExactNs}{%.3g}\n"
        "\\newcommand{\\BenchMidpointNewton}{%.2g}\n\\newcommand{\\BenchVariationalNewton}{%.2g}\n",
        c->ns_raw[irk4], c->ns_gsl_rk4, speedup, c->ns_raw[imid] / c->ns_raw[irk4],
        c->ns_raw[ivar] / c->ns_raw[irk4], c->ns_exact, c->newton[imid], c->newton[ivar]);
    fprintf(fp, "\\newcommand{\\BenchPassRkSpeedup}{%s}\n\\newcommand{\\BenchPassImplicit}{%s}\n",
            pass_word(speedup >= 5), pass_word(sus_lab_bench_implicit_pass(b)));
    /* each of the paper's implicit steps against the same target, as make bench prints it */
    fprintf(fp, "\\newcommand{\\BenchPassMidpoint}{%s}\n\\newcommand{\\BenchPassVariational}{%s}\n",
            pass_word(sus_lab_bench_implicit_step_pass(b, imid)),
            pass_word(sus_lab_bench_implicit_step_pass(b, ivar)));
    tex_levels(fp, b);
    tex_long(fp, b);
}

/* ---- what_to_use.tsv and longruns.tsv ----
 * A ratio is written to two decimals, from the same double that make bench prints and bench.tex
 * holds to two decimals: one rounding, so the tables, bench.txt and the software note agree
 * (summary.md prints it as written here). */

/* ---- what_to_use.tsv: at each level the fastest of ours and of the peers, from their timed
 * runs, with the suslov arguments that reproduce ours ---- */

static void write_what_to_use(FILE *fp, const sus_lab_bench *b)
{
    char args[256];
    fprintf(fp, "quantity\tlevel\tours\tours_seconds\tpeer\tpeer_parameter_name\tpeer_parameter\t"
                "peer_seconds\tratio\ttarget\tverdict\tsuslov_args\n");
    for (int c = 0; c < SUS_LAB_BENCH_NCOMP; c++)
        for (int l = 0; l < NLEVELS; l++) {
            const sus_lab_bench_level v =
                sus_lab_bench_level_verdict(b, (sus_lab_bench_comparison)c, l);
            if (v.ours.series < 0)
                continue;
            const sus_lab_bench_series *os = b->S[v.ours.series];
            const sus_lab_bench_series *ps = v.peer.series < 0 ? NULL : b->S[v.peer.series];
            sus_lab_bench_suslov_args(os, v.ours.point, args, sizeof args);
            fprintf(fp, "%s\t%.0e\t%s\t%.4g\t%s\t%s\t%.2g\t%.4g\t%.2f\t%g\t%s\t%s\n",
                    sus_lab_bench_comparison_name((sus_lab_bench_comparison)c), LEVELS[l], os->name,
                    v.ours.sec, ps ? ps->name : "none reaches it",
                    ps ? sus_lab_bench_param_name(ps) : "none", ps ? ps->param[v.peer.point] : NAN,
                    ps ? v.peer.sec : NAN, v.ratio, v.target, sus_lab_bench_level_word(&v), args);
        }
}

/* ---- longruns.tsv: the runs to T = 1e4 at equal error, and to T = 1e6 ---- */

static void long_row(FILE *fp, const sus_lab_bench *b, const sus_lab_bench_equal_error *e, int best)
{
    char args[256], target[16] = ""; /* the best row's target; the others are information */
    const sus_lab_bench_series *s = b->S[e->series];
    const double r = e->peer_sec / e->sec;
    sus_lab_bench_suslov_args_to(s, e->point, SUS_LAB_BENCH_T_LONG, args, sizeof args);
    if (best)
        snprintf(target, sizeof target, "%g", SUS_LAB_BENCH_LONG_TARGET);
    fprintf(fp,
            "equal-error\t%s\t%s\t%.4g\t%g\t%.4g\t%.3g\tGSL rk8pd (w,q) driver h0 0.001"
            "\t%.2g\t%.4g\t%.3g\t%.2f\t%s\t%s\t%.2g\t%.4g\t%.3g\t%.2f\t%s\n",
            s->name, sus_lab_bench_param_name(s), s->param[e->point], SUS_LAB_BENCH_T_LONG, e->sec,
            e->err, e->peer_tol, e->peer_sec, e->peer_err, r, target,
            best ? pass_word(r >= SUS_LAB_BENCH_LONG_TARGET) : "info", e->red_tol, e->red_sec,
            e->red_err, e->red_sec / e->sec, args);
}

static void write_long_runs(FILE *fp, const sus_lab_bench *b)
{
    char args[256];
    fprintf(fp, "row\tours\tparameter_name\tparameter\tT\tseconds\tattitude_error\tpeer\tpeer_tol\t"
                "peer_seconds\tpeer_error\tratio\ttarget\tverdict\treduced_tol\treduced_seconds\t"
                "reduced_error\treduced_ratio\tsuslov_args\n");
    const int best = sus_lab_bench_best_equal_error(b);
    for (int k = 0; k < b->neq; k++)
        long_row(fp, b, &b->EQ[k], k == best);
    const sus_lab_bench_growth *g = &b->growth;
    if (g->series < 0)
        return;
    const sus_lab_bench_series *s = b->S[g->series];
    const double r = sus_lab_bench_growth_ratio(b);
    sus_lab_bench_suslov_args_to(s, g->point, SUS_LAB_BENCH_T_GROWTH, args, sizeof args);
    fprintf(fp,
            "growth\t%s\t%s\t%.4g\t%g\t%.4g\t\tthe same run "
            "to T = %g\t\t%.4g\t\t%.2f\t%g\t%s\t\t\t\t\t%s\n",
            s->name, sus_lab_bench_param_name(s), s->param[g->point], SUS_LAB_BENCH_T_GROWTH,
            g->sec, SUS_LAB_BENCH_T_LONG, g->sec_long, r, SUS_LAB_BENCH_GROWTH_TARGET,
            pass_word(r <= SUS_LAB_BENCH_GROWTH_TARGET), args);
}

/* DIR/NAME.EXT written by write(fp, b), all or nothing. */
static int write_file(const char *dir, const char *name, const char *ext,
                      void (*write)(FILE *, const sus_lab_bench *), const sus_lab_bench *b)
{
    char err[256], path[4096];
    sus_sys_atomic_file af;
    sus_plot_fig_path(path, sizeof path, dir, name, ext);
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    write(af.fp, b);
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return -1;
    }
    return 0;
}

int sus_plot_bench_tables(const sus_lab_bench *b, const char *datadir)
{
    if (write_file(datadir, "bench", "csv", write_csv, b) != 0 ||
        write_file(datadir, "bench", "tex", write_tex, b) != 0 ||
        write_file(datadir, "what_to_use", "tsv", write_what_to_use, b) != 0 ||
        write_file(datadir, "longruns", "tsv", write_long_runs, b) != 0)
        return -1;
    return 0;
}
