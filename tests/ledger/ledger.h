/* The claims ledger: every claim of the paper we measure, with the number, what the paper
 * (or, for an extension, our own analysis) expects, the tolerance, and the verdict. Written
 * to build/claims.tsv with the columns
 *     id  paper_ref  quantity  measured  expected  tolerance  verdict  test  source
 * where `test` is the check in words ("<= b", ">= b", "|x - e| <= tol" with the numbers) and
 * `source` the file and line of the call that recorded the line (the functions below are macros
 * that pass __FILE__ and __LINE__); printed as a table that says, for each line, whether its
 * check passed and what its finding is. The quantity and the paper reference of a line are
 * written once, in the notation of notation.h (LaTeX that KaTeX takes too, and the paper's
 * numbering by label); claims.tsv and the table show their plain text. */
#ifndef SUSLOV_LEDGER_H
#define SUSLOV_LEDGER_H

typedef enum {
    LEDGER_REPRODUCED,     /* we assert the paper's claim holds: |measured - expected| <= tol */
    LEDGER_NOT_REPRODUCED, /* we assert the measurement contradicts it: |measured - expected| > tol
                            */
    LEDGER_EXTENSION,      /* our own claim beyond the paper: |measured - expected| <= tol */
    LEDGER_ERRATUM, /* as NOT_REPRODUCED, for a typo or an internal inconsistency of the paper
                     * (it contradicts the paper's own formulas, not its results) */
    LEDGER_BY_CONSTRUCTION /* a line that holds because the code sets it so (every stepper writes
                            * w3 = 0.0): it checks the implementation, cannot refute the paper and
                            * is not counted as evidence; passes when it holds */
} ledger_assert;

/* Records one line. The verdict column follows from the numbers alone ("reproduced" or "not
 * reproduced" for a claim of the paper, "erratum" in place of "not reproduced" for an erratum,
 * "by construction" for a line the code makes hold, "extension" otherwise); the check passes
 * when it is
 * what `truth` asserts, which the caller states and justifies next to the call. */
#define ledger_add(...) ledger_add_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_add_at(const char *file, int line, const char *id, const char *paper_ref,
                   const char *quantity, double measured, double expected, double tol,
                   ledger_assert truth);

/* The same for a one-sided claim: it holds when measured >= bound (at_least) or measured <=
 * bound (otherwise); the TSV shows the bound as "expected" and tolerance 0, and the quantity
 * text must say which side is claimed. */
#define ledger_add_bound(...) ledger_add_bound_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_add_bound_at(const char *file, int line, const char *id, const char *paper_ref,
                         const char *quantity, double measured, double bound, int at_least,
                         ledger_assert truth);

/* The same, for a limit in the dimensionless step h that may be +infinity, meaning "none found
 * up to the bound, the largest h tested" (a stability limit that is never reached): such a line
 * prints "none found for h <= BOUND" as its measured value, in claims.tsv and in the companion,
 * never inf. Every other line fails on an infinite value. */
#define ledger_add_bound_unbounded(...)                                                            \
    ledger_add_bound_unbounded_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_add_bound_unbounded_at(const char *file, int line, const char *id,
                                   const char *paper_ref, const char *quantity, double measured,
                                   double bound, int at_least, ledger_assert truth);

/* The same for the smallest h at which something happens, asserted >= bound, searched for up to
 * `searched` (> bound): +infinity when none was found, printed "none found for h <= searched". */
#define ledger_add_none_found(...) ledger_add_none_found_at(__FILE__, __LINE__, __VA_ARGS__)
void ledger_add_none_found_at(const char *file, int line, const char *id, const char *paper_ref,
                              const char *quantity, double measured, double bound, double searched,
                              ledger_assert truth);

/* The smallest value noted in a slot (0 .. 3), over every section however the ledger runs them
 * (ledger_jobs.h): +infinity when none was noted. */
void ledger_keep_min(int slot, double value);
double ledger_min(int slot);

/* Stops the claims program (exit 2) when a measurement a claim needs could not be made, with
 * "claims: WHAT failed" on stderr: no line is recorded for a run that did not happen. */
void ledger_die(const char *what);

/* A further number for the companion text, as the macro \NAME (letters only). */
void ledger_number(const char *name, double value);

/* Writes the TSV (through a temporary file) and prints the table, then the findings (the
 * tally by verdict and each line that is not reproduced or an erratum) and
 * "claims: N passed, N failed". Next to the TSV it writes, for the companion (make paper):
 *   numbers.tex  for each line \Id, \IdExpected, \IdTol, \IdVerdict and \IdTest (the
 *                comparison, e.g. $|m-1|\le 0.1$ or $m\ge b$), the id in CamelCase with digits
 *                spelled out, numbers for math mode; every ledger_number; and the counts
 *                \LedgerLines, \LedgerPassed, \LedgerFailed, \LedgerReproduced,
 *                \LedgerNotReproduced, \LedgerErratum, \LedgerExtension, \LedgerByConstruction,
 *                \LedgerPaperLines (the lines that test the paper: not the extensions, and not
 *                the lines that hold by construction);
 *   ledger.tex   the whole ledger as a longtable, quantities and references as written (the
 *                companion resolves \eqref and \PaperRefOr to the paper's published numbers);
 *   summary.tex  the lines that test the paper, one row per claim (a claim tested on several
 *                methods of the registry is one row; no extension, and no line that holds by
 *                construction);
 * and, for the web edition, claims_tex.tsv: each line's quantity and test as LaTeX.
 * Returns the number of failed checks, or -1 on a write error. */
int ledger_finish(const char *tsv_path);

#endif
