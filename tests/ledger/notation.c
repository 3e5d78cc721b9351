#include "notation.h"

#include "paper_ref.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the table: every macro the notation knows, and its plain text ------------------------ */

enum { IN_MATH = 1, IN_TEXT = 2, ANYWHERE = 3 };

typedef enum {
    M_SYMBOL, /* a symbol: its plain text */
    M_FONT,   /* \mathrm{x}: its argument, in math */
    M_TEXT,   /* \text{x}, \emph{x}: its argument, in text */
    M_ACCENT, /* \hat{x}: the argument, then a combining accent */
    M_SQRT,   /* \sqrt{x}: √x or √(x) */
    M_FRAC,   /* \frac{a}{b}: a/b, each in parentheses unless one token */
    M_EQREF,  /* \eqref{LABEL}: (27) */
    M_REF,    /* \PaperRefOr{LABEL}: Proposition 5.1 */
    M_DELIM   /* \left( and \right): the delimiter that follows */
} macro_kind;

typedef struct {
    const char *name;
    macro_kind kind;
    int where;
    const char *plain;
} macro;

static const macro MACROS[] = {
    /* Greek */
    {"alpha", M_SYMBOL, IN_MATH, "α"},
    {"beta", M_SYMBOL, IN_MATH, "β"},
    {"gamma", M_SYMBOL, IN_MATH, "γ"},
    {"delta", M_SYMBOL, IN_MATH, "δ"},
    {"epsilon", M_SYMBOL, IN_MATH, "ϵ"},
    {"varepsilon", M_SYMBOL, IN_MATH, "ε"},
    {"zeta", M_SYMBOL, IN_MATH, "ζ"},
    {"eta", M_SYMBOL, IN_MATH, "η"},
    {"theta", M_SYMBOL, IN_MATH, "θ"},
    {"kappa", M_SYMBOL, IN_MATH, "κ"},
    {"lambda", M_SYMBOL, IN_MATH, "λ"},
    {"mu", M_SYMBOL, IN_MATH, "μ"},
    {"nu", M_SYMBOL, IN_MATH, "ν"},
    {"xi", M_SYMBOL, IN_MATH, "ξ"},
    {"pi", M_SYMBOL, IN_MATH, "π"},
    {"rho", M_SYMBOL, IN_MATH, "ρ"},
    {"sigma", M_SYMBOL, IN_MATH, "σ"},
    {"tau", M_SYMBOL, IN_MATH, "τ"},
    {"phi", M_SYMBOL, IN_MATH, "ϕ"},
    {"varphi", M_SYMBOL, IN_MATH, "φ"},
    {"chi", M_SYMBOL, IN_MATH, "χ"},
    {"psi", M_SYMBOL, IN_MATH, "ψ"},
    {"omega", M_SYMBOL, IN_MATH, "ω"},
    {"Gamma", M_SYMBOL, IN_MATH, "Γ"},
    {"Delta", M_SYMBOL, IN_MATH, "Δ"},
    {"Theta", M_SYMBOL, IN_MATH, "Θ"},
    {"Lambda", M_SYMBOL, IN_MATH, "Λ"},
    {"Sigma", M_SYMBOL, IN_MATH, "Σ"},
    {"Phi", M_SYMBOL, IN_MATH, "Φ"},
    {"Psi", M_SYMBOL, IN_MATH, "Ψ"},
    {"Omega", M_SYMBOL, IN_MATH, "Ω"},
    /* relations, operators, arrows */
    {"le", M_SYMBOL, IN_MATH, "≤"},
    {"ge", M_SYMBOL, IN_MATH, "≥"},
    {"ll", M_SYMBOL, IN_MATH, "≪"},
    {"gg", M_SYMBOL, IN_MATH, "≫"},
    {"ne", M_SYMBOL, IN_MATH, "≠"},
    {"approx", M_SYMBOL, IN_MATH, "≈"},
    {"sim", M_SYMBOL, IN_MATH, "~"},
    {"equiv", M_SYMBOL, IN_MATH, "≡"},
    {"propto", M_SYMBOL, IN_MATH, "∝"},
    {"in", M_SYMBOL, IN_MATH, "∈"},
    {"to", M_SYMBOL, IN_MATH, "→"},
    {"mapsto", M_SYMBOL, IN_MATH, "↦"},
    {"times", M_SYMBOL, IN_MATH, "×"},
    {"cdot", M_SYMBOL, IN_MATH, "·"},
    {"circ", M_SYMBOL, IN_MATH, "∘"},
    {"otimes", M_SYMBOL, IN_MATH, "⊗"},
    {"pm", M_SYMBOL, IN_MATH, "±"},
    {"mid", M_SYMBOL, IN_MATH, "|"},
    {"infty", M_SYMBOL, IN_MATH, "∞"},
    {"partial", M_SYMBOL, IN_MATH, "∂"},
    {"nabla", M_SYMBOL, IN_MATH, "∇"},
    {"sum", M_SYMBOL, IN_MATH, "Σ"},
    {"prod", M_SYMBOL, IN_MATH, "Π"},
    {"int", M_SYMBOL, IN_MATH, "∫"},
    {"langle", M_SYMBOL, IN_MATH, "⟨"},
    {"rangle", M_SYMBOL, IN_MATH, "⟩"},
    {"top", M_SYMBOL, IN_MATH, "T"},
    {"vee", M_SYMBOL, IN_MATH, "∨"},
    {"wedge", M_SYMBOL, IN_MATH, "∧"},
    {"prime", M_SYMBOL, IN_MATH, "'"},
    {"dots", M_SYMBOL, ANYWHERE, "…"},
    {"ldots", M_SYMBOL, ANYWHERE, "…"},
    {"cdots", M_SYMBOL, IN_MATH, "…"},
    {"quad", M_SYMBOL, IN_MATH, "  "},
    /* operators set upright */
    {"max", M_SYMBOL, IN_MATH, "max"},
    {"min", M_SYMBOL, IN_MATH, "min"},
    {"lim", M_SYMBOL, IN_MATH, "lim"},
    {"sup", M_SYMBOL, IN_MATH, "sup"},
    {"det", M_SYMBOL, IN_MATH, "det"},
    {"exp", M_SYMBOL, IN_MATH, "exp"},
    {"log", M_SYMBOL, IN_MATH, "log"},
    {"ln", M_SYMBOL, IN_MATH, "ln"},
    {"sin", M_SYMBOL, IN_MATH, "sin"},
    {"cos", M_SYMBOL, IN_MATH, "cos"},
    {"tanh", M_SYMBOL, IN_MATH, "tanh"},
    {"cosh", M_SYMBOL, IN_MATH, "cosh"},
    {"sinh", M_SYMBOL, IN_MATH, "sinh"},
    {"arg", M_SYMBOL, IN_MATH, "arg"},
    {"cot", M_SYMBOL, IN_MATH, "cot"},
    /* fonts and text */
    {"mathrm", M_FONT, IN_MATH, NULL},
    {"mathit", M_FONT, IN_MATH, NULL},
    {"mathbf", M_FONT, IN_MATH, NULL},
    {"mathcal", M_FONT, IN_MATH, NULL},
    {"mathbb", M_FONT, IN_MATH, NULL},
    {"text", M_TEXT, IN_MATH, NULL},
    {"emph", M_TEXT, IN_TEXT, NULL},
    {"textit", M_TEXT, IN_TEXT, NULL},
    {"textbf", M_TEXT, IN_TEXT, NULL},
    {"texttt", M_TEXT, IN_TEXT, NULL},
    /* accents: the combining character after the argument */
    {"hat", M_ACCENT, IN_MATH, "\xcc\x82"},
    {"widehat", M_ACCENT, IN_MATH, "\xcc\x82"},
    {"tilde", M_ACCENT, IN_MATH, "\xcc\x83"},
    {"bar", M_ACCENT, IN_MATH, "\xcc\x84"},
    {"dot", M_ACCENT, IN_MATH, "\xcc\x87"},
    {"sqrt", M_SQRT, IN_MATH, "√"},
    {"frac", M_FRAC, IN_MATH, NULL},
    {"left", M_DELIM, IN_MATH, NULL},
    {"right", M_DELIM, IN_MATH, NULL},
    /* the paper's numbering */
    {"eqref", M_EQREF, IN_TEXT, NULL},
    {"PaperRefOr", M_REF, IN_TEXT, NULL},
};
#define NMACROS ((int)(sizeof MACROS / sizeof MACROS[0]))

/* Control symbols: a backslash and one non-letter. */
static const char *control_symbol(char c, int math)
{
    switch (c) {
        case ',':
        case ';':
        case ':':
        case ' ': return " ";
        case '!': return "";
        case '%': return "%";
        case '&': return "&";
        case '#': return "#";
        case '_': return "_";
        case '{': return "{";
        case '}': return "}";
        case '|': return math ? "‖" : NULL;
        default: return NULL;
    }
}

/* ---- the renderer ---------------------------------------------------------------------------- */

typedef struct {
    const char *s; /* the whole string, for messages */
    const char *p; /* the position */
    char *out;
    size_t len, n;
    notation_refs refs; /* how references read */
    int failed;
    char *err;
    size_t errlen;
} renderer;

static void fail(renderer *r, const char *fmt, ...)
{
    if (r->failed++)
        return;
    char msg[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(r->err, r->errlen, "%s at byte %d of \"%s\"", msg, (int)(r->p - r->s), r->s);
}

static void emit(renderer *r, const char *t, size_t n)
{
    if (r->n + n >= r->len) {
        fail(r, "plain text longer than %d bytes", (int)r->len - 1);
        return;
    }
    memcpy(r->out + r->n, t, n);
    r->n += n;
    r->out[r->n] = '\0';
}

static void emits(renderer *r, const char *t) { emit(r, t, strlen(t)); }

static int is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

static void render(renderer *r, int math, char close);

/* A {group} at the position, rendered (math or text) into the output. */
static void group(renderer *r, int math)
{
    if (*r->p != '{') {
        fail(r, "'{' expected");
        return;
    }
    r->p++;
    render(r, math, '}');
    if (*r->p == '}')
        r->p++;
    else
        fail(r, "unclosed '{'");
}

/* A {LABEL} argument: its bytes, not rendered. */
static const char *label_arg(renderer *r, size_t *n)
{
    const char *start = r->p + 1, *end = start;
    if (*r->p != '{')
        return fail(r, "'{LABEL}' expected"), NULL;
    while (*end && *end != '}')
        end++;
    if (*end != '}' || end == start)
        return fail(r, "'{LABEL}' expected"), NULL;
    r->p = end + 1;
    *n = (size_t)(end - start);
    return start;
}

/* The published name of the first n bytes of a label: "(27)" for an equation (with "eq. " in
 * front when not bare), "Proposition 5.1", "Section 5.6", "Figure 2" otherwise; NULL when the
 * paper has no such label (paper/labels.tsv, compiled into src/render/paper_labels.c). */
static const char *published(const char *label, size_t n, int bare, char *buf, size_t len)
{
    char name[64];
    const sus_paper_label *p = sus_paper_label_find(label, n);
    if (!p || n >= sizeof name)
        return NULL;
    if (strcmp(p->kind, "equation") == 0 || strcmp(p->kind, "subequation") == 0) {
        snprintf(buf, len, "%s(%s)", bare ? "" : "eq. ", p->number);
        return buf;
    }
    snprintf(name, sizeof name, "%.*s", (int)n, label);
    return sus_paper_name(name, buf, len);
}

/* The published name of a reference, and with ids its label: "Proposition 5.1 (TeoL)"; an
 * unlabelled statement's stand-in (nolabel:KIND-N) is never shown. */
static void reference(renderer *r, int equation)
{
    char name[64];
    size_t n;
    const char *label = label_arg(r, &n);
    if (!label)
        return;
    if (!published(label, n, equation && r->refs == PLAIN_QUANTITY, name, sizeof name)) {
        fail(r, "no label '%.*s' in paper/labels.tsv", (int)n, label);
        return;
    }
    emits(r, name);
    if (r->refs == PLAIN_REF_IDS && strncmp(label, "nolabel:", 8) != 0) {
        emits(r, " (");
        emit(r, label, n);
        emits(r, ")");
    }
}

/* Whether rendered text is one token that needs no parentheses as a script or a root: a word, a
 * number, or a symbol; a leading minus sign allowed. */
static int one_token(const char *t)
{
    if (*t == '-')
        t++;
    if (!*t)
        return 0;
    for (; *t; t++)
        if (strchr(" +-*/=,;:()[]<>|", *t))
            return 0;
    return 1;
}

/* Renders one {group} and emits it after `before`, in parentheses unless it is one token. */
static void operand(renderer *r, const char *before)
{
    const size_t at = r->n;
    char tmp[1024];
    group(r, 1);
    if (r->failed)
        return;
    snprintf(tmp, sizeof tmp, "%s", r->out + at);
    const int paren = !one_token(tmp);
    r->n = at;
    r->out[at] = '\0';
    emits(r, before ? before : "");
    emits(r, paren ? "(" : "");
    emits(r, tmp);
    emits(r, paren ? ")" : "");
}

static void macro_call(renderer *r, const macro *m, int math)
{
    switch (m->kind) {
        case M_SYMBOL: emits(r, m->plain); break;
        case M_FONT: group(r, 1); break;
        case M_TEXT: group(r, 0); break;
        case M_ACCENT: operand(r, NULL), emits(r, m->plain); break;
        case M_SQRT: operand(r, m->plain); break;
        case M_FRAC: operand(r, NULL), emits(r, "/"), operand(r, NULL); break;
        case M_EQREF: reference(r, 1); break;
        case M_REF: reference(r, 0); break;
        case M_DELIM:
            if (*r->p && strchr("()[]|.", *r->p))
                emit(r, r->p, *r->p != '.'), r->p++;
            else
                fail(r, "a delimiter expected after \\left or \\right");
            break;
    }
    (void)math;
}

/* A backslash at the position: a control word of the table, or a control symbol. */
static void control(renderer *r, int math)
{
    const char *name = ++r->p;
    while (is_letter(*r->p))
        r->p++;
    const size_t n = (size_t)(r->p - name);
    if (n == 0) {
        const char *t = *r->p ? control_symbol(*r->p, math) : NULL;
        if (!t)
            return fail(r, "unknown control symbol '\\%c'", *r->p ? *r->p : '0');
        r->p++;
        emits(r, t);
        return;
    }
    for (int i = 0; i < NMACROS; i++)
        if (strlen(MACROS[i].name) == n && strncmp(MACROS[i].name, name, n) == 0) {
            if (!(MACROS[i].where & (math ? IN_MATH : IN_TEXT)))
                return fail(r, "\\%s is not allowed in %s", MACROS[i].name, math ? "math" : "text");
            if (*r->p == ' ' && MACROS[i].kind == M_SYMBOL && !math)
                r->p++; /* TeX eats the blank after a control word; text keeps one */
            macro_call(r, &MACROS[i], math);
            return;
        }
    fail(r, "unknown macro '\\%.*s'", (int)n, name);
}

/* A script ^x or _x: one character or macro as it is, a {group} in parentheses unless it is one
 * token. */
static void script(renderer *r)
{
    emit(r, r->p++, 1);
    if (*r->p == '{')
        operand(r, NULL);
    else if (*r->p == '\\')
        control(r, 1);
    else if (*r->p && *r->p != ' ' && *r->p != '$')
        emit(r, r->p++, 1);
    else
        fail(r, "a script without its argument");
}

/* Text-mode characters TeX reads as something else: quotes and dashes. */
static int text_ligature(renderer *r)
{
    static const char *const lig[][2] = {{"``", "\""}, {"''", "\""}, {"---", "—"}, {"--", "–"}};
    for (int i = 0; i < 4; i++) {
        const size_t n = strlen(lig[i][0]);
        if (strncmp(r->p, lig[i][0], n) == 0) {
            emits(r, lig[i][1]);
            r->p += n;
            return 1;
        }
    }
    return 0;
}

/* Renders until the closing character (a '}' of a group, '$' of math, or the end of the string
 * for close '\0'), which is left at the position. */
static void render(renderer *r, int math, char close)
{
    while (*r->p && *r->p != close && !r->failed) {
        const char c = *r->p;
        if (c == '}' && close != '}')
            return fail(r, "unbalanced '}'");
        if (c == '\\')
            control(r, math);
        else if (c == '{')
            group(r, math);
        else if (c == '$') {
            if (math)
                return fail(r, "'$' inside a group");
            r->p++;
            render(r, 1, '$');
            if (*r->p != '$')
                return fail(r, "unclosed '$'");
            r->p++;
        } else if (math && (c == '^' || c == '_'))
            script(r);
        else if (c == '~')
            emits(r, " "), r->p++;
        else if (!math && strchr("_^<>|", c))
            return fail(r, "'%c' outside $...$", c);
        else if (!math && text_ligature(r))
            ;
        else
            emit(r, r->p++, 1);
    }
}

int notation_plain(const char *s, notation_refs refs, char *out, size_t len, char *err,
                   size_t errlen)
{
    renderer r = {s, s, out, len, 0, refs, 0, err, errlen};
    out[0] = '\0';
    render(&r, 0, '\0');
    if (!r.failed && *r.p)
        fail(&r, "unbalanced '%c'", *r.p);
    return r.failed ? -1 : 0;
}

notation_num notation_g(double v, int digits)
{
    notation_num n;
    char e[32];
    snprintf(e, sizeof e, "%.*g", digits, v);
    char *x = strchr(e, 'e');
    if (!x || !isfinite(v)) {
        snprintf(n.s, sizeof n.s, "%s", e);
        return n;
    }
    *x = '\0';
    const int exponent = (int)strtol(x + 1, NULL, 10);
    if (strcmp(e, "1") == 0 || strcmp(e, "-1") == 0) /* 1e-14 -> 10^{-14} */
        snprintf(n.s, sizeof n.s, "%s10^{%d}", e[0] == '-' ? "-" : "", exponent);
    else
        snprintf(n.s, sizeof n.s, "%s\\times10^{%d}", e, exponent);
    return n;
}
