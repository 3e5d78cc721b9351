/* The ledger's lines as recorded (ledger.c), for the files that write them out: claims.tsv and
 * the printed table (ledger_table.c), the companion's LaTeX and the web's claims_tex.tsv
 * (ledger_tex.c), and the parallel sections that pass them back (ledger_jobs.c). */
#ifndef SUSLOV_LEDGER_ROWS_H
#define SUSLOV_LEDGER_ROWS_H

#include <stddef.h>

#define LEDGER_MAX 1024
#define LEDGER_MINS 4 /* slots of ledger_keep_min */

/* How a line is tested: |measured - expected| <= tol, or a one-sided bound. */
typedef enum { ROW_WITHIN, ROW_AT_LEAST, ROW_AT_MOST } row_kind;

typedef struct {
    char id[64], verdict[16], source[80];
    char ref[160], quantity[800];             /* as written, in the notation (notation.h) */
    char ref_plain[224], quantity_plain[800]; /* their plain text; the reference with its ids */
    double measured, expected, tol;
    row_kind kind;
    int pass;
    int none_found;  /* an unbounded limit never reached: "none found for h <= expected" */
    double searched; /* > 0: the largest h searched, printed in place of expected there */
} ledger_row;

typedef struct {
    char name[64];
    double value;
} ledger_extra;

/* Everything a run of the ledger records: what a section run in another process passes back. */
typedef struct {
    ledger_row rows[LEDGER_MAX];
    int nrows;
    ledger_extra extras[LEDGER_MAX];
    int nextras;
    double mins[LEDGER_MINS];
} ledger_state;

/* The state of this process. */
ledger_state *ledger_state_get(void);

/* The verdicts in the order the tally prints them, and a line's index among them. */
#define LEDGER_NVERDICTS 5
extern const char *const LEDGER_VERDICTS[LEDGER_NVERDICTS];
int ledger_verdict_index(const char *verdict);

/* The test column in plain text ("|x - e| <= tol", ">= b", "<= b") and the measured one (the
 * number, or "none found for h <= H"). */
void ledger_test_text(const ledger_row *r, char *out, size_t len);
void ledger_measured_text(const ledger_row *r, char *out, size_t len);

/* The companion's LaTeX (numbers.tex, ledger.tex, summary.tex) and the web's claims_tex.tsv,
 * beside claims.tsv in dir; 0, or -1 on a write error. */
int ledger_write_tex(const char *dir);

#endif
