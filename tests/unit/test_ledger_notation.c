/* The claims ledger's notation (tests/ledger/notation.h): a quantity written once in LaTeX that
 * KaTeX takes too, and its plain text for the terminal and claims.tsv, derived macro by macro.
 * The expected plain texts are written out here by hand; the references' numbers are the
 * paper's own (Proposition 5.1 is TeoL, (27) is ContDyn). Strings outside the notation must be
 * refused, with where. The claims program's files are no library: notation.c is compiled in. */
#include "check.h"

#include "notation.c"

static void plain_is(const char *s, notation_refs refs, const char *want)
{
    char out[256], err[256] = "";
    const int rc = notation_plain(s, refs, out, sizeof out, err, sizeof err);
    CHECK(rc == 0 && !strcmp(out, want), "'%s' reads '%s' (got '%s'%s%s)", s, want, rc ? "" : out,
          rc ? ": " : "", err);
}

static void refused(const char *s, const char *why)
{
    char out[256], err[256] = "";
    const int rc = notation_plain(s, PLAIN_QUANTITY, out, sizeof out, err, sizeof err);
    CHECK(rc != 0 && strstr(err, why) != NULL, "'%s' is refused: %s (got: %s)", s, why,
          rc ? err : "accepted");
}

static void number_is(double v, int digits, const char *want)
{
    const notation_num n = notation_g(v, digits);
    CHECK(!strcmp(n.s, want), "%.17g to %d digits is '%s' (got '%s')", v, digits, want, n.s);
}

int main(void)
{
    /* math: Greek letters, scripts, accents, roots and operators */
    plain_is("$|\\omega(t_k+\\varepsilon) - \\omega^{k+1}|$", PLAIN_QUANTITY,
             "|ω(t_k+ε) - ω^(k+1)|");
    plain_is("$2^{-10}$, $x_{31}$, $e_{p+1}$", PLAIN_QUANTITY, "2^-10, x_31, e_(p+1)");
    plain_is("$\\hat{\\omega}_k$ and $\\widehat{x \\times y}$", PLAIN_QUANTITY,
             "ω\xcc\x82_k and (x × y)\xcc\x82");
    plain_is("$\\sqrt{E_N / E_0}$, $\\sqrt{2}$, $\\frac{1}{2}$", PLAIN_QUANTITY,
             "√(E_N / E_0), √2, 1/2");
    plain_is("$\\max |R^\\top R - I| \\le 10^{-14}$", PLAIN_QUANTITY, "max |R^T R - I| ≤ 10^-14");
    plain_is("$1000\\,u \\times \\mathrm{size}$", PLAIN_QUANTITY, "1000 u × size");
    plain_is("$\\langle e_3, (R^\\top V)^\\vee \\rangle$", PLAIN_QUANTITY, "⟨ e_3, (R^T V)^∨ ⟩");
    /* text: quotes, dashes, escaped characters, fonts */
    plain_is("``much faster'' -- 5\\% of \\texttt{a\\_b}, Jorba \\& Zou", PLAIN_QUANTITY,
             "\"much faster\" – 5% of a_b, Jorba & Zou");
    /* the paper's numbering: a quantity's (27); a reference's eq. (27), with its label */
    plain_is("the distance \\eqref{MetMat}, \\PaperRefOr{TeoL}", PLAIN_QUANTITY,
             "the distance (22), Proposition 5.1");
    plain_is("\\eqref{ContDyn}, \\PaperRefOr{algo}", PLAIN_REF, "eq. (27), Algorithm 5.1");
    plain_is("\\PaperRefOr{TeoL}, extension", PLAIN_REF_IDS, "Proposition 5.1 (TeoL), extension");
    plain_is("\\eqref{ContDyn}; \\PaperRefOr{nolabel:proposition-5.2}", PLAIN_REF_IDS,
             "eq. (27) (ContDyn); Proposition 5.2");
    plain_is("\\PaperRefOr{Fig2} caption; \\PaperRefOr{nolabel:subsection-5.6} text", PLAIN_REF_IDS,
             "Figure 2 (Fig2) caption; Section 5.6 text");
    /* what the notation refuses, and says where */
    refused("|w(t)|", "'|' outside $...$");
    refused("w_k", "'_' outside $...$");
    refused("$\\omegaa$", "unknown macro '\\omegaa'");
    refused("$x^{2$", "'$' inside a group");
    refused("$x", "unclosed '$'");
    refused("x}", "unbalanced '}'");
    refused("\\eqref{NoSuchLabel}", "no label 'NoSuchLabel'");
    refused("$\\eqref{ContDyn}$", "\\eqref is not allowed in math");
    refused("\\omega", "\\omega is not allowed in text");
    refused("$x^$", "a script without its argument");
    refused("$\\hat\\omega$", "'{' expected");
    char small[8], err[128] = "";
    CHECK(notation_plain("$\\omega\\omega\\omega\\omega$", PLAIN_QUANTITY, small, sizeof small, err,
                         sizeof err) != 0 &&
              strstr(err, "longer than 7 bytes"),
          "a plain text that does not fit is refused, not cut (got: %s)", err);
    /* numbers for math mode */
    number_is(0.0105, 3, "0.0105");
    number_is(3.49e-9, 3, "3.49\\times10^{-9}");
    number_is(1e-14, 3, "10^{-14}");
    number_is(-1e-14, 3, "-10^{-14}");
    number_is(2.5e5, 6, "250000");
    number_is(1.5e-14, 2, "1.5\\times10^{-14}");
    return check_summary("test_ledger_notation");
}
