/* suslov: integrate the Suslov problem with one of the paper's methods and print CSV rows
 * (k, t, w, lambda, E, R). See usage() and README.md. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include "driver.h"
#include "exact_run.h"
#include "model.h"
#include "monoclock.h"
#include "registry.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { EXIT_BAD_INPUT = 2, EXIT_SOLVER = 3 };

static void usage(FILE *fp)
{
    fputs("usage: suslov --method M --eps H (--steps N | --time T)\n", fp);
    fputs("              [--omega0 W1,W2] [--inertia I11,I12,I13,I21,I22,I23,I31,I32,I33]\n", fp);
    fputs("              [--reconstruct ", fp);
    for (int r = 0; r < SUSLOV_RECON_COUNT; r++)
        fprintf(fp, "%s%s", r ? "|" : "", SUSLOV_RECON_NAMES[r]);
    fputs("] [--every K] [--output FILE] [--quiet] [--help]\n"
          "\n"
          "Integrates the Suslov problem (Jimenez & Scheurle, Section 5) and writes CSV with the header\n"
          "k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n"
          "\n"
          "  --method M        exact        closed-form w(t), lambda(w(t)) from (LagMult), reference R(t)\n"
          "                                 (long-double Taylor series along the exact w; once w has reached\n"
          "                                 the steady rotation, R in closed form)\n",
          fp);
    for (int i = 0; i < suslov_method_count(); i++) {
        const suslov_method *me = suslov_method_get(i);
        fprintf(fp, "                    %-12s %s\n", me->type->name, me->about);
    }
    fputs("  --eps H           time step, H > 0\n"
          "  --steps N         number of steps, N > 0\n"
          "  --time T          final time instead of --steps: N = round(T/H)\n"
          "  --omega0 W1,W2    initial body angular velocity (w3 = 0); default 0.4,0.5\n"
          "  --inertia ...     inertia tensor by rows, as printed in the paper (only I_m and the third\n"
          "                    row enter); I_m must be symmetric positive definite;\n"
          "                    default 1,0.1,0.2,0.1,1,0.2,0.2,0.1,1\n"
          "  --reconstruct R   how R_{k+1} is built from R_k:\n",
          fp);
    for (int r = 0; r < SUSLOV_RECON_COUNT; r++)
        fprintf(fp, "                    %-12s %s\n", SUSLOV_RECON_NAMES[r], SUSLOV_RECON_ABOUT[r]);
    fputs("                    default, the method's own:\n", fp);
    for (int r = 0; r < SUSLOV_RECON_COUNT; r++) {
        int n = 0;
        for (int i = 0; i < suslov_method_count(); i++)
            if (suslov_method_get(i)->recon == (suslov_recon)r)
                fprintf(fp, "%s%s", n++ ? ", " : "                      ", suslov_method_get(i)->type->name);
        if (n)
            fprintf(fp, ": %s\n", SUSLOV_RECON_NAMES[r]);
    }
    fputs("  --every K         write step 0, every K-th step and the last step; default 1\n"
          "  --output FILE     write to FILE instead of stdout: all or nothing, no temporary file\n"
          "                    outlives the program (even when killed); FILE keeps its mode (new: 0666\n"
          "                    less the umask) and a symbolic link is written through\n"
          "  --quiet           no progress line (shown on a terminal stderr when a run takes > 1 s)\n"
          "  --help            this text\n"
          "\n"
          "Row 0 has R = I and lambda = lambda(w0) from (LagMult) for every method.\n"
          "Exit status: 0 success, 2 bad input (one line; nothing written), 3 solver failure or\n"
          "blow-up (one line naming the step and t; the output keeps every row before the failure,\n"
          "the last good step included), 1 output error, 128+n killed by signal n.\n",
          fp);
}

/* ---- progress on a terminal ---- */

/* Shown on stderr, only when it is a terminal (and rows do not go to the same terminal),
 * after the run has lasted PROGRESS_AFTER seconds, redrawn every PROGRESS_EVERY seconds on
 * one line and erased at the end: scripts and the one-line error contract never see it. */
#define PROGRESS_AFTER 1.0
#define PROGRESS_EVERY 0.25
static struct {
    int on, shown;
    long total;
    double start, next, after;
} progress;

static void progress_erase(void)
{
    if (progress.shown)
        fputs("\r\033[K", stderr);
    progress.shown = 0;
}

static void progress_tick(long k, double t)
{
    const double now = suslov_now(), dt = now - progress.start;
    if (now < progress.next)
        return;
    progress.next = now + PROGRESS_EVERY;
    if (dt < progress.after)
        return;
    const double rate = (double)k / dt, left = rate > 0.0 ? (double)(progress.total - k) / rate : 0.0;
    fprintf(stderr, "\r\033[Ksuslov: step %ld of %ld (%.1f%%), t = %.6g, %.3g steps/s, %.0f s left", k,
            progress.total, 100.0 * (double)k / (double)progress.total, t, rate, left);
    fflush(stderr);
    progress.shown = 1;
}

/* ---- errors and input ---- */

/* Prints "suslov: error: MESSAGE" on exactly one line: every control character in the
 * message (which quotes user text: arguments, paths) is escaped as \n, \t, \r or \xNN. */
static void say_error(const char *fmt, va_list ap, const char *suffix)
{
    char msg[2048];
    vsnprintf(msg, sizeof msg, fmt, ap);
    progress_erase();
    fputs("suslov: error: ", stderr);
    for (const unsigned char *p = (const unsigned char *)msg; *p; p++) {
        if (*p == '\n')
            fputs("\\n", stderr);
        else if (*p == '\t')
            fputs("\\t", stderr);
        else if (*p == '\r')
            fputs("\\r", stderr);
        else if (*p < 0x20 || *p == 0x7f)
            fprintf(stderr, "\\x%02x", *p);
        else
            fputc(*p, stderr);
    }
    fputs(suffix, stderr);
    fputc('\n', stderr);
}

/* Bad input: one line, exit 2, nothing written. */
static void die_input(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say_error(fmt, ap, " (see suslov --help)");
    va_end(ap);
    exit(EXIT_BAD_INPUT);
}

static int error_line(int status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say_error(fmt, ap, "");
    va_end(ap);
    return status;
}

/* A finite, normal (or zero) double: a subnormal is accepted by strtod with ERANGE but has
 * lost precision, and no quantity here is meaningful at that size. */
static double parse_double(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end != '\0')
        die_input("%s: '%s' is not a number", opt, s);
    if (!isfinite(v))
        die_input("%s: '%s' is not a finite number (largest %.17g)", opt, s, DBL_MAX);
    if (errno == ERANGE || fpclassify(v) == FP_SUBNORMAL)
        die_input("%s: '%s' is too small: it underflows to a subnormal number or zero "
                  "(smallest normal %.17g)", opt, s, DBL_MIN);
    return v;
}

static long parse_positive_long(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const long v = strtol(s, &end, 10);
    if (end == s || *end != '\0')
        die_input("%s: '%s' is not an integer", opt, s);
    if (errno == ERANGE)
        die_input("%s: '%s' is out of range (at most %ld)", opt, s, LONG_MAX);
    if (v <= 0)
        die_input("%s must be positive, got %ld", opt, v);
    return v;
}

/* Exactly n comma-separated numbers; an empty field ("1,,2", ",1,2", "1,2,") is an error,
 * never skipped. */
static void parse_list(const char *opt, const char *s, double *out, int n)
{
    char buf[1024];
    if (strlen(s) >= sizeof buf)
        die_input("%s: list too long", opt);
    int i = 0;
    for (const char *p = s;; i++) {
        const char *comma = strchr(p, ',');
        const size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (i == n)
            die_input("%s takes %d comma-separated numbers, got more in '%s'", opt, n, s);
        if (len == 0)
            die_input("%s: field %d of '%s' is empty", opt, i + 1, s);
        memcpy(buf, p, len);
        buf[len] = '\0';
        out[i] = parse_double(opt, buf);
        if (!comma)
            break;
        p = comma + 1;
    }
    if (i + 1 != n)
        die_input("%s takes %d comma-separated numbers, got %d in '%s'", opt, n, i + 1, s);
}

/* I_m (upper-left 2x2 of I) must be symmetric and positive definite, tested relative to
 * M = max |I_m entry| so that nothing overflows (the unscaled sum of |entries| is inf at
 * 1e308, and inf > 4u inf is false), and its determinant, which (ContDyn) divides by, must
 * be a finite normal number. The tolerance 4u (1 + 1 + 1 + 1) allows the rounding of four
 * entries of size <= M; suslov_model_init repeats the unscaled test for the other callers. */
static void check_inertia(const double I[9])
{
    for (int i = 0; i < 9; i++)
        if (!isfinite(I[i]))
            die_input("--inertia: entry %d is not finite", i + 1);
    const double M = fmax(fmax(fabs(I[0]), fabs(I[1])), fmax(fabs(I[3]), fabs(I[4])));
    if (M == 0.0)
        die_input("--inertia: I_m is zero, not positive definite");
    const double a = I[0] / M, b = I[1] / M, c = I[3] / M, d = I[4] / M;
    if (fabs(b - c) > 4.0 * DBL_EPSILON * (fabs(a) + fabs(b) + fabs(c) + fabs(d)))
        die_input("--inertia: I_m is not symmetric: I12 = %.17g but I21 = %.17g", I[1], I[3]);
    if (!(a > 0.0) || !(a * d - b * c > 0.0))
        die_input("--inertia: I_m is not positive definite (I11 = %.17g, I22 = %.17g, I12 = %.17g)",
                  I[0], I[4], I[1]);
    const double det = I[0] * I[4] - I[1] * I[3];
    if (!isfinite(det) || !(det >= DBL_MIN))
        die_input("--inertia: the determinant of I_m, %.17g * %.17g - %.17g * %.17g, is not a finite "
                  "normal number (entries too large or too small)", I[0], I[4], I[1], I[3]);
}

/* ---- rows ---- */

typedef struct {
    FILE *fp;
    const suslov_model *m;
    long every, steps;
    long next;            /* the next row to write: 0, K, 2K, ..., N (no division per step) */
    unsigned tick_mask;   /* check the clock when (calls & mask) == 0 */
    unsigned long calls;
    int write_failed;
    int blowup;           /* the energy overflowed at row blow_k (w finite but |w| > ~1e154) */
    long blow_k;
    double blow_t;
    int have_pending;     /* `pending` is the last good row and was not written */
    suslov_row pending;
} csv_ctx;

static int print_row(csv_ctx *ctx, const suslov_row *r)
{
    fprintf(ctx->fp, "%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", r->k, r->t, r->w[0], r->w[1], r->w[2],
            r->lambda, suslov_energy(ctx->m, r->w));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            fprintf(ctx->fp, ",%.17g", r->R[i][j]);
    ctx->have_pending = 0;
    if (fputc('\n', ctx->fp) == EOF) {
        ctx->write_failed = 1;
        return 1;
    }
    return 0;
}

/* The driver hands over every row (its every = 1); the rows 0, K, 2K, ... and N are written,
 * the others kept one at a time so that the last good row can be written before a failure. */
static int take_row(void *vctx, const suslov_row *r)
{
    csv_ctx *ctx = vctx;
    if (progress.on && (ctx->calls++ & ctx->tick_mask) == 0)
        progress_tick(r->k, r->t);
    if (!isfinite(suslov_energy(ctx->m, r->w))) {
        ctx->blowup = 1;
        ctx->blow_k = r->k;
        ctx->blow_t = r->t;
        return 1;
    }
    if (r->k == ctx->next) {
        /* k + K would overflow for N, K near LONG_MAX: compare with what is left. */
        ctx->next = ctx->steps - r->k > ctx->every ? r->k + ctx->every : ctx->steps;
        return print_row(ctx, r);
    }
    ctx->pending = *r;
    ctx->have_pending = 1;
    return 0;
}

static const char *failure_reason(int status)
{
    return status == SUSLOV_STEP_SINGULAR
               ? "the Jacobian of the step equation is singular ((REGLOC) fails)"
               : "Newton did not converge";
}

int main(int argc, char **argv)
{
    const char *method = NULL, *output = NULL, *recon_name = NULL;
    double eps = NAN, T = NAN, w0[2] = {SUSLOV_PAPER_OMEGA0[0], SUSLOV_PAPER_OMEGA0[1]};
    double inertia[9];
    long steps = 0, every = 1;
    int quiet = 0;
    memcpy(inertia, SUSLOV_PAPER_INERTIA, sizeof inertia);

    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i], *val = NULL;
        char name[64];
        const char *eq = strchr(opt, '=');
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0) {
            usage(stdout);
            return 0;
        }
        if (strcmp(opt, "--quiet") == 0) {
            quiet = 1;
            continue;
        }
        if (strncmp(opt, "--", 2) != 0)
            die_input("unexpected argument '%s'", opt);
        if (eq && (size_t)(eq - opt) < sizeof name) {
            memcpy(name, opt, (size_t)(eq - opt));
            name[eq - opt] = '\0';
            val = eq + 1;
        } else {
            snprintf(name, sizeof name, "%s", opt);
            if (i + 1 >= argc)
                die_input("%s needs a value", opt);
            val = argv[++i];
        }
        if (strcmp(name, "--method") == 0)
            method = val;
        else if (strcmp(name, "--eps") == 0)
            eps = parse_double(name, val);
        else if (strcmp(name, "--steps") == 0)
            steps = parse_positive_long(name, val);
        else if (strcmp(name, "--time") == 0)
            T = parse_double(name, val);
        else if (strcmp(name, "--omega0") == 0)
            parse_list(name, val, w0, 2);
        else if (strcmp(name, "--inertia") == 0)
            parse_list(name, val, inertia, 9);
        else if (strcmp(name, "--reconstruct") == 0)
            recon_name = val;
        else if (strcmp(name, "--every") == 0)
            every = parse_positive_long(name, val);
        else if (strcmp(name, "--output") == 0)
            output = val;
        else if (strcmp(name, "--quiet") == 0 || strcmp(name, "--help") == 0)
            die_input("%s takes no value", name);
        else
            die_input("unknown option '%s'", name);
    }

    if (!method)
        die_input("--method is required");
    const int exact = strcmp(method, "exact") == 0;
    const suslov_method *me = exact ? NULL : suslov_method_by_name(method);
    const suslov_stepper_type *stepper = me ? me->type : NULL;
    char names[1024];
    if (!exact && !stepper)
        die_input("unknown method '%s' (exact, %s)", method, suslov_method_names(names, sizeof names, ", "));
    suslov_recon recon = me ? me->recon : SUSLOV_RECON_CAYLEY;
    if (recon_name && suslov_recon_by_name(recon_name, &recon) != 0) {
        size_t len = 0;
        for (int r = 0; r < SUSLOV_RECON_COUNT; r++)
            len += (size_t)snprintf(names + len, sizeof names - len, "%s%s", r ? ", " : "", SUSLOV_RECON_NAMES[r]);
        die_input("unknown reconstruction '%s' (%s)", recon_name, names);
    }
    if (isnan(eps))
        die_input("--eps is required");
    if (!(eps > 0.0))
        die_input("--eps must be positive, got %.17g", eps);
    if ((steps > 0) == !isnan(T))
        die_input("give exactly one of --steps and --time");
    if (!isnan(T)) {
        const double n = round(T / eps); /* T / eps may be inf: caught below */
        if (!(n >= 1.0))
            die_input("--time %.17g with --eps %.17g gives %.17g steps; need at least 1", T, eps, n);
        /* (long)n is defined only below 2^63 = LONG_MAX + 1. */
        if (!(n < 0x1p63))
            die_input("--time %.17g with --eps %.17g gives %.17g steps, more than %ld", T, eps, n, LONG_MAX);
        steps = (long)n;
    }
    /* Every t_k = k eps <= N eps must be a finite number. */
    if (!isfinite((double)steps * eps))
        die_input("--steps %ld with --eps %.17g: the final time N H overflows", steps, eps);
    check_inertia(inertia);
    char err[1024];
    suslov_model model;
    if (suslov_model_init(&model, inertia, err, sizeof err) != 0)
        die_input("--inertia: %s", err);
    {
        const double w[3] = {w0[0], w0[1], 0.0};
        if (!isfinite(suslov_energy(&model, w)) || !isfinite(suslov_lagmult(&model, w)))
            die_input("--omega0 %.17g,%.17g: the energy or the multiplier at w0 overflows", w0[0], w0[1]);
    }
    if (atomic_file_check(output, err, sizeof err) != 0)
        die_input("--output: %s", err);

    gsl_set_error_handler_off();
    atomic_file af;
    if (atomic_file_open(&af, output, err, sizeof err) != 0)
        die_input("--output: %s", err);
    static char buf[1 << 16];
    setvbuf(af.fp, buf, _IOFBF, sizeof buf);
    fputs("k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n", af.fp);

    /* Progress only where a person watches stderr and the rows do not scroll over it. */
    progress.on = !quiet && isatty(STDERR_FILENO) && (output != NULL || !isatty(STDOUT_FILENO));
    progress.total = steps;
    progress.start = progress.next = suslov_now();
    /* SUSLOV_PROGRESS_AFTER=0 (a test hook) shows it from the first step. */
    const char *after = getenv("SUSLOV_PROGRESS_AFTER");
    progress.after = after && *after ? atof(after) : PROGRESS_AFTER;
    /* The exact run computes only the rows it writes (each may cost a stretch of the reference integration), so it
     * gets its K; the integrators step every k anyway and hand every row to take_row. */
    const suslov_run_config cfg = {&model, stepper, recon, eps, steps, exact ? every : 1};
    csv_ctx ctx = {.fp = af.fp, .m = &model, .every = every, .steps = steps, .tick_mask = exact ? 0u : 1023u};
    suslov_run_report report;
    int rc = exact ? suslov_run_exact(&cfg, w0, take_row, &ctx, &report)
                   : suslov_run(&cfg, w0, take_row, &ctx, &report);
    progress_erase();
    if (rc == SUSLOV_RUN_STOPPED && ctx.blowup) { /* the energy overflowed: a blow-up too */
        rc = SUSLOV_RUN_BLOWUP;
        report.step = ctx.blow_k;
        report.t = ctx.blow_t;
    }
    if (rc == SUSLOV_RUN_STOPPED) {
        atomic_file_abort(&af);
        return error_line(1, "writing %s failed: %s", output ? output : "stdout", strerror(errno));
    }
    /* A failure: the last good row goes out as it would at the end of a normal run. */
    if (rc != SUSLOV_RUN_OK && ctx.have_pending && print_row(&ctx, &ctx.pending) != 0) {
        atomic_file_abort(&af);
        return error_line(1, "writing %s failed: %s", output ? output : "stdout", strerror(errno));
    }
    if (atomic_file_commit(&af, err, sizeof err) != 0)
        return error_line(1, "%s", err);
    const char *name = exact ? "exact" : stepper->name;
    switch (rc) {
    case SUSLOV_RUN_OK:
        return 0;
    case SUSLOV_RUN_BLOWUP:
        return error_line(EXIT_SOLVER, "%s blow-up at step %ld (t = %.17g): w, lambda, R or the energy is "
                          "not a finite number", name, report.step, report.t);
    default: /* SUSLOV_RUN_STEP_FAILED */
        if (report.status == SUSLOV_STEP_DIVERGED)
            return error_line(EXIT_SOLVER,
                              "%s step %ld (t = %.17g) failed: the Taylor series diverges or is not "
                              "proved to converge: the step is %.3g times the radius proved for it "
                              "(|w|_2 = %.3g)",
                              name, report.step, report.t, report.stats.residual, report.stats.scale);
        return error_line(EXIT_SOLVER,
                          "%s step %ld (t = %.17g) failed: %s; residual %.3g (scale %.3g), "
                          "Jacobian determinant %.3g, after %d Newton iterations",
                          name, report.step, report.t, failure_reason(report.status),
                          report.stats.residual, report.stats.scale, report.stats.det, report.stats.iterations);
    }
}
