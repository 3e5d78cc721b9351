#define _POSIX_C_SOURCE 200809L
#include "cli_options.h"

#include "echo.h"
#include "paper_ref.h"

#include <errno.h>
#include <float.h>
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_BAD_INPUT = 2 };
static const char *prog = "suslov";

/* ---- messages ---- */

/* The message (which quotes user text: arguments, paths) on exactly one line of UTF-8: every
 * control character is escaped as \n, \t, \r or \xNN, and so is every byte that is not part of a
 * well-formed UTF-8 character. */
static void say(const char *kind, const char *fmt, va_list ap, const char *suffix)
{
    char msg[2048];
    vsnprintf(msg, sizeof msg, fmt, ap);
    fprintf(stderr, "%s: %s: ", prog, kind);
    const size_t n = strlen(msg);
    for (size_t i = 0, len; i < n; i += len ? len : 1) {
        const unsigned char c = (unsigned char)msg[i];
        len = sus_sys_utf8_len(msg + i, n - i);
        if (c == '\n')
            fputs("\\n", stderr);
        else if (c == '\t')
            fputs("\\t", stderr);
        else if (c == '\r')
            fputs("\\r", stderr);
        else if (!len || c < 0x20 || c == 0x7f)
            fprintf(stderr, "\\x%02x", c);
        else
            fwrite(msg + i, 1, len, stderr);
    }
    fprintf(stderr, "%s\n", suffix);
}

const char *suslov_cli_quote_n(const char *s, size_t n)
{
    return sus_sys_echo_ring(s, n, SUSLOV_CLI_ECHO_MAX, '\'');
}

const char *suslov_cli_quote(const char *s) { return suslov_cli_quote_n(s, strlen(s)); }

void suslov_cli_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say("error", fmt, ap, "");
    va_end(ap);
}

void suslov_cli_warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say("warning", fmt, ap, "");
    va_end(ap);
}

void suslov_cli_note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    say("note", fmt, ap, "");
    va_end(ap);
}

void suslov_cli_die(const char *fmt, ...)
{
    char suffix[64];
    snprintf(suffix, sizeof suffix, " (see %s --help)", prog);
    va_list ap;
    va_start(ap, fmt);
    say("error", fmt, ap, suffix);
    va_end(ap);
    exit(EXIT_BAD_INPUT);
}

void suslov_cli_exit_stdout(void)
{
    const int failed = (fflush(stdout) != 0) | ferror(stdout); /* both, whichever fails */
    if (failed) {
        suslov_cli_error("writing stdout failed: %s", strerror(errno));
        exit(1);
    }
    exit(0);
}

/* ---- numbers ---- */

/* A subnormal is accepted by strtod with ERANGE but has lost precision, and no quantity here
 * is meaningful at that size. */
double suslov_cli_number(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end != '\0' || isspace((unsigned char)*s))
        suslov_cli_die("%s: %s is not a number", opt, suslov_cli_quote(s));
    if (!isfinite(v))
        suslov_cli_die("%s: %s is not a finite number (largest %.17g)", opt, suslov_cli_quote(s),
                       DBL_MAX);
    if (errno == ERANGE || fpclassify(v) == FP_SUBNORMAL)
        suslov_cli_die("%s: %s is too small: it underflows to a subnormal number or zero "
                       "(smallest normal %.17g)",
                       opt, suslov_cli_quote(s), DBL_MIN);
    return v;
}

void suslov_cli_list(const char *opt, const char *s, double *out, int n)
{
    char buf[1024];
    if (strlen(s) >= sizeof buf)
        suslov_cli_die("%s: the list is %zu characters long, more than the %zu it may have", opt,
                       strlen(s), sizeof buf - 1);
    int i = 0;
    for (const char *p = s;; i++) {
        const char *comma = strchr(p, ',');
        const size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (i == n)
            suslov_cli_die("%s takes %d comma-separated numbers, got more in %s", opt, n,
                           suslov_cli_quote(s));
        if (len == 0)
            suslov_cli_die("%s: field %d of %s is empty", opt, i + 1, suslov_cli_quote(s));
        memcpy(buf, p, len);
        buf[len] = '\0';
        out[i] = suslov_cli_number(opt, buf);
        if (!comma)
            break;
        p = comma + 1;
    }
    if (i + 1 != n)
        suslov_cli_die("%s takes %d comma-separated numbers, got %d in %s", opt, n, i + 1,
                       suslov_cli_quote(s));
}

/* ---- parsing ---- */

/* The option whose name is the first len characters of s. */
static int find(const suslov_cli_spec *spec, const char *s, size_t len)
{
    for (int i = 0; i < spec->nopts; i++)
        if (strlen(spec->opts[i].name) == len && strncmp(spec->opts[i].name, s, len) == 0)
            return i;
    return -1;
}

void suslov_cli_parse(const suslov_cli_spec *spec, int argc, char **argv, void *cfg)
{
    char seen[64] = {0};
    prog = spec->prog;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i], *eq = strchr(arg, '='), *val = NULL;
        if (strcmp(arg, "--") == 0) {
            if (i + 1 < argc)
                suslov_cli_die("unexpected argument %s (%s takes no operands)",
                               suslov_cli_quote(argv[i + 1]), prog);
            break;
        }
        if (strncmp(arg, "--", 2) != 0)
            suslov_cli_die("unexpected argument %s", suslov_cli_quote(arg));
        const size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
        const int k = find(spec, arg, len);
        if (k < 0)
            suslov_cli_die("unknown option %s", suslov_cli_quote_n(arg, len));
        const suslov_cli_option *o = &spec->opts[k];
        if (!o->arg && eq)
            suslov_cli_die("%s takes no value", o->name);
        if (o->arg && !eq && i + 1 >= argc)
            suslov_cli_die("%s needs a value (%s)", o->name, o->arg);
        if (o->arg)
            val = eq ? eq + 1 : argv[++i];
        if (k < (int)sizeof seen && seen[k]++)
            suslov_cli_die("%s is given twice", o->name);
        o->set(cfg, o, val);
    }
}

int suslov_cli_peek(const suslov_cli_spec *spec, int argc, char **argv, const char *name,
                    const char **val)
{
    int count = 0;
    *val = NULL;
    for (int i = 1; i < argc; i++, count++) {
        const char *arg = argv[i], *eq = strchr(arg, '=');
        if (strcmp(arg, "--") == 0)
            return count + (i + 1 < argc);
        const size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
        const int k = strncmp(arg, "--", 2) == 0 ? find(spec, arg, len) : -1;
        if (k < 0 || !spec->opts[k].arg)
            continue;
        const char *v = eq ? eq + 1 : i + 1 < argc ? argv[++i] : NULL;
        if (strcmp(spec->opts[k].name, name) == 0)
            *val = v;
    }
    return count;
}

/* ---- --help ---- */

/* The texts cite the paper by its LaTeX labels, as the code does; a reader gets the published
 * numbers ("(ContDyn)" -> "eq. (27)", paper_ref.h). One text at a time: the buffer is reused. */
static const char *numbered(const char *text)
{
    static char buf[8192];
    return sus_paper_numbered(text, buf, sizeof buf);
}

/* Lines of text, the first after `first`, the others after `indent`; an empty line stays empty. */
static void help_lines(FILE *fp, const char *text, const char *first, const char *indent)
{
    const char *p = numbered(text);
    for (int n = 0; *p || n == 0; n++) {
        const char *nl = strchr(p, '\n');
        const int len = nl ? (int)(nl - p) : (int)strlen(p);
        fprintf(fp, "%s%.*s\n", len == 0 ? "" : n ? indent : first, len, p);
        p = nl ? nl + 1 : p + len;
    }
}

static void roff_text(FILE *fp, const char *s, int len);

void suslov_cli_line(FILE *fp, int man, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    const char *text = numbered(buf);
    if (!man) {
        fprintf(fp, "%22s%s\n", "", text);
        return;
    }
    roff_text(fp, text, (int)strlen(text));
    fputc('\n', fp);
}

void suslov_cli_help(const suslov_cli_spec *spec, FILE *fp)
{
    fprintf(fp, "usage: %s\n\n", spec->synopsis);
    fprintf(fp, "%s\n\n", numbered(spec->description));
    for (int i = 0; i < spec->nopts; i++) {
        const suslov_cli_option *o = &spec->opts[i];
        char head[64];
        snprintf(head, sizeof head, "  %s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
        fprintf(fp, "%-22s", head);
        if (strlen(head) >= 22)
            fprintf(fp, "\n%22s", "");
        help_lines(fp, o->help, "", "                      ");
        if (o->more)
            o->more(fp, 0);
    }
    for (int i = 0; i < spec->nsections; i++) {
        fprintf(fp, "\n%s\n", spec->sections[i].title);
        help_lines(fp, spec->sections[i].body, "  ", "  ");
    }
}

/* ---- the manual page ---- */

/* Text for roff: '-' as \-, '\' as \e, and a line that would start with '.' or '\'' guarded. */
static void roff_text(FILE *fp, const char *s, int len)
{
    for (int i = 0; i < len; i++) {
        if (i == 0 && (s[i] == '.' || s[i] == '\''))
            fputs("\\&", fp);
        if (s[i] == '-')
            fputs("\\-", fp);
        else if (s[i] == '\\')
            fputs("\\e", fp);
        else
            fputc(s[i], fp);
    }
}

/* The indentation of a line of section text: 4 (a description), 2 (kept as it is) or 0. */
static int indent_of(const char *line)
{
    return strncmp(line, "    ", 4) == 0 ? 4 : strncmp(line, "  ", 2) == 0 ? 2 : 0;
}

/* Section text in roff (suslov_cli_section): prose filled, an empty line a new paragraph (.PP),
 * lines indented by two kept as they are (.nf, indented), and a line followed by lines indented by
 * four a tag (.TP) and its description, filled under it. */
static void roff_body(FILE *fp, const char *text)
{
    enum { PROSE, KEPT, LIST } mode = PROSE;
    for (const char *p = numbered(text); *p;) {
        const char *nl = strchr(p, '\n');
        const int len = nl ? (int)(nl - p) : (int)strlen(p), ind = len ? indent_of(p) : 0;
        const char *next = nl ? nl + 1 : p + len;
        if (mode == KEPT && (ind != 2 || len == 0)) {
            fputs(".fi\n.RE\n", fp);
            mode = PROSE;
        }
        if (len == 0) {
            fputs(".PP\n", fp);
            mode = PROSE;
        } else if (ind == 2) {
            fputs(mode == KEPT ? "" : mode == LIST ? ".PP\n.RS 4\n.nf\n" : ".RS 4\n.nf\n", fp);
            mode = KEPT;
        } else if (ind == 0 && *next && indent_of(next) == 4) {
            fputs(".TP\n.B ", fp);
            mode = LIST;
        } else if (ind == 0 && mode == LIST) {
            fputs(".PP\n", fp);
            mode = PROSE;
        }
        if (len) {
            roff_text(fp, p + ind, len - ind);
            fputc('\n', fp);
        }
        p = next;
    }
    if (mode == KEPT)
        fputs(".fi\n.RE\n", fp);
}

void suslov_cli_man(const suslov_cli_spec *spec, const char *version, FILE *fp)
{
    fprintf(fp, ".TH SUSLOV 1 \"\" \"%s %s\" \"User Commands\"\n.SH NAME\n%s \\- ", spec->prog,
            version, spec->prog);
    roff_body(fp, spec->summary);
    fputs(".SH SYNOPSIS\n", fp);
    roff_body(fp, spec->synopsis);
    fputs(".SH DESCRIPTION\n", fp);
    roff_body(fp, spec->description);
    fputs(".SH OPTIONS\n", fp);
    for (int i = 0; i < spec->nopts; i++) {
        const suslov_cli_option *o = &spec->opts[i];
        fputs(o->arg ? ".TP\n.BI \"" : ".TP\n.B ", fp); /* the name bold, its argument italic */
        roff_text(fp, o->name, (int)strlen(o->name));
        if (o->arg) {
            fputs(" \" ", fp);
            roff_text(fp, o->arg, (int)strlen(o->arg));
        }
        fputc('\n', fp);
        roff_body(fp, o->help);
        if (o->more) { /* a list: one entry a line, unfilled */
            fputs(".nf\n", fp);
            o->more(fp, 1);
            fputs(".fi\n", fp);
        }
    }
    for (int i = 0; i < spec->nsections; i++) {
        fprintf(fp, ".SH %s\n", spec->sections[i].title);
        roff_body(fp, spec->sections[i].body);
    }
}
