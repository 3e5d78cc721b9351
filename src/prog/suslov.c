/* suslov: integrate the Suslov problem with one of the paper's methods and print CSV rows
 * (k, t, w, lambda, E, R). Its options, --help and manual page come from one table
 * (suslov_cli.c); see docs/reference/cli.md. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include "cli_options.h"
#include "driver.h"
#include "exact_run.h"
#include "model.h"
#include "paper_ref.h"
#include "progress.h"
#include "suslov_cli.h"

#include <errno.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

enum { EXIT_WRITE = 1, EXIT_SOLVER = 3 };
#define PROGRESS_PARTS 10000L /* a --tol run's progress: t / T in these parts */

/* ---- rows ---- */

typedef struct {
    FILE *fp;
    const sus_model *m;
    long every, steps;
    long next;          /* the next row to write: 0, K, 2K, ..., N (no division per step) */
    unsigned tick_mask; /* check the clock when (calls & mask) == 0 */
    double t_end;       /* > 0: progress as the share of [0, t_end] done (a --tol run), else k */
    unsigned long calls;
    int blowup; /* the energy overflowed at row blow_k (w finite but |w| > ~1e154) */
    long blow_k;
    double blow_t;
    int all;          /* write every row handed over (a tolerance-driven run's rows) */
    int renumber;     /* k := the row's index (--every-time: t = k DT), not the driver's step */
    long row;         /* rows written so far, when renumbering */
    int have_pending; /* `pending` is the last good row and was not written */
    sus_row pending;
} csv_ctx;

static int print_row(csv_ctx *ctx, const sus_row *r)
{
    fprintf(ctx->fp, "%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", r->k, r->t, r->w[0], r->w[1],
            r->w[2], r->lambda, sus_energy(ctx->m, r->w));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            fprintf(ctx->fp, ",%.17g", r->R[i][j]);
    ctx->have_pending = 0;
    return fputc('\n', ctx->fp) == EOF;
}

/* The driver hands over every row (its every = 1); the rows 0, K, 2K, ... and N are written,
 * the others kept one at a time so that the last good row can be written before a failure. */
static int take_row(void *vctx, const sus_row *r)
{
    csv_ctx *ctx = vctx;
    if ((ctx->calls++ & ctx->tick_mask) == 0)
        suslov_progress_tick(ctx->t_end > 0.0 ? (long)(PROGRESS_PARTS * (r->t / ctx->t_end)) : r->k,
                             "t = %.6g", r->t);
    if (!isfinite(sus_energy(ctx->m, r->w))) {
        ctx->blowup = 1;
        ctx->blow_k = r->k;
        ctx->blow_t = r->t;
        return 1;
    }
    if (ctx->renumber) { /* the driver's k repeats (rows between two accepted steps share it) */
        sus_row own = *r;
        own.k = ctx->row++;
        return print_row(ctx, &own);
    }
    if (ctx->all)
        return print_row(ctx, r);
    if (r->k == ctx->next) {
        /* k + K would overflow for N, K near LONG_MAX: compare with what is left. */
        ctx->next = ctx->steps - r->k > ctx->every ? r->k + ctx->every : ctx->steps;
        return print_row(ctx, r);
    }
    ctx->pending = *r;
    ctx->have_pending = 1;
    return 0;
}

/* ---- the failure message ---- */

/* A Newton solve that failed: the step, t and always the residual; one that is not a finite
 * number (the iteration overflowed) is described, with the last finite one before it. */
static void newton_failure(char *msg, size_t len, const sus_run_report *rep)
{
    const sus_stepper_stats *st = &rep->stats;
    char res[160], det[64] = "";
    if (isfinite(st->residual) && isfinite(st->scale))
        snprintf(res, sizeof res, "residual %.3g (scale %.3g)", st->residual, st->scale);
    else if (isfinite(st->residual))
        snprintf(res, sizeof res,
                 "residual %.3g, but its scale (the sum of |terms| of G) is not a finite number",
                 st->residual);
    else if (isfinite(st->last_residual))
        snprintf(res, sizeof res,
                 "the residual is not a finite number; the last finite residual was %.3g",
                 st->last_residual);
    else
        snprintf(res, sizeof res,
                 "the residual is not a finite number already at the starting guess");
    if (isfinite(st->det))
        snprintf(det, sizeof det, ", Jacobian determinant %.3g", st->det);
    const int finite = isfinite(st->residual) && isfinite(st->scale);
    char regloc[200];
    const char *why =
        rep->status == SUS_STEPPER_SINGULAR
            ? sus_paper_numbered(
                  "the step equation's root, continued from eps = 0, meets a fold where the "
                  "Jacobian of (REGLOC) vanishes: no root on that branch for this step",
                  regloc, sizeof regloc)
        : finite
            ? "Newton did not converge, from the prediction nor along the continuation from eps = 0"
            : "Newton's iteration overflowed";
    snprintf(msg, len, "step %ld (t = %.17g) failed: %s; %s%s, after %d Newton iterations",
             rep->step, rep->t, why, res, det, st->iterations);
}

/* One line naming the step and t; a NaN or infinity is described, never printed. */
static void failure_message(char *msg, size_t len, const char *name, int rc,
                            const sus_run_report *rep)
{
    const sus_stepper_stats *st = &rep->stats;
    const int n = snprintf(msg, len, "%s ", name);
    msg += n;
    len -= (size_t)n;
    if (rc == SUS_RUN_BLOWUP)
        snprintf(
            msg, len,
            "blow-up at step %ld (t = %.17g): w, lambda, R or the energy is not a finite number",
            rep->step, rep->t);
    else if (rep->status == SUS_STEPPER_REJECTED && !isfinite(st->residual))
        snprintf(
            msg, len,
            "step %ld (t = %.17g) failed: its error estimate was not a finite number (the series "
            "overflowed) after %d tries (last step tried %.3g)",
            rep->step, rep->t, st->iterations, st->det);
    else if (rep->status == SUS_STEPPER_REJECTED)
        snprintf(
            msg, len,
            "step %ld (t = %.17g) failed: its error estimate %.3g stayed above --tol %.3g after %d "
            "tries (last step tried %.3g)",
            rep->step, rep->t, st->residual, st->scale, st->iterations, st->det);
    else if (rep->status == SUS_STEPPER_STEP_LIMIT)
        snprintf(
            msg, len,
            "stopped before step %ld at t = %.17g: a --tol run takes at most %ld steps (the last "
            "was %.3g long; a shorter --time, a looser --tol or a smaller --omega0 needs fewer)",
            rep->step, rep->t, SUSLOV_TOL_MAX_STEPS, st->det);
    else if (rep->status == SUS_STEPPER_NO_MEMORY)
        snprintf(msg, len, "step %ld (t = %.17g) failed: out of memory for the method's workspace",
                 rep->step, rep->t);
    else if (rep->status == SUS_STEPPER_DIVERGED)
        snprintf(msg, len,
                 "step %ld (t = %.17g) failed: the Taylor series diverges or is not proved to "
                 "converge: the step is %.3g times the radius proved for it (|w|_2 = %.3g)",
                 rep->step, rep->t, st->residual, st->scale);
    else
        newton_failure(msg, len, rep);
}

/* ---- the run ---- */

/* Progress only where a person watches stderr and the rows do not scroll over it. */
static int progress_modes(const suslov_args *a)
{
    return !a->quiet && (a->output != NULL || !isatty(STDOUT_FILENO)) ? PROGRESS_TERMINAL : 0;
}

/* A tolerance-driven run: the driver hands over exactly the rows to write. Its steps are uneven,
 * so progress is the share of [0, T] done, in PROGRESS_PARTS. */
static int run_tol(const suslov_args *a, FILE *fp, sus_run_report *report, csv_ctx *ctx)
{
    const sus_tol_config cfg = {&a->model, a->method->type, a->tol,
                                a->t_end,  a->every_time,   SUSLOV_TOL_MAX_STEPS};
    *ctx = (csv_ctx){.fp = fp,
                     .m = &a->model,
                     .all = 1,
                     .renumber = a->every_time > 0.0,
                     .tick_mask = 15u,
                     .t_end = a->t_end};
    suslov_progress_start("suslov", NULL, PROGRESS_PARTS, progress_modes(a));
    const int rc = sus_run_tol(&cfg, a->w0, take_row, ctx, report);
    suslov_progress_end();
    if (rc == SUS_RUN_STOPPED && ctx->blowup) { /* the energy overflowed: a blow-up too */
        report->step = ctx->blow_k;
        report->t = ctx->blow_t;
        return SUS_RUN_BLOWUP;
    }
    return rc;
}

static int run(const suslov_args *a, FILE *fp, sus_run_report *report, csv_ctx *ctx)
{
    const int exact = a->method == NULL;
    if (a->tol > 0.0)
        return run_tol(a, fp, report, ctx);
    /* The exact run computes only the rows it writes (each may cost a stretch of the reference
     * integration), so it gets its K; the integrators step every k anyway and hand every row
     * to take_row. */
    const sus_run_config cfg = {&a->model, a->stepper, a->recon,
                                a->eps,    a->steps,   exact ? a->every : 1};
    *ctx = (csv_ctx){.fp = fp,
                     .m = &a->model,
                     .every = a->every,
                     .steps = a->steps,
                     .tick_mask = exact ? 0u : 1023u};
    suslov_progress_start("suslov", "step", a->steps, progress_modes(a));
    int rc = exact ? sus_run_exact(&cfg, a->w0, take_row, ctx, report)
                   : sus_run(&cfg, a->w0, take_row, ctx, report);
    suslov_progress_end();
    if (rc == SUS_RUN_STOPPED && ctx->blowup) { /* the energy overflowed: a blow-up too */
        rc = SUS_RUN_BLOWUP;
        report->step = ctx->blow_k;
        report->t = ctx->blow_t;
    }
    /* A failure: the last good row goes out as it would at the end of a normal run. */
    if (rc != SUS_RUN_OK && rc != SUS_RUN_STOPPED && ctx->have_pending &&
        print_row(ctx, &ctx->pending))
        rc = SUS_RUN_STOPPED;
    return rc;
}

static int write_failed(sus_sys_atomic_file *af, const char *output)
{
    const int saved = errno;
    sus_sys_atomic_file_abort(af);
    suslov_cli_error("writing %s failed: %s", output && strcmp(output, "-") ? output : "stdout",
                     strerror(saved));
    return EXIT_WRITE;
}

/* Exit 3. A file that would be renamed into place is not: the temporary is discarded and the
 * target left as it was (all or nothing), which the line says. Stdout, a device or a pipe has
 * its rows already, the last good step included: a last comment line marks them incomplete. */
static int solver_failed(sus_sys_atomic_file *af, const suslov_args *a, int rc,
                         const sus_run_report *rep)
{
    char msg[1024], err[1024];
    failure_message(msg, sizeof msg, a->stepper ? a->stepper->name : "exact", rc, rep);
    if (!af->in_place) {
        sus_sys_atomic_file_abort(af);
        suslov_cli_error("%s; --output %s %s", msg, suslov_cli_quote(a->output),
                         af->existed ? "is left as it was" : "was not created");
        return EXIT_SOLVER;
    }
    if (a->header &&
        fprintf(af->fp, "# incomplete: the run stopped with exit status 3: %s\n", msg) < 0)
        return write_failed(af, a->output);
    if (sus_sys_atomic_file_commit(af, err, sizeof err) != 0) {
        suslov_cli_error("%s", err);
        return EXIT_WRITE;
    }
    suslov_cli_error("%s", msg);
    return EXIT_SOLVER;
}

int main(int argc, char **argv)
{
    suslov_args a;
    char err[1024];
    suslov_args_parse(&a, argc, argv);
    gsl_set_error_handler_off();
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, a.output, err, sizeof err) != 0) {
        /* Nothing is written yet: a path the system will not let us create in (a permission,
         * a read-only filesystem, which root's access() checks cannot foresee) is bad input, as
         * the checks before; anything else (no space, no inode, I/O) is an output error. */
        if (errno == EACCES || errno == EPERM || errno == EROFS)
            suslov_cli_die("--output: %s", err);
        suslov_cli_error("--output: %s", err);
        return EXIT_WRITE;
    }
    static char buf[1 << 16];
    setvbuf(af.fp, buf, _IOFBF, sizeof buf);
    if (a.header)
        suslov_args_header(&a, argc, argv, af.fp);
    fputs("k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n", af.fp);
    sus_run_report report;
    csv_ctx ctx;
    const int rc = run(&a, af.fp, &report, &ctx);
    if (rc == SUS_RUN_STOPPED)
        return write_failed(&af, a.output);
    if (rc != SUS_RUN_OK)
        return solver_failed(&af, &a, rc, &report);
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        suslov_cli_error("%s", err);
        return EXIT_WRITE;
    }
    return 0;
}
