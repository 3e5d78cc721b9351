#define _POSIX_C_SOURCE 200809L
#include "suslov_cli.h"

#include "atomic_file.h"
#include "cli_options.h"
#include "dsp.h"
#include "echo.h"
#include "exact_run.h"
#include "inertia_check.h"
#include "midpoint_sweeps.h"
#include "paper_ref.h"
#include "stepper.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef SUSLOV_VERSION
#define SUSLOV_VERSION "unknown" /* the Makefile passes the git commit; a tarball has none */
#endif

/* The reference attitude of --method exact costs this many long-double Taylor steps at most
 * (hours of computing); beyond, the run is refused before it starts. */
#define EXACT_MAX_REFERENCE_STEPS 1e9

/* The options as given, before the checks that need several of them. */
typedef struct {
    const char *method, *recon, *output;
    double eps, T, tol, every_time;
    long steps, every;
    double w0[2], inertia[9];
    int quiet, header, header_given, list, every_given, omega0_given, inertia_given;
    long sweeps;
} given;

static const suslov_cli_spec SPEC;

/* ---- handlers: one per option ---- */

static void set_method(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((given *)g)->method = v;
}
static void set_eps(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->eps = suslov_cli_number(o->name, v);
}
static void set_steps(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->steps = suslov_cli_count(o->name, v);
}
static void set_time(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->T = suslov_cli_number(o->name, v);
}
static void set_omega0(void *g, const suslov_cli_option *o, const char *v)
{
    suslov_cli_list(o->name, v, ((given *)g)->w0, 2);
    ((given *)g)->omega0_given = 1;
}
static void set_inertia(void *g, const suslov_cli_option *o, const char *v)
{
    suslov_cli_list(o->name, v, ((given *)g)->inertia, 9);
    ((given *)g)->inertia_given = 1;
}
static void set_recon(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((given *)g)->recon = v;
}
static void set_every(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->every = suslov_cli_count(o->name, v);
    ((given *)g)->every_given = 1;
}
static void set_tol(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->tol = suslov_cli_number(o->name, v);
}
static void set_every_time(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->every_time = suslov_cli_number(o->name, v);
}
static void set_sweeps(void *g, const suslov_cli_option *o, const char *v)
{
    ((given *)g)->sweeps = suslov_cli_count(o->name, v);
}
static void set_output(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((given *)g)->output = v;
}
static void set_quiet(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, (void)v, ((given *)g)->quiet = 1;
}

static void set_header(void *vg, const suslov_cli_option *o, const char *v)
{
    given *g = vg;
    (void)v;
    if (g->header_given++)
        suslov_cli_die("--header and --no-header are both given");
    g->header = strcmp(o->name, "--header") == 0;
}

static void show_help(void *g, const suslov_cli_option *o, const char *v)
{
    (void)g, (void)o, (void)v;
    suslov_cli_help(&SPEC, stdout);
    suslov_cli_exit_stdout();
}

static void show_man(void *g, const suslov_cli_option *o, const char *v)
{
    (void)g, (void)o, (void)v;
    suslov_cli_man(&SPEC, SUSLOV_VERSION, stdout);
    suslov_cli_exit_stdout();
}

static void show_version(void *g, const suslov_cli_option *o, const char *v)
{
    (void)g, (void)o, (void)v;
    printf("suslov %s\n", SUSLOV_VERSION);
    suslov_cli_exit_stdout();
}

/* ---- lists under --method and --reconstruct ---- */

/* A method that carries its own attitude says so on its line: the registry's field says which,
 * so no list of names is kept here. */
static void more_methods(FILE *fp, int man)
{
    suslov_cli_line(fp, man, "%-12s %s", "exact",
                    "closed-form w(t), lambda(w(t)) from (LagMult), reference R(t)");
    for (int i = 0; i < sus_step_method_count_all(); i++) {
        const sus_step_method *me = sus_step_method_get(i);
        suslov_cli_line(fp, man, "%-15s %s%s", me->type->name, me->about,
                        me->type->desc.follows_recon ? "" : " (ignores --reconstruct)");
    }
}

/* The names of the methods whose attitude follows --reconstruct (follows = 1) with default
 * reconstruction `which`, or that carry their own attitude of form `which` (follows = 0). */
static void names_where(char *buf, size_t len, int follows, int which)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < sus_step_method_count_all(); i++) {
        const sus_step_method *me = sus_step_method_get(i);
        const int key = follows ? (int)me->recon : (int)me->type->desc.attitude;
        if (!me->type->desc.follows_recon == !follows && key == which && n < len)
            n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? ", " : "  ", me->type->name);
    }
}

static void more_recons(FILE *fp, int man)
{
    char names[512];
    for (int r = 0; r < SUS_RECON_COUNT; r++)
        suslov_cli_line(fp, man, "%-12s %s", SUS_RECON_NAMES[r], SUS_RECON_ABOUT[r]);
    suslov_cli_line(fp, man, "default, the method's own:");
    for (int r = 0; r < SUS_RECON_COUNT; r++)
        if (names_where(names, sizeof names, 1, r), names[0])
            suslov_cli_line(fp, man, "%s: %s", names, SUS_RECON_NAMES[r]);
    for (int f = SUS_ATTITUDE_NONE; f <= SUS_ATTITUDE_QUAT; f++)
        if (names_where(names, sizeof names, 0, f), names[0])
            suslov_cli_line(fp, man, "%s: none, their own %s attitude", names,
                            sus_step_attitude_name((sus_attitude_form)f));
}

/* ---- the table ---- */

static const suslov_cli_option OPTIONS[] = {
    {"--method", "M",
     "the method (required); `--method list`, given alone (no other option),\n"
     "prints name, family, order, default reconstruction and description (a\n"
     "table on a terminal, TSV otherwise)",
     set_method, more_methods},
    {"--eps", "H", "time step, H > 0", set_eps, NULL},
    {"--steps", "N",
     "number of steps, 1 <= N <= 2^63 - 1, read exactly as written: 1e6 and\n"
     "0x10 are whole numbers, 2.0000000000000001 is refused (as for --every,\n"
     "--sweeps)",
     set_steps, NULL},
    {"--time", "T",
     "final time instead of --steps: T/H must be a whole number N (to 4\n"
     "rounding units of T), else it is refused with the nearest valid T",
     set_time, NULL},
    {"--omega0", "W1,W2", "initial body angular velocity (w3 = 0); default 0.4,0.5", set_omega0,
     NULL},
    {"--inertia", "I11,...,I33",
     "inertia tensor by rows, as printed in the paper (only I_m and the\n"
     "third row enter); I_m must be symmetric positive definite, its\n"
     "determinant resolved and the coefficients of (ContDyn) and\n"
     "(LagMult) finite in double precision (else refused, saying which);\n"
     "default 1,0.1,0.2,0.1,1,0.2,0.2,0.1,1",
     set_inertia, NULL},
    {"--reconstruct", "R",
     "how R_{k+1} is built from R_k; an error with exact, a warning with a\n"
     "method that carries its own attitude (it is ignored there):",
     set_recon, more_recons},
    {"--sweeps", "N",
     "with --method midpoint: solve its implicit equation by N fixed-point\n"
     "sweeps instead of Newton, 1 <= N <= 8 (Figure 2's readings: 1 is explicit\n"
     "Euler, 2 the explicit midpoint rule)",
     set_sweeps, NULL},
    {"--every", "K", "write step 0, every K-th step and the last step; default 1", set_every, NULL},
    {"--tol", "TOL",
     "error tolerance of a step, 2^-52 <= TOL < 1, for a tolerance-driven\n"
     "method (taylor-adaptive), which then chooses its order and steps; with\n"
     "--time T, never with --eps, --steps or --every; a run stops (exit 3)\n"
     "after 10^6 steps short of T",
     set_tol, NULL},
    {"--every-time", "DT",
     "with --tol: write rows at t = 0, DT, 2 DT, ... and T, by the\n"
     "method's dense output, k numbering them (default: the end of every\n"
     "accepted step, k counting the steps); T/DT <= 2^63 - 1, and a time\n"
     "within 4 rounding units of T is T",
     set_every_time, NULL},
    {"--output", "FILE", "write to FILE (see FILES); - or no --output: stdout", set_output, NULL},
    {"--header", NULL,
     "write #-comment lines before the CSV header (the default): version,\n"
     "command line, method, eps, steps, body, w0 and units",
     set_header, NULL},
    {"--no-header", NULL, "bare CSV: no comment lines at all", set_header, NULL},
    {"--quiet", NULL,
     "no progress line (shown on a terminal stderr when a run takes > 1 s;\n"
     "without escape sequences under TERM=dumb or NO_COLOR; never with\n"
     "NO_PROGRESS)",
     set_quiet, NULL},
    {"--version", NULL, "print the version (the git commit built from, or unknown) and exit",
     show_version, NULL},
    {"--help", NULL, "print this text and exit", show_help, NULL},
    {"--man", NULL, "print this text as a manual page (roff) and exit", show_man, NULL},
};

/* Section text (cli_options.h): prose is filled; a line indented by two spaces is kept as it is;
 * a line followed by lines indented by four is a tag and its description. */
static const suslov_cli_section SECTIONS[] = {
    {"OUTPUT",
     "Unless --no-header, #-comment lines first (version, command line, method, eps, steps,\n"
     "inertia, w0, units), then the CSV header\n"
     "  k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n"
     "and one row for step 0, every K-th step and the last step, numbers in %.17g; non-finite\n"
     "numbers are never printed. The command line is quoted so that a shell runs it again: in\n"
     "$'...' (bash, ksh, zsh) where an argument holds a control character or a byte that is\n"
     "not UTF-8, so that the header is always one line of UTF-8. The columns:\n"
     "k\n"
     "    the row's index: the step k (t = k H); with --tol the accepted step k, and with\n"
     "    --every-time DT the output time k (t = k DT, the last row at T): it always increases\n"
     "t\n"
     "    the time\n"
     "omega1,omega2,omega3\n"
     "    the body angular velocity w (omega3 = 0)\n"
     "lambda\n"
     "    the multiplier; row 0 has lambda(w0) from (LagMult) for every method\n"
     "energy\n"
     "    E = <I_m w, w>/2\n"
     "R11,...,R33\n"
     "    the attitude R by rows; row 0 has R = I\n"
     "After a solver failure or blow-up (exit 3), --output FILE is not written (see FILES); on\n"
     "stdout, a device or a pipe the rows before it are written, the last good step included,\n"
     "and (unless --no-header) a last line # incomplete: ... naming the failure."},
    {"FILES",
     "--output FILE replaces a regular FILE atomically: all or nothing, and no temporary file\n"
     "outlives the program, even when killed. A run that fails (exit 3) leaves an existing FILE\n"
     "as it was and creates none. The new FILE keeps the mode of the old one (a new one gets\n"
     "0666 less the umask) but is owned by the user who ran suslov, and other hard links keep\n"
     "the old contents. A read-only FILE is refused (as cp does without -f), and so is one that\n"
     "the rename could not replace: in a sticky directory owned by neither, or a mount point\n"
     "(a bind-mounted file; redirect stdout to write it in place). A symbolic link, or a chain\n"
     "of them, is written through to the file at its end, which is created if missing (as a\n"
     "shell redirection does); the links stay links. A device, a pipe, - and a name of an open\n"
     "descriptor (/dev/stdout, /dev/fd/N) are written in place, never renamed, at the\n"
     "descriptor's offset. Every condition that can be checked before the run (directory\n"
     "writable, names within the system's limits with the temporary's suffix, permissions,\n"
     "mount points) is checked before it."},
    {"EXIT STATUS",
     "0\n"
     "    success\n"
     "1\n"
     "    output error (writing failed: disk full, inodes exhausted, I/O error)\n"
     "2\n"
     "    bad input (one line; nothing written), --output FILE that permissions or a read-only\n"
     "    filesystem keep from being created included\n"
     "3\n"
     "    solver failure or blow-up: one line naming the step and t, for a failed solve its\n"
     "    residual or error estimate, and whether --output FILE was left as it was\n"
     "128+n\n"
     "    killed by signal n"},
    {"ENVIRONMENT",
     "NO_COLOR (non-empty), TERM=dumb\n"
     "    the progress line uses no escape sequence\n"
     "NO_PROGRESS (non-empty)\n"
     "    no progress line, as with --quiet\n"
     "SUSLOV_NO_O_TMPFILE (non-empty, for tests)\n"
     "    use a named temporary file instead of an unnamed one; every catchable fatal signal\n"
     "    then removes it\n"
     "SUSLOV_PROGRESS_AFTER=S (for tests)\n"
     "    show progress after S seconds instead of 1"},
    {"EXAMPLES",
     "  suslov --method variational --eps 1 --time 200 --every 10\n"
     "  suslov --method exact --eps 1e-3 --time 60 --every 100 --output data/exact.csv\n"
     "  suslov --method taylor-adaptive --tol 1e-10 --time 50 --every-time 0.5\n"
     "  suslov --method list"},
};

static const suslov_cli_spec SPEC = {
    "suslov",
    "integrate the Suslov problem with the methods of Jimenez & Scheurle",
    "suslov --method M (--eps H (--steps N | --time T) | --tol TOL --time T) [OPTION]...",
    "Integrates the Suslov problem (Jimenez & Scheurle, Section 5) and writes CSV.",
    OPTIONS,
    (int)(sizeof OPTIONS / sizeof OPTIONS[0]),
    SECTIONS,
    (int)(sizeof SECTIONS / sizeof SECTIONS[0]),
};

/* ---- --method list ---- */

/* The reconstruction column says "own" for a method that carries its own attitude. */
static void method_list(void)
{
    const int tty = isatty(STDOUT_FILENO);
    const char *fmt = tty ? "%-10s %-12s %-5s %-11s %s\n" : "%s\t%s\t%s\t%s\t%s\n";
    printf(fmt, "name", "family", "order", "reconstruct", "about");
    printf(fmt, "exact", "closed form", "-", "-", "closed-form w(t), lambda(w(t)), reference R(t)");
    for (int i = 0; i < sus_step_method_count_all(); i++) {
        const sus_step_method *me = sus_step_method_get(i);
        char order[16];
        snprintf(order, sizeof order, me->type->tol ? "tol" : "%d", me->type->desc.order);
        char about[512];
        printf(fmt, me->type->name, me->family, order,
               me->type->desc.follows_recon ? SUS_RECON_NAMES[me->recon] : "own",
               sus_paper_numbered(me->about, about, sizeof about));
    }
    suslov_cli_exit_stdout();
}

/* ---- checks that need several options ---- */

/* The nearest final time to n steps, written as briefly as it is still accepted. */
static void time_choice(char *buf, size_t len, double n, double eps)
{
    const double T = n * eps;
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(buf, len, "--time %.*g", digits, T);
        const double back = strtod(buf + 7, NULL);
        if (fabs(round(back / eps) * eps - back) <= 2.0 * DBL_EPSILON * back)
            return;
    }
}

/* N = T/H when that is a whole number to within the rounding of T, H and their quotient:
 * |N H - T| <= 4u T (u = DBL_EPSILON / 2), so that the last row is at T; else refused. */
static long steps_for_time(double T, double eps)
{
    const double n = round(T / eps); /* T / eps may be inf: caught below */
    char lo[64], hi[64];
    if (!(n >= 1.0)) {
        time_choice(hi, sizeof hi, 1.0, eps);
        suslov_cli_die(
            "--time %.17g with --eps %.17g gives %.17g steps; need at least 1: the shortest is %s",
            T, eps, n, hi);
    }
    if (!(n < 0x1p63)) /* (long)n is defined only below 2^63 = LONG_MAX + 1 */
        suslov_cli_die("--time %.17g with --eps %.17g gives %.17g steps, more than %ld", T, eps, n,
                       LONG_MAX);
    if (fabs(n * eps - T) > 2.0 * DBL_EPSILON * T) {
        const double f = floor(T / eps);
        time_choice(lo, sizeof lo, f, eps);
        time_choice(hi, sizeof hi, f + 1.0, eps);
        suslov_cli_die(
            "--time %.17g is not a whole number of steps of --eps %.17g; nearest: %s%s%s", T, eps,
            f >= 1.0 ? lo : "", f >= 1.0 ? " or " : "", hi);
    }
    return (long)n;
}

/* Returns 1 when --reconstruct is given to a method that ignores it (a warning, given once every
 * check has passed, so that bad input still gets exactly one line). */
static int resolve_method(suslov_args *a, const given *g)
{
    char names[1024];
    const int exact = strcmp(g->method, "exact") == 0;
    a->method = exact ? NULL : sus_step_method_by_name(g->method);
    if (!exact && !a->method)
        suslov_cli_die("unknown method %s (exact, %s; or list)", suslov_cli_quote(g->method),
                       sus_step_method_names(names, sizeof names, ", "));
    a->recon = a->method ? a->method->recon : SUS_RECON_CAYLEY;
    if (!g->recon)
        return 0;
    if (sus_recon_by_name(g->recon, &a->recon) != 0) {
        size_t len = 0;
        for (int r = 0; r < SUS_RECON_COUNT; r++)
            len += (size_t)snprintf(names + len, sizeof names - len, "%s%s", r ? ", " : "",
                                    SUS_RECON_NAMES[r]);
        suslov_cli_die("unknown reconstruction %s (%s)", suslov_cli_quote(g->recon), names);
    }
    if (exact)
        suslov_cli_die(
            "--reconstruct does not apply to --method exact (its R is the reference attitude)");
    return !a->method->type->desc.follows_recon;
}

/* --sweeps replaces the midpoint rule's Newton solve, so it needs that method. */
static void check_sweeps(suslov_args *a, const given *g)
{
    a->stepper = a->method ? a->method->type : NULL;
    if (!g->sweeps)
        return;
    if (!a->method || a->method->type != sus_step_midpoint)
        suslov_cli_die(
            "--sweeps applies only to --method midpoint (it solves the midpoint rule's equation)");
    if (g->sweeps > SUS_LAB_MAX_SWEEPS)
        suslov_cli_die("--sweeps must be at most %d, got %ld", SUS_LAB_MAX_SWEEPS, g->sweeps);
    a->sweeps = (int)g->sweeps;
    a->stepper = sus_lab_midpoint_sweeps_type(a->sweeps);
}

/* A tolerance-driven method: --tol and --time, no fixed step. The smallest TOL is one rounding
 * unit of 1: a step's estimate cannot be resolved below the rounding of the state it corrects. */
static void check_tol_run(suslov_args *a, const given *g)
{
    if (isnan(g->tol))
        suslov_cli_die("--method %s chooses its steps from --tol, which is required", g->method);
    if (!(g->tol >= DBL_EPSILON && g->tol < 1.0))
        suslov_cli_die("--tol must be in [2^-52, 1), got %.17g", g->tol);
    if (!isnan(g->eps) || g->steps > 0)
        suslov_cli_die("--tol chooses the steps: give --time, not --eps or --steps");
    if (g->every_given)
        suslov_cli_die(
            "--every counts fixed steps; with --tol rows come at each step or by --every-time");
    if (isnan(g->T) || !(g->T > 0.0))
        suslov_cli_die("--tol needs a final time --time T > 0");
    if (!isnan(g->every_time) && !(g->every_time > 0.0))
        suslov_cli_die("--every-time must be positive, got %.17g", g->every_time);
    /* The rows' count, as --steps's: at most 2^63 - 1 (the row index is a long). */
    if (!isnan(g->every_time) && !(g->T / g->every_time < 0x1p63))
        suslov_cli_die("--time %.17g with --every-time %.17g asks for %.3g rows, more than %ld",
                       g->T, g->every_time, g->T / g->every_time, LONG_MAX);
    a->tol = g->tol;
    a->t_end = g->T;
    a->every_time = isnan(g->every_time) ? 0.0 : g->every_time;
}

static void check_fixed_steps(suslov_args *a, const given *g)
{
    if (!isnan(g->tol) || !isnan(g->every_time))
        suslov_cli_die("%s applies to a tolerance-driven method (--method list: order tol)",
                       isnan(g->tol) ? "--every-time" : "--tol");
    if (isnan(g->eps))
        suslov_cli_die("--eps is required");
    if (!(g->eps > 0.0))
        suslov_cli_die("--eps must be positive, got %.17g", g->eps);
    if ((g->steps > 0) == !isnan(g->T))
        suslov_cli_die("give exactly one of --steps and --time");
    a->eps = g->eps;
    a->steps = isnan(g->T) ? g->steps : steps_for_time(g->T, g->eps);
    /* Every t_k = k eps <= N eps must be a finite number. */
    if (!isfinite((double)a->steps * a->eps))
        suslov_cli_die("--steps %ld with --eps %.17g: the final time N H overflows", a->steps,
                       a->eps);
    a->t_end = (double)a->steps * a->eps;
}

/* E and lambda at w0 must be finite numbers (row 0 prints them). They depend on w0 and the body
 * alike, so the message names the options that were given: the default of the other is not the
 * user's doing. */
static void check_start(const suslov_args *a, const given *g)
{
    const double w[3] = {g->w0[0], g->w0[1], 0.0};
    const char *what = !isfinite(sus_energy(&a->model, w))    ? "energy"
                       : !isfinite(sus_lagmult(&a->model, w)) ? "multiplier lambda"
                                                              : NULL;
    if (!what)
        return;
    const char *opts =
        g->inertia_given ? (g->omega0_given ? "--omega0 and --inertia" : "--inertia") : "--omega0";
    suslov_cli_die("%s: the %s at w0 = (%.17g, %.17g) overflows with %s inertia", opts, what,
                   g->w0[0], g->w0[1], g->inertia_given ? "this" : "the paper's (default)");
}

static void check_run(suslov_args *a, const given *g)
{
    char err[1024];
    if (!g->method)
        suslov_cli_die("--method is required");
    if (strcmp(g->method, "list") == 0)
        method_list();
    const sus_step_method *me = sus_step_method_by_name(g->method);
    if (me && me->type->tol)
        check_tol_run(a, g);
    else
        check_fixed_steps(a, g);
    char bad[512];
    if (suslov_inertia_check(g->inertia, bad, sizeof bad) != 0)
        suslov_cli_die("%s", bad);
    if (sus_model_init(&a->model, g->inertia, err, sizeof err) != 0) {
        char said[sizeof err]; /* the model cites the paper by labels; the reader gets numbers */
        suslov_cli_die("--inertia: %s", sus_paper_numbered(err, said, sizeof said));
    }
    check_start(a, g);
    const int ignored = resolve_method(a, g);
    check_sweeps(a, g);
    const double cost = a->method ? 0.0 : sus_exact_reference_steps(&a->model, g->w0, a->t_end);
    if (!(cost <= EXACT_MAX_REFERENCE_STEPS))
        suslov_cli_die("--method exact: this body and w0 approach the steady rotation so slowly "
                       "that the reference "
                       "attitude needs %.3g Taylor steps (at most %.0e)",
                       cost, EXACT_MAX_REFERENCE_STEPS);
    if (sus_sys_atomic_file_check(g->output, err, sizeof err) != 0)
        suslov_cli_die("--output: %s", err);
    if (ignored)
        suslov_cli_warn("--reconstruct %s is ignored: %s carries its own attitude", g->recon,
                        a->method->type->name);
}

void suslov_args_parse(suslov_args *a, int argc, char **argv)
{
    given g = {.eps = NAN,
               .T = NAN,
               .tol = NAN,
               .every_time = NAN,
               .every = 1,
               .header = 1,
               .w0 = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]}};
    memcpy(g.inertia, SUS_PAPER_INERTIA, sizeof g.inertia);
    /* before any handler: another option's check or action (--help) would come first */
    const char *method;
    if (suslov_cli_peek(&SPEC, argc, argv, "--method", &method) > 1 && method &&
        strcmp(method, "list") == 0)
        suslov_cli_die("--method list takes no other options");
    suslov_cli_parse(&SPEC, argc, argv, &g);
    memset(a, 0, sizeof *a);
    check_run(a, &g);
    a->output = g.output;
    a->every = g.every;
    memcpy(a->w0, g.w0, sizeof a->w0);
    memcpy(a->inertia, g.inertia, sizeof a->inertia);
    a->quiet = g.quiet;
    a->header = g.header;
}

/* ---- the header ---- */

/* 1 when s can stand raw inside single quotes on a line of UTF-8: no control character and no
 * byte that is not part of a well-formed UTF-8 character. */
static int quotable(const char *s, size_t n)
{
    for (size_t i = 0, len; i < n; i += len) {
        const unsigned char c = (unsigned char)s[i];
        if (!(len = sus_sys_utf8_len(s + i, n - i)) || c < 0x20 || c == 0x7f)
            return 0;
    }
    return 1;
}

/* An argument as a shell reads it back, on one line of valid UTF-8 (so that the header can be
 * parsed as text, and the line pasted into a shell runs the same command): bare when it holds
 * only [A-Za-z0-9_.,:/=+-]; else in single quotes; else, when it holds a control character or a
 * byte that is not UTF-8, in $'...' quoting with those bytes as \xNN (bash, ksh, zsh, busybox
 * sh, and POSIX sh since 2024; not dash 0.5.12). */
static void put_arg(FILE *fp, const char *s)
{
    const size_t n = strlen(s);
    static const char BARE[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.,:/=+-";
    if (n && strspn(s, BARE) == n) {
        fputs(s, fp);
        return;
    }
    const int single = quotable(s, n);
    fputs(single ? "'" : "$'", fp);
    for (size_t i = 0, len; i < n; i += len) {
        const unsigned char c = (unsigned char)s[i];
        len = sus_sys_utf8_len(s + i, n - i);
        if (c == '\'' && single)
            fputs("'\\''", fp);
        else if ((c == '\'' || c == '\\') && !single)
            fprintf(fp, "\\%c", c);
        else if (!len || c < 0x20 || c == 0x7f)
            fprintf(fp, "\\x%02x", c);
        else
            fwrite(s + i, 1, len, fp);
        len = len ? len : 1;
    }
    fputc('\'', fp);
}

void suslov_args_header(const suslov_args *a, int argc, char **argv, FILE *fp)
{
    fprintf(fp, "# suslov %s\n# command:", SUSLOV_VERSION);
    for (int i = 0; i < argc; i++) {
        fputc(' ', fp);
        put_arg(fp, i ? argv[i] : "suslov");
    }
    if (a->method)
        fprintf(fp, "\n# method: %s (%s, order %d), ", a->method->type->name, a->method->family,
                a->tol > 0.0 ? a->method->type->tol->order(a->tol) : a->method->type->desc.order);
    if (a->method && a->method->type->desc.follows_recon)
        fprintf(fp, "reconstruction %s\n", SUS_RECON_NAMES[a->recon]);
    else if (a->method) /* what --method list calls "own" */
        fprintf(fp, "attitude: own (%s; --reconstruct does not apply)\n",
                sus_step_attitude_name(a->method->type->desc.attitude));
    else
        fputs("\n# method: exact (closed-form w and lambda, reference attitude R)\n", fp);
    if (a->sweeps)
        fprintf(fp, "# sweeps: the implicit equation solved by %d fixed-point sweeps, not Newton\n",
                a->sweeps);
    if (a->tol > 0.0)
        fprintf(fp, "# tol: %.17g, every time: %.17g (%s), final time: %.17g\n", a->tol,
                a->every_time,
                a->every_time > 0.0 ? "k is the row's index: t = k DT, the last row at T"
                                    : "0: a row at each accepted step, k counting them",
                a->t_end);
    else
        fprintf(fp, "# eps: %.17g, steps: %ld, every: %ld, final time: %.17g\n", a->eps, a->steps,
                a->every, a->t_end);
    fputs("# inertia (rows of I):", fp);
    for (int i = 0; i < 9; i++)
        fprintf(fp, "%s%.17g", i ? "," : " ", a->inertia[i]);
    fprintf(fp, "\n# omega0: %.17g,%.17g,0\n", a->w0[0], a->w0[1]);
    fputs("# units: those of the paper's data: t in time units, omega in radians per time unit, "
          "lambda\n"
          "# in units of I omega^2, energy = <I_m w, w>/2 in units of I omega^2\n",
          fp);
}
