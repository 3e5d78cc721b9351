/* The bench's bookkeeping, on a bench filled by hand (no timing): which peer each comparison
 * takes (src/lab/bench_floor.c: the full problem's peers for the attitude target, the reduced
 * problem's for the other, never a peer given w(t) for the w race, never a w-only one for the
 * attitude), the implicit steps' cost verdicts, and the data file the figures are drawn from
 * (src/render/bench_tables.c writes bench.csv, src/lab/bench_load.c reads it back: the same
 * series, points and step costs); and, on one real run to T = 1e4, the long-run line's energy
 * error by T/2. */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"
#include "bench_floor.h"
#include "bench_load.h"
#include "bench_longrun.h"
#include "bench_tables.h"
#include "check.h"
#include "composition.h"
#include "driver.h"
#include "dsp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* A series of one point: error e_w and e_R (INFINITY: none) in sec seconds. */
static sus_lab_bench_series *one_point(sus_lab_bench *b, const char *name, int ours, int w_only,
                                       int reduced, double e_w, double e_R, double sec)
{
    sus_lab_bench_series *s = sus_lab_bench_new_series(b);
    snprintf(s->name, sizeof s->name, "%s", name);
    s->ours = ours;
    s->preserves = ours;
    s->w_only = w_only;
    s->reduced = reduced;
    s->me = ours ? sus_step_method_by_name("taylor8") : NULL;
    s->recon = ours ? s->me->recon : SUS_RECON_CAYLEY;
    s->n = 1;
    s->param[0] = 0.5;
    s->steps[0] = 100;
    s->err_w[0] = e_w;
    s->err_R[0] = e_R;
    s->sec[0] = s->smin[0] = s->smax[0] = sec;
    b->npoints++;
    return s;
}

/* Per-step costs for every registered method (the tables name some by type). */
static void fill_costs(sus_lab_bench *b)
{
    const int n = sus_step_method_count();
    sus_lab_bench_costs *c = &b->cost;
    c->n = n;
    c->name = sus_lab_bench_calloc((size_t)n, sizeof *c->name);
    c->ns_raw = sus_lab_bench_calloc((size_t)n, sizeof(double));
    c->ns_full = sus_lab_bench_calloc((size_t)n, sizeof(double));
    c->newton = sus_lab_bench_calloc((size_t)n, sizeof(double));
    for (int m = 0; m < n; m++) {
        snprintf(c->name[m], sizeof c->name[m], "%s", sus_step_method_get(m)->type->name);
        c->ns_raw[m] = 10.0 + m;
        c->ns_full[m] = 20.0 + m;
    }
    c->ns_gsl_rk4 = 150.0;
    c->ns_exact = 27.5;
    c->ns_exact_one_exp = 12.5;
}

/* ours 1 us; a full-problem peer 3 us; a reduced-problem peer 0.4 us; a w-only peer 0.5 us. */
static void fill(sus_lab_bench *b)
{
    *b = (sus_lab_bench){.growth = {.series = -1, .point = -1, .eq = -1}};
    sus_lab_bench_init(b, NULL);
    one_point(b, "ours", 1, 0, 0, 1e-5, 1e-5, 1e-6);
    one_point(b, "full peer", 0, 0, 0, 1e-5, 1e-5, 3e-6);
    one_point(b, "reduced peer", 0, 0, 1, 0.0, 1e-5, 0.4e-6);
    one_point(b, "w peer", 0, 1, 0, 1e-5, INFINITY, 0.5e-6);
    b->growth = (sus_lab_bench_growth){.series = -1, .point = -1, .eq = -1};
    fill_costs(b);
    sus_lab_bench_envelopes(b);
}

static void check_verdicts(const sus_lab_bench *b)
{
    const sus_lab_bench_level f = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_FULL, 0),
                              r = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_REDUCED, 0),
                              w = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_W_INFO, 0);
    CHECK(f.ours.series == 0 && f.peer.series == 1 && f.ratio == 3e-6 / 1e-6 && f.pass,
          "attitude, full problem: ours against the full problem's "
          "peer (series %d, ratio %g, target %g)",
          f.peer.series, f.ratio, f.target);
    CHECK(r.peer.series == 2 && r.ratio == 0.4e-6 / 1e-6 && !r.pass &&
              r.target == SUS_LAB_BENCH_REDUCED_TARGET,
          "attitude, reduced problem: against the peer given w(t) (series %d, ratio %g, target %g)",
          r.peer.series, r.ratio, r.target);
    CHECK(w.peer.series == 3 && isnan(w.target),
          "w: against the w-only peer, never the one given w(t); "
          "information, no target (series %d, target %g)",
          w.peer.series, w.target);
    CHECK(b->env[1].n == 1 && b->env[1].sec[0] == 3e-6 && b->env[2].n == 1 &&
              b->env[2].sec[0] == 0.4e-6,
          "the attitude envelopes: the full problem's peers, and apart the reduced one's");
}

/* The implicit-step target: at most SUS_LAB_BENCH_IMPLICIT_TARGET rk4 steps, each step its own
 * verdict, the joint one all of them; the compositions (many substeps a step) are not held to it.
 */
static void check_implicit(sus_lab_bench *b)
{
    double *ns = b->cost.ns_raw;
    const double rk4 = ns[sus_step_method_index_of(sus_step_rk4)];
    const int mid = sus_step_method_index_of(sus_step_midpoint),
              var = sus_step_method_index_of(sus_step_variational),
              comp = sus_step_method_index_of(&sus_step_comp10_ss_type);
    for (int m = 0; m < b->cost.n; m++)
        if (sus_lab_bench_implicit_target(sus_step_method_get(m)))
            ns[m] = SUS_LAB_BENCH_IMPLICIT_TARGET * rk4;
    ns[comp] = 100.0 * rk4;
    CHECK(sus_lab_bench_implicit_step_pass(b, mid) && sus_lab_bench_implicit_pass(b) &&
              !sus_lab_bench_implicit_target(sus_step_method_get(comp)),
          "implicit steps at exactly the target pass (at most), a composition is not held to it");
    ns[mid] = nextafter(SUS_LAB_BENCH_IMPLICIT_TARGET * rk4, INFINITY);
    CHECK(!sus_lab_bench_implicit_step_pass(b, mid) && sus_lab_bench_implicit_step_pass(b, var) &&
              !sus_lab_bench_implicit_pass(b),
          "the midpoint a rounding above the target: its verdict and the joint one MISS, the "
          "variational step's still PASS");
    ns[mid] = SUS_LAB_BENCH_IMPLICIT_TARGET * rk4;
    ns[var] = NAN;
    CHECK(!sus_lab_bench_implicit_step_pass(b, var) && !sus_lab_bench_implicit_pass(b),
          "a step with no measured cost (NaN) is a MISS, not a PASS");
}

/* The second estimate: each side's fastest round. Where it lands on the other side of the target
 * the verdict is UNDECIDED; where both land on the same side, PASS or MISS as the medians say. */
static void check_undecided(sus_lab_bench *b)
{
    const double target = SUS_LAB_BENCH_LEVEL_TARGET[0]; /* the medians give 3x: a PASS */
    b->S[1]->smin[0] = 0.99 * target * b->S[0]->smin[0];
    sus_lab_bench_level v = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_FULL, 0);
    CHECK(v.pass && !v.decided && strcmp(sus_lab_bench_level_word(&v), "UNDECIDED") == 0 &&
              fabs(v.ratio_fast - 0.99 * target) < 1e-12,
          "a PASS by the medians that the fastest rounds put below the target is UNDECIDED "
          "(fastest rounds %g)",
          v.ratio_fast);
    b->S[0]->smin[0] *= 0.9;
    v = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_ATT_FULL, 0);
    CHECK(v.pass && v.decided && strcmp(sus_lab_bench_level_word(&v), "PASS") == 0,
          "the fastest rounds on the same side as the medians: PASS (fastest rounds %g)",
          v.ratio_fast);
    b->S[0]->smin[0] = b->S[0]->sec[0], b->S[1]->smin[0] = b->S[1]->sec[0];
    const sus_lab_bench_level w = sus_lab_bench_level_verdict(b, SUS_LAB_BENCH_W_INFO, 0);
    CHECK(w.decided && strcmp(sus_lab_bench_level_word(&w), "info") == 0,
          "a comparison without a target is information, never undecided");
}

static int same_series(const sus_lab_bench_series *a, const sus_lab_bench_series *b)
{
    const double rel = 1e-5; /* bench.csv prints errors and seconds to 6 digits */
    return strcmp(a->name, b->name) == 0 && a->ours == b->ours && a->w_only == b->w_only &&
           a->reduced == b->reduced && a->n == b->n && a->param[0] == b->param[0] &&
           a->steps[0] == b->steps[0] && fabs(a->sec[0] - b->sec[0]) <= rel * a->sec[0] &&
           fabs(a->err_w[0] - b->err_w[0]) <= rel * a->err_w[0] &&
           (isinf(a->err_R[0]) ? isinf(b->err_R[0])
                               : fabs(a->err_R[0] - b->err_R[0]) <= rel * a->err_R[0]);
}

/* Field col (1-based) of the first line of DIR/NAME that starts with head, into out. */
static int tsv_field(const char *dir, const char *name, const char *head, int col, char *out,
                     size_t len)
{
    char path[96], line[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *fp = fopen(path, "r");
    int found = 0;
    while (fp && !found && fgets(line, sizeof line, fp))
        if (strncmp(line, head, strlen(head)) == 0) {
            char *f = strtok(line, "\t\n");
            for (int k = 1; f && k < col; k++)
                f = strtok(NULL, "\t\n");
            found = f != NULL;
            if (found)
                snprintf(out, len, "%s", f);
        }
    if (fp)
        fclose(fp);
    return found;
}

/* One rounding of a ratio everywhere: what_to_use.tsv holds it to two decimals, as bench.tex and
 * make bench print it (3 us over 1 us is 3.00, not 3; 0.4 over 1 is 0.40). */
static void check_ratio_digits(const char *dir)
{
    char full[32] = "", red[32] = "", tex[4096] = "", path[96];
    tsv_field(dir, "what_to_use.tsv", "attitude\t1e-04\t", 9, full, sizeof full);
    tsv_field(dir, "what_to_use.tsv", "attitude-reduced\t1e-04\t", 9, red, sizeof red);
    snprintf(path, sizeof path, "%s/bench.tex", dir);
    FILE *fp = fopen(path, "r");
    const size_t n = fp ? fread(tex, 1, sizeof tex - 1, fp) : 0;
    tex[n] = '\0';
    if (fp)
        fclose(fp);
    CHECK(strcmp(full, "3.00") == 0 && strcmp(red, "0.40") == 0 &&
              strstr(tex, "\\BenchRatioRFour}{3.00}") && strstr(tex, "\\BenchRatioRedFour}{0.40}"),
          "what_to_use.tsv's ratios to two decimals, as bench.tex's (full %s, reduced %s)", full,
          red);
}

static void check_round_trip(const sus_lab_bench *b)
{
    char dir[] = "/tmp/test_bench.XXXXXX", path[64];
    if (!mkdtemp(dir)) {
        CHECK(0, "a scratch directory");
        return;
    }
    sus_lab_bench c;
    const int wrote = sus_plot_bench_tables(b, dir) == 0;
    const int read = wrote && sus_lab_bench_load(&c, dir) == 0;
    CHECK(read, "bench.csv written and read back");
    if (read) {
        int same = c.nseries == b->nseries;
        for (int i = 0; same && i < b->nseries; i++)
            same = same_series(b->S[i], c.S[i]);
        CHECK(same, "the same %d series, each its points (read %d)", b->nseries, c.nseries);
        same = c.cost.n == b->cost.n && c.cost.ns_gsl_rk4 == 150.0 && c.cost.ns_exact == 27.5;
        for (int m = 0; same && m < b->cost.n; m++)
            same = strcmp(c.cost.name[m], b->cost.name[m]) == 0 &&
                   c.cost.ns_raw[m] == b->cost.ns_raw[m] && c.cost.ns_full[m] == b->cost.ns_full[m];
        CHECK(same, "the same per-step costs, in the registry's order");
        CHECK(c.env[2].n == 1, "the envelopes again from what was read");
        sus_lab_bench_free(&c);
    }
    if (wrote)
        check_ratio_digits(dir);
    /* a file that is not the bench's: refused, with a message */
    snprintf(path, sizeof path, "%s/bench.csv", dir);
    FILE *fp = fopen(path, "w");
    if (fp) {
        fputs("section,method\nwork,x\n", fp);
        fclose(fp);
    }
    CHECK(sus_lab_bench_load(&c, dir) != 0, "a bench.csv that is not the bench's is refused");
    static const char *const files[] = {"bench.csv", "bench.tex", "what_to_use.tsv",
                                        "longruns.tsv"};
    for (int k = 0; k < 4; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        remove(path);
    }
    rmdir(dir);
}

/* Row by row of a long run: max |E - E0| over the rows by T/2 and over all of them. */
typedef struct {
    const sus_model *m;
    double e0, half, all;
} energy_acc;

static int energy_row(void *ctx, const sus_row *row)
{
    energy_acc *a = ctx;
    const double de = fabs(sus_energy(a->m, row->w) - a->e0);
    a->all = fmax(a->all, de);
    if (row->t <= 0.5 * SUS_LAB_BENCH_T_LONG)
        a->half = fmax(a->half, de);
    return 0;
}

/* The long-run line's |E - E0| by T/2 (bench_longrun.c), on a composition whose energy error
 * still grows at T = 1e4 (comp6-kl): it is the maximum over the rows up to T/2 of the same run
 * taken here through the public driver, and below the maximum over the whole run. A line that
 * took the whole run, or the second half, for the first would fail one of the two. */
static void check_energy_half(sus_lab_bench *b)
{
    const double eps = 0.5;
    const long N = lround(SUS_LAB_BENCH_T_LONG / eps);
    sus_lab_bench_series *s = one_point(b, "comp6-kl + exp-mid", 1, 0, 0, 1e-12, 1e-11, 1e-6);
    s->me = sus_step_method_by_name("comp6-kl");
    s->recon = SUS_RECON_EXP_MID;
    s->param[0] = eps;
    for (int i = 0; i < b->nseries - 1; i++) /* only this series reaches 1e-10 */
        b->S[i]->err_R[0] = INFINITY;
    sus_lab_bench_long_runs(b);
    const sus_run_config cfg = {&b->pb.model, s->me->type, SUS_RECON_EXP_MID, eps, N, N / 1000};
    energy_acc a = {&b->pb.model, sus_energy(&b->pb.model, b->pb.ex.w0), 0.0, 0.0};
    sus_run_report rep;
    const int rc = sus_run(&cfg, b->pb.ex.w0, energy_row, &a, &rep);
    const sus_lab_bench_longrun *L = b->nlr == 1 ? &b->LR[0] : NULL;
    CHECK(rc == SUS_RUN_OK && L && L->energy_half == a.half && L->energy == a.all && a.half < a.all,
          "long run of comp6-kl + exp-mid to T = 1e4: |E - E0| by T/2 %.3g (the driver's rows: "
          "%.3g), at T %.3g (%.3g); below it",
          L ? L->energy_half : NAN, a.half, L ? L->energy : NAN, a.all);
}

int main(void)
{
    sus_lab_bench b;
    fill(&b);
    check_verdicts(&b);
    check_round_trip(&b);
    check_implicit(&b);
    check_undecided(&b);
    check_energy_half(&b);
    sus_lab_bench_free(&b);
    return check_summary("test_bench");
}
