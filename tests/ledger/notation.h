/* The ledger's notation: what a line measures, and where the paper says it, written once.
 *
 * A quantity or a paper reference is LaTeX text with inline math in $...$, in a subset that the
 * companion's LaTeX and the web edition's KaTeX both take as it is. The plain text of the
 * terminal and of claims.tsv is derived from it by the table in notation.c, macro by macro:
 * \omega -> ω, \le -> ≤, \mathrm{dist} -> dist, x^{k+1} -> x^(k+1), 2^{-10} -> 2^-10.
 *
 *   text   words, digits and punctuation; ``quotes''; -- (a dash); ~ (a tie); \% \& \# \_;
 *          \emph{..} \textit{..} \textbf{..} \texttt{..}; and the paper's numbering:
 *          \eqref{LABEL}      an equation, "(27)"
 *          \PaperRefOr{LABEL} a statement, a figure or a section, "Proposition 5.1"
 *          (LABEL as in paper/labels.tsv; nolabel:proposition-5.2 for an unlabelled one).
 *   math   letters, digits, + - * / = < > | ( ) [ ] , ; : ! ' and spaces; x^{..} and x_{..};
 *          \hat \tilde \bar \dot \sqrt \frac \mathrm \text \left \right, and the symbols of the
 *          table (Greek letters, relations, \max ..., \| \{ \}).
 * Anything else (a raw _ ^ < > | \ in text, an unknown macro, unbalanced braces or $) is an
 * error: notation_plain says which and where, and the ledger stops. */
#ifndef SUSLOV_LEDGER_NOTATION_H
#define SUSLOV_LEDGER_NOTATION_H

#include <stddef.h>

/* How references read in plain text: a quantity's "(27)"; a paper_ref's "eq. (27)"; and with its
 * label as a secondary id, "eq. (27) (ContDyn)", "Proposition 5.1 (TeoL)" (never the stand-in of
 * an unlabelled statement, nolabel:KIND-N). */
typedef enum { PLAIN_QUANTITY, PLAIN_REF, PLAIN_REF_IDS } notation_refs;

/* The plain text of s into out (UTF-8, at most len - 1 bytes), references by the paper's
 * published numbers. Returns 0, or -1 with a message in err when s is outside the notation (or
 * a label is not the paper's) or the text does not fit. */
int notation_plain(const char *s, notation_refs refs, char *out, size_t len, char *err,
                   size_t errlen);

/* A number for math mode, to a given count of significant digits: 0.0105, 3.49\times10^{-9},
 * 10^{-14}; the text of %.*g otherwise (no exponent). */
typedef struct {
    char s[64];
} notation_num;
notation_num notation_g(double v, int digits);

#endif
