#include "bench_report.h"

#include "bench_floor.h"
#include "bench_longrun.h"
#include "dsp.h"

#include <stdio.h>

#define ROUNDS SUS_LAB_BENCH_ROUNDS
#define COST_STEPS SUS_LAB_BENCH_COST_STEPS
#define LEVELS SUS_LAB_BENCH_LEVELS

void sus_plot_bench_header(const sus_lab_bench *b, int differ, int with_odeint)
{
    printf("Benchmark (T = %g, w(0) = (0.4, 0.5), the paper's body). Times are the CPU time of "
           "the bench's thread.\n"
           "Work-precision times: median over %d interleaved rounds, each a batch of >= %g s, "
           "min and max in bench.csv.\n"
           "On a shared machine, compare the ratios measured in this same run rather than "
           "absolute times.\n",
           SUS_LAB_BENCH_T_END, SUS_LAB_BENCH_WP_ROUNDS, SUS_LAB_BENCH_BATCH_SECONDS);
    if (!with_odeint)
        printf("(built without Boost.Odeint: `make bench` builds the bench with it)\n");
    printf("  %s %d of %d timed points end their timed runs with the error recorded for them\n\n",
           differ ? "CHECK FAILED:" : "CHECK ok:", b->npoints - differ, b->npoints);
}

static void print_costs(const sus_lab_bench *b)
{
    const sus_lab_bench_costs *c = &b->cost;
    printf("Per-step cost (ns, median of %d interleaved rounds of %ld steps; eps = %g):\n", ROUNDS,
           COST_STEPS, SUS_LAB_BENCH_T_END / (double)COST_STEPS);
    const int irk4 = sus_step_method_index_of(sus_step_rk4);
    printf("  %-12s %10s %18s %12s %12s\n", "method", "w-step", "whole step (recon)", "Newton/step",
           "x our rk4");
    for (int m = 0; m < c->n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        /* the default reconstruction, or the attitude the method carries itself */
        const char *att = me->type->desc.follows_recon
                              ? SUS_RECON_NAMES[me->recon]
                              : sus_step_attitude_name(me->type->desc.attitude);
        printf("  %-12s %10.1f %10.1f %-10s %9.2f %12.2f\n", me->type->name, c->ns_raw[m],
               c->ns_full[m], att, c->newton[m], c->ns_raw[m] / c->ns_raw[irk4]);
    }
    printf("  %-12s %10.1f\n", "GSL rk4", c->ns_gsl_rk4);
    printf("  %-12s %10.1f   (one closed-form w(t): the floor)\n", "exact w(t)", c->ns_exact);
    printf("  %-12s %10.1f   (the same with one exp, as the peers on the reduced problem have "
           "it)\n\n",
           "w(t), 1 exp", c->ns_exact_one_exp);
}

/* The driver's overhead on the own-attitude methods and on the tolerance-driven runs. */
static void print_overheads(const sus_lab_bench *b)
{
    const sus_lab_bench_costs *c = &b->cost;
    for (int m = 0; m < c->n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        if (!sus_lab_bench_own_attitude(me))
            continue;
        const double over = c->ns_full_min[m] / c->ns_direct[m] - 1.0;
        printf("  %s the driver adds <= 10 %% to a %s step (%.1f "
               "ns in a bare loop, fastest rounds): %+.1f %%\n",
               over <= 0.10 ? "PASS" : "MISS", me->type->name, c->ns_direct[m], 100.0 * over);
    }
    if (c->tol_bare_min > 0.0) {
        const double over = c->tol_drv_min / c->tol_bare_min - 1.0;
        printf("  %s the driver (sus_run_tol, one row) adds <= 10 %% to a tolerance-driven run "
               "to t = 50, summed over its TOL grid (fastest rounds): %+.1f %%\n",
               over <= 0.10 ? "PASS" : "MISS", 100.0 * over);
    }
}

static void print_step_targets(const sus_lab_bench *b)
{
    const double speedup = sus_lab_bench_rk4_speedup(b);
    printf("  %s our rk4 step is >= 5x faster than GSL rk4 through "
           "gsl_odeiv2_driver_apply_fixed_step: %.1fx\n",
           speedup >= 5 ? "PASS" : "MISS", speedup);
    for (int m = 0; m < b->cost.n; m++) {
        const sus_step_method *me = sus_step_method_get(m);
        if (!sus_lab_bench_implicit_target(me))
            continue;
        const double r = sus_lab_bench_implicit_ratio(b, m);
        printf("  %s an implicit %s step costs <= %gx our rk4 step: %.2fx (%.2f Newton iterations "
               "per step)\n",
               sus_lab_bench_implicit_step_pass(b, m) ? "PASS" : "MISS", me->type->name,
               SUS_LAB_BENCH_IMPLICIT_TARGET, r, b->cost.newton[m]);
    }
    print_overheads(b);
}

static void print_floor(int l, const sus_lab_bench_level *v)
{
    if (isinf(v->floor))
        printf("  MISS attitude accuracy %.0e: no floor (none of our explicit methods reaches "
               "it)\n",
               LEVELS[l]);
    else
        printf("  %s attitude accuracy %.0e: our best %.3g s is within 1.15x of the floor %.3g s "
               "(an estimate: fewest steps x cost per step, timed apart): %.3fx\n",
               v->ours.sec <= 1.15 * v->floor ? "PASS" : "MISS", LEVELS[l], v->ours.sec, v->floor,
               v->ours.sec / v->floor);
}

static const char *const WHAT[SUS_LAB_BENCH_NCOMP] = {"attitude", "attitude (reduced problem)",
                                                      "w"};
static const char *const AGAINST[SUS_LAB_BENCH_NCOMP] = {
    "best peer on the full problem", "best peer on the reduced problem", "best peer"};

static void print_level(const sus_lab_bench *b, sus_lab_bench_comparison c, int l)
{
    const sus_lab_bench_level v = sus_lab_bench_level_verdict(b, c, l);
    if (v.ours.series < 0) {
        printf("  %s %s accuracy %.0e at t = 50: none of our structure-preserving methods "
               "reaches it\n",
               isnan(v.target) ? "info" : "MISS", WHAT[c], LEVELS[l]);
        return;
    }
    const sus_lab_bench_series *os = b->S[v.ours.series];
    if (c == SUS_LAB_BENCH_ATT_FULL)
        print_floor(l, &v);
    printf("  %s %s accuracy %.0e at t = 50: ours %.3g s (%s, %s %.4g) ",
           sus_lab_bench_level_word(&v), WHAT[c], LEVELS[l], v.ours.sec, os->name,
           sus_lab_bench_param_name(os), os->param[v.ours.point]);
    if (v.peer.series < 0) {
        printf("; no peer configuration reaches it\n");
        return;
    }
    const sus_lab_bench_series *ps = b->S[v.peer.series];
    printf("vs %s %.3g s (%s, %s %.2g, its timed runs' error %.2g): %.2fx", AGAINST[c], v.peer.sec,
           ps->name, sus_lab_bench_param_name(ps), ps->param[v.peer.point],
           c != SUS_LAB_BENCH_W_INFO ? ps->err_R[v.peer.point] : ps->err_w[v.peer.point], v.ratio);
    if (isnan(v.target))
        printf(" (no target: the closed form gives w(t) in %.3g ns)\n", b->cost.ns_exact);
    else
        printf(" (target %gx; fastest rounds %.2fx)\n", v.target, v.ratio_fast);
}

void sus_plot_bench_costs_and_targets(const sus_lab_bench *b)
{
    print_costs(b);
    printf("Targets:\n");
    print_step_targets(b);
    for (int c = 0; c < SUS_LAB_BENCH_NCOMP; c++)
        for (int l = 0; l < SUS_LAB_BENCH_NLEVELS; l++)
            print_level(b, (sus_lab_bench_comparison)c, l);
}

void sus_plot_bench_long_runs(const sus_lab_bench *b)
{
    for (int i = 0; i < b->nlr; i++) {
        const sus_lab_bench_longrun *L = &b->LR[i];
        if (L->ours) {
            /* |R^T R - I|: every long run of ours builds R afresh from a unit quaternion at each
             * row, one rounding per entry whatever the number of steps: the ledger's round-off
             * bound for that construction (method-orth-*, adaptive-orth). |E - E0|: a guard. */
            const int ok = L->orth <= 1e-14 && L->energy <= 1e-13 && L->w3 == 0.0;
            printf("  %s T = 1e4, %s: |R^T R - I| = %.2g, |E - E0| = %.2g, |w3| = %.2g "
                   "(targets 1e-14, 1e-13, 0); |E - E0| by T/2: %.2g\n",
                   ok ? "PASS" : "MISS", L->name, L->orth, L->energy, L->w3, L->energy_half);
        } else {
            printf("  (peer) T = 1e4, %s at the tolerance reaching 1e-10 at t = 50: "
                   "%s = %.2g, |E - E0| = %.2g\n",
                   L->name, L->dim == 6 ? "||q| - 1|" : "|R^T R - I|", L->orth, L->energy);
        }
    }
}

/* A peer of a long run: its tolerance, seconds, error and ratio, or that none reaches the level. */
static void print_long_peer(const char *name, double tol, double sec, double err, double ours)
{
    if (isinf(sec))
        printf("no %s tolerance down to 1e-15 reaches it", name);
    else
        printf("%s tol %.2g %.3g s, error %.2g: %.2fx", name, tol, sec, err, sec / ours);
}

/* Each of ours at T = 1e4 (information), then the target: the best of them. */
void sus_plot_bench_equal_error(const sus_lab_bench *b)
{
    for (int k = 0; k < b->neq; k++) {
        const sus_lab_bench_equal_error *e = &b->EQ[k];
        const sus_lab_bench_series *s = b->S[e->series];
        printf("  info T = 1e4, attitude error <= %g: %s (%s %.4g) %.3g s, error %.2g; ",
               SUS_LAB_BENCH_LONG_LEVEL, s->name, sus_lab_bench_param_name(s), s->param[e->point],
               e->sec, e->err);
        print_long_peer("GSL rk8pd (w,q)", e->peer_tol, e->peer_sec, e->peer_err, e->sec);
        printf("; ");
        print_long_peer("GSL rk8pd reduced (q)", e->red_tol, e->red_sec, e->red_err, e->sec);
        printf("\n");
    }
    const int best = sus_lab_bench_best_equal_error(b);
    if (best < 0) {
        printf("  MISS T = 1e4 at equal error: none of our explicit own-attitude methods reaches "
               "attitude %g there\n",
               SUS_LAB_BENCH_LONG_LEVEL);
        return;
    }
    const sus_lab_bench_equal_error *e = &b->EQ[best];
    const double ratio = e->peer_sec / e->sec;
    if (isinf(ratio))
        printf("  PASS T = 1e4 at equal error (attitude <= %g): ours %s %.3g s; no rk8pd (w,q) "
               "tolerance down to 1e-15 reaches it\n",
               SUS_LAB_BENCH_LONG_LEVEL, b->S[e->series]->name, e->sec);
    else
        printf("  %s T = 1e4 at equal error (attitude <= %g): ours %s is %.2fx faster than GSL "
               "rk8pd (w,q) (target %gx)\n",
               ratio >= SUS_LAB_BENCH_LONG_TARGET ? "PASS" : "MISS", SUS_LAB_BENCH_LONG_LEVEL,
               b->S[e->series]->name, ratio, SUS_LAB_BENCH_LONG_TARGET);
}

void sus_plot_bench_growth(const sus_lab_bench *b)
{
    const sus_lab_bench_growth *g = &b->growth;
    if (g->series < 0)
        return;
    const sus_lab_bench_series *s = b->S[g->series];
    const double r = sus_lab_bench_growth_ratio(b);
    printf("  %s cost at T = 1e6 <= %gx the cost at T = 1e4: %s (%s %.4g) %.3g s against "
           "%.3g s: %.2fx\n",
           r <= SUS_LAB_BENCH_GROWTH_TARGET ? "PASS" : "MISS", SUS_LAB_BENCH_GROWTH_TARGET, s->name,
           sus_lab_bench_param_name(s), s->param[g->point], g->sec, g->sec_long, r);
}

void sus_plot_bench_reproduced(const sus_lab_bench *b, const sus_lab_bench_reproduced *r,
                               const char *suslov)
{
    for (int k = 0; k < r->nfailed; k++) {
        const sus_lab_bench_series *s = b->S[r->failed[k].series];
        printf("  row not reproduced by suslov: %s %s %.17g to T = %g\n", s->name,
               sus_lab_bench_param_name(s), s->param[r->failed[k].point], r->failed[k].T);
    }
    printf("  %s %d of %d \"ours\" rows re-run with %s give the same results (suslov_args in "
           "bench.csv, longruns.tsv)\n",
           r->ok == r->tried ? "CHECK ok:" : "CHECK FAILED:", r->ok, r->tried, suslov);
}
