/* The library in the reader's browser (the web edition's live pages, tools/web/live.js): a thin
 * entry over the same driver, steppers, reconstructions and exact solution the suslov command
 * runs, compiled to WebAssembly (make wasm). It adds no equation: it records the rows of a run in
 * the CSV's column order (k, t, w1, w2, w3, lambda, E, R11 .. R33), so that the page shows the
 * numbers the CLI prints. Inputs go through one static block the page fills. */
#include "driver.h"
#include "dsp.h"
#include "exact.h"
#include "exact_run.h"
#include "experiments.h"
#include "inertia_check.h"
#include "midpoint_sweeps.h"
#include "model.h"
#include "orderfit.h"
#include "registry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NCOL = 16, MAX_ROWS = 1 << 18 };

/* The page writes w0 (2) and the inertia by rows (9) here before a run. */
static double input[11];
static double *rows;
static long nrows, cap;
static char message[512];
static const sus_model *row_model;

double *wasm_input(void) { return input; }
double *wasm_rows(void) { return rows; }
long wasm_nrows(void) { return nrows; }
const char *wasm_message(void) { return message; }
int wasm_method_count(void) { return sus_step_method_count(); }
const char *wasm_method_name(int i) { return sus_step_method_get(i)->type->name; }
const char *wasm_method_about(int i) { return sus_step_method_get(i)->about; }
int wasm_method_recon(int i) { return (int)sus_step_method_get(i)->recon; }
int wasm_recon_count(void) { return SUS_RECON_COUNT; }
const char *wasm_recon_name(int i)
{
    return i >= 0 && i < SUS_RECON_COUNT ? SUS_RECON_NAMES[i] : "";
}

/* The other reading of the printed inertia (experiments.h): the input body's third row replaced
 * by its third column. */
void wasm_inertia_column(void)
{
    double I[9];
    sus_lab_inertia_column_swap(input + 2, I);
    memcpy(input + 2, I, sizeof I);
}

/* The exact solution's steady rotation w_inf for the body and w0 of the input block. */
double *wasm_limit(void)
{
    static double w[2];
    sus_model m;
    sus_exact ex;
    char err[256];
    const double w0[2] = {input[0], input[1]};
    w[0] = w[1] = NAN;
    if (sus_model_init(&m, input + 2, err, sizeof err) == 0) {
        sus_exact_init(&ex, &m, w0);
        sus_exact_limit(&ex, w);
    }
    return w;
}

/* The message of a failure: fmt takes a and b as doubles (or only a, or neither). */
static int say(int status, const char *fmt, double a, double b)
{
    snprintf(message, sizeof message, fmt, a, b);
    return status;
}

static void put_row(const sus_row *r)
{
    double *o = rows + nrows++ * NCOL;
    o[0] = (double)r->k;
    o[1] = r->t;
    o[2] = r->w[0];
    o[3] = r->w[1];
    o[4] = r->w[2];
    o[5] = r->lambda;
    o[6] = sus_energy(row_model, r->w);
    for (int i = 0; i < 9; i++)
        o[7 + i] = r->R[i / 3][i % 3];
}

static int take(void *ctx, const sus_row *r)
{
    (void)ctx;
    if (nrows == cap)
        return 1;
    put_row(r);
    return 0;
}

/* Room for the rows 0, K, 2K, ..., N: allocated once, before the run. */
static int reserve(long steps, long every)
{
    const long want = steps / every + 2;
    if (want > cap) {
        free(rows);
        rows = malloc((size_t)want * NCOL * sizeof *rows);
        cap = rows ? want : 0;
        if (!rows)
            return say(1, "out of memory for %.0f rows", (double)want, 0.0);
    }
    nrows = 0;
    return 0;
}

/* The checks every entry makes before a run, the model of the input body, and the room for
 * the rows 0, K, 2K, ..., N. N and K come as doubles: a page's N = T / eps may exceed a 32-bit
 * long. Returns 0 or 2 (bad input, with the message). */
static int setup(double eps, double nsteps, double nevery)
{
    static sus_model model;
    message[0] = '\0';
    if (!(eps > 0.0))
        return say(2, "--eps must be positive, got %.17g", eps, 0);
    if (!(nsteps >= 1.0 && nevery >= 1.0) || nsteps != floor(nsteps) || nevery != floor(nevery))
        return say(2, "--steps and --every must be positive integers, got %.17g and %.17g", nsteps,
                   nevery);
    if (nsteps / nevery + 2.0 > MAX_ROWS)
        return say(2,
                   "--steps/--every: %.0f rows to keep, more than the page's %.0f (raise --every)",
                   floor(nsteps / nevery) + 2.0, (double)MAX_ROWS);
    if (!isfinite(nsteps * eps))
        return say(2, "--steps %.0f with --eps %.17g: the final time N H overflows", nsteps, eps);
    if (suslov_inertia_model(&model, input + 2, message, sizeof message) != 0) /* the CLI's */
        return 2;
    row_model = &model;
    return reserve((long)nsteps, (long)nevery);
}

static int failed(int rc, const sus_run_report *rep)
{
    if (rc == SUS_RUN_OK)
        return 0;
    /* what the library refuses: a start whose E or lambda overflows, a final time past the
     * attitude's angle limit (exact_run.h) */
    if (rc == SUS_RUN_BAD_ARGUMENT)
        return snprintf(message, sizeof message, "%s", rep->message), 2;
    if (rc == SUS_RUN_BLOWUP)
        return say(
            3,
            "blow-up at step %.0f (t = %.17g): w, lambda, R or the energy is not a finite number",
            (double)rep->step, rep->t);
    return say(3, "step %.0f (t = %.17g) failed: the step's solver did not converge",
               (double)rep->step, rep->t);
}

/* A run of stepper `type` (NULL: the exact solution) with reconstruction rk, step eps, N steps,
 * rows every K-th step. */
static int run_stepper(const sus_stepper_type *type, sus_recon rk, double eps, double nsteps,
                       double nevery)
{
    const int rc = setup(eps, nsteps, nevery);
    if (rc)
        return rc;
    const sus_run_config cfg = {row_model, type, rk, eps, (long)nsteps, (long)nevery};
    sus_run_report rep;
    const double w0[2] = {input[0], input[1]};
    return failed(type ? sus_run(&cfg, w0, take, NULL, &rep)
                       : sus_run_exact(&cfg, w0, take, NULL, &rep),
                  &rep);
}

/* The reconstruction `recon`, or (-1) the method's own. */
static sus_recon recon_or(int recon, sus_recon own)
{
    return recon >= 0 && recon < SUS_RECON_COUNT ? (sus_recon)recon : own;
}

/* One run of method `method` (registry index; -1 the exact solution) with reconstruction
 * `recon` (-1: the method's own), step eps, N steps, rows every K-th step. Returns 0, 2 for bad
 * input, 3 for a failed step or a blow-up (wasm_message says which, as the CLI does). */
int wasm_run(int method, int recon, double eps, double nsteps, double nevery)
{
    if (method < -1 || method >= sus_step_method_count())
        return say(2, "unknown method", 0, 0);
    const sus_step_method *me = method >= 0 ? sus_step_method_get(method) : NULL;
    return run_stepper(me ? me->type : NULL, recon_or(recon, me ? me->recon : SUS_RECON_CAYLEY),
                       eps, nsteps, nevery);
}

/* Figure 2's other readings of the midpoint rule, as suslov --method midpoint --sweeps n
 * (midpoint_sweeps.h): n fixed-point sweeps per step instead of Newton, reconstruction `recon`
 * (-1: the midpoint method's own). Same returns as wasm_run. */
int wasm_sweeps(int n, int recon, double eps, double nsteps, double nevery)
{
    const sus_stepper_type *type = sus_lab_midpoint_sweeps_type(n);
    if (!type)
        return n < 1 ? say(2, "--sweeps must be positive, got %.0f", n, 0)
                     : say(2, "--sweeps must be at most %.0f, got %.0f", SUS_LAB_MAX_SWEEPS, n);
    sus_recon own = SUS_RECON_CAYLEY;
    for (int i = 0; i < sus_step_method_count(); i++)
        if (sus_step_method_get(i)->type == sus_step_midpoint)
            own = sus_step_method_get(i)->recon;
    return run_stepper(type, recon_or(recon, own), eps, nsteps, nevery);
}

/* The exact solution without the attitude: closed-form w(t_k) and lambda(w(t_k)) at the rows
 * 0, K, 2K, ..., N (R is NaN). The full exact run (wasm_run with method -1) integrates the
 * reference attitude in long double, which WebAssembly emulates in software: far slower. */
int wasm_exact_omega(double eps, double nsteps, double nevery)
{
    const int rc = setup(eps, nsteps, nevery);
    if (rc)
        return rc;
    const long steps = (long)nsteps, every = (long)nevery;
    sus_exact ex;
    const double w0[2] = {input[0], input[1]};
    sus_exact_init(&ex, row_model, w0);
    for (long k = 0;; k = steps - k > every ? k + every : steps) {
        sus_row r = {.k = k, .t = (double)k * eps};
        for (int i = 0; i < 9; i++)
            r.R[i / 3][i % 3] = NAN;
        sus_exact_omega(&ex, r.t, r.w);
        r.lambda = sus_lagmult_c(row_model, r.w, sus_exact_c(&ex, r.t));
        put_row(&r);
        if (k == steps)
            return 0;
    }
}

/* The convergence page's fit: the page writes n <= FIT_MAX steps eps_i at fit_in[i] and their
 * errors at fit_in[FIT_MAX + i], and sus_lab_fit_order (orderfit.c, the ledger's fit) fits
 * the points with eps <= eps_max above the round-off floor 1000 u size. Returns slope,
 * intercept, points used, the eps range fitted and the floor (slope NaN when no fit). */
enum { FIT_MAX = 64 };
static double fit_in[2 * FIT_MAX];
double *wasm_fit_input(void) { return fit_in; }

double *wasm_fit(int n, double eps_max, double size)
{
    static double out[6];
    sus_lab_order_fit f;
    const double round_off = SUS_LAB_FIT_FLOOR_REL * size;
    const int ok = n >= 0 && n <= FIT_MAX &&
                   sus_lab_fit_order(fit_in, fit_in + FIT_MAX, n, eps_max, round_off, &f) == 0;
    out[0] = ok ? f.slope : NAN;
    out[1] = ok ? f.intercept : NAN;
    out[2] = ok ? f.used : 0;
    out[3] = ok ? f.eps_lo : NAN;
    out[4] = ok ? f.eps_hi : NAN;
    out[5] = round_off;
    return out;
}
