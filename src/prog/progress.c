#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include "monoclock.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define PROGRESS_AFTER 1.0      /* s before a terminal's line: a short run shows none */
#define PROGRESS_EVERY 0.25     /* s between redraws of a terminal's line */
#define PROGRESS_LOG_EVERY 10.0 /* s between the lines of a log */

typedef struct {
    int on, log, shown, plain, width;
    const char *who, *unit;
    long total;
    double start, next;
} progress_state;
static progress_state pr;

static int env_set(const char *name)
{
    const char *v = getenv(name);
    return v && *v;
}

int suslov_progress_modes(int *argc, char **argv)
{
    int quiet = 0, n = 1;
    for (int i = 1; i < *argc; i++)
        if (strcmp(argv[i], "--quiet") == 0)
            quiet = 1;
        else
            argv[n++] = argv[i];
    argv[n] = NULL;
    *argc = n;
    return quiet ? 0 : PROGRESS_TERMINAL | PROGRESS_LOG;
}

void suslov_progress_start(const char *who, const char *unit, long total, int modes)
{
    const char *term = getenv("TERM");
    const int tty = isatty(STDERR_FILENO);
    pr = (progress_state){0};
    pr.on = !env_set("NO_PROGRESS") && (modes & (tty ? PROGRESS_TERMINAL : PROGRESS_LOG));
    pr.log = !tty;
    pr.who = who;
    pr.unit = unit;
    pr.total = total;
    /* https://no-color.org: a set, non-empty NO_COLOR; a dumb terminal knows no escapes */
    pr.plain = env_set("NO_COLOR") || (term && strcmp(term, "dumb") == 0);
    /* SUSLOV_PROGRESS_AFTER=S (a test hook): the first line after S seconds, in either mode */
    const char *after = getenv("SUSLOV_PROGRESS_AFTER");
    pr.start = sus_sys_now();
    const double first = pr.log ? PROGRESS_LOG_EVERY : PROGRESS_AFTER;
    pr.next = pr.start + (after && *after ? atof(after) : first);
}

/* Back to the start of the line and clear it: ESC[K, or spaces over what was written. */
static void clear_line(void)
{
    if (pr.plain)
        fprintf(stderr, "\r%*s\r", pr.width, "");
    else
        fputs("\r\033[K", stderr);
}

void suslov_progress_end(void)
{
    if (pr.shown && !pr.log)
        clear_line();
    pr.shown = 0;
    pr.on = 0;
}

/* Seconds as "42 s" or "3 min 05 s". */
static const char *secs(double s, char *buf, size_t len)
{
    const long n = (long)(s + 0.5);
    if (n < 60)
        snprintf(buf, len, "%ld s", n);
    else
        snprintf(buf, len, "%ld min %02ld s", n / 60, n % 60);
    return buf;
}

/* One part of the line: after "WHO:" with a space, after another part with a comma. */
static void part(char *line, size_t len, size_t *n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void part(char *line, size_t len, size_t *n, const char *fmt, ...)
{
    const int first = line[*n - 1] == ':';
    if (*n + 2 >= len)
        return;
    *n += (size_t)snprintf(line + *n, len - *n, first ? " " : ", ");
    va_list ap;
    va_start(ap, fmt);
    const int k = vsnprintf(line + *n, len - *n, fmt, ap);
    va_end(ap);
    if (k > 0)
        *n = *n + (size_t)k < len ? *n + (size_t)k : len - 1;
}

/* "WHO: UNIT k of N (p%)" or "WHO: p% done", then the detail, the rate, the time taken and the
 * estimate of what is left (from the mean rate so far); returns the line's length. */
static size_t format_line(char *line, size_t len, long done, double dt, const char *detail)
{
    char a[32], b[32];
    const int known = pr.total > 0 && done < pr.total;
    const double frac = known ? (double)done / (double)pr.total : 0.0;
    size_t n = (size_t)snprintf(line, len, "%s:", pr.who);
    if (pr.unit && known)
        part(line, len, &n, "%s %ld of %ld (%.1f%%)", pr.unit, done, pr.total, 100.0 * frac);
    else if (pr.unit)
        part(line, len, &n, "%s %ld of %ld", pr.unit, done, pr.total);
    else if (known)
        part(line, len, &n, "%.0f%% done", 100.0 * frac);
    if (*detail)
        part(line, len, &n, "%s", detail);
    if (pr.unit && done > 0 && dt > 0.0)
        part(line, len, &n, "%.3g %ss/s", (double)done / dt, pr.unit);
    part(line, len, &n, "%s elapsed", secs(dt, a, sizeof a));
    if (known && done > 0)
        part(line, len, &n, "about %s left", secs(dt * (1.0 - frac) / frac, b, sizeof b));
    return n;
}

void suslov_progress_tick(long done, const char *detail, ...)
{
    if (!pr.on)
        return;
    const double now = sus_sys_now();
    if (now < pr.next)
        return;
    pr.next = now + (pr.log ? PROGRESS_LOG_EVERY : PROGRESS_EVERY);
    char what[160] = "", line[512]; /* room for every part at its longest */
    if (detail) {
        va_list ap;
        va_start(ap, detail);
        vsnprintf(what, sizeof what, detail, ap);
        va_end(ap);
    }
    const size_t n = format_line(line, sizeof line - 1, done, now - pr.start, what);
    if (pr.log) { /* one write a line, so that two programs' lines never mix */
        line[n] = '\n';
        fwrite(line, 1, n + 1, stderr);
    } else {
        clear_line();
        fputs(line, stderr);
        pr.width = (int)n > pr.width ? (int)n : pr.width;
    }
    fflush(stderr);
    pr.shown = 1;
}
