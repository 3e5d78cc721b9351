/* suslov: integrate the Suslov problem with one of the paper's methods and print CSV rows
 * (k, t, w, lambda, E, R). See usage() and README.md. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include "driver.h"
#include "exact_run.h"
#include "model.h"
#include "stepper.h"

#include <errno.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_BAD_INPUT = 2, EXIT_SOLVER = 3 };

static void usage(FILE *fp)
{
    fputs(
        "usage: suslov --method exact|euler|midpoint|rk4|variational --eps H (--steps N | --time T)\n"
        "              [--omega0 W1,W2] [--inertia I11,I12,I13,I21,I22,I23,I31,I32,I33]\n"
        "              [--reconstruct cayley|cayley-mid] [--every K] [--output FILE] [--help]\n"
        "\n"
        "Integrates the Suslov problem (Jimenez & Scheurle, Section 5) and writes CSV with the header\n"
        "k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n"
        "\n"
        "  --method M        exact        closed-form w(t), lambda(w(t)) from (LagMult), reference R(t)\n"
        "                                 (GSL rk8pd along the exact w, tolerance 1e-13)\n"
        "                    euler, rk4   general DSPs (Discretization), lambda_{k+1} = lambda(w^{k+1})\n"
        "                    midpoint     (Discretization) with the midpoint l1, l2, lambda(w^{k+1})\n"
        "                    variational  (taudyn) for w^{k+1}, (taualg) for lambda_{k+1}\n"
        "  --eps H           time step, H > 0\n"
        "  --steps N         number of steps, N > 0\n"
        "  --time T          final time instead of --steps: N = round(T/H)\n"
        "  --omega0 W1,W2    initial body angular velocity (w3 = 0); default 0.4,0.5\n"
        "  --inertia ...     inertia tensor by rows, as printed in the paper (only I_m and the third\n"
        "                    row enter); I_m must be symmetric positive definite;\n"
        "                    default 1,0.1,0.2,0.1,1,0.2,0.2,0.1,1\n"
        "  --reconstruct R   cayley      R_{k+1} = R_k cay(H w_k^), Algorithm (algo) (default)\n"
        "                    cayley-mid  R_{k+1} = R_k cay(H (w_k^ + w_{k+1}^)/2) (extension)\n"
        "  --every K         write step 0, every K-th step and the last step; default 1\n"
        "  --output FILE     write to FILE (all or nothing) instead of stdout\n"
        "  --help            this text\n"
        "\n"
        "Row 0 has R = I and lambda = lambda(w0) from (LagMult) for every method.\n"
        "Exit status: 0 success, 2 bad input (nothing written), 3 solver failure (the message names\n"
        "the step, t and the residual; with --output the file keeps every row before the failure),\n"
        "1 output error.\n",
        fp);
}

static void die_input(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("suslov: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputs(" (see suslov --help)\n", stderr);
    va_end(ap);
    exit(EXIT_BAD_INPUT);
}

static double parse_double(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v))
        die_input("%s: '%s' is not a finite number", opt, s);
    return v;
}

static long parse_positive_long(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE)
        die_input("%s: '%s' is not an integer", opt, s);
    if (v <= 0)
        die_input("%s must be positive, got %ld", opt, v);
    return v;
}

static void parse_list(const char *opt, const char *s, double *out, int n)
{
    char buf[1024];
    if (strlen(s) >= sizeof buf)
        die_input("%s: list too long", opt);
    strcpy(buf, s);
    int i = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (i == n)
            die_input("%s takes %d comma-separated numbers, got more", opt, n);
        out[i++] = parse_double(opt, tok);
    }
    if (i != n)
        die_input("%s takes %d comma-separated numbers, got %d", opt, n, i);
}

typedef struct {
    FILE *fp;
    const suslov_model *m;
} csv_ctx;

static int write_row(void *vctx, const suslov_row *r)
{
    csv_ctx *ctx = vctx;
    fprintf(ctx->fp, "%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", r->k, r->t, r->w[0], r->w[1], r->w[2],
            r->lambda, suslov_energy(ctx->m, r->w));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            fprintf(ctx->fp, ",%.17g", r->R[i][j]);
    return fputc('\n', ctx->fp) == EOF;
}

static const char *failure_reason(int status)
{
    return status == SUSLOV_STEP_SINGULAR
               ? "the Jacobian of the step equation is singular ((REGLOC) fails)"
               : "Newton did not converge";
}

int main(int argc, char **argv)
{
    const char *method = NULL, *output = NULL, *recon_name = "cayley";
    double eps = NAN, T = NAN, w0[2] = {SUSLOV_PAPER_OMEGA0[0], SUSLOV_PAPER_OMEGA0[1]};
    double inertia[9];
    long steps = 0, every = 1;
    memcpy(inertia, SUSLOV_PAPER_INERTIA, sizeof inertia);

    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i], *val = NULL;
        char name[64];
        const char *eq = strchr(opt, '=');
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0) {
            usage(stdout);
            return 0;
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
        else
            die_input("unknown option '%s'", name);
    }

    if (!method)
        die_input("--method is required");
    const int exact = strcmp(method, "exact") == 0;
    const suslov_stepper_type *stepper = exact ? NULL : suslov_stepper_by_name(method);
    if (!exact && !stepper)
        die_input("unknown method '%s' (exact, euler, midpoint, rk4, variational)", method);
    suslov_recon recon;
    if (suslov_recon_by_name(recon_name, &recon) != 0)
        die_input("unknown reconstruction '%s' (cayley, cayley-mid)", recon_name);
    if (isnan(eps))
        die_input("--eps is required");
    if (!(eps > 0.0))
        die_input("--eps must be positive, got %.17g", eps);
    if ((steps > 0) == !isnan(T))
        die_input("give exactly one of --steps and --time");
    if (!isnan(T)) {
        const double n = round(T / eps);
        if (!(n >= 1.0))
            die_input("--time %.17g with --eps %.17g gives %.17g steps; need at least 1", T, eps, n);
        if (n > 9.0e15)
            die_input("--time %.17g with --eps %.17g gives too many steps", T, eps);
        steps = (long)n;
    }
    char err[512];
    suslov_model model;
    if (suslov_model_init(&model, inertia, err, sizeof err) != 0)
        die_input("--inertia: %s", err);

    gsl_set_error_handler_off();
    atomic_file af;
    if (atomic_file_open(&af, output, err, sizeof err) != 0) {
        fprintf(stderr, "suslov: error: %s\n", err);
        return 1;
    }
    static char buf[1 << 16];
    setvbuf(af.fp, buf, _IOFBF, sizeof buf);
    fputs("k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n", af.fp);

    const suslov_run_config cfg = {&model, stepper, recon, eps, steps, every};
    csv_ctx ctx = {af.fp, &model};
    suslov_run_report report;
    const int rc = exact ? suslov_run_exact(&cfg, w0, write_row, &ctx, &report)
                         : suslov_run(&cfg, w0, write_row, &ctx, &report);
    if (rc < 0) {
        atomic_file_abort(&af);
        fprintf(stderr, "suslov: error: writing %s failed\n", output ? output : "stdout");
        return 1;
    }
    if (atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "suslov: error: %s\n", err);
        return 1;
    }
    if (rc > 0) {
        if (exact)
            fprintf(stderr, "suslov: error: reference attitude (rk8pd) failed at row k = %ld, t = %.17g: %s\n",
                    report.step, report.t, gsl_strerror(report.status));
        else
            fprintf(stderr,
                    "suslov: error: %s step %ld (t = %.17g) failed: %s; residual %.3g (scale %.3g), "
                    "Jacobian determinant %.3g, after %d Newton iterations\n",
                    stepper->name, report.step, report.t, failure_reason(report.status),
                    report.stats.residual, report.stats.scale, report.stats.det, report.stats.iterations);
        return EXIT_SOLVER;
    }
    return 0;
}
