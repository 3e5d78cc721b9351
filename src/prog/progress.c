#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include "monoclock.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PROGRESS_AFTER 1.0
#define PROGRESS_EVERY 0.25

static struct {
    int on, shown, plain, width;
    long total;
    double start, next, after;
} pr;

void progress_start(int on, long total)
{
    const char *term = getenv("TERM"), *no_color = getenv("NO_COLOR");
    pr.on = on;
    pr.total = total;
    pr.start = pr.next = sus_sys_now();
    /* https://no-color.org: a set, non-empty NO_COLOR; a dumb terminal knows no escapes */
    pr.plain = (no_color && *no_color) || (term && strcmp(term, "dumb") == 0);
    /* SUSLOV_PROGRESS_AFTER=0 (a test hook) shows it from the first step. */
    const char *after = getenv("SUSLOV_PROGRESS_AFTER");
    pr.after = after && *after ? atof(after) : PROGRESS_AFTER;
}

/* Back to the start of the line and clear it: ESC[K, or spaces over what was written. */
static void clear_line(void)
{
    if (pr.plain)
        fprintf(stderr, "\r%*s\r", pr.width, "");
    else
        fputs("\r\033[K", stderr);
}

void progress_erase(void)
{
    if (pr.shown)
        clear_line();
    pr.shown = 0;
}

void progress_tick(long k, double t)
{
    if (!pr.on)
        return;
    const double now = sus_sys_now(), dt = now - pr.start;
    if (now < pr.next)
        return;
    pr.next = now + PROGRESS_EVERY;
    if (dt < pr.after)
        return;
    const double rate = (double)k / dt, left = rate > 0.0 ? (double)(pr.total - k) / rate : 0.0;
    char line[256];
    const int n =
        snprintf(line, sizeof line, "suslov: step %ld of %ld (%.1f%%), t = %.6g, %.3g steps/s, %.0f s left",
                 k, pr.total, 100.0 * (double)k / (double)pr.total, t, rate, left);
    clear_line();
    fputs(line, stderr);
    fflush(stderr);
    pr.width = n > pr.width ? n : pr.width;
    pr.shown = 1;
}
