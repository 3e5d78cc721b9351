/* The paper's statements and equations by their published numbers: the programs' texts cite the
 * paper by its LaTeX labels, as the code's comments do ("(ContDyn)", "(TeoL)"), and every text a
 * reader sees (--help, the manual page, messages, figure captions) shows the number printed in
 * the paper instead: "eq. (27)", "Proposition 5.1". The numbers are paper/labels.tsv's (LaTeX's
 * counters replayed over the paper's source), compiled into paper_labels.c. */
#ifndef SUS_PLOT_PAPER_REF_H
#define SUS_PLOT_PAPER_REF_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const char *label;  /* the LaTeX label: "ContDyn"; "nolabel:KIND-N" for an unlabelled one */
    const char *kind;   /* "equation", "subequation", "proposition", "section", ... */
    const char *number; /* as printed: "27", "5.1", "12a" */
} sus_paper_label;

extern const sus_paper_label SUS_PAPER_LABELS[];
extern const int SUS_PAPER_NLABELS;

/* The entry of a label (n bytes of it), or NULL when the paper has no such label. */
const sus_paper_label *sus_paper_label_find(const char *label, size_t n);
/* Its published name: "eq. (27)" for an equation, "Proposition 5.1", "Section 5.6", "Figure 2";
 * NULL (buf untouched) when the paper has no such label. */
const char *sus_paper_name(const char *label, char *buf, size_t len);
/* text with every "(LABEL)" whose LABEL is one of the paper's replaced by its published name
 * ("from (LagMult)" -> "from eq. (28)"); other text unchanged. Truncated to len - 1 bytes;
 * returns out. */
char *sus_paper_numbered(const char *text, char *out, size_t len);

#ifdef __cplusplus
}
#endif

#endif
