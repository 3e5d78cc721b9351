/* The ledger for people and programs: claims.tsv, and the printed table, which ends with the
 * findings (the tally by verdict, and every line that contradicts the paper by its published
 * number). Each printed line says apart whether its check passed and what the finding is: a
 * check passes when the measurement is what the line asserts, and a line may assert that the
 * paper's claim does not hold. */
#include "ledger.h"

#include "atomic_file.h"
#include "ledger_rows.h"
#include "notation.h"

#include <stdio.h>
#include <string.h>

/* claims.tsv, its header first. */
static int write_tsv(const char *path, const ledger_state *s)
{
    char err[256], test[96], meas[64];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    fputs("id\tpaper_ref\tquantity\tmeasured\texpected\ttolerance\tverdict\ttest\tsource\n", af.fp);
    for (int i = 0; i < s->nrows; i++) {
        const ledger_row *r = &s->rows[i];
        ledger_test_text(r, test, sizeof test);
        ledger_measured_text(r, meas, sizeof meas);
        fprintf(af.fp, "%s\t%s\t%s\t%s\t%.6g\t%.3g\t%s\t%s\t%s\n", r->id, r->ref_plain,
                r->quantity_plain, meas, r->expected, r->tol, r->verdict, test, r->source);
    }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    return 0;
}

/* One line in full: the id with its check and its finding, the numbers and where the paper
 * says it, then what is measured and where the line is recorded. */
static void print_line(FILE *fp, const ledger_row *r)
{
    char test[96], meas[64];
    ledger_test_text(r, test, sizeof test);
    ledger_measured_text(r, meas, sizeof meas);
    fprintf(fp, "%-44s check: %-4s  finding: %s\n", r->id, r->pass ? "pass" : "FAIL", r->verdict);
    fprintf(fp, "    measured x = %s, test %s%s; in the paper: %s\n", meas,
            r->kind == ROW_WITHIN ? "" : "x ", test, r->ref_plain);
    fprintf(fp, "    %s  [%s]\n", r->quantity_plain, r->source);
}

/* The findings: the tally by verdict, then each line that does not reproduce the paper or finds
 * an erratum in it, by its published number (the reference without the labels). */
static void print_findings(FILE *fp, const ledger_state *s)
{
    int count[LEDGER_NVERDICTS] = {0};
    char ref[256], err[256];
    for (int i = 0; i < s->nrows; i++)
        count[ledger_verdict_index(s->rows[i].verdict)]++;
    fprintf(fp, "findings of the %d lines:", s->nrows);
    for (int v = 0; v < LEDGER_NVERDICTS; v++)
        fprintf(fp, "%s %d %s", v ? "," : "", count[v], LEDGER_VERDICTS[v]);
    fputc('\n', fp);
    for (int v = 1; v <= 2; v++) /* not reproduced, erratum */
        for (int i = 0; i < s->nrows; i++) {
            const ledger_row *r = &s->rows[i];
            if (strcmp(r->verdict, LEDGER_VERDICTS[v]) != 0)
                continue;
            if (notation_plain(r->ref, PLAIN_REF, ref, sizeof ref, err, sizeof err) != 0)
                snprintf(ref, sizeof ref, "%s", r->ref_plain);
            fprintf(fp, "  %-14s  %s: %s\n", r->verdict, ref, r->id);
        }
}

int ledger_finish(const char *tsv_path)
{
    const ledger_state *s = ledger_state_get();
    char dir[4096];
    int failed = 0;
    snprintf(dir, sizeof dir, "%s", tsv_path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    else
        strcpy(dir, ".");
    if (write_tsv(tsv_path, s) != 0 || ledger_write_tex(dir) != 0) {
        fprintf(stderr, "ledger: writing the ledger's files beside %s failed\n", tsv_path);
        return -1;
    }
    printf("The claims ledger: each line's id, whether its check passed, and its finding\n"
           "(reproduced, not reproduced, erratum: the paper's claim; extension: our own; by\n"
           "construction: set by the code); then the measured value x, the test, the paper's\n"
           "reference, what is measured and the test code that records it.\n\n");
    for (int i = 0; i < s->nrows; i++)
        print_line(stdout, &s->rows[i]);
    for (int i = 0; i < s->nrows; i++)
        failed += !s->rows[i].pass;
    if (failed) {
        printf("\nchecks that failed:\n");
        for (int i = 0; i < s->nrows; i++)
            if (!s->rows[i].pass)
                print_line(stdout, &s->rows[i]);
    }
    putchar('\n');
    print_findings(stdout, s);
    printf("claims: %d passed, %d failed\n", s->nrows - failed, failed);
    return failed;
}
