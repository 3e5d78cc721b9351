/* The claims ledger: every claim of the paper we measure, with the number, what the paper
 * (or, for an extension, our own analysis) expects, the tolerance, and the verdict. Written
 * to build/claims.tsv with the columns
 *     id  paper_ref  quantity  measured  expected  tolerance  verdict
 * and printed as a table with a PASS/FAIL check per line. */
#ifndef SUSLOV_LEDGER_H
#define SUSLOV_LEDGER_H

typedef enum {
    LEDGER_REPRODUCED,     /* we assert the paper's claim holds: |measured - expected| <= tol */
    LEDGER_NOT_REPRODUCED, /* we assert the measurement contradicts it: |measured - expected| > tol */
    LEDGER_EXTENSION       /* our own claim beyond the paper: |measured - expected| <= tol */
} ledger_assert;

/* Records one line. The verdict column follows from the numbers alone ("reproduced" or "not
 * reproduced" for a claim of the paper, "extension" otherwise); the check passes when it is
 * what `truth` asserts, which the caller states and justifies next to the call. */
void ledger_add(const char *id, const char *paper_ref, const char *quantity, double measured,
                double expected, double tol, ledger_assert truth);

/* The same for a one-sided claim: it holds when measured >= bound (at_least) or measured <=
 * bound (otherwise); the TSV shows the bound as "expected" and tolerance 0, and the quantity
 * text must say which side is claimed. */
void ledger_add_bound(const char *id, const char *paper_ref, const char *quantity, double measured,
                      double bound, int at_least, ledger_assert truth);

/* A further number for the companion text, as the macro \NAME (letters only). */
void ledger_number(const char *name, double value);

/* Writes the TSV (through a temporary file) and prints the table followed by
 * "claims: N passed, N failed". Next to the TSV it writes numbers.tex (for each line \Id, \IdExpected,
 * \IdTol and \IdVerdict, the id in CamelCase with digits spelled out, numbers for math mode; and
 * every ledger_number) and ledger.tex (the ledger as a LaTeX table). Returns the number of
 * failed checks, or -1 on a write error. */
int ledger_finish(const char *tsv_path);

#endif
