/* suslov's option table: one handler per option, the lists under --method and --reconstruct,
 * the sections of --help and the manual page, and --method list. The parser, --help and --man come
 * from it (cli_options.h); the checks that need several options are in suslov_cli_checks.c, the
 * output's header in suslov_cli_header.c. */
#define _POSIX_C_SOURCE 200809L
#include "suslov_cli.h"

#include "cli_options.h"
#include "paper_ref.h"
#include "stepper.h"
#include "suslov_cli_checks.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const suslov_cli_spec SPEC;

/* ---- handlers: one per option ---- */

static void set_method(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((suslov_args_given *)g)->method = v;
}
static void set_eps(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->eps = suslov_cli_number(o->name, v);
}
static void set_steps(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->steps = suslov_cli_count(o->name, v);
}
static void set_time(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->T = suslov_cli_number(o->name, v);
}
static void set_omega0(void *g, const suslov_cli_option *o, const char *v)
{
    suslov_cli_list(o->name, v, ((suslov_args_given *)g)->w0, 2);
    ((suslov_args_given *)g)->omega0_given = 1;
}
static void set_inertia(void *g, const suslov_cli_option *o, const char *v)
{
    suslov_cli_list(o->name, v, ((suslov_args_given *)g)->inertia, 9);
    ((suslov_args_given *)g)->inertia_given = 1;
}
static void set_recon(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((suslov_args_given *)g)->recon = v;
}
static void set_every(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->every = suslov_cli_count(o->name, v);
    ((suslov_args_given *)g)->every_given = 1;
}
static void set_tol(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->tol = suslov_cli_number(o->name, v);
}
static void set_every_time(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->every_time = suslov_cli_number(o->name, v);
}
static void set_sweeps(void *g, const suslov_cli_option *o, const char *v)
{
    ((suslov_args_given *)g)->sweeps = suslov_cli_count(o->name, v);
}
static void set_output(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, ((suslov_args_given *)g)->output = v;
}
static void set_quiet(void *g, const suslov_cli_option *o, const char *v)
{
    (void)o, (void)v, ((suslov_args_given *)g)->quiet = 1;
}

static void set_header(void *vg, const suslov_cli_option *o, const char *v)
{
    suslov_args_given *g = vg;
    (void)v;
    if (g->header_given++)
        suslov_cli_die("--header and --no-header are both given");
    g->header = strcmp(o->name, "--header") == 0;
}

/* --help, --man and --version act once the whole command line is read and checked
 * (suslov_args_parse), so that bad input is exit 2 wherever it stands, with them or without. */
static void show_help(void)
{
    suslov_cli_help(&SPEC, stdout);
    suslov_cli_exit_stdout();
}

static void show_man(void)
{
    suslov_cli_man(&SPEC, suslov_version(), stdout);
    suslov_cli_exit_stdout();
}

static void show_version(void)
{
    printf("suslov %s\n", suslov_version());
    suslov_cli_exit_stdout();
}

/* One text per run: two of them are as contradictory as --header with --no-header. */
static void want_show(suslov_args_given *g, const suslov_cli_option *o, void (*show)(void))
{
    if (g->show)
        suslov_cli_die("%s and %s are both given (each prints its text and exits)", g->show_name,
                       o->name);
    g->show = show;
    g->show_name = o->name;
}
static void set_help(void *g, const suslov_cli_option *o, const char *v)
{
    (void)v, want_show(g, o, show_help);
}
static void set_man(void *g, const suslov_cli_option *o, const char *v)
{
    (void)v, want_show(g, o, show_man);
}
static void set_version(void *g, const suslov_cli_option *o, const char *v)
{
    (void)v, want_show(g, o, show_version);
}

/* ---- lists under --method and --reconstruct ---- */

/* A method that carries its own attitude says so on its line: the registry's field says which,
 * so no list of names is kept here. */
static void more_methods(FILE *fp, int man)
{
    suslov_cli_line(fp, man, "%-15s %s", "exact",
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
     "rounding units of T), else it is refused with the nearest valid T; the\n"
     "last row's t is then N H (see OUTPUT, t), which may differ from T in\n"
     "its last digits: --eps 0.1 --time 0.3 ends at t = 0.30000000000000004.\n"
     "exact and the --tol methods refuse a final time (T, or N H) by which the\n"
     "steady rotation turns the body by more than their attitude keeps\n"
     "accurate, |w_inf| T over 2^60 radians for exact and 2^50 for --tol,\n"
     "naming the longest T; exact also refuses a run whose reference attitude\n"
     "it estimates at over ten minutes (long slow approaches, many rows)",
     set_time, NULL},
    {"--omega0", "W1,W2",
     "initial body angular velocity (w3 = 0); default 0.4,0.5. A w0 within a\n"
     "rounding of the repelling steady rotation (I31 w1 + I32 w2 below the\n"
     "rounding of its terms, not 0) is warned of for a method that steps w:\n"
     "it stays there, or leaves when its roundings say (exact, exact-attitude\n"
     "follow the motion)",
     set_omega0, NULL},
    {"--inertia", "I11,...,I33",
     "inertia tensor by rows, as printed in the paper (only I_m and the\n"
     "third row enter); I_m must be symmetric positive definite, its\n"
     "determinant resolved and the coefficients of (ContDyn) and\n"
     "(LagMult) finite in double precision, and lambda along the motion\n"
     "from w0 too (else refused, saying which);\n"
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
     "error tolerance, 2^-52 <= TOL < 1, for a tolerance-driven method (order\n"
     "tol in --method list), which then chooses its steps; with --time T, never\n"
     "with --eps, --steps or --every; a run stops (exit 3) after 10^6 steps\n"
     "short of T. TOL bounds absolute errors. taylor-adaptive: its estimate,\n"
     "in each step, of the error of w and of the attitude quaternion (max\n"
     "norm); over a run the steps' errors add up, an error in w shifts the\n"
     "rest of the motion in time, which the attitude carries: most where w\n"
     "starts near the repelling steady rotation, where the error can exceed\n"
     "N TOL after N steps; and on a nearly singular I_m, whose steps the\n"
     "series' radius holds short whatever TOL, where round-off, not TOL, sets\n"
     "the error and a tight TOL may stop the run (exit 3): exact-attitude is\n"
     "the method there. exact-attitude: |R R_ref^T - I|_F over the whole\n"
     "run, as the sum of its steps' estimates (checked on the test bodies, not\n"
     "proved), to a few roundings a step: its w is the closed form. Both turn\n"
     "R over the steady tail by an angle formed in two doubles, so the error\n"
     "against the inputs as given does not grow with T there. Not relative\n"
     "ones: where |w| is far below TOL, TOL promises nothing of the relative\n"
     "error of w, nor of lambda, computed from w by (LagMult) and quadratic\n"
     "in w. A w0 not 0 with |w0| below 2^-500 (3e-151) or an energy below the\n"
     "normal doubles is refused: the series multiply w by w, and lose their\n"
     "bits there",
     set_tol, NULL},
    {"--every-time", "DT",
     "with --tol: write rows at t = 0, DT, 2 DT, ... and T, by the\n"
     "method's dense output, k numbering them (default: the end of every\n"
     "accepted step, k counting the steps); T/DT < 2^62, and a time\n"
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
     "NO_PROGRESS), nor the note that a --method exact run will take over 5 s",
     set_quiet, NULL},
    {"--version", NULL, "print the version (the git commit built from, or unknown) and exit",
     set_version, NULL},
    {"--help", NULL,
     "print this text and exit; as with --version and --man, every option given\n"
     "is checked first as a run checks it (bad input: exit 2), none is required",
     set_help, NULL},
    {"--man", NULL, "print this text as a manual page (roff) and exit", set_man, NULL},
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
     "    the time k H, rounded once: the time that k steps of H reach. With --time T the last\n"
     "    row's t is N H, within 4 rounding units of T but not always T. With --tol, the end\n"
     "    of the step, or k DT, the last row at T\n"
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
     "the old contents. A read-only FILE is refused (as cp does without -f), and so is one in a\n"
     "read-only directory: read-only is what you may not write, or what its owner may not (mode\n"
     "u-w, which stops root too). So is a FILE the rename could not replace (in a sticky\n"
     "directory owned by neither, or a mount point: a bind-mounted file; redirect stdout to\n"
     "write it in place), and one in a directory where no file can be created (/proc, /sys). A\n"
     "symbolic link, or a chain of them, is written through to the file at its end, which is\n"
     "created if missing (as a shell redirection does); the links stay links. A device, a pipe,\n"
     "the name - and a name of an open descriptor (/dev/stdout, /dev/fd/N) are written in\n"
     "place, never renamed, at the descriptor's offset. Every condition that can be checked\n"
     "before the run (directory writable, a file can be created in it, names within the\n"
     "system's limits with the temporary's suffix, permissions, mount points) is checked before\n"
     "it."},
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
     "    no progress line nor note, as with --quiet\n"
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

void suslov_args_parse(suslov_args *a, int argc, char **argv)
{
    suslov_args_given g = {.eps = NAN,
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
    if (!g.method && !g.show)
        suslov_cli_die("--method is required");
    if (g.method && strcmp(g.method, "list") == 0) /* alone: the peek above saw to that */
        method_list();
    memset(a, 0, sizeof *a);
    suslov_args_check(a, &g);
    if (g.show)
        g.show();
    a->output = g.output;
    a->every = g.every;
    memcpy(a->w0, g.w0, sizeof a->w0);
    memcpy(a->inertia, g.inertia, sizeof a->inertia);
    a->quiet = g.quiet;
    a->header = g.header;
}
