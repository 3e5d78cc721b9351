#include "ledger.h"

#include "atomic_file.h"
#include "registry.h"
#include "stepper.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LEDGER_MAX 1024

/* How a line is tested: |measured - expected| <= tol, or a one-sided bound. */
typedef enum { ROW_WITHIN, ROW_AT_LEAST, ROW_AT_MOST } row_kind;

typedef struct {
    char id[64], ref[96], quantity[512], verdict[16], source[80];
    double measured, expected, tol;
    row_kind kind;
    int pass;
    int none_found; /* an unbounded limit never reached: "none found for h <= expected" */
} ledger_row;

static ledger_row rows[LEDGER_MAX];
static int nrows;

typedef struct {
    char name[64];
    double value;
} ledger_extra;

static ledger_extra extras[LEDGER_MAX];
static int nextras;

void ledger_number(const char *name, double value)
{
    if (nextras < LEDGER_MAX) {
        snprintf(extras[nextras].name, sizeof extras[nextras].name, "%s", name);
        extras[nextras++].value = value;
    }
}

/* "fig1-energy-midpoint" -> "FigOneEnergyMidpoint": TeX macro names are letters only. */
static void macro_name(const char *id, char *out, size_t len)
{
    static const char *digits[10] = {"Zero", "One", "Two", "Three", "Four",
                                     "Five", "Six", "Seven", "Eight", "Nine"};
    size_t n = 0;
    int up = 1;
    for (const char *c = id; *c && n + 6 < len; c++) {
        if (*c >= '0' && *c <= '9') {
            n += (size_t)snprintf(out + n, len - n, "%s", digits[*c - '0']);
            up = 1;
        } else if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z')) {
            out[n++] = up && *c >= 'a' ? (char)(*c - 'a' + 'A') : *c;
            up = 0;
        } else {
            up = 1;
        }
    }
    out[n] = '\0';
}

/* A number for math mode: 1.99, 0.0105, 3.49\times10^{-9}. */
static void tex_number(double v, char *out, size_t len)
{
    if (!isfinite(v))
        snprintf(out, len, "%s", isnan(v) ? "\\text{n/a}" : (v > 0 ? "\\infty" : "-\\infty"));
    else if (v == 0.0)
        snprintf(out, len, "0");
    else if (fabs(v) >= 1e-3 && fabs(v) < 1e4)
        snprintf(out, len, "%.4g", v);
    else {
        const int e = (int)floor(log10(fabs(v)));
        char mant[32];
        snprintf(mant, sizeof mant, "%.3g", v / pow(10.0, e));
        if (strcmp(mant, "1") == 0 || strcmp(mant, "-1") == 0) /* 1e-14 -> 10^{-14} */
            snprintf(out, len, "%s10^{%d}", mant[0] == '-' ? "-" : "", e);
        else
            snprintf(out, len, "%s\\times10^{%d}", mant, e);
    }
}

/* Text with LaTeX's special characters escaped. */
static void tex_text(FILE *fp, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '\\': fputs("\\textbackslash{}", fp); break;
        case '_': case '%': case '&': case '#': case '$': case '{': case '}': fprintf(fp, "\\%c", *s); break;
        case '^': fputs("\\^{}", fp); break;
        case '~': fputs("\\~{}", fp); break;
        case '<': fputs("$<$", fp); break;
        case '>': fputs("$>$", fp); break;
        case '|': fputs("$|$", fp); break;
        default: fputc(*s, fp);
        }
}

/* A ledger id in typewriter type that may break after its hyphens. */
static void tex_id(FILE *fp, const char *id)
{
    fputs("\\texttt{", fp);
    for (const char *c = id; *c; c++) {
        char one[2] = {*c, '\0'};
        tex_text(fp, one);
        if (*c == '-')
            fputs("\\allowbreak{}", fp);
    }
    fputc('}', fp);
}

/* ---- ASCII -> LaTeX for the quantity and paper_ref strings of tests/claims*.c ----------------
 * The strings are written for a terminal ("|w(t_k+eps) - w^{k+1}|", "1e6 steps", "(MetMat)").
 * The typeset ledger splits each string at blanks into prose words and math tokens, joins
 * neighbouring math tokens into one $...$ span and rewrites the ASCII conventions the claims
 * use: w -> \omega, eps -> \varepsilon, w^_k -> \hat\omega_k, 1e-12 -> 10^{-12}, 2^-10 ->
 * 2^{-10}, <e3, v> -> \langle e_3, v\rangle, "3x3"/"u x size" -> \times, "->" -> \to,
 * sqrt(a) -> \sqrt{a}. A word "(label)" becomes \PaperRefParen{label}, which the companion
 * resolves to the paper's published number (paper/labels.tsv) or prints as it is. Anything
 * not recognised is escaped, so a new string can look plain but never breaks the build. */

static int is_alpha(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
static int is_digit(int c) { return c >= '0' && c <= '9'; }
static int is_lower_word(const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!(s[i] >= 'a' && s[i] <= 'z') && !(i > 0 && i + 1 < n && (s[i] == '-' || s[i] == '.')) &&
            !(i + 1 == n && s[i] == '.'))
            return 0;
    return n > 0;
}

/* Lowercase words that are math, not prose. */
static const char *const math_words[] = {"eps", "lambda", "lim", "max", "min", "sqrt", "cay", "dist", "vee",
                                         "xi", "psi", "phi", "inf", "size", "dcay", "det", "exp", "log",
                                         "mid", "var", "row", "col", "gd", "sech", "tanh", "cos", "sin",
                                         NULL};

static int in_list(const char *const *list, const char *s, size_t n)
{
    for (int i = 0; list[i]; i++)
        if (strlen(list[i]) == n && strncmp(list[i], s, n) == 0)
            return 1;
    return 0;
}

/* Whether a blank-separated token is prose: a lowercase word (hyphens, "i.e." allowed), or a
 * capitalised name without underscores or digits inside ("Newton", "RK4", "TeoL"), once the
 * surrounding punctuation ( ' " , ; : . ) is set aside. "a" is prose, other single letters math. */
static int is_prose(const char *t, size_t n)
{
    size_t a = 0, b = n;
    while (a < b && (t[a] == '(' || t[a] == '\'' || t[a] == '"'))
        a++;
    while (b > a && (t[b - 1] == ',' || t[b - 1] == ';' || t[b - 1] == ':' || t[b - 1] == ')' ||
                     t[b - 1] == '\'' || t[b - 1] == '"' || t[b - 1] == '.'))
        b--;
    if (b - a > 2 && t[b - 2] == '\'' && t[b - 1] == 's') /* "midpoint's" */
        b -= 2;
    const char *w = t + a;
    const size_t m = b - a;
    if (m == 0)
        return 0;
    if (is_lower_word(w, m))
        return (m > 1 || w[0] == 'a') && !in_list(math_words, w, m);
    /* names of methods and programs: rk4, rk8pd, magnus4, comp4-s5, exp-mid, RK4, Newton, TeoL
     * (not I31, E0, Phi, and not a math word such as eps) */
    size_t letters_all = 0, ok = w[0] >= 'a' && w[0] <= 'z';
    for (size_t k = 0; k < m && ok; k++) {
        letters_all += is_alpha(w[k]) != 0;
        ok = (w[k] >= 'a' && w[k] <= 'z') || is_digit(w[k]) ||
             (w[k] == '-' && k > 0 && k + 1 < m && w[k - 1] != '-');
    }
    if (ok && letters_all >= 2 && memchr(w, '-', m) && !in_list(math_words, w, m))
        return 1;
    size_t i = 0;
    while (i < m && is_alpha(w[i]))
        i++;
    const size_t letters = i;
    while (i < m && (is_alpha(w[i]) || is_digit(w[i])))
        i++;
    if (i != m || letters < 2 || strncmp(w, "Phi", m) == 0)
        return 0;
    return (w[0] >= 'A' && w[0] <= 'Z') || letters < m;
}

/* "(label)" with a label-like word inside: a citation of the paper. */
static int is_ref_token(const char *t, size_t n, size_t *a, size_t *b)
{
    size_t i = 0;
    while (i < n && t[i] != '(')
        i++;
    if (i == n || !is_alpha(t[i + 1]))
        return 0;
    size_t j = i + 1;
    while (j < n && (is_alpha(t[j]) || is_digit(t[j])))
        j++;
    if (j >= n || t[j] != ')' || i > 0)
        return 0;
    for (size_t k = j + 1; k < n; k++)
        if (t[k] != ',' && t[k] != ';' && t[k] != ':' && t[k] != '.')
            return 0;
    *a = i + 1;
    *b = j;
    return 1;
}

static void tex_prose(FILE *fp, const char *t, size_t n)
{
    char buf[256];
    size_t a, b;
    if (is_ref_token(t, n, &a, &b)) {
        fprintf(fp, "\\PaperRefParen{%.*s}", (int)(b - a), t + a);
        snprintf(buf, sizeof buf, "%.*s", (int)(n - b - 1), t + b + 1);
        tex_text(fp, buf);
        return;
    }
    for (size_t i = 0; i < n; i++) {
        if (t[i] == '\'' && (i == 0 || t[i - 1] == '(')) {
            fputc('`', fp);
            continue;
        }
        if (t[i] == '"') { /* TeX quotes */
            fputs(i == 0 || t[i - 1] == '(' ? "``" : "''", fp);
            continue;
        }
        snprintf(buf, sizeof buf, "%c", t[i]);
        tex_text(fp, buf);
    }
}

/* The state of one math span being rewritten: the text, the position, and what is open. */
typedef struct {
    FILE *fp;
    const char *s;
    size_t n, i;
    int angle;                     /* open <e3, v> brackets */
    int sqrt_depth[8], nsqrt;      /* the paren depth at which each open \sqrt{ closes */
    int depth;                     /* paren depth */
    int braces_ok, bd;             /* braces balance within the span; brace depth */
    int sub, sup, arg;             /* scripts on the current base at brace depth 0; arg: the next atom
                                    * is a script's argument, not a new base */
} math_state;

/* A new atom: at brace depth 0 it starts a new base unless it is a script's argument. */
static void math_atom(math_state *m)
{
    if (m->bd == 0) {
        if (m->arg)
            m->arg = 0;
        else
            m->sub = m->sup = 0;
    }
}

/* A script: a second '_' (or '^') on the same base gets an empty base {}, so that "a_b_c" cannot
 * stop TeX with a double subscript. */
static void math_script(math_state *m, int *flag)
{
    if (m->bd == 0) {
        if (*flag) {
            fputs("{}", m->fp);
            m->sub = m->sup = 0;
        }
        *flag = 1;
        m->arg = 1;
    }
}

/* The TeX for a word of wl letters followed by dl digits; 0 when it is no symbol of its own. */
static int math_word_name(const char *w, size_t wl, char *name, size_t len)
{
    static const char *const greek[] = {"lambda", "xi", "psi", "phi", "Phi", NULL};
    static const char *const ops[] = {"lim", "max", "min", "det", "exp", "log", "cos", "sin", NULL};
    if (wl == 1 && w[0] == 'w')
        snprintf(name, len, "\\omega");
    else if (wl == 3 && !strncmp(w, "eps", 3))
        snprintf(name, len, "\\varepsilon");
    else if (wl == 3 && !strncmp(w, "inf", 3))
        snprintf(name, len, "\\infty");
    else if (in_list(greek, w, wl) || in_list(ops, w, wl))
        snprintf(name, len, "\\%.*s", (int)wl, w);
    else
        return 0;
    return 1;
}

/* A word: w -> \omega, eps -> \varepsilon, sqrt( -> \sqrt{, " x " -> \times, w3 -> \omega_3,
 * "w^_k" -> a hat, any other name upright. */
static void math_word(math_state *m)
{
    const char *s = m->s;
    const size_t n = m->n, i = m->i;
    size_t j = i;
    while (j < n && is_alpha(s[j]))
        j++;
    size_t k = j;
    while (k < n && is_digit(s[k]))
        k++;
    if (j - i > 1) /* a name: rk8pd, magnus4 */
        while (k < n && (is_alpha(s[k]) || is_digit(s[k])))
            k++;
    const char *w = s + i;
    const size_t wl = j - i, dl = k - j;
    char name[64];
    if (wl == 4 && !strncmp(w, "sqrt", 4) && k < n && s[k] == '(' && dl == 0 && m->nsqrt < 8) {
        math_atom(m);
        fputs("\\sqrt{", m->fp);
        m->sqrt_depth[m->nsqrt++] = m->depth++;
        m->i = k + 1;
        return;
    }
    if (math_word_name(w, wl, name, sizeof name))
        ;
    else if (wl == 1 && w[0] == 'x' && dl == 0 && i > 0 && s[i - 1] == ' ' && (k == n || s[k] == ' '))
        snprintf(name, sizeof name, "\\times "); /* "1000 u x size" */
    else if (wl == 1)
        snprintf(name, sizeof name, "%c", w[0]);
    else
        snprintf(name, sizeof name, "\\mathrm{%.*s}", (int)(k - i), w);
    /* "w^_k", "w^/2": a hat on this symbol (a '^' not followed by an exponent) */
    const char after = k + 1 < n ? s[k + 1] : '\0';
    const int hat = k < n && s[k] == '^' &&
                    (k + 1 == n || (!is_alpha(after) && !is_digit(after) && after != '{' && after != '-'));
    math_atom(m);
    fprintf(m->fp, hat ? "\\hat{%s}" : "%s", name);
    if (wl == 1 && dl > 0) { /* w3 -> \omega_3, I31 -> I_{31} */
        math_script(m, &m->sub);
        fprintf(m->fp, "_{%.*s}", (int)dl, s + j);
        m->arg = 0;
    }
    m->i = k + hat;
}

/* A number: 1e-05 -> 10^{-5}, 2.5e3 -> 2.5\times10^{3}, 3x3 and 100x -> \times. */
static void math_number(math_state *m)
{
    const char *s = m->s;
    const size_t n = m->n, i = m->i;
    math_atom(m);
    size_t j = i;
    while (j < n && (is_digit(s[j]) || (s[j] == '.' && j + 1 < n && is_digit(s[j + 1]))))
        j++;
    const int exponent = j + 1 < n && s[j] == 'e' &&
                         (is_digit(s[j + 1]) || (s[j + 1] == '-' && j + 2 < n && is_digit(s[j + 2])));
    if (exponent) {
        size_t k = j + 1 + (s[j + 1] == '-');
        while (k < n && is_digit(s[k]))
            k++;
        const int ex = atoi(s + j + 1);
        if (j - i == 1 && s[i] == '1')
            fprintf(m->fp, "10^{%d}", ex);
        else
            fprintf(m->fp, "%.*s\\times10^{%d}", (int)(j - i), s + i, ex);
        if (m->bd == 0)
            m->sub = 0, m->sup = 1;
        m->i = k;
        return;
    }
    fprintf(m->fp, "%.*s", (int)(j - i), s + i);
    m->i = j;
    if (j < n && s[j] == 'x' && (j + 1 == n || !is_alpha(s[j + 1]))) {
        fputs("\\times ", m->fp);
        m->i++;
    }
}

/* The two-character conventions and angle brackets: 2^-10, ->, <=, >=, <e3, v>, "..".
 * Returns 0 when the text at the position is none of them. */
static int math_operator(math_state *m)
{
    const char *s = m->s;
    const size_t n = m->n, i = m->i;
    const char c = s[i], d = i + 1 < n ? s[i + 1] : '\0';
    if (c == '^' && d == '-') { /* 2^-10 -> 2^{-10} */
        size_t k = i + 2;
        while (k < n && (is_digit(s[k]) || is_alpha(s[k])))
            k++;
        math_script(m, &m->sup);
        fprintf(m->fp, "^{%.*s}", (int)(k - i - 1), s + i + 1);
        m->arg = 0;
        m->i = k;
        return 1;
    }
    const char *tex = c == '-' && d == '>'   ? "\\to "
                      : c == '<' && d == '=' ? "\\le "
                      : c == '>' && d == '=' ? "\\ge "
                      : c == '.' && d == '.' ? "\\dots "
                                             : NULL;
    if (tex) {
        fputs(tex, m->fp);
        m->i += 2;
        return 1;
    }
    if (c == '<' && d != '\0' && d != ' ') {
        fputs("\\langle ", m->fp);
        m->angle++;
    } else if (c == '>') {
        fputs(m->angle > 0 ? "\\rangle " : ">", m->fp);
        m->angle -= m->angle > 0;
    } else
        return 0;
    m->i++;
    return 1;
}

/* A space inside the span at brace depth 0. One between two words of the math ("eps 0.1",
 * "N s u") is kept as a math space; TeX drops plain spaces and spaces relations and operators
 * itself. "x" as times is not a word. */
static void math_space(math_state *m)
{
    const char *s = m->s;
    const size_t i = m->i;
    const char a = s[i - 1], b = s[i + 1];
    const int times_before = a == 'x' && (i < 2 || s[i - 2] == ' ');
    const int times_after = b == 'x' && (i + 2 == m->n || s[i + 2] == ' ');
    if ((is_alpha(a) || is_digit(a) || a == ')') && (is_alpha(b) || is_digit(b) || b == '(') &&
        !times_before && !times_after)
        fputs("\\ ", m->fp);
    m->i++;
}

/* A brace: a TeX group when the span's braces balance, else printed. */
static void math_brace(math_state *m, char c)
{
    if (!m->braces_ok) {
        fputs(c == '{' ? "\\{" : "\\}", m->fp);
        return;
    }
    if (c == '{') {
        if (m->bd == 0 && !m->arg)
            m->sub = m->sup = 0;
        m->arg = m->bd == 0 ? 0 : m->arg;
        m->bd++;
    } else
        m->bd--;
    fputc(c, m->fp);
}

/* Any other character: parentheses (closing a \sqrt{), TeX specials, scripts, primes, braces. */
static void math_char(math_state *m)
{
    const char c = m->s[m->i], d = m->i + 1 < m->n ? m->s[m->i + 1] : '\0';
    FILE *fp = m->fp;
    m->i++;
    if (c == '(')
        m->depth++;
    if (c == ')' && m->nsqrt > 0 && m->sqrt_depth[m->nsqrt - 1] == m->depth - 1) {
        fputc('}', fp);
        m->nsqrt--;
        m->depth--;
        return;
    }
    if (c == ')')
        m->depth -= m->depth > 0;
    if (c == '%' || c == '&' || c == '#' || c == '$')
        fprintf(fp, "\\%c", c);
    else if (c == '\\')
        fputs("\\backslash ", fp);
    else if (c == '~')
        fputs("\\sim ", fp);
    else if (c == '\'') { /* a prime is a superscript: none may come before it */
        if (m->bd == 0 && m->sup)
            fputs("{}", fp);
        fputc('\'', fp);
        m->sup = 0;
    } else if ((c == '^' || c == '_') && d != '\0' && d != ' ') {
        math_script(m, c == '^' ? &m->sup : &m->sub);
        fputc(c, fp);
    } else if (c == '^')
        fputs("\\wedge ", fp);
    else if (c == '_')
        fputs("\\_", fp);
    else if (c == '{' || c == '}')
        math_brace(m, c);
    else {
        if (m->bd == 0)
            m->sub = m->sup = m->arg = 0;
        fputc(c, fp);
    }
}

/* Whether the braces of s[0..n) balance (never closing more than is open). */
static int braces_balance(const char *s, size_t n)
{
    int bd = 0;
    for (size_t i = 0; i < n; i++) {
        bd += (s[i] == '{') - (s[i] == '}');
        if (bd < 0)
            return 0;
    }
    return bd == 0;
}

/* One math span (the blank-separated tokens between two prose words), rewritten for math mode. */
static void tex_math(FILE *fp, const char *s, size_t n)
{
    size_t punct = 0; /* a trailing , ; : belongs to the sentence, outside the math */
    while (punct < n && (s[n - 1 - punct] == ',' || s[n - 1 - punct] == ';' || s[n - 1 - punct] == ':'))
        punct++;
    math_state m = {.fp = fp, .s = s, .n = n - punct, .braces_ok = braces_balance(s, n - punct)};
    fputc('$', fp);
    while (m.i < m.n) {
        const char c = s[m.i];
        if (is_alpha(c))
            math_word(&m);
        else if (is_digit(c))
            math_number(&m);
        else if (math_operator(&m))
            ;
        else if (c == ' ' && m.bd == 0 && m.i > 0 && m.i + 1 < m.n)
            math_space(&m);
        else
            math_char(&m);
    }
    while (m.nsqrt-- > 0)
        fputc('}', fp);
    fputc('$', fp);
    fprintf(fp, "%.*s", (int)punct, s + m.n);
}

/* A whole ASCII string (quantity or reference): prose words as text, the rest as math. */
static void tex_ascii(FILE *fp, const char *s)
{
    const char *math = NULL, *math_end = NULL;
    while (*s) {
        const char *t = s;
        while (*s && *s != ' ')
            s++;
        const size_t n = (size_t)(s - t);
        size_t a, b;
        const int prose = n > 0 && (is_prose(t, n) || is_ref_token(t, n, &a, &b));
        if (n > 0 && !prose) {
            if (!math)
                math = t;
            math_end = s;
        } else if (n > 0) {
            if (math) {
                tex_math(fp, math, (size_t)(math_end - math));
                fputc(' ', fp);
                math = NULL;
            }
            tex_prose(fp, t, n);
        }
        if (*s == ' ') {
            if (!math)
                fputc(' ', fp);
            s++;
        }
    }
    if (math)
        tex_math(fp, math, (size_t)(math_end - math));
}

/* Free-text references written before the paper's numbers were tabulated, mapped to the
 * labels of paper/labels.tsv (the unlabelled statements have "nolabel:KIND-NUMBER" there). */
static const char *const ref_alias[][2] = {
    {"Prop. general DSP", "nolabel:proposition-5.2"},
    {"Sec. 5.6 text", "nolabel:subsection-5.6 text"},
    {"Algorithm (algo), Remark", "algo, nolabel:remark-5.2"},
    {"Algorithm (algo)", "algo"},
    {"Def. UnredConsis", "UnredConsis"},
    {"Conclusions", "nolabel:section-7"},
    {"Fig. 1", "Fig1"},
    {"Fig. 2", "Fig2"},
    {NULL, NULL}};

/* The paper_ref column: every word that may be a label goes through \PaperRefOr, which prints
 * the published number when paper/labels.tsv knows the label and the word itself otherwise. */
static void tex_ref(FILE *fp, const char *ref)
{
    char buf[256];
    size_t n = 0;
    for (const char *s = ref; *s && n + 1 < sizeof buf;) {
        int hit = 0;
        for (int i = 0; ref_alias[i][0]; i++) {
            const size_t l = strlen(ref_alias[i][0]);
            if (strncmp(s, ref_alias[i][0], l) == 0) {
                n += (size_t)snprintf(buf + n, sizeof buf - n, "%s", ref_alias[i][1]);
                s += l;
                hit = 1;
                break;
            }
        }
        if (!hit)
            buf[n++] = *s++;
        if (n >= sizeof buf)
            n = sizeof buf - 1;
    }
    buf[n] = '\0';
    for (const char *s = buf; *s;) {
        if (is_alpha(*s)) {
            const char *t = s;
            while (is_alpha(*s) || is_digit(*s) || *s == ':' ||
                   (*s == '-' && (is_alpha(s[1]) || is_digit(s[1]))) || (*s == '.' && is_digit(s[1])))
                s++;
            fprintf(fp, "\\PaperRefOr{%.*s}", (int)(s - t), t);
            continue;
        }
        if (*s == '(' && is_alpha(s[1])) { /* "(cayinver)" */
            const char *t = s + 1, *e = t;
            while (is_alpha(*e) || is_digit(*e))
                e++;
            if (*e == ')') {
                fprintf(fp, "\\PaperRefParen{%.*s}", (int)(e - t), t);
                s = e + 1;
                continue;
            }
        }
        if (*s == '"') { /* "order (2,1)": TeX quotes */
            fputs(s == buf || s[-1] == ' ' ? "``" : "''", fp);
            s++;
            continue;
        }
        char one[2] = {*s++, '\0'};
        tex_text(fp, one);
    }
}

/* What the check compares, in words and math: the direction of each test. */
static void tex_test(FILE *fp, const ledger_row *r)
{
    char e[64], t[64];
    tex_number(r->expected, e, sizeof e);
    tex_number(r->tol, t, sizeof t);
    if (r->kind == ROW_AT_LEAST)
        fprintf(fp, "$m\\ge %s$", e);
    else if (r->kind == ROW_AT_MOST)
        fprintf(fp, "$m\\le %s$", e);
    else if (r->expected == 0.0)
        fprintf(fp, "$|m|\\le %s$", t);
    else { /* |m + 1|, not |m - -1| */
        tex_number(fabs(r->expected), e, sizeof e);
        fprintf(fp, "$|m%s%s|\\le %s$", r->expected < 0.0 ? "+" : "-", e, t);
    }
}

/* The measured value for math mode: the number, or what an unbounded limit's search found. */
static void tex_measured(const ledger_row *r, char *out, size_t len)
{
    char b[32];
    if (r->none_found) {
        tex_number(r->expected, b, sizeof b);
        /* breakable: the ledger's measured column is narrow */
        snprintf(out, len, "\\text{none found}\\allowbreak\\ \\text{for }h\\le %.31s", b);
    } else
        tex_number(r->measured, out, len);
}

/* One ledger line as two rows of a longtable: the numbers, then (kept on the same page) what
 * was measured. Used for the appendix; the summary uses the first row only. */
static void tex_line(FILE *fp, const ledger_row *r)
{
    char num[96];
    tex_id(fp, r->id);
    fputs(" & ", fp);
    tex_ref(fp, r->ref);
    tex_measured(r, num, sizeof num);
    fprintf(fp, " & $%s$ & ", num);
    tex_test(fp, r);
    fprintf(fp, " & %s%s\\\\*\n", r->verdict, r->pass ? "" : " \\textbf{(check FAILS)}");
    fputs("\\multicolumn{5}{@{}p{\\linewidth}@{}}{\\hspace{1.5em}\\parbox[t]{\\dimexpr\\linewidth-1.5em}{"
          "\\raggedright ", fp);
    tex_ascii(fp, r->quantity);
    fputs("}}\\\\[2pt]\n", fp);
}

/* The appendix: every line, then (kept on the same page: \\* and one parbox) what it measures. */
static const char *const tex_header =
    "\\begin{longtable}{@{}>{\\raggedright}p{0.29\\linewidth} >{\\raggedright}p{0.19\\linewidth} "
    ">{\\raggedleft}p{0.13\\linewidth} >{\\raggedright}p{0.17\\linewidth} "
    ">{\\raggedright\\arraybackslash}p{0.1\\linewidth}@{}}\n\\toprule\n"
    "ledger line & in the paper & measured $m$ & test & verdict\\\\\n\\midrule\\endhead\n"
    "\\midrule\\multicolumn{5}{r@{}}{continued on the next page}\\\\\\endfoot\n\\bottomrule\\endlastfoot\n";

/* The grouping key of a line for the summary: its id without a trailing "-METHOD" (a name of
 * the method registry), so that one row stands for the same claim tested on every method. */
static void group_key(const char *id, char *key, size_t len)
{
    snprintf(key, len, "%s", id);
    const size_t n = strlen(key);
    size_t best = 0;
    for (int i = 0; i < sus_step_method_count(); i++) {
        const char *name = sus_step_method_get(i)->type->name;
        const size_t l = strlen(name);
        if (l + 1 < n && l > best && key[n - l - 1] == '-' && strcmp(key + n - l, name) == 0)
            best = l;
    }
    if (best)
        key[n - best - 1] = '\0';
}

static int same_group(const ledger_row *a, const ledger_row *b, const char *key)
{
    char kb[64];
    group_key(b->id, kb, sizeof kb);
    return a->kind == ROW_WITHIN && b->kind == ROW_WITHIN && strcmp(key, kb) == 0 &&
           strcmp(a->ref, b->ref) == 0 && strcmp(a->verdict, b->verdict) == 0 && a->pass == b->pass;
}

/* The summary table: the lines that test the paper (no extensions), one row per claim. Lines
 * that test the same claim on several methods share a row, which gives the number of methods,
 * the worst deviation |m - e| among them and the tolerances. */
static void write_summary(FILE *fp)
{
    char key[64], num[128], lo[64], hi[64];
    int done[LEDGER_MAX] = {0};
    fputs("\\begin{longtable}{@{}>{\\raggedright}p{0.29\\linewidth} >{\\raggedright}p{0.2\\linewidth} "
          ">{\\raggedright}p{0.2\\linewidth} >{\\raggedright}p{0.17\\linewidth} "
          ">{\\raggedright\\arraybackslash}p{0.06\\linewidth}@{}}\n"
          "\\caption{Every ledger line that tests a statement of the paper, one row per claim; "
          "a claim tested on "
          "$n$ methods of the registry is one row ($\\times n$). $m$: measured; $e$, $t$: expected value and "
          "tolerance; $b$: the bound of a one-sided claim, usually the other method's value.}"
          "\\label{tab:summary}\\\\\n"
          "\\toprule claim (ledger lines) & in the paper & measured $m$ & test & repro\\-duced?\\\\\n"
          "\\midrule\\endfirsthead\n"
          "\\toprule claim (ledger lines) & in the paper & measured $m$ & test & repro\\-duced?\\\\\n"
          "\\midrule\\endhead\n\\bottomrule\\endlastfoot\n", fp);
    for (int i = 0; i < nrows; i++) {
        const ledger_row *r = &rows[i];
        if (done[i] || strcmp(r->verdict, "extension") == 0 || strcmp(r->verdict, "by construction") == 0)
            continue;
        group_key(r->id, key, sizeof key);
        int n = 0;
        double worst = 0.0, tmin = INFINITY, tmax = -INFINITY;
        for (int j = i; j < nrows; j++)
            if (!done[j] && (j == i || same_group(r, &rows[j], key))) {
                done[j] = 1;
                n++;
                worst = fmax(worst, fabs(rows[j].measured - rows[j].expected));
                tmin = fmin(tmin, rows[j].tol);
                tmax = fmax(tmax, rows[j].tol);
            }
        if (n > 1) {
            char star[80];
            snprintf(star, sizeof star, "%s-*", key);
            tex_id(fp, star);
            fprintf(fp, "~$\\times%d$", n); /* the count stays beside the id */
        } else
            tex_id(fp, r->id);
        fputs(" & ", fp);
        tex_ref(fp, r->ref);
        fputs(" & ", fp);
        if (n == 1) {
            tex_measured(r, num, sizeof num);
            fprintf(fp, "$%s$ & ", num);
            tex_test(fp, r);
        } else {
            tex_number(worst, num, sizeof num);
            fprintf(fp, "$\\max|m-e|=%s$ & ", num);
            tex_number(tmin, lo, sizeof lo);
            tex_number(tmax, hi, sizeof hi);
            if (tmin == tmax)
                fprintf(fp, "$|m-e|\\le %s$", lo);
            else
                fprintf(fp, "$|m-e|\\le t\\in[%s,%s]$", lo, hi);
        }
        const char *verdict = strcmp(r->verdict, "reproduced") == 0 ? "yes"
                              : strcmp(r->verdict, "erratum") == 0 ? "erratum" : "\\textbf{no}";
        fprintf(fp, " & %s%s\\\\\n", verdict,
                r->pass ? "" : " \\textbf{(check FAILS)}");
    }
    fputs("\\end{longtable}\n", fp);
}

static int write_tex(const char *dir)
{
    char path[4200], err[256], name[96], num[96];
    sus_sys_atomic_file af;
    int failed = 0, reproduced = 0, not_reproduced = 0, extension = 0, erratum = 0, bycons = 0;
    for (int i = 0; i < nrows; i++) {
        failed += !rows[i].pass;
        reproduced += strcmp(rows[i].verdict, "reproduced") == 0;
        not_reproduced += strcmp(rows[i].verdict, "not reproduced") == 0;
        extension += strcmp(rows[i].verdict, "extension") == 0;
        erratum += strcmp(rows[i].verdict, "erratum") == 0;
        bycons += strcmp(rows[i].verdict, "by construction") == 0;
    }
    snprintf(path, sizeof path, "%s/numbers.tex", dir);
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0)
        return -1;
    fputs("% Generated by the claims ledger (tests/ledger/claims.c): do not edit.\n", af.fp);
    for (int i = 0; i < nrows; i++) {
        macro_name(rows[i].id, name, sizeof name);
        tex_measured(&rows[i], num, sizeof num);
        fprintf(af.fp, "\\newcommand{\\%s}{%s}\n", name, num);
        tex_number(rows[i].expected, num, sizeof num);
        fprintf(af.fp, "\\newcommand{\\%sExpected}{%s}\n", name, num);
        tex_number(rows[i].tol, num, sizeof num);
        fprintf(af.fp, "\\newcommand{\\%sTol}{%s}\n", name, num);
        fprintf(af.fp, "\\newcommand{\\%sVerdict}{%s}\n", name, rows[i].verdict);
        fprintf(af.fp, "\\newcommand{\\%sTest}{", name);
        tex_test(af.fp, &rows[i]);
        fputs("}\n", af.fp);
    }
    for (int i = 0; i < nextras; i++) {
        tex_number(extras[i].value, num, sizeof num);
        fprintf(af.fp, "\\newcommand{\\%s}{%s}\n", extras[i].name, num);
    }
    /* The counts the text quotes: lines, checks, verdicts. */
    fprintf(af.fp,
            "\\newcommand{\\LedgerLines}{%d}\n\\newcommand{\\LedgerFailed}{%d}\n"
            "\\newcommand{\\LedgerPassed}{%d}\n"
            "\\newcommand{\\LedgerReproduced}{%d}\n\\newcommand{\\LedgerNotReproduced}{%d}\n"
            "\\newcommand{\\LedgerExtension}{%d}\n\\newcommand{\\LedgerPaperLines}{%d}\n"
            "\\newcommand{\\LedgerErratum}{%d}\n\\newcommand{\\LedgerByConstruction}{%d}\n",
            nrows, failed, nrows - failed, reproduced, not_reproduced, extension,
            reproduced + not_reproduced + erratum, erratum, bycons);
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0)
        return -1;

    snprintf(path, sizeof path, "%s/ledger.tex", dir);
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0)
        return -1;
    fputs("% Generated by the claims ledger (tests/ledger/claims.c): do not edit.\n", af.fp);
    fputs(tex_header, af.fp);
    for (int i = 0; i < nrows; i++)
        tex_line(af.fp, &rows[i]);
    fputs("\\end{longtable}\n", af.fp);
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0)
        return -1;

    /* The summary: every line that tests a claim of the paper (no extensions), one row each. */
    snprintf(path, sizeof path, "%s/summary.tex", dir);
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0)
        return -1;
    fputs("% Generated by the claims ledger (tests/ledger/claims.c): do not edit.\n", af.fp);
    write_summary(af.fp);
    return sus_sys_atomic_file_commit(&af, err, sizeof err);
}

/* claims_tex.tsv: each line's quantity and test in the LaTeX the companion prints (text, math in
 * $...$), one line each, for the web edition, which typesets them with KaTeX. */
static int write_tex_tsv(const char *dir)
{
    char path[4200], err[256];
    sus_sys_atomic_file af;
    snprintf(path, sizeof path, "%s/claims_tex.tsv", dir);
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0)
        return -1;
    fputs("id\tquantity\ttest\n", af.fp);
    for (int i = 0; i < nrows; i++) {
        fprintf(af.fp, "%s\t", rows[i].id);
        tex_ascii(af.fp, rows[i].quantity);
        fputc('\t', af.fp);
        tex_test(af.fp, &rows[i]);
        fputc('\n', af.fp);
    }
    return sus_sys_atomic_file_commit(&af, err, sizeof err);
}

/* Where a line was recorded: "tests/FILE.c:LINE". */
typedef struct {
    const char *file;
    int line;
} ledger_source;

static void add_row(ledger_source src, const char *id, const char *paper_ref, const char *quantity,
                    double measured, double expected, double tol, row_kind kind, int holds,
                    ledger_assert truth, int inf_ok)
{
    if (nrows == LEDGER_MAX) {
        fprintf(stderr, "ledger: more than %d lines\n", LEDGER_MAX);
        return;
    }
    /* the companion prints every description whole: a cut one is a bug of the caller */
    if (strlen(quantity) >= sizeof rows[0].quantity || strlen(id) >= sizeof rows[0].id)
        ledger_die("fitting a ledger line's id and description into their buffers");
    ledger_row *r = &rows[nrows++];
    snprintf(r->id, sizeof r->id, "%s", id);
    snprintf(r->ref, sizeof r->ref, "%s", paper_ref);
    snprintf(r->quantity, sizeof r->quantity, "%s", quantity);
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
        strcpy(r->verdict, holds ? "reproduced" : truth == LEDGER_ERRATUM ? "erratum" : "not reproduced");
        r->pass = usable && holds == (truth == LEDGER_REPRODUCED);
    }
}

void ledger_die(const char *what)
{
    fprintf(stderr, "claims: %s failed\n", what);
    exit(2);
}

void ledger_add_at(const char *file, int line, const char *id, const char *paper_ref, const char *quantity,
                   double measured, double expected, double tol, ledger_assert truth)
{
    add_row((ledger_source){file, line}, id, paper_ref, quantity, measured, expected, tol, ROW_WITHIN,
            fabs(measured - expected) <= tol, truth, 0);
}

static void add_bound(ledger_source src, const char *id, const char *paper_ref, const char *quantity,
                      double measured, double bound, int at_least, ledger_assert truth, int inf_ok)
{
    add_row(src, id, paper_ref, quantity, measured, bound, 0.0, at_least ? ROW_AT_LEAST : ROW_AT_MOST,
            at_least ? measured >= bound : measured <= bound, truth, inf_ok);
}

void ledger_add_bound_at(const char *file, int line, const char *id, const char *paper_ref,
                         const char *quantity, double measured, double bound, int at_least,
                         ledger_assert truth)
{
    add_bound((ledger_source){file, line}, id, paper_ref, quantity, measured, bound, at_least, truth, 0);
}

void ledger_add_bound_unbounded_at(const char *file, int line, const char *id, const char *paper_ref,
                                   const char *quantity, double measured, double bound, int at_least,
                                   ledger_assert truth)
{
    add_bound((ledger_source){file, line}, id, paper_ref, quantity, measured, bound, at_least, truth, 1);
}

/* The test column: the check in words, "<= b", ">= b" or "|x - e| <= tol" with the numbers. */
static void test_text(const ledger_row *r, char *out, size_t len)
{
    if (r->kind == ROW_AT_LEAST)
        snprintf(out, len, ">= %.6g", r->expected);
    else if (r->kind == ROW_AT_MOST)
        snprintf(out, len, "<= %.6g", r->expected);
    else if (r->expected == 0.0)
        snprintf(out, len, "|x| <= %.3g", r->tol);
    else /* |x + 1|, not |x - -1| */
        snprintf(out, len, "|x %c %.6g| <= %.3g", r->expected < 0.0 ? '+' : '-', fabs(r->expected), r->tol);
}

/* The measured column: the number, or what an unbounded limit's search found. */
static void measured_text(const ledger_row *r, char *out, size_t len)
{
    if (r->none_found)
        snprintf(out, len, "none found for h <= %.6g", r->expected);
    else
        snprintf(out, len, "%.6g", r->measured);
}

int ledger_finish(const char *tsv_path)
{
    char err[256];
    sus_sys_atomic_file af;
    int failed = 0;
    if (sus_sys_atomic_file_open(&af, tsv_path, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    char test[96], meas[64];
    fputs("id\tpaper_ref\tquantity\tmeasured\texpected\ttolerance\tverdict\ttest\tsource\n", af.fp);
    for (int i = 0; i < nrows; i++) {
        test_text(&rows[i], test, sizeof test);
        const ledger_row *r = &rows[i];
        measured_text(r, meas, sizeof meas);
        fprintf(af.fp, "%s\t%s\t%s\t%s\t%.6g\t%.3g\t%s\t%s\t%s\n", r->id, r->ref, r->quantity, meas,
                r->expected, r->tol, r->verdict, test, r->source);
    }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "ledger: %s\n", err);
        return -1;
    }
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", tsv_path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    else
        strcpy(dir, ".");
    if (write_tex(dir) != 0 || write_tex_tsv(dir) != 0) {
        fprintf(stderr, "ledger: writing the LaTeX files next to %s failed\n", tsv_path);
        return -1;
    }
    printf("\n%-4s  %-44s %-14s %-26s %-14s  %s\n", "", "claim", "measured", "test", "verdict", "paper");
    for (int i = 0; i < nrows; i++) {
        const ledger_row *r = &rows[i];
        failed += !r->pass;
        test_text(r, test, sizeof test);
        measured_text(r, meas, sizeof meas);
        printf("%-4s  %-44s %-14s %-26s %-14s  %s\n", r->pass ? "PASS" : "FAIL", r->id, meas, test,
               r->verdict, r->ref);
        printf("      %s  [%s]\n", r->quantity, r->source);
    }
    printf("\nledger written to %s\nclaims: %d passed, %d failed\n", tsv_path, nrows - failed, failed);
    return failed;
}
