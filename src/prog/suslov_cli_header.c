/* The #-comment header of suslov's output: the version, the command line quoted as a shell reads
 * it back, and the run's settings. */
#define _POSIX_C_SOURCE 200809L
#include "suslov_cli.h"

#include "cli_options.h"
#include "echo.h"

#include <string.h>

/* 1 when s can stand raw inside single quotes on a line of UTF-8: no control character and no
 * byte that is not part of a well-formed UTF-8 character. */
static int quotable(const char *s, size_t n)
{
    for (size_t i = 0, len; i < n; i += len) {
        const unsigned char c = (unsigned char)s[i];
        if (!(len = sus_sys_utf8_len(s + i, n - i)) || c < 0x20 || c == 0x7f)
            return 0;
    }
    return 1;
}

/* An argument as a shell reads it back, on one line of valid UTF-8 (so that the header can be
 * parsed as text, and the line pasted into a shell runs the same command): bare when it holds
 * only [A-Za-z0-9_.,:/=+-]; else in single quotes; else, when it holds a control character or a
 * byte that is not UTF-8, in $'...' quoting with those bytes as \xNN (bash, ksh, zsh, busybox
 * sh, and POSIX sh since 2024; not dash 0.5.12). */
static void put_arg(FILE *fp, const char *s)
{
    const size_t n = strlen(s);
    static const char BARE[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.,:/=+-";
    if (n && strspn(s, BARE) == n) {
        fputs(s, fp);
        return;
    }
    const int single = quotable(s, n);
    fputs(single ? "'" : "$'", fp);
    for (size_t i = 0, len; i < n; i += len) {
        const unsigned char c = (unsigned char)s[i];
        len = sus_sys_utf8_len(s + i, n - i);
        if (c == '\'' && single)
            fputs("'\\''", fp);
        else if ((c == '\'' || c == '\\') && !single)
            fprintf(fp, "\\%c", c);
        else if (!len || c < 0x20 || c == 0x7f)
            fprintf(fp, "\\x%02x", c);
        else
            fwrite(s + i, 1, len, fp);
        len = len ? len : 1;
    }
    fputc('\'', fp);
}

void suslov_args_header(const suslov_args *a, int argc, char **argv, FILE *fp)
{
    fprintf(fp, "# suslov %s\n# command:", suslov_version());
    for (int i = 0; i < argc; i++) {
        fputc(' ', fp);
        put_arg(fp, i ? argv[i] : "suslov");
    }
    if (a->method && a->tol > 0.0) /* a --tol method's order is the one it chose for TOL */
        fprintf(fp, "\n# method: %s (%s, order %d at this TOL), ", a->method->type->name,
                a->method->family, a->method->type->tol->order(a->tol));
    else if (a->method)
        fprintf(fp, "\n# method: %s (%s, order %d), ", a->method->type->name, a->method->family,
                a->method->type->desc.order);
    if (a->method && a->method->type->desc.follows_recon)
        fprintf(fp, "reconstruction %s\n", SUS_RECON_NAMES[a->recon]);
    else if (a->method) /* what --method list calls "own" */
        fprintf(fp, "attitude: own (%s; --reconstruct does not apply)\n",
                sus_step_attitude_name(a->method->type->desc.attitude));
    else
        fputs("\n# method: exact (closed-form w and lambda, reference attitude R)\n", fp);
    if (a->sweeps)
        fprintf(fp, "# sweeps: the implicit equation solved by %d fixed-point sweeps, not Newton\n",
                a->sweeps);
    if (a->tol > 0.0)
        fprintf(fp, "# tol: %.17g, every time: %.17g (%s), final time: %.17g\n", a->tol,
                a->every_time,
                a->every_time > 0.0 ? "k is the row's index: t = k DT, the last row at T"
                                    : "0: a row at each accepted step, k counting them",
                a->t_end);
    else
        fprintf(fp, "# eps: %.17g, steps: %ld, every: %ld, final time: %.17g\n", a->eps, a->steps,
                a->every, a->t_end);
    fputs("# inertia (rows of I):", fp);
    for (int i = 0; i < 9; i++)
        fprintf(fp, "%s%.17g", i ? "," : " ", a->inertia[i]);
    fprintf(fp, "\n# omega0: %.17g,%.17g,0\n", a->w0[0], a->w0[1]);
    fputs("# units: those of the paper's data: t in time units, omega in radians per time unit, "
          "lambda\n"
          "# in units of I omega^2, energy = <I_m w, w>/2 in units of I omega^2\n",
          fp);
}
