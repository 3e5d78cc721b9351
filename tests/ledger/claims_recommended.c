/* The recorded bench run's settings (claims_recommended.h), each run by suslov at its level.
 *
 * data/bench-recorded/what_to_use.tsv holds, at each accuracy level of the bench (the attitude
 * R(50), the attitude against the reduced peers, and w(50)), the fastest setting of ours whose
 * error reached the level, with the suslov arguments that run it. Each setting is run here by
 * the suslov program beside the claims program, with those arguments: its parser is the one that
 * reads them, and a row it refuses, or a run that fails, stops the ledger (its message on stderr
 * says why). Its last row, printed to 17 digits, reads back exactly, and its error is the one the
 * bench records (sus_lab_bench_errors): dist(R_ref, R) = |R_ref R^T - I|_F of (MetMat) against
 * the long-double reference, |w - w_N| against the closed form.
 *
 * The bounds are the file's, not theory's. The bench names at a level L the fastest setting
 * whose error is at most L: the line checks that this build still reaches L. Where the file
 * names another setting at a level L' below L, this one did not reach L' in the recorded run
 * (every setting that reaches L' reaches L, and this one was the fastest of those), so the line
 * checks L' < error <= L. That lower side is what tells the attitude from w: w is far more
 * accurate than R for these settings, and a line that measured w, or R against itself, would lie
 * far below L'. The smallest level has no L' and keeps the upper side alone. A setting the file
 * names at several levels (the same arguments on two rows of one target) is checked at the
 * smallest. A fixed-step series (a stepper with apply_order) that conserves E bounds |E - E0|
 * over the run too: each step evaluates E twice, divides, takes a root and scales, at most 8
 * roundings of E per step that need not cancel, 8 N u E0. A re-recorded bench moves the lines
 * with it; their ids name the target and the level, not the setting. */
#define _POSIX_C_SOURCE 200809L
#include "claims_recommended.h"

#include "ledger.h"
#include "notation.h"
#include "registry.h"
#include "so3.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define T_END 50.0 /* the bench's time (bench.h); the reference R_T is there */
#define MAX_ROWS 64
#define MAX_ARGS 32
#define E_ROUNDINGS 8.0
/* suslov's CSV header (suslov --help, OUTPUT): the columns read below by their place */
#define CSV_HEADER "k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n"

typedef struct {
    char quantity[24]; /* attitude, attitude-reduced or omega */
    double level;
    char args[256];
} rec_row;

/* What suslov printed: the method and setting its header names, and its rows. */
typedef struct {
    const sus_step_method *me;
    sus_recon recon;
    double eps, tol; /* a fixed-step run's step, a tolerance-driven run's TOL */
    int failed;      /* suslov's exit 3: a solver failure or blow-up, said on its stderr */
    long rows, k;    /* the rows read; the last row's k */
    double t, w[2], R[3][3];
    double e0, energy; /* E at row 0; max |E - E0| over the rows */
} rec_run;

static char suslov_path[4096] = "build/suslov";

void recommended_program(const char *argv0)
{
    const char *slash = strrchr(argv0, '/');
    snprintf(suslov_path, sizeof suslov_path, "%.*ssuslov", slash ? (int)(slash - argv0 + 1) : 0,
             argv0);
}

/* The fields of a line split at tabs in place (the newline dropped); returns how many. */
static int split(char *line, char **field, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = '\0';
    for (char *p = line; n < max; p++) {
        field[n++] = p;
        p = strchr(p, '\t');
        if (!p)
            break;
        *p = '\0';
    }
    return n;
}

static int column(char **field, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(field[i], name) == 0)
            return i;
    ledger_die("finding a column of " RECOMMENDED_TSV);
    return -1;
}

/* The rows of the file; the ledger stops on a file it cannot read. */
static int read_rows(rec_row *rows)
{
    char line[1024], *f[16];
    FILE *fp = fopen(RECOMMENDED_TSV, "r");
    if (!fp || !fgets(line, sizeof line, fp))
        ledger_die("reading " RECOMMENDED_TSV);
    int nf = split(line, f, 16), n = 0;
    const int cq = column(f, nf, "quantity"), cl = column(f, nf, "level"),
              ca = column(f, nf, "suslov_args");
    while (fgets(line, sizeof line, fp)) {
        if (!strchr(line, '\n') || n == MAX_ROWS || split(line, f, 16) <= ca)
            ledger_die("reading a row of " RECOMMENDED_TSV);
        rec_row *r = &rows[n++];
        snprintf(r->quantity, sizeof r->quantity, "%s", f[cq]);
        r->level = strtod(f[cl], NULL);
        snprintf(r->args, sizeof r->args, "%s", f[ca]);
        if (!(r->level > 0.0 && r->level < 1.0))
            ledger_die("reading a level of " RECOMMENDED_TSV);
    }
    fclose(fp);
    if (n == 0)
        ledger_die("finding a setting in " RECOMMENDED_TSV);
    return n;
}

/* 1 when the row's target is R(50), 0 for w(50); the ledger stops on another quantity. */
static int targets_R(const rec_row *r)
{
    if (strcmp(r->quantity, "omega") == 0)
        return 0;
    if (strcmp(r->quantity, "attitude") != 0 && strcmp(r->quantity, "attitude-reduced") != 0)
        ledger_die("knowing a quantity of " RECOMMENDED_TSV);
    return 1;
}

/* ---- running suslov ---- */

/* suslov with the row's arguments (the words of the field, as a shell would split them: the
 * bench writes no quoting), its stdout on a pipe; the ledger stops where it cannot start it. */
static FILE *start_suslov(const char *args, pid_t *pid)
{
    char words[256], *argv[MAX_ARGS], *w;
    int n = 0, fd[2];
    snprintf(words, sizeof words, "%s", args);
    argv[n++] = suslov_path;
    for (w = strtok(words, " "); w && n < MAX_ARGS - 1; w = strtok(NULL, " "))
        argv[n++] = w;
    argv[n] = NULL;
    if (w || pipe(fd) != 0)
        ledger_die("starting suslov on a setting of " RECOMMENDED_TSV);
    fflush(NULL); /* nothing buffered is written twice */
    *pid = fork();
    if (*pid == 0) {
        dup2(fd[1], STDOUT_FILENO);
        close(fd[0]);
        close(fd[1]);
        execv(suslov_path, argv);
        fprintf(stderr, "claims: %s: %s\n", suslov_path, strerror(errno));
        _exit(127);
    }
    close(fd[1]);
    FILE *fp = *pid > 0 ? fdopen(fd[0], "r") : NULL;
    if (!fp)
        ledger_die("starting suslov on a setting of " RECOMMENDED_TSV);
    return fp;
}

/* A #-line of the header: the method (and the reconstruction, where the method follows one),
 * the step, the tolerance. */
static void header_line(const char *line, rec_run *r)
{
    char name[40];
    const char *rc = strstr(line, "), reconstruction ");
    if (sscanf(line, "# method: %39s", name) == 1) {
        r->me = sus_step_method_by_name(name);
        if (!r->me)
            ledger_die("finding suslov's method in the registry");
        r->recon = r->me->recon;
        if (rc && sscanf(rc, "), reconstruction %39s", name) == 1 &&
            sus_recon_by_name(name, &r->recon) != 0)
            ledger_die("knowing suslov's reconstruction");
    } else if (sscanf(line, "# eps: %lf", &r->eps) != 1) {
        sscanf(line, "# tol: %lf", &r->tol);
    }
}

/* One CSV row: row 0 must be the paper's start (w0, and E(w0) on the paper's body); the last row
 * read is where the run ends. */
static void data_row(char *line, const sus_model *m, const double w0[2], rec_run *r)
{
    double v[16];
    char *p = line, *end;
    for (int i = 0; i < 16; i++, p = end + (*end == ',')) {
        v[i] = strtod(p, &end);
        if (end == p)
            ledger_die("reading a row of suslov's output");
    }
    if (r->rows++ == 0) {
        if (v[2] != w0[0] || v[3] != w0[1] || v[6] != sus_energy(m, w0))
            ledger_die("finding the paper's start in suslov's first row");
        r->e0 = v[6];
    }
    r->k = (long)v[0];
    r->t = v[1];
    r->w[0] = v[2];
    r->w[1] = v[3];
    for (int i = 0; i < 9; i++)
        r->R[i / 3][i % 3] = v[7 + i];
    r->energy = fmax(r->energy, fabs(v[6] - r->e0));
}

/* The run of the row's arguments, or r.failed where suslov reports a failed run (exit 3); the
 * ledger stops where suslov refuses them or its output is not a run to t = 50 from the paper's
 * start. */
static rec_run run_suslov(const char *args, const sus_model *m, const double w0[2])
{
    rec_run r = {.me = NULL};
    char line[1024];
    pid_t pid;
    int status;
    FILE *fp = start_suslov(args, &pid);
    while (fgets(line, sizeof line, fp)) {
        if (!strchr(line, '\n'))
            ledger_die("reading a line of suslov's output");
        if (line[0] == '#')
            header_line(line, &r);
        else if (strcmp(line, CSV_HEADER) != 0)
            data_row(line, m, w0, &r);
    }
    fclose(fp);
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) ||
        (WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 3))
        ledger_die("running suslov on a setting of " RECOMMENDED_TSV " (its message is above)");
    r.failed = WEXITSTATUS(status) == 3;
    if (!r.me || (!r.failed && (r.rows < 2 || !(fabs(r.t - T_END) <= 1e-12 * T_END))))
        ledger_die("reading a run to t = 50 from suslov on a setting of " RECOMMENDED_TSV);
    return r;
}

/* ---- the lines ---- */

/* Is row j the same setting of the same target as row i, at a smaller level or at the same one
 * earlier in the file: row i is then checked by row j's line. */
static int covered_by(const rec_row *rows, int i, int j)
{
    return j != i && targets_R(&rows[j]) == targets_R(&rows[i]) &&
           strcmp(rows[j].args, rows[i].args) == 0 &&
           (rows[j].level < rows[i].level || (rows[j].level == rows[i].level && j < i));
}

/* The rows row i's line checks, as "attitude $10^{-4}$, attitude-reduced $10^{-4}$". */
static void levels_of(const rec_row *rows, int n, int i, char *out, size_t len)
{
    out[0] = '\0';
    for (int j = 0, k = 0; j < n; j++)
        if (j == i || covered_by(rows, j, i)) {
            const size_t at = strlen(out);
            snprintf(out + at, len - at, "%s%.23s $%.15s$", k++ ? ", " : "", rows[j].quantity,
                     notation_g(rows[j].level, 1).s);
        }
}

/* The largest level below row i's (the smallest of its setting) in a target that names the
 * setting, where the file names another setting: its error was above it. 0 where none is. */
static double level_below(const rec_row *rows, int n, int i)
{
    double below = 0.0;
    for (int j = 0; j < n; j++)
        if (j == i || covered_by(rows, j, i))
            for (int k = 0; k < n; k++)
                if (strcmp(rows[k].quantity, rows[j].quantity) == 0 &&
                    rows[k].level < rows[i].level)
                    below = fmax(below, rows[k].level);
    return below;
}

/* The setting in words: "taylor10 (quaternion) with 12 steps ($\varepsilon = 4.167$)". */
static void describe(const rec_run *r, char *out, size_t len)
{
    char label[64];
    sus_step_method_label(r->me->type, r->recon, label, sizeof label);
    if (r->me->type->tol)
        snprintf(out, len, "%s at $\\mathrm{TOL} = %s$", label, notation_g(r->tol, 4).s);
    else
        snprintf(out, len, "%s with %ld steps ($\\varepsilon = %.4g$)", label, r->k, r->eps);
}

static void energy_line(const rec_row *row, const char *word, const rec_run *r)
{
    char id[96], what[400];
    const double bound = E_ROUNDINGS * (double)r->k * SUS_U * r->e0;
    if (!r->failed && r->rows != r->k + 1)
        ledger_die("reading every step of a recommended run from suslov");
    snprintf(id, sizeof id, "recommended-energy-%s-%.0e", word, row->level);
    snprintf(what, sizeof what,
             "$\\max |E - E_0|$ over the same run (%s, %ld steps of $\\varepsilon = %.4g$): $E$ "
             "restored after each step, bound $8 N u E_0 = %s$",
             r->me->type->name, r->k, r->eps, notation_g(bound, 2).s);
    ledger_add_bound(id, "(extension)", what, r->failed ? INFINITY : r->energy, bound, 0,
                     LEDGER_EXTENSION);
}

/* The smallest attitude level has no level below it, and w is far more accurate than R in these
 * runs: a line that measured w there would pass its upper side all the same. This one tells the
 * two apart: dist(R(50), R_N) and |w(50) - w_N| come from different columns of the run (R's nine
 * entries against the reference, w's two against the closed form), each within a few roundings,
 * so they agree to 8 u relative only when the same columns are read. */
static void not_w_line(const rec_row *row, const rec_run *r, double err, const double w_T[2])
{
    char id[96], what[400];
    const double err_w = hypot(r->w[0] - w_T[0], r->w[1] - w_T[1]);
    snprintf(id, sizeof id, "recommended-%s-%.0e-not-w", row->quantity, row->level);
    snprintf(what, sizeof what,
             "$|d_R - d_\\omega| / \\max(d_R, d_\\omega)$ in the same run, $d_R$ its distance "
             "\\eqref{MetMat} at $t = 50$ and $d_\\omega = |\\omega(50) - \\omega_N|$ ($%s$): the "
             "line above measures the attitude, not $\\omega$; at least $8u$",
             notation_g(err_w, 2).s);
    ledger_add_bound(id, "(recorded bench)", what,
                     r->failed ? 0.0 : fabs(err - err_w) / fmax(err, err_w), 8.0 * SUS_U, 1,
                     LEDGER_EXTENSION);
}

/* Row i's lines: its error at t = 50 between the level below and its own, and E where the
 * setting restores it. */
static void setting_lines(const rec_row *rows, int n, int i, const sus_model *m, const double w0[2],
                          const double w_T[2], const double R_T[3][3])
{
    const rec_row *row = &rows[i];
    const rec_run r = run_suslov(row->args, m, w0);
    const int on_R = targets_R(row);
    const double level = row->level, below = level_below(rows, n, i);
    const double err = r.failed ? INFINITY
                       : on_R   ? sus_so3_dist(R_T, r.R)
                                : hypot(r.w[0] - w_T[0], r.w[1] - w_T[1]);
    char id[96], what[800], how[256], levels[160], side[96] = "";
    describe(&r, how, sizeof how);
    levels_of(rows, n, i, levels, sizeof levels);
    if (below > 0.0)
        snprintf(side, sizeof side, "above $%.15s$ (the next level, where it chose another) and ",
                 notation_g(below, 1).s);
    snprintf(id, sizeof id, "recommended-%s-%.0e", on_R ? row->quantity : "w", level);
    snprintf(what, sizeof what,
             "%s at $t = 50$ in suslov's run of %s, the recorded bench's fastest setting of ours "
             "for %s: %sat most $%s$",
             on_R ? "the distance \\eqref{MetMat} $\\mathrm{dist}(R(50), R_N)$"
                  : "$|\\omega(50) - \\omega_N|$",
             how, levels, side, notation_g(level, 1).s);
    if (below > 0.0) /* (below, level]: its middle, and half its width */
        ledger_add(id, "(recorded bench)", what, err, 0.5 * (level + below), 0.5 * (level - below),
                   LEDGER_EXTENSION);
    else
        ledger_add_bound(id, "(recorded bench)", what, err, level, 0, LEDGER_EXTENSION);
    if (on_R && below == 0.0)
        not_w_line(row, &r, err, w_T);
    if (!r.me->type->tol && r.me->type->step->apply_order && r.me->type->desc.conserves_energy)
        energy_line(row, on_R ? row->quantity : "w", &r);
}

void recommended_claims(const sus_model *m, const double w0[2], const double w_T[2],
                        const double R_T[3][3])
{
    static rec_row rows[MAX_ROWS];
    const int n = read_rows(rows);
    for (int i = 0; i < n; i++) {
        int covered = 0;
        for (int j = 0; j < n && !covered; j++)
            covered = covered_by(rows, i, j);
        if (!covered)
            setting_lines(rows, n, i, m, w0, w_T, R_T);
    }
}
