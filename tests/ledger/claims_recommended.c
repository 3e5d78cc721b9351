/* The recorded bench run's settings (claims_recommended.h), each at its level.
 *
 * data/bench-recorded/what_to_use.tsv holds, at each accuracy level of the bench (the attitude
 * R(50), the attitude against the reduced peers, and w(50)), the fastest setting of ours whose
 * error reached the level, with the suslov arguments that run it. Each setting is run here
 * again on the paper's body to t = 50 and its error measured as the bench measures it: R against
 * the long-double reference, w against the closed form. The bound is the level itself, a claim of
 * that file, not one of theory: the line says that this build still reaches each level where the
 * recorded run did. The settings are large steps, where a defect shows that the asymptotic order
 * lines cannot see (a quaternion series one degree short, E no longer restored). A setting the
 * file recommends at several levels (the same arguments on two rows of one target) is checked
 * at the smallest. A fixed-step series (a stepper with apply_order) that conserves E bounds
 * |E - E0| over the run too: each step evaluates E twice, divides, takes a root and scales, at
 * most 8 roundings of E per step that need not cancel, 8 N u E0. A row the ledger cannot run (an
 * argument it does not know, a method not registered, a run not to t = 50) stops the ledger: the
 * file and the ledger disagree on what a setting is. A re-recorded bench moves the lines with
 * it; their ids name the target and the level, not the setting. */
#include "claims_recommended.h"

#include "driver.h"
#include "ledger.h"
#include "notation.h"
#include "registry.h"
#include "so3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define T_END 50.0 /* the bench's time (bench.h); the reference R_T is there */
#define MAX_ROWS 64
#define E_ROUNDINGS 8.0

typedef struct {
    char quantity[24]; /* attitude, attitude-reduced or omega */
    double level;
    char args[256];
} rec_row;

/* A row's suslov arguments, read back. */
typedef struct {
    const sus_step_method *me;
    sus_recon recon;
    double eps, tol, time, every_time;
    long steps;
} rec_setting;

typedef struct {
    const sus_model *m;
    double e0, energy;
    long k;
    double w[3], R[3][3];
} rec_track;

static int track(void *vctx, const sus_row *row)
{
    rec_track *c = vctx;
    c->k = row->k;
    memcpy(c->w, row->w, sizeof c->w);
    memcpy(c->R, row->R, sizeof c->R);
    c->energy = fmax(c->energy, fabs(sus_energy(c->m, row->w) - c->e0));
    return 0;
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

/* Where a numeric option's value goes, or NULL for another option. */
static double *number_of(const char *o, rec_setting *s)
{
    static const char *const names[] = {"--eps", "--tol", "--time", "--every-time"};
    double *const to[] = {&s->eps, &s->tol, &s->time, &s->every_time};
    for (int i = 0; i < 4; i++)
        if (strcmp(o, names[i]) == 0)
            return to[i];
    return NULL;
}

/* One option and its value into s; 0, or -1 for an option or a name it does not know. */
static int option(const char *o, const char *v, rec_setting *s)
{
    double *x = number_of(o, s);
    if (x)
        *x = strtod(v, NULL);
    else if (strcmp(o, "--reconstruct") == 0)
        return sus_recon_by_name(v, &s->recon);
    else if (strcmp(o, "--steps") == 0)
        s->steps = strtol(v, NULL, 10);
    else
        return -1;
    return 0;
}

/* The setting of suslov arguments; the ledger stops where it cannot run one to t = 50. Without
 * --reconstruct, the method's own (the bench leaves it out where the method ignores it). */
static rec_setting setting_of(const char *args)
{
    char buf[256];
    rec_setting s = {.me = NULL};
    snprintf(buf, sizeof buf, "%s", args);
    const char *o = strtok(buf, " ");
    if (!o || strcmp(o, "--method") != 0 || !(s.me = sus_step_method_by_name(strtok(NULL, " "))))
        ledger_die("finding a recommended method in the registry");
    s.recon = s.me->recon;
    while ((o = strtok(NULL, " "))) {
        const char *v = strtok(NULL, " ");
        if (!v || option(o, v, &s) != 0)
            ledger_die("knowing an argument in " RECOMMENDED_TSV);
    }
    const int tol = s.me->type->tol != NULL;
    const double T = tol ? s.time : s.eps * (double)s.steps;
    if ((tol ? !(s.tol > 0.0) : !(s.eps > 0.0 && s.steps > 0)) ||
        !(fabs(T - T_END) <= 1e-12 * T_END))
        ledger_die("running a setting of " RECOMMENDED_TSV " to t = 50");
    return s;
}

static int run(const rec_setting *s, const sus_model *m, const double w0[2], rec_track *c)
{
    *c = (rec_track){.m = m, .e0 = sus_energy(m, w0)};
    sus_run_report rep;
    if (s->me->type->tol) {
        const sus_tol_config cfg = {m, s->me->type, s->tol, s->time, s->every_time, 0};
        return sus_run_tol(&cfg, w0, track, c, &rep);
    }
    const sus_run_config cfg = {m, s->me->type, s->recon, s->eps, s->steps, 1};
    return sus_run(&cfg, w0, track, c, &rep);
}

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

/* The setting in words: "taylor10 (quaternion) with 12 steps ($\varepsilon = 4.167$)". */
static void describe(const rec_setting *s, long k, char *out, size_t len)
{
    char label[64];
    sus_step_method_label(s->me->type, s->recon, label, sizeof label);
    if (s->me->type->tol)
        snprintf(out, len, "%s at $\\mathrm{TOL} = %s$ (%ld accepted steps)", label,
                 notation_g(s->tol, 4).s, k);
    else
        snprintf(out, len, "%s with %ld steps ($\\varepsilon = %.4g$)", label, s->steps, s->eps);
}

static void energy_line(const rec_row *r, const char *word, const rec_setting *s,
                        const rec_track *c, int ok)
{
    char id[96], what[400];
    const double bound = E_ROUNDINGS * (double)s->steps * SUS_U * c->e0;
    snprintf(id, sizeof id, "recommended-energy-%s-%.0e", word, r->level);
    snprintf(what, sizeof what,
             "$\\max |E - E_0|$ over the same run (%s, %ld steps of $\\varepsilon = %.4g$): $E$ "
             "restored after each step, bound $8 N u E_0 = %s$",
             s->me->type->name, s->steps, s->eps, notation_g(bound, 2).s);
    ledger_add_bound(id, "(extension)", what, ok ? c->energy : INFINITY, bound, 0,
                     LEDGER_EXTENSION);
}

/* Row i's lines: its error at t = 50 against its level, and E where the setting restores it. */
static void setting_lines(const rec_row *rows, int n, int i, const sus_model *m, const double w0[2],
                          const double w_T[2], const double R_T[3][3])
{
    const rec_row *r = &rows[i];
    const rec_setting s = setting_of(r->args);
    const int on_R = targets_R(r);
    const char *word = on_R ? r->quantity : "w";
    rec_track c;
    const int ok = run(&s, m, w0, &c) == SUS_RUN_OK;
    const double err = !ok    ? INFINITY
                       : on_R ? sus_so3_dist(R_T, c.R)
                              : hypot(c.w[0] - w_T[0], c.w[1] - w_T[1]);
    char id[96], what[800], how[256], levels[160];
    describe(&s, c.k, how, sizeof how);
    levels_of(rows, n, i, levels, sizeof levels);
    snprintf(id, sizeof id, "recommended-%s-%.0e", word, r->level);
    snprintf(what, sizeof what,
             "%s at $t = 50$, %s: the recorded bench's fastest setting of ours for %s; at most "
             "$%s$",
             on_R ? "the distance \\eqref{MetMat} $\\mathrm{dist}(R(50), R_N)$"
                  : "$|\\omega(50) - \\omega_N|$",
             how, levels, notation_g(r->level, 1).s);
    ledger_add_bound(id, "(recorded bench)", what, err, r->level, 0, LEDGER_EXTENSION);
    if (!s.me->type->tol && s.me->type->step->apply_order && s.me->type->desc.conserves_energy)
        energy_line(r, word, &s, &c, ok);
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
