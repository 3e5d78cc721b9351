/* The claims program: every section of the ledger, in the order of its lines, run on the
 * available cores (ledger_jobs.h) once what they share is made; then the lines that compare
 * the reference attitude with what the sections fitted, and the files.
 * Usage: claims [-j JOBS | --in-process] [--method NAME] [CLAIMS_TSV]   (JOBS: default the
 * processors online; --in-process runs the sections one after the other in this process, the run
 * every other is compared with;
 * --method NAME: only the per-method sections, for that method alone, as a new method's first
 * check: tests/build/scaffold_method.sh) */
#include "atomic_file.h"
#include "claims_adaptive.h"
#include "claims_bodies.h"
#include "claims_coverage.h"
#include "claims_distfinal.h"
#include "claims_fig2more.h"
#include "claims_fig2readings.h"
#include "claims_figures.h"
#include "claims_global.h"
#include "claims_highorder.h"
#include "claims_inputs.h"
#include "claims_methods.h"
#include "claims_paper.h"
#include "claims_propocons1.h"
#include "claims_quad.h"
#include "claims_recommended.h"
#include "claims_remark55.h"
#include "claims_section6.h"
#include "claims_sensitivity.h"
#include "claims_stability.h"
#include "ledger.h"
#include "ledger_jobs.h"
#include "registry.h"

#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const double PAPER_TK[PAPER_NTK] = {0.0, 3.0, 7.0, 12.0, 20.0};

static claims_paper P;
static const char *tsv_path = "build/claims.tsv";
static int only = -1; /* --method: the method's index, else -1 */

/* ---- the sections, as the jobs run them: arg is a method's index where there is one ---- */

static void s_local(int a) { (void)a, consistency_local_claims(&P); }
static void s_methods(int i) { methods_claims_of(i); }
static void s_limit(int a) { (void)a, multiplier_limit_claims(&P); }
static void s_multiplier(int a) { (void)a, consistency_multiplier_claims(&P); }
static void s_cayinver(int a) { (void)a, consistency_cayinver_claims(); }
static void s_distfinal(int a) { (void)a, distfinal_claims(); }
static void s_global(int a) { (void)a, consistency_global_claims(&P); }
static void s_unreduced(int a) { (void)a, consistency_unreduced_claims(&P); }
static void s_preserve(int i) { preserve_claims(&P, i); }
static void s_controls(int a) { (void)a, preserve_control_claims(&P); }
static void s_figures(int a) { (void)a, figure_claims(&P.m, &P.ex); }
static void s_boundary(int i) { stability_boundary_claims(i); }
static void s_solvable(int i) { stability_solvable_claims(&P.ex, i); }
static void s_fold(int i) { stability_fold_claims(&P.ex, i); }
static void s_section6(int a) { (void)a, section6_claims(&P.m, &P.ex); }
static void s_remark55(int a) { (void)a, remark55_claims(&P.m, &P.ex); }
static void s_quad(int a) { (void)a, quad_claims(&P.m, &P.ex); }
static void s_inputs(int a) { (void)a, inputs_claims(&P.m); }
static void s_fig2more(int a) { (void)a, fig2more_claims(&P.m, &P.ex); }
static void s_propocons1(int a) { (void)a, propocons1_claims(); }
static void s_reference(int a) { (void)a, highorder_reference_claims(&P.m, &P.ex); }
static void s_global_reference(int a) { (void)a, global_reference_claims(); }
static void s_global_orders(int i) { global_order_claims_of(i); }
static void s_highorder(int i) { highorder_method_claims(&P.m, &P.ex, i); }
static void s_adaptive(int a) { (void)a, adaptive_claims(); }
static void s_coverage(int a) { (void)a, coverage_claims(&P.m); }
static void s_fig2readings(int a) { (void)a, fig2readings_claims(&P.m); }
static void s_sensitivity(int a) { (void)a, sensitivity_claims(tsv_path); }

typedef struct {
    const char *name;
    void (*run)(int);
    int per_method; /* one job per registered method */
} section;

static const section SECTIONS[] = {
    {"local orders", s_local, 0},
    {"methods", s_methods, 1},
    {"multiplier limit", s_limit, 0},
    {"corrected multiplier", s_multiplier, 0},
    {"(36)", s_cayinver, 0},
    {"(29)", s_distfinal, 0},
    {"global orders", s_global, 0},
    {"unreduced", s_unreduced, 0},
    {"preservation", s_preserve, 1},
    {"negative controls", s_controls, 0},
    {"figures", s_figures, 0},
    {"stability boundary", s_boundary, 1},
    {"solvability", s_solvable, 1},
    {"folds", s_fold, 1},
    {"Section 6", s_section6, 0},
    {"Remark 5.5", s_remark55, 0},
    {"binary128", s_quad, 0},
    {"Figure 2, more", s_fig2more, 0},
    {"Proposition 4.1", s_propocons1, 0},
    {"reference attitude", s_reference, 0},
    {"reference attitude, every body", s_global_reference, 0},
    {"global orders, every body", s_global_orders, 1},
    {"long runs", s_highorder, 1},
    {"taylor-adaptive", s_adaptive, 0},
    {"coverage", s_coverage, 0},
    {"Figure 2 readings", s_fig2readings, 0},
    {"sensitivity", s_sensitivity, 0},
    {"inputs as decimals", s_inputs, 0},
};
#define NSECTIONS ((int)(sizeof SECTIONS / sizeof SECTIONS[0]))

/* The sections as jobs, a section per method one job for each registered method. */
static int section_tasks(ledger_task *tasks, int max)
{
    int n = 0;
    for (int s = 0; s < NSECTIONS; s++)
        for (int i = 0; i < (SECTIONS[s].per_method ? sus_step_method_count() : 1); i++) {
            if (n == max)
                ledger_die("fitting the sections into their table");
            if (only < 0 || (SECTIONS[s].per_method && i == only))
                tasks[n++] = (ledger_task){SECTIONS[s].name, SECTIONS[s].run, i};
        }
    return n;
}

/* What every section shares: the paper's body, its closed form, the convergence sweep (which no
 * per-method section reads: not made under --method), and the bodies of tests/unit/bodies.h with
 * their references (made here once, not in every job). */
static void prepare(void)
{
    char err[256];
    double winf[2];
    if (sus_model_init(&P.m, SUS_PAPER_INERTIA, err, sizeof err) != 0)
        ledger_die(err);
    sus_exact_init(&P.ex, &P.m, SUS_PAPER_OMEGA0);
    sus_exact_limit(&P.ex, winf);
    ledger_number("RateK", P.ex.k);
    ledger_number("EnergyZero", sus_energy(&P.m, SUS_PAPER_OMEGA0));
    ledger_number("SteadyOmegaOne", winf[0]);
    ledger_number("SteadyOmegaTwo", winf[1]);
    if (only < 0 &&
        sus_lab_convergence_run(&P.conv, &P.ex, PAPER_TK, PAPER_NTK, PAPER_T_GLOBAL) != 0)
        ledger_die("the convergence sweep");
    for (int k = 0; k < BODIES_COUNT; k++)
        claims_body_get(k);
}

/* The reference attitude against an independent Magnus integrator: its error must sit far (100x)
 * below the smallest SO(3) error that entered an order fit, for the local increments and for
 * R(10) alike. */
static void reference_claims(void)
{
    ledger_add(
        "reference-attitude-local", "(method)",
        "$\\max |\\Phi_\\mathrm{ref} - \\Phi_\\mathrm{magnus4}|$ over all one-step increments "
        "(long-double Taylor reference); tolerance 1\\% of the smallest fitted local "
        "$\\mathrm{SO}(3)$ error",
        P.conv.ref_local_err, 0.0, 0.01 * ledger_min(CLAIMS_MIN_SO3_LOCAL), LEDGER_EXTENSION);
    ledger_add("reference-attitude-global", "(method)",
               "$|R_\\mathrm{ref}(10) - R_\\mathrm{magnus4}(10)|$ (long-double Taylor reference); "
               "tolerance 1\\% of the smallest fitted global $\\mathrm{SO}(3)$ error",
               P.conv.ref_global_err, 0.0, 0.01 * ledger_min(CLAIMS_MIN_SO3_GLOBAL),
               LEDGER_EXTENSION);
}

/* The registry as a table (src/methods/registry.h), methods.tsv beside the claims file, whole or
 * not at all. */
static void write_methods(const char *tsv)
{
    char path[4096], err[256];
    const char *slash = strrchr(tsv, '/');
    snprintf(path, sizeof path, "%.*smethods.tsv", slash ? (int)(slash - tsv + 1) : 0, tsv);
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0)
        ledger_die(err);
    if (sus_step_methods_write_tsv(af.fp) != 0) {
        sus_sys_atomic_file_abort(&af);
        ledger_die("writing methods.tsv");
    }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0)
        ledger_die(err);
}

/* --method NAME at argv[*i], if there: sets only, or one line and exit 2 for a name that is not a
 * fixed-step method (the per-method sections iterate those). */
static void parse_method(int argc, char **argv, int *i)
{
    if (*i >= argc || strcmp(argv[*i], "--method") != 0)
        return;
    const char *name = *i + 1 < argc ? argv[*i + 1] : "";
    only = sus_step_method_index(name);
    if (only < 0 || only >= sus_step_method_count()) {
        fprintf(stderr, "claims: --method takes a fixed-step method of the registry, not '%s'\n",
                name);
        exit(2);
    }
    *i += 2;
}

/* -j JOBS (or -jJOBS) or --in-process (jobs 0), --method NAME and the path; bad arguments: one
 * line and exit 2. */
static int parse_args(int argc, char **argv)
{
    int jobs = ledger_jobs_online(), i = 1;
    parse_method(argc, argv, &i);
    if (i < argc && strncmp(argv[i], "-j", 2) == 0) {
        const char *v = argv[i][2] ? argv[i] + 2 : i + 1 < argc ? argv[++i] : "";
        char *end;
        const long j = strtol(v, &end, 10);
        if (!*v || *end || j < 1 || j > 256) {
            fprintf(stderr, "claims: -j takes a number of jobs from 1 to 256, not '%s'\n", v);
            exit(2);
        }
        jobs = (int)j;
        i++;
    } else if (i < argc && strcmp(argv[i], "--in-process") == 0) {
        jobs = 0;
        i++;
    }
    parse_method(argc, argv, &i);
    if (argc - i > 1 || (i < argc && argv[i][0] == '-')) {
        fprintf(stderr, "usage: claims [-j JOBS | --in-process] [--method NAME] [CLAIMS_TSV]\n");
        exit(2);
    }
    if (i < argc)
        tsv_path = argv[i];
    return jobs;
}

int main(int argc, char **argv)
{
    static ledger_task tasks[512];
    const int jobs = parse_args(argc, argv);
    recommended_program(argv[0]);
    gsl_set_error_handler_off();
    prepare();
    ledger_run_tasks(tasks, section_tasks(tasks, 512), jobs);
    if (only < 0) { /* it compares with what the convergence sweep fitted */
        reference_claims();
        sus_lab_convergence_free(&P.conv);
    }
    const int failed = ledger_finish(tsv_path);
    write_methods(tsv_path);
    return failed != 0;
}
