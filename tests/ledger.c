#include "ledger.h"

#include "atomic_file.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define LEDGER_MAX 128

typedef struct {
    char id[64], ref[96], quantity[256], verdict[16];
    double measured, expected, tol;
    int pass;
} ledger_row;

static ledger_row rows[LEDGER_MAX];
static int nrows;

static void add_row(const char *id, const char *paper_ref, const char *quantity, double measured,
                    double expected, double tol, int holds, ledger_assert truth)
{
    if (nrows == LEDGER_MAX) {
        fprintf(stderr, "ledger: more than %d lines\n", LEDGER_MAX);
        return;
    }
    ledger_row *r = &rows[nrows++];
    snprintf(r->id, sizeof r->id, "%s", id);
    snprintf(r->ref, sizeof r->ref, "%s", paper_ref);
    snprintf(r->quantity, sizeof r->quantity, "%s", quantity);
    r->measured = measured;
    r->expected = expected;
    r->tol = tol;
    if (truth == LEDGER_EXTENSION) {
        strcpy(r->verdict, "extension");
        r->pass = holds;
    } else {
        strcpy(r->verdict, holds ? "reproduced" : "not reproduced");
        r->pass = isfinite(measured) && holds == (truth == LEDGER_REPRODUCED);
    }
}

void ledger_add(const char *id, const char *paper_ref, const char *quantity, double measured,
                double expected, double tol, ledger_assert truth)
{
    add_row(id, paper_ref, quantity, measured, expected, tol, fabs(measured - expected) <= tol, truth);
}

void ledger_add_bound(const char *id, const char *paper_ref, const char *quantity, double measured,
                      double bound, int at_least, ledger_assert truth)
{
    add_row(id, paper_ref, quantity, measured, bound, 0.0, at_least ? measured >= bound : measured <= bound, truth);
}

int ledger_finish(const char *tsv_path)
{
    char err[256];
    atomic_file af;
    int failed = 0;
    if (atomic_file_open(&af, tsv_path, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    fputs("id\tpaper_ref\tquantity\tmeasured\texpected\ttolerance\tverdict\n", af.fp);
    for (int i = 0; i < nrows; i++)
        fprintf(af.fp, "%s\t%s\t%s\t%.6g\t%.6g\t%.3g\t%s\n", rows[i].id, rows[i].ref, rows[i].quantity,
                rows[i].measured, rows[i].expected, rows[i].tol, rows[i].verdict);
    if (atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    printf("\n%-4s  %-44s %-14s %-14s %-9s %-14s  %s\n", "", "claim", "measured", "expected", "tol",
           "verdict", "paper");
    for (int i = 0; i < nrows; i++) {
        const ledger_row *r = &rows[i];
        failed += !r->pass;
        printf("%-4s  %-44s %-14.6g %-14.6g %-9.2g %-14s  %s\n", r->pass ? "PASS" : "FAIL", r->id,
               r->measured, r->expected, r->tol, r->verdict, r->ref);
        printf("      %s\n", r->quantity);
    }
    printf("\nledger written to %s\nclaims: %d passed, %d failed\n", tsv_path, nrows - failed, failed);
    return failed;
}
