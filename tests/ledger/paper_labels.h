/* The paper's published numbering, as the ledger names it: paper/labels.tsv (label, kind,
 * number, section; LaTeX's counters replayed over the paper's source), read once. */
#ifndef SUSLOV_LEDGER_PAPER_LABELS_H
#define SUSLOV_LEDGER_PAPER_LABELS_H

#include <stddef.h>

/* The published name of the first n bytes of label into buf: "eq. (27)" for an equation,
 * "Proposition 5.1", "Figure 2", "Section 5.6" otherwise; the number alone for an equation
 * when bare ("(27)"). Returns buf, or NULL when the paper has no such label. The table is
 * read from paper/labels.tsv (relative to the working directory, the repository's root) the
 * first time; an unreadable table stops the ledger. */
const char *paper_label_name(const char *label, size_t n, int bare, char *buf, size_t len);

/* Whether the label is an unlabelled statement's stand-in ("nolabel:KIND-NUMBER"), which is
 * never shown as a secondary id. */
int paper_label_is_stand_in(const char *label, size_t n);

#endif
