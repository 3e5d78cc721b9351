/* Recording the ledger's lines: the verdict from the numbers, the check from what the caller
 * asserts, the quantity and the reference checked against the notation and made plain text. */
#include "ledger.h"

#include "ledger_rows.h"
#include "notation.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static ledger_state state = {.mins = {INFINITY, INFINITY, INFINITY, INFINITY}};

ledger_state *ledger_state_get(void) { return &state; }

const char *const LEDGER_VERDICTS[LEDGER_NVERDICTS] = {"reproduced", "not reproduced", "erratum",
                                                       "extension", "by construction"};

int ledger_verdict_index(const char *verdict)
{
    for (int i = 0; i < LEDGER_NVERDICTS; i++)
        if (strcmp(verdict, LEDGER_VERDICTS[i]) == 0)
            return i;
    return -1;
}

void ledger_die(const char *what)
{
    fprintf(stderr, "claims: %s failed\n", what);
    exit(2);
}

void ledger_number(const char *name, double value)
{
    if (state.nextras == LEDGER_MAX)
        ledger_die("fitting the numbers for the companion into LEDGER_MAX");
    snprintf(state.extras[state.nextras].name, sizeof state.extras[0].name, "%s", name);
    state.extras[state.nextras++].value = value;
}

void ledger_keep_min(int slot, double value) { state.mins[slot] = fmin(state.mins[slot], value); }

double ledger_min(int slot) { return state.mins[slot]; }

/* Where a line was recorded: "tests/FILE.c:LINE". */
typedef struct {
    const char *file;
    int line;
} ledger_source;

/* A string of the notation, kept as written and as plain text; a string outside the notation
 * stops the ledger with the line that recorded it. */
static void keep(const char *s, notation_refs refs, char *tex, size_t tlen, char *plain,
                 size_t plen, ledger_source src)
{
    char err[800], what[1000];
    if (strlen(s) >= tlen || notation_plain(s, refs, plain, plen, err, sizeof err) != 0) {
        if (strlen(s) >= tlen)
            snprintf(err, sizeof err, "longer than %d bytes: \"%s\"", (int)tlen - 1, s);
        snprintf(what, sizeof what, "the notation of the line recorded at %s:%d: %s", src.file,
                 src.line, err);
        ledger_die(what);
    }
    snprintf(tex, tlen, "%s", s);
}

static void add_row(ledger_source src, const char *id, const char *paper_ref, const char *quantity,
                    double measured, double expected, double tol, row_kind kind, int holds,
                    ledger_assert truth, int inf_ok)
{
    if (state.nrows == LEDGER_MAX)
        ledger_die("fitting the ledger into LEDGER_MAX lines");
    if (strlen(id) >= sizeof state.rows[0].id)
        ledger_die("fitting a ledger line's id into its buffer");
    ledger_row *r = &state.rows[state.nrows++];
    memset(r, 0, sizeof *r);
    snprintf(r->id, sizeof r->id, "%s", id);
    keep(paper_ref, PLAIN_REF_IDS, r->ref, sizeof r->ref, r->ref_plain, sizeof r->ref_plain, src);
    keep(quantity, PLAIN_QUANTITY, r->quantity, sizeof r->quantity, r->quantity_plain,
         sizeof r->quantity_plain, src);
    snprintf(r->source, sizeof r->source, "%s:%d", src.file, src.line);
    r->measured = measured;
    r->expected = expected;
    r->tol = tol;
    r->kind = kind;
    /* A NaN never passes; an infinity only where the caller says it means "beyond the range". */
    const int usable = isfinite(measured) || (inf_ok && isinf(measured));
    r->none_found = inf_ok && isinf(measured) && measured > 0.0;
    if (truth == LEDGER_EXTENSION || truth == LEDGER_BY_CONSTRUCTION) {
        strcpy(r->verdict, truth == LEDGER_EXTENSION ? "extension" : "by construction");
        r->pass = usable && holds;
    } else {
        strcpy(r->verdict, holds                     ? "reproduced"
                           : truth == LEDGER_ERRATUM ? "erratum"
                                                     : "not reproduced");
        r->pass = usable && holds == (truth == LEDGER_REPRODUCED);
    }
}

void ledger_add_at(const char *file, int line, const char *id, const char *paper_ref,
                   const char *quantity, double measured, double expected, double tol,
                   ledger_assert truth)
{
    add_row((ledger_source){file, line}, id, paper_ref, quantity, measured, expected, tol,
            ROW_WITHIN, fabs(measured - expected) <= tol, truth, 0);
}

static void add_bound(ledger_source src, const char *id, const char *paper_ref,
                      const char *quantity, double measured, double bound, int at_least,
                      ledger_assert truth, int inf_ok)
{
    add_row(src, id, paper_ref, quantity, measured, bound, 0.0,
            at_least ? ROW_AT_LEAST : ROW_AT_MOST, at_least ? measured >= bound : measured <= bound,
            truth, inf_ok);
}

void ledger_add_bound_at(const char *file, int line, const char *id, const char *paper_ref,
                         const char *quantity, double measured, double bound, int at_least,
                         ledger_assert truth)
{
    add_bound((ledger_source){file, line}, id, paper_ref, quantity, measured, bound, at_least,
              truth, 0);
}

void ledger_add_bound_unbounded_at(const char *file, int line, const char *id,
                                   const char *paper_ref, const char *quantity, double measured,
                                   double bound, int at_least, ledger_assert truth)
{
    add_bound((ledger_source){file, line}, id, paper_ref, quantity, measured, bound, at_least,
              truth, 1);
}

void ledger_add_none_found_at(const char *file, int line, const char *id, const char *paper_ref,
                              const char *quantity, double measured, double bound, double searched,
                              ledger_assert truth)
{
    add_bound((ledger_source){file, line}, id, paper_ref, quantity, measured, bound, 1, truth, 1);
    state.rows[state.nrows - 1].searched = searched;
}

/* The test column: the check in words, "<= b", ">= b" or "|x - e| <= tol" with the numbers. */
void ledger_test_text(const ledger_row *r, char *out, size_t len)
{
    if (r->kind == ROW_AT_LEAST)
        snprintf(out, len, ">= %.6g", r->expected);
    else if (r->kind == ROW_AT_MOST)
        snprintf(out, len, "<= %.6g", r->expected);
    else if (r->expected == 0.0)
        snprintf(out, len, "|x| <= %.3g", r->tol);
    else /* |x + 1|, not |x - -1| */
        snprintf(out, len, "|x %c %.6g| <= %.3g", r->expected < 0.0 ? '+' : '-', fabs(r->expected),
                 r->tol);
}

/* The measured column: the number, or what an unbounded limit's search found. */
void ledger_measured_text(const ledger_row *r, char *out, size_t len)
{
    if (r->none_found)
        snprintf(out, len, "none found for h <= %.6g",
                 r->searched > 0.0 ? r->searched : r->expected);
    else
        snprintf(out, len, "%.6g", r->measured);
}
