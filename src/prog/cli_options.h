/* One table of command-line options, from which come the parser, --help and the manual page
 * (so that the three cannot disagree), and the one grammar of numbers every option uses.
 * Adding an option is one table row and its handler. */
#ifndef SUSLOV_CLI_OPTIONS_H
#define SUSLOV_CLI_OPTIONS_H

#include <stdio.h>

typedef struct suslov_cli_option suslov_cli_option;
struct suslov_cli_option {
    const char *name; /* "--eps" */
    const char *arg;  /* "H", or NULL for a flag */
    const char *help; /* lines of at most 76 columns separated by '\n' */
    void (*set)(void *cfg, const suslov_cli_option *opt, const char *val);
    /* Optional: further lines written after the help (lists taken from a registry); each line
     * goes through suslov_cli_line so that it reaches --help and the manual page alike. */
    void (*more)(FILE *fp, int man);
};

/* A section's body: lines separated by '\n', printed as they are by --help. The manual page
 * fills prose lines; an empty line starts a new paragraph; a line indented by two spaces is kept
 * as it is (a command, a CSV header); a line followed by lines indented by four is a tag (a
 * column, a status, a variable) and those lines its description. */
typedef struct {
    const char *title; /* "EXIT STATUS" */
    const char *body;
} suslov_cli_section;

typedef struct {
    const char *prog, *summary, *synopsis, *description;
    const suslov_cli_option *opts;
    int nopts;
    const suslov_cli_section *sections;
    int nsections;
} suslov_cli_spec;

/* Parses argv: --name VALUE, --name=VALUE, "--" ends the options; an argument that is not an
 * option, an unknown option, a missing value, a value given to a flag and an option given
 * twice are each bad input (suslov_cli_die). Calls each option's handler in order. */
void suslov_cli_parse(const suslov_cli_spec *spec, int argc, char **argv, void *cfg);
/* Walks argv as suslov_cli_parse does, calling no handler: returns the number of options given (an
 * operand or an unknown option counts as one), and sets *val to the value of option `name` (NULL
 * when it is absent or has none), so that a caller can see one option before any handler runs. */
int suslov_cli_peek(const suslov_cli_spec *spec, int argc, char **argv, const char *name,
                    const char **val);
void suslov_cli_help(const suslov_cli_spec *spec, FILE *fp);
/* The manual page in roff (man(7)); version goes into its header line. */
void suslov_cli_man(const suslov_cli_spec *spec, const char *version, FILE *fp);
/* One line of a `more` list: indented under its option in --help, a line break in roff. */
void suslov_cli_line(FILE *fp, int man, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Exits 0 after a text on stdout, or 1 with one line when it could not be written. */
void suslov_cli_exit_stdout(void) __attribute__((noreturn));

/* A user's argument (its first n bytes) as a message quotes it: 'TEXT', or, beyond
 * SUSLOV_CLI_ECHO_MAX characters, 'FIRST...' (N characters), so that the reason after it always
 * fits the line. The text lives in echo.h's ring of buffers used in turn: one message may quote up
 * to SUS_SYS_ECHO_RING arguments. */
#define SUSLOV_CLI_ECHO_MAX 40
const char *suslov_cli_quote_n(const char *s, size_t n);
const char *suslov_cli_quote(const char *s);

/* "suslov: error: MESSAGE" on one line, control characters escaped; suslov_cli_die adds
 * " (see suslov --help)" and exits 2. */
void suslov_cli_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void suslov_cli_die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
void suslov_cli_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* "suslov: note: MESSAGE": what a person waiting should know (a long run ahead). */
void suslov_cli_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The number grammar: strtod's (decimal or hexadecimal, with exponent), no leading blank, no
 * trailing text; the value must be finite and normal or zero. */
double suslov_cli_number(const char *opt, const char *s);
/* A count: a number of the same grammar that is a whole number in [1, 2^63 - 1]; a string of
 * digits is read exactly (a double cannot hold every integer up to 2^63 - 1). */
long suslov_cli_count(const char *opt, const char *s);
/* Exactly n comma-separated numbers; an empty field is an error, never skipped. */
void suslov_cli_list(const char *opt, const char *s, double *out, int n);

#endif
