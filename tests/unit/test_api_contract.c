/* The library's contract (src/methods/suslov.h): every public function, given hostile arguments
 * (NULL, zero, negative, NaN and infinite counts, steps and times, a model never initialised or
 * changed after sus_model_init, a method of the wrong kind), returns its documented error code
 * and never crashes, loops or emits a row. Each refusal is checked with a good control beside
 * it, so that a check which refuses everything fails too. Run under `make SAN=1 check`, ASan and
 * UBSan stop the test at the first invalid access. An alarm turns a run that loops into a
 * failure instead of a hang. */
#include "check.h"
#include "suslov.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

/* The longest any run below may take: each is a few steps (the controls) or none. */
#define ALARM_SECONDS 60

static long rows_seen;

static int count_rows(void *ctx, const sus_row *r)
{
    (void)ctx, (void)r;
    rows_seen++;
    return 0;
}

static sus_model model;         /* the paper's body, from sus_model_init */
static sus_model model_zero;    /* never initialised: all bits zero */
static sus_model model_garbage; /* never initialised: a byte pattern */
static sus_model model_changed; /* initialised, then one coefficient changed */

static void models_init(void)
{
    char err[128];
    CHECK(sus_model_init(&model, SUS_PAPER_INERTIA, err, sizeof err) == 0,
          "the paper's body initialises");
    memset(&model_zero, 0, sizeof model_zero);
    memset(&model_garbage, 0xA5, sizeof model_garbage);
    model_changed = model;
    model_changed.b[0] *= 2.0;
}

/* A refusal: SUS_RUN_BAD_ARGUMENT, a message that names `what`, no row emitted. */
static void refused(const char *fn, const char *what, int rc, const sus_run_report *rep)
{
    const char *msg = rep->message ? rep->message : "(none)";
    CHECK(rc == SUS_RUN_BAD_ARGUMENT && rows_seen == 0 && strstr(msg, what) != NULL,
          "%s, bad %s: rc %d (BAD_ARGUMENT %d), %ld rows, message \"%s\"", fn, what, rc,
          SUS_RUN_BAD_ARGUMENT, rows_seen, msg);
}

static const double W0[2] = {0.4, 0.5};
static const double W0_NAN[2] = {NAN, 0.5};
static const double W0_INF[2] = {0.4, -INFINITY};
static const double W0_SUB[2] = {0.4, 1e-310};  /* subnormal: refused, as the command refuses it */
static const double W0_BIG[2] = {1e200, 1e200}; /* its energy overflows */

/* Bad configuration number i of a fixed-step run (or -1: none left); `what` is the word the
 * message must hold. */
static int bad_fixed(int i, sus_run_config *c, const char **what)
{
    static const sus_step_ops empty = {0};
    static const sus_stepper_type no_step = {.name = "no-step",
                                             .desc = {.order = 1, .substeps = 1}};
    static const sus_stepper_type no_apply = {
        .name = "no-apply", .step = &empty, .desc = {.order = 1, .substeps = 1}};
    switch (i) {
        case 0: c->every = 0, *what = "every"; return 1;
        case 1: c->every = -3, *what = "every"; return 1;
        case 2: c->steps = -5, *what = "steps"; return 1;
        case 3: c->steps = LONG_MIN, *what = "steps"; return 1;
        case 4: c->eps = 0.0, *what = "eps"; return 1;
        case 5: c->eps = -0.1, *what = "eps"; return 1;
        case 6: c->eps = NAN, *what = "eps"; return 1;
        case 7: c->eps = INFINITY, *what = "eps"; return 1;
        case 8: c->eps = 1e300, c->steps = LONG_MAX, *what = "overflows"; return 1;
        case 9: c->model = NULL, *what = "model"; return 1;
        case 10: c->model = &model_zero, *what = "model"; return 1;
        case 11: c->model = &model_garbage, *what = "model"; return 1;
        case 12: c->model = &model_changed, *what = "model"; return 1;
        case 13: c->stepper = NULL, *what = "stepper"; return 0; /* exact: no stepper needed */
        case 14:
            c->stepper = sus_step_method_by_name("taylor-adaptive")->type, *what = "_tol";
            return 0;
        case 15: c->stepper = &no_apply, *what = "apply"; return 0;
        case 16: c->stepper = &no_step, *what = "step is NULL"; return 0;
        case 17: c->recon = (sus_recon)-1, *what = "recon"; return 0;
        case 18: c->recon = SUS_RECON_COUNT, *what = "recon"; return 0;
        default: return -1;
    }
}

typedef int (*fixed_run_fn)(const sus_run_config *, const double *, sus_emit_fn, void *,
                            sus_run_report *);

/* The pointers and w0 every run checks. */
static void bad_pointers(const char *fn, fixed_run_fn run, const sus_run_config *good)
{
    sus_run_report rep;
    rows_seen = 0;
    refused(fn, "cfg", run(NULL, W0, count_rows, NULL, &rep), &rep);
    refused(fn, "w0", run(good, NULL, count_rows, NULL, &rep), &rep);
    refused(fn, "w0", run(good, W0_NAN, count_rows, NULL, &rep), &rep);
    refused(fn, "w0", run(good, W0_INF, count_rows, NULL, &rep), &rep);
    refused(fn, "subnormal", run(good, W0_SUB, count_rows, NULL, &rep), &rep);
    refused(fn, "emit", run(good, W0, NULL, NULL, &rep), &rep);
    const int rc = run(good, W0, count_rows, NULL, NULL);
    CHECK(rc == SUS_RUN_BAD_ARGUMENT && rows_seen == 0, "%s, NULL report: rc %d, %ld rows", fn, rc,
          rows_seen);
}

/* sus_run (with_stepper) or sus_run_exact: every bad configuration refused, the good one runs
 * (N = 7, K = 3: rows 0, 3, 6, 7). */
static void fixed_runs(const char *fn, fixed_run_fn run, int with_stepper)
{
    const sus_stepper_type *rk4 = sus_step_method_by_name("rk4")->type;
    const sus_run_config good = {&model, rk4, SUS_RECON_CAYLEY, 0.1, 7, 3};
    sus_run_report rep;
    rows_seen = 0;
    int rc = run(&good, W0, count_rows, NULL, &rep);
    CHECK(rc == SUS_RUN_OK && rows_seen == 4 && rep.message == NULL,
          "%s, control: rc %d, %ld rows (4), no message", fn, rc, rows_seen);
    const char *what;
    for (int i = 0;; i++) {
        sus_run_config c = good;
        const int kind = bad_fixed(i, &c, &what);
        if (kind < 0)
            break;
        rows_seen = 0;
        rc = run(&c, W0, count_rows, NULL, &rep);
        if (kind || with_stepper)
            refused(fn, what, rc, &rep);
        else /* the exact run takes no stepper and no reconstruction */
            CHECK(rc == SUS_RUN_OK && rows_seen == 4, "%s ignores %s: rc %d, %ld rows", fn, what,
                  rc, rows_seen);
    }
    bad_pointers(fn, run, &good);
}

static int run_fixed(const sus_run_config *c, const double *w0, sus_emit_fn e, void *x,
                     sus_run_report *r)
{
    return sus_run(c, w0, e, x, r);
}

static int run_exact(const sus_run_config *c, const double *w0, sus_emit_fn e, void *x,
                     sus_run_report *r)
{
    return sus_run_exact(c, w0, e, x, r);
}

static sus_tol_work *fake_alloc(const sus_model *m, double tol, const double w0[2])
{
    (void)m, (void)tol, (void)w0;
    return NULL;
}

/* Bad configuration number i of a tolerance-driven run, as bad_fixed. */
static int bad_tol(int i, sus_tol_config *c, const char **what)
{
    static const sus_tol_ops no_dense = {.alloc = fake_alloc, .step = NULL};
    static const sus_stepper_type half = {.name = "half", .tol = &no_dense};
    switch (i) {
        case 0:
            c->stepper = sus_step_method_by_name("midpoint")->type, *what = "fixed-step";
            return 1;
        case 1: c->stepper = NULL, *what = "stepper"; return 1;
        case 2: c->stepper = &half, *what = "alloc, step or free"; return 1;
        case 3: c->tol = 0.0, *what = "tol"; return 1;
        case 4: c->tol = -1e-8, *what = "tol"; return 1;
        case 5: c->tol = NAN, *what = "tol"; return 1;
        case 6: c->tol = INFINITY, *what = "tol"; return 1;
        case 7: c->t_end = NAN, *what = "t_end"; return 1;
        case 8: c->t_end = -1.0, *what = "t_end"; return 1;
        case 9: c->t_end = INFINITY, *what = "t_end"; return 1;
        case 10: c->every_time = NAN, *what = "every_time"; return 1;
        case 11: c->every_time = -0.5, *what = "every_time"; return 1;
        case 12: c->every_time = INFINITY, *what = "every_time"; return 1;
        case 13: c->every_time = 1e-300, *what = "rows"; return 1;
        case 14: c->max_steps = -1, *what = "max_steps"; return 1;
        case 15: c->model = NULL, *what = "model"; return 1;
        case 16: c->model = &model_zero, *what = "model"; return 1;
        case 17: c->model = &model_changed, *what = "model"; return 1;
        case 18: c->tol = 1.0, *what = "tol"; return 1;
        default: return -1;
    }
}

static void tol_runs(void)
{
    const sus_stepper_type *ta = sus_step_method_by_name("taylor-adaptive")->type;
    const sus_tol_config good = {&model, ta, 1e-10, 2.0, 0.5, 1000};
    sus_run_report rep;
    rows_seen = 0;
    int rc = sus_run_tol(&good, W0, count_rows, NULL, &rep);
    CHECK(rc == SUS_RUN_OK && rows_seen == 5 && rep.message == NULL,
          "sus_run_tol, control: rc %d, %ld rows (t = 0, 0.5, ..., 2)", rc, rows_seen);
    const char *what;
    for (int i = 0;; i++) {
        sus_tol_config c = good;
        if (bad_tol(i, &c, &what) < 0)
            break;
        rows_seen = 0;
        refused("sus_run_tol", what, sus_run_tol(&c, W0, count_rows, NULL, &rep), &rep);
    }
    /* |w0| ~ 1e-152, below 2^-500 = 3.05e-151 (api_args.h); 5e-151 and 0 are served */
    static const double tiny[2] = {4e-152, 5e-152}, small[2] = {4e-151, 5e-151}, zero[2] = {0, 0};
    rows_seen = 0;
    refused("sus_run_tol, |w0| ~ 1e-152", "w0: below 2^-500",
            sus_run_tol(&good, tiny, count_rows, NULL, &rep), &rep);
    int served = 0;
    for (int i = 0; i < 2; i++) {
        rows_seen = 0;
        served += sus_run_tol(&good, i ? zero : small, count_rows, NULL, &rep) == SUS_RUN_OK &&
                  rows_seen == 5;
    }
    CHECK(served == 2, "sus_run_tol from |w0| ~ 5e-151 and from 0: %d of 2 run", served);
    rows_seen = 0;
    refused("sus_run_tol", "cfg", sus_run_tol(NULL, W0, count_rows, NULL, &rep), &rep);
    refused("sus_run_tol", "w0", sus_run_tol(&good, W0_NAN, count_rows, NULL, &rep), &rep);
    refused("sus_run_tol", "subnormal", sus_run_tol(&good, W0_SUB, count_rows, NULL, &rep), &rep);
    refused("sus_run_tol", "emit", sus_run_tol(&good, W0, NULL, NULL, &rep), &rep);
    rc = sus_run_tol(&good, W0, count_rows, NULL, NULL);
    CHECK(rc == SUS_RUN_BAD_ARGUMENT && rows_seen == 0, "sus_run_tol, NULL report: rc %d", rc);
}

/* Legal but extreme: huge w0 (1e150: the energy, about |w0|^2, still a double), the loosest
 * tolerance (the double below 1), t_end = 0, steps = 0. Each ends with a status (a failure reported
 * with its step, or success), and every row it emits is finite; a tolerance-driven run from 1e150
 * turns the body past its method's max_angle by t = 1, and is refused. */
static int finite_rows(void *ctx, const sus_row *r)
{
    *(int *)ctx &= sus_row_finite(r);
    return 0;
}

static void extreme_runs(void)
{
    const double big[2] = {1e150, -1e150};
    sus_run_report rep;
    int fin = 1;
    for (int i = 0; i < sus_step_method_count(); i++) {
        const sus_run_config c = {&model, sus_step_method_get(i)->type, SUS_RECON_EXP_MID, 0.1, 3,
                                  1};
        const int rc = sus_run(&c, big, finite_rows, &fin, &rep);
        fin &= rc == SUS_RUN_OK || rc == SUS_RUN_STEP_FAILED || rc == SUS_RUN_BLOWUP;
    }
    CHECK(fin,
          "sus_run from |w0| = 1e150, every fixed-step method: a status, and finite rows only");
    const sus_stepper_type *ta = sus_step_method_by_name("taylor-adaptive")->type;
    const sus_tol_config loose = {&model, ta, 0x1.fffffffffffffp-1, 1.0, 0.0, 100000};
    const sus_tol_config zero = {&model, ta, 1e-8, 0.0, 0.0, 0};
    const sus_tol_config huge = {&model, ta, 1e-8, 1.0, 0.25, 1000};
    int rc = sus_run_tol(&loose, W0, finite_rows, &fin, &rep);
    CHECK(fin && (rc == SUS_RUN_OK || rc == SUS_RUN_STEP_FAILED),
          "sus_run_tol, tol just below 1: rc %d", rc);
    rows_seen = 0;
    rc = sus_run_tol(&zero, W0, count_rows, NULL, &rep);
    CHECK(rc == SUS_RUN_OK && rows_seen == 1, "sus_run_tol, t_end = 0: rc %d, %ld rows (1)", rc,
          rows_seen);
    rows_seen = 0;
    refused("sus_run_tol from |w0| = 1e150 to t = 1", "max_angle",
            sus_run_tol(&huge, big, count_rows, NULL, &rep), &rep);
    const double fast[2] = {1e12, -1e12}; /* turns by some 1e12 rad to t = 1: below max_angle */
    const sus_tol_config few = {&model, ta, 1e-8, 1.0, 0.25, 3};
    rc = sus_run_tol(&few, fast, finite_rows, &fin, &rep);
    CHECK(fin && rc == SUS_RUN_STEP_FAILED && rep.status == SUS_STEPPER_STEP_LIMIT,
          "sus_run_tol from |w0| = 1e12 with 3 steps to t = 1: the budget spent, rc %d", rc);
    const sus_run_config none = {&model, NULL, SUS_RECON_CAYLEY, 0.5, 0, 1};
    rows_seen = 0;
    rc = sus_run_exact(&none, W0, count_rows, NULL, &rep);
    CHECK(rc == SUS_RUN_OK && rows_seen == 1, "sus_run_exact, steps = 0: rc %d, %ld rows (1)", rc,
          rows_seen);
}

/* A start whose first row cannot be finite is refused before it, by every run function, with
 * the suslov command's reason: the energy at |w0| = 1e200 overflows on the paper's body, and
 * lambda at the paper's w0 on a body with I31 = I32 = 1e300 (its coefficients, each finite,
 * multiply past the range). Controls: the same runs from a smaller w0 are not refused. */
static void start_overflow_runs(void)
{
    const double big[2] = {1e200, -1e200}, tiny[2] = {1e-200, 1e-200};
    const double I[9] = {1, 0, 0, 0, 1, 0, 1e300, 1e300, 1};
    sus_model heavy;
    char err[128] = "";
    CHECK(sus_model_init(&heavy, I, err, sizeof err) == 0,
          "I31 = I32 = 1e300: a body (its coefficients are finite): %s", err);
    const sus_run_config fixed = {
        &model, sus_step_method_by_name("rk4")->type, SUS_RECON_CAYLEY, 0.1, 3, 1};
    const sus_run_config fixed_heavy = {&heavy, fixed.stepper, SUS_RECON_CAYLEY, 0.1, 3, 1};
    const sus_tol_config tol = {
        &model, sus_step_method_by_name("taylor-adaptive")->type, 1e-8, 1.0, 0.0, 1000};
    const char *energy = "the energy at w0 overflows", *lambda = "the multiplier lambda at w0";
    sus_run_report rep;
    rows_seen = 0;
    refused("sus_run", energy, sus_run(&fixed, big, count_rows, NULL, &rep), &rep);
    refused("sus_run_exact", energy, sus_run_exact(&fixed, big, count_rows, NULL, &rep), &rep);
    refused("sus_run_tol", energy, sus_run_tol(&tol, big, count_rows, NULL, &rep), &rep);
    refused("sus_run", lambda, sus_run(&fixed_heavy, W0, count_rows, NULL, &rep), &rep);
    refused("sus_run_exact", lambda, sus_run_exact(&fixed_heavy, W0, count_rows, NULL, &rep), &rep);
    const int rc = sus_run(&fixed_heavy, tiny, count_rows, NULL, &rep);
    const int rc_exact = sus_run_exact(&fixed_heavy, tiny, count_rows, NULL, &rep);
    CHECK(rc == SUS_RUN_OK && rc_exact == SUS_RUN_OK && rows_seen == 8,
          "control: the same body from |w0| = 1e-200 runs (rc %d, %d; %ld rows of 8)", rc, rc_exact,
          rows_seen);
}

/* sus_model_sealed: a copy of a good model passes, and one bit changed anywhere in the 64-bit words
 * it covers, or in the seal itself, fails it (bits 0, 31 and 63 of each). */
static void model_seal(void)
{
    const size_t words = sizeof(sus_model) / 8;
    int passed = 0;
    for (size_t i = 0; i < words; i++)
        for (int b = 0; b < 64; b += b < 31 ? 31 : 32) { /* 0, 31, 63 */
            sus_model m = model;
            unsigned long long x;
            memcpy(&x, (unsigned char *)&m + 8 * i, 8);
            x ^= 1ull << b;
            memcpy((unsigned char *)&m + 8 * i, &x, 8);
            passed += sus_model_sealed(&m);
        }
    const sus_model copy = model;
    CHECK(passed == 0 && sus_model_sealed(&copy) && !sus_model_sealed(NULL),
          "sus_model_sealed: %d of %zu models with one bit changed pass (none should); a copy "
          "passes, NULL fails",
          passed, 3 * words);
}

static void model_functions(void)
{
    sus_model m;
    char err[64] = "unchanged";
    const double bad[9] = {1, 0, 0, 0, -1, 0, 0, 0, 1};
    CHECK(sus_model_init(NULL, SUS_PAPER_INERTIA, err, sizeof err) == -1 && strstr(err, "NULL"),
          "sus_model_init(NULL model): -1, \"%s\"", err);
    CHECK(sus_model_init(&m, NULL, err, sizeof err) == -1 && strstr(err, "NULL"),
          "sus_model_init(NULL inertia): -1, \"%s\"", err);
    CHECK(sus_model_init(&m, bad, NULL, 64) == -1 && sus_model_init(&m, bad, err, 0) == -1,
          "sus_model_init with a NULL err or errlen 0: -1, nothing written");
    m = model;
    CHECK(sus_model_sealed(&m) && sus_model_init(&m, bad, NULL, 0) == -1 && !sus_model_sealed(&m),
          "a good model that sus_model_init then refuses is sealed no more");
    model_seal();
    double f[2], J[2][2];
    sus_contdyn(NULL, W0, f);
    sus_contdyn(&model, W0, NULL);
    sus_contdyn_jacobian(&model, NULL, J);
    sus_contdyn_jacobian(NULL, W0, NULL);
    CHECK(isnan(sus_c(NULL, W0)) && isnan(sus_c(&model, NULL)) && isnan(sus_lagmult(NULL, W0)) &&
              isnan(sus_lagmult_o0(&model, NULL)) && isnan(sus_energy(NULL, W0)) && isnan(f[0]) &&
              isnan(f[1]) && isnan(J[0][0]) && isnan(J[1][1]),
          "model kernels with a NULL model or w: NaN, nothing written to a NULL output");
    CHECK(!isnan(sus_lagmult(&model, W0)) && !isnan(sus_energy(&model, W0)),
          "control: finite with good arguments");
}

static void exact_functions(void)
{
    sus_exact ex;
    double w[2] = {0, 0};
    const int bad =
        (sus_exact_init(NULL, &model, W0) == -1) + (sus_exact_init(&ex, NULL, W0) == -1) +
        (sus_exact_init(&ex, &model_zero, W0) == -1) +
        (sus_exact_init(&ex, &model_changed, W0) == -1) +
        (sus_exact_init(&ex, &model, NULL) == -1) + (sus_exact_init(&ex, &model, W0_NAN) == -1);
    sus_exact_omega(&ex, 1.0, w);
    CHECK(bad == 6 && isnan(w[0]) && isnan(w[1]),
          "sus_exact_init refuses a NULL ex, a NULL, uninitialised or changed "
          "model, a NULL or NaN w0 (%d of 6): -1, and the refused ex gives NaN",
          bad);
    w[0] = 0.0;
    sus_exact_omega(NULL, 1.0, w);
    sus_exact_limit(NULL, w + 0);
    CHECK(isnan(w[0]), "sus_exact_omega, sus_exact_limit(NULL ex): NaN");
    CHECK(sus_exact_init(&ex, &model, W0) == 0, "control: sus_exact_init on the paper's body: 0");
    sus_exact_omega(&ex, 1.0, NULL);
    sus_exact_limit(&ex, NULL);
    sus_exact_omega(&ex, 1.0, w);
    CHECK(isfinite(w[0]) && isfinite(w[1]), "control: w(1) finite");
    const sus_run_config ten = {&model, NULL, SUS_RECON_CAYLEY, 0.01, 1000, 1000};
    const double s = sus_exact_reference_steps(&ten, W0);
    double nbad = (sus_exact_reference_steps(NULL, W0) == -1.0) +
                  (sus_exact_reference_steps(&ten, NULL) == -1.0) +
                  (sus_exact_reference_steps(&ten, W0_INF) == -1.0) +
                  (sus_exact_reference_steps(&ten, W0_SUB) == -1.0) +
                  (sus_exact_reference_steps(&ten, W0_BIG) == -1.0);
    const char *what;
    for (int i = 0;; i++) {
        sus_run_config c = ten;
        const int kind = bad_fixed(i, &c, &what);
        if (kind < 0)
            break;
        nbad += kind && sus_exact_reference_steps(&c, W0) == -1.0;
    }
    CHECK(nbad == 18 && s > 0.0 && isfinite(s),
          "sus_exact_reference_steps: -1 for the 18 bad arguments sus_run_exact refuses (%g), "
          "%g > 0 for a good one",
          nbad, s);
    /* t = 10 is before the paper's body's tail (w(10) is still 0.2 from w_inf, the tail starts
     * within 2^-64 of it), so each of the rows 0, 1, ..., 1000 costs one partial step: 999 more
     * than the rows 0 and 1000 */
    const sus_run_config all_rows = {&model, NULL, SUS_RECON_CAYLEY, 0.01, 1000, 1};
    const double d = sus_exact_reference_steps(&all_rows, W0) - s;
    CHECK(fabs(d - 999.0) <= 1e-9,
          "sus_exact_reference_steps counts the rows: %.17g more for "
          "every row than for --every 1000 (999)",
          d);
}

/* One step through sus_stepper_full: each bad argument gives SUS_STEPPER_BAD_ARGUMENT. */
#define BAD_STEP(...) (sus_stepper_full(__VA_ARGS__) == SUS_STEPPER_BAD_ARGUMENT)
static void stepper_functions(void)
{
    const sus_stepper_type *rk4 = sus_step_method_by_name("rk4")->type;
    const sus_stepper_type *ta = sus_step_method_by_name("taylor-adaptive")->type;
    const sus_recon C = SUS_RECON_CAYLEY;
    sus_attitude a;
    sus_attitude_identity(&a);
    const double w[3] = {0.4, 0.5, 0.0}, wn[3] = {NAN, 0.5, 0.0};
    double next[3], lam;
    sus_stepper_stats st;
    const int nbad = BAD_STEP(rk4, &model, 0.1, C, &a, w, next, &lam, NULL) +
                     BAD_STEP(NULL, &model, 0.1, C, &a, w, next, &lam, &st) +
                     BAD_STEP(ta, &model, 0.1, C, &a, w, next, &lam, &st) +
                     BAD_STEP(rk4, NULL, 0.1, C, &a, w, next, &lam, &st) +
                     BAD_STEP(rk4, &model, NAN, C, &a, w, next, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, (sus_recon)7, &a, w, next, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, C, NULL, w, next, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, C, &a, wn, next, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, C, &a, NULL, next, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, C, &a, w, NULL, &lam, &st) +
                     BAD_STEP(rk4, &model, 0.1, C, &a, w, next, NULL, &st);
    const int ok = sus_stepper_full(rk4, &model, 0.1, C, &a, w, next, &lam, &st);
    CHECK(
        nbad == 11 && ok == SUS_STEPPER_OK && isfinite(next[0]),
        "sus_stepper_full: %d of 11 bad arguments give SUS_STEPPER_BAD_ARGUMENT; control: %d (OK)",
        nbad, ok);
}

static void reconstruct_functions(void)
{
    sus_attitude a;
    double R[3][3], q[4] = {1, 0, 0, 0};
    const double w[3] = {0.4, 0.5, 0.0};
    sus_attitude_identity(NULL);
    sus_attitude_get(&a, NULL);
    sus_attitude_get(NULL, R);
    int nan_ok = isnan(R[0][0]) && isnan(R[2][2]);
    sus_attitude_identity(&a);
    sus_reconstruct((sus_recon)-2, 0.1, &a, w, w);
    sus_attitude_get(&a, R);
    nan_ok &= isnan(R[1][1]);
    sus_attitude_identity(&a);
    sus_reconstruct(SUS_RECON_CAYLEY, 0.1, &a, NULL, w);
    sus_reconstruct(SUS_RECON_CAYLEY, 0.1, NULL, w, w);
    sus_attitude_get(&a, R);
    nan_ok &= isnan(R[0][1]);
    sus_attitude_identity(&a);
    sus_attitude_increment(&a, NULL);
    sus_attitude_increment(NULL, R);
    sus_attitude_get(&a, R);
    nan_ok &= isnan(R[2][0]);
    sus_reconstruct_quat(SUS_RECON_COUNT, 0.1, q, w, w);
    sus_reconstruct_quat(SUS_RECON_CAYLEY, 0.1, NULL, w, w);
    nan_ok &= isnan(q[0]);
    CHECK(nan_ok, "attitude functions with a NULL pointer or an unknown kind: NaN, never a made-up "
                  "rotation");
    sus_recon k = SUS_RECON_EXP_MID;
    const int r = sus_recon_by_name(NULL, &k) + sus_recon_by_name("cayley", NULL) +
                  sus_recon_by_name("nope", &k);
    CHECK(r == -3 && k == SUS_RECON_EXP_MID && sus_recon_by_name("cayley", &k) == 0 &&
              k == SUS_RECON_CAYLEY,
          "sus_recon_by_name: -1 for a NULL or unknown name or NULL kind; control: cayley found");
}

static void registry_functions(void)
{
    char buf[8] = "x";
    const int n = sus_step_method_count_all();
    CHECK(sus_step_method_get(-1) == NULL && sus_step_method_get(n) == NULL &&
              sus_step_method_get(INT_MIN) == NULL && sus_step_method_get(n - 1) != NULL,
          "sus_step_method_get: NULL outside 0 .. %d", n - 1);
    CHECK(sus_step_method_by_name(NULL) == NULL && sus_step_method_by_name("nope") == NULL &&
              sus_step_method_index(NULL) == -1 && sus_step_method_index_of(NULL) == -1 &&
              sus_step_method_by_name("rk4") != NULL,
          "sus_step_method_by_name, _index, _index_of: NULL or -1 for NULL and unknown names");
    CHECK(strcmp(sus_step_attitude_name((sus_attitude_form)99), "?") == 0 &&
              strcmp(sus_step_attitude_name((sus_attitude_form)-1), "?") == 0,
          "sus_step_attitude_name of an unknown form: \"?\"");
    CHECK(sus_step_method_names(NULL, 8, "|") == NULL &&
              sus_step_method_names(buf, 0, "|") == NULL && buf[0] == 'x',
          "sus_step_method_names with a NULL buf or len 0: NULL, nothing written");
    const char *s = sus_step_method_names(buf, sizeof buf, NULL);
    CHECK(s == buf && strlen(buf) == sizeof buf - 1,
          "sus_step_method_names, NULL sep, 8 bytes: \"%s\"", buf);
    CHECK(sus_step_methods_write_tsv(NULL) == -1, "sus_step_methods_write_tsv(NULL): -1");
    const sus_stepper_type *rk4 = sus_step_method_by_name("rk4")->type;
    char lab[32] = "x";
    const int refused =
        sus_step_method_label(rk4, SUS_RECON_CAYLEY, NULL, 8) == NULL &&
        sus_step_method_label(rk4, SUS_RECON_CAYLEY, lab, 0) == NULL && lab[0] == 'x' &&
        sus_step_method_label(NULL, SUS_RECON_CAYLEY, lab, sizeof lab) == NULL && lab[0] == '\0' &&
        sus_step_method_label(rk4, SUS_RECON_COUNT, lab, sizeof lab) == NULL &&
        sus_step_method_label(rk4, (sus_recon)-1, lab, sizeof lab) == NULL;
    CHECK(refused && sus_step_method_label(rk4, SUS_RECON_CAYLEY, lab, sizeof lab) == lab &&
              strcmp(lab, "rk4 + cayley") == 0,
          "sus_step_method_label: NULL for a NULL buf, len 0, "
          "a NULL type or an unknown recon; control: \"%s\"",
          lab);
}

static void row_functions(void)
{
    sus_row r = {0};
    CHECK(sus_keep_last(NULL, &r) != 0 && sus_keep_last(&r, NULL) != 0 &&
              sus_keep_last(&r, &r) == 0,
          "sus_keep_last: non-zero (stop) for a NULL ctx or row");
    CHECK(sus_row_finite(NULL) == 0 && sus_row_finite(&r) == 1, "sus_row_finite(NULL): 0");
}

/* The angle limits (exact_run.h; a tolerance-driven method's max_angle, stepper.h): a run whose
 * final time turns the body by more than its attitude's limit is refused, one just under it runs
 * (1 % either side, far beyond the roundings of the angle). |w_inf| of the paper's body, apart
 * from the library: the steady rotations are the w with c(w) = I31 w1 + I32 w2 = 0, w = s d with
 * d = (-I32, I31), and the energy is conserved, so |w_inf|^2 = |d|^2 <I_m w0, w0> / <I_m d, d>
 * = 0.05 * 0.45 / 0.046. */
static void angle_limits(void)
{
    const double speed = sqrt(0.05 * 0.45 / 0.046);
    const double a2 = sus_exact_turn_angle(&model, W0, 2.0);
    /* some ten roundings in the closed form's limit, four in the line above */
    CHECK(fabs(a2 - 2.0 * speed) <= 32 * DBL_EPSILON * a2,
          "sus_exact_turn_angle(paper's body, t = 2) = %.17g, 2 |w_inf| = %.17g", a2, 2 * speed);
    const int nbad = (sus_exact_turn_angle(NULL, W0, 1.0) == -1.0) +
                     (sus_exact_turn_angle(&model_zero, W0, 1.0) == -1.0) +
                     (sus_exact_turn_angle(&model, NULL, 1.0) == -1.0) +
                     (sus_exact_turn_angle(&model, W0_NAN, 1.0) == -1.0) +
                     (sus_exact_turn_angle(&model, W0, -1.0) == -1.0) +
                     (sus_exact_turn_angle(&model, W0, NAN) == -1.0) +
                     (sus_exact_turn_angle(&model, W0, INFINITY) == -1.0);
    CHECK(nbad == 7, "sus_exact_turn_angle: -1 for 7 bad arguments (%d)", nbad);
    sus_run_report rep;
    for (int over = 0; over < 2; over++) {
        const double f = over ? 1.01 : 0.99;
        const sus_run_config c = {&model, NULL, SUS_RECON_CAYLEY, f * SUS_EXACT_MAX_ANGLE / speed,
                                  1,      1};
        rows_seen = 0;
        const int rc = sus_run_exact(&c, W0, count_rows, NULL, &rep);
        if (over)
            refused("sus_run_exact, angle 1.01 SUS_EXACT_MAX_ANGLE", "SUS_EXACT_MAX_ANGLE", rc,
                    &rep);
        else
            CHECK(rc == SUS_RUN_OK && rows_seen == 2,
                  "sus_run_exact, angle 0.99 SUS_EXACT_MAX_ANGLE: rc %d, %ld rows (2)", rc,
                  rows_seen);
    }
    for (int i = 0; i < sus_step_method_count_all(); i++) {
        const sus_stepper_type *st = sus_step_method_get(i)->type;
        if (!st->tol)
            continue;
        const double lim = st->tol->max_angle;
        CHECK(lim >= 1.0 && isfinite(lim), "%s: max_angle %g is set", st->name, lim);
        for (int over = 0; over < 2; over++) {
            const double f = over ? 1.01 : 0.99;
            const sus_tol_config c = {&model, st, 1e-8, f * lim / speed, 0.0, 100000};
            rows_seen = 0;
            const int rc = sus_run_tol(&c, W0, count_rows, NULL, &rep);
            if (over)
                refused(st->name, "max_angle", rc, &rep);
            else
                CHECK(rc == SUS_RUN_OK && rows_seen > 1,
                      "%s, angle 0.99 max_angle: rc %d, %ld rows", st->name, rc, rows_seen);
        }
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0); /* the lines before a crash are kept */
    signal(SIGALRM, SIG_DFL);
    alarm(ALARM_SECONDS);
    models_init();
    fixed_runs("sus_run", run_fixed, 1);
    fixed_runs("sus_run_exact", run_exact, 0);
    tol_runs();
    extreme_runs();
    start_overflow_runs();
    model_functions();
    exact_functions();
    angle_limits();
    stepper_functions();
    reconstruct_functions();
    registry_functions();
    row_functions();
    return check_summary("test_api_contract");
}
