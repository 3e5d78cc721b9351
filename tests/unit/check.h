/* A minimal test harness: CHECK prints a PASS or FAIL line with what was measured, and
 * check_summary ends the program with "NAME: N passed, N failed". */
#ifndef SUSLOV_CHECK_H
#define SUSLOV_CHECK_H

#include <stdarg.h>
#include <stdio.h>

static int check_passed, check_failed;

static void check_line(int ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs(ok ? "PASS " : "FAIL ", stdout);
    vprintf(fmt, ap);
    putchar('\n');
    va_end(ap);
    ok ? check_passed++ : check_failed++;
}

#define CHECK(cond, ...) check_line((cond) ? 1 : 0, __VA_ARGS__)

static int check_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, check_passed, check_failed);
    return check_failed != 0;
}

#endif
