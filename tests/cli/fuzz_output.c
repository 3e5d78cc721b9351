/* The fuzzer's checks on what a run wrote (fuzz.c): its line counts, and rows that are complete
 * and finite under a header of valid UTF-8. */
#include "fuzz_output.h"

#include "fuzz_args.h"
#include "fuzz_workdir.h"

#include <stdio.h>
#include <string.h>

long fuzz_count_lines(const char *path, char *first, size_t flen)
{
    FILE *fp = fopen(path, "r");
    long n = 0;
    int c, last = '\n';
    if (first)
        first[0] = '\0';
    if (!fp)
        return -1;
    if (first && fgets(first, (int)flen, fp))
        n = 1, last = first[strlen(first) - 1];
    while ((c = fgetc(fp)) != EOF) {
        n += c == '\n';
        last = c;
    }
    fclose(fp);
    return n + (last != '\n'); /* an unterminated last line counts */
}

/* Well-formed UTF-8 (RFC 3629: no overlong form, surrogate or code point past U+10FFFF). */
static int utf8_ok(const char *s)
{
    const unsigned char *u = (const unsigned char *)s;
    while (*u) {
        const int n = *u < 0x80   ? 1
                      : *u < 0xC2 ? 0
                      : *u < 0xE0 ? 2
                      : *u < 0xF0 ? 3
                      : *u < 0xF5 ? 4
                                  : 0;
        const unsigned lo = *u == 0xE0 ? 0xA0 : *u == 0xF0 ? 0x90 : 0x80;
        const unsigned hi = *u == 0xED ? 0x9F : *u == 0xF4 ? 0x8F : 0xBF;
        if (n == 0 || (n > 1 && (u[1] < lo || u[1] > hi)))
            return 0;
        for (int i = 2; i < n; i++)
            if ((u[i] & 0xC0) != 0x80)
                return 0;
        u += n;
    }
    return 1;
}

static const char HEADER[] =
    "k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33\n";

/* Rows complete (16 fields, newline-terminated) and finite. Reads at most 4 MB. */
static int rows_ok(const char *path, char *why, size_t len)
{
    FILE *fp = fopen(path, "r");
    char line[2048];
    long n = 0;
    if (!fp) {
        snprintf(why, len, "cannot read %.200s", path);
        return 0;
    }
    int ok = 1;
    while (ok && n < 10000 && fgets(line, sizeof line, fp)) {
        if (line[0] == '#') { /* the header's comment lines, and the trailer of exit 3 */
            if (!utf8_ok(line))
                ok = 0, snprintf(why, len, "a comment line is not valid UTF-8: %.200s", line);
            continue;
        }
        n++;
        if (n == 1) {
            if (strcmp(line, HEADER) != 0)
                ok = 0, snprintf(why, len, "bad header");
            continue;
        }
        int commas = 0;
        for (char *p = line; *p; p++)
            commas += *p == ',';
        if (commas != 15 || line[strlen(line) - 1] != '\n')
            ok = 0, snprintf(why, len, "row %ld incomplete", n - 1);
        else if (strstr(line, "nan") || strstr(line, "inf"))
            ok = 0, snprintf(why, len, "row %ld is not finite", n - 1);
    }
    fclose(fp);
    return ok;
}

/* ---- one run ---- */

/* Rows that were written, to stdout or to the file named after --output, are complete. A text
 * that is not CSV (--help, --man, --version, --method list) is not judged here, nor the file of a
 * failed run (code 3), which must not exist (fuzz.c's judge compares the directory before and
 * after). */
int fuzz_output_ok(int code, char *why, size_t len)
{
    const char *o = NULL;
    int text = 0;
    for (int i = 1; i < fuzz_nargs; i++) {
        if (!strcmp(fuzz_args[i], "--output") && i + 1 < fuzz_nargs)
            o = fuzz_args[i + 1];
        else if (!strncmp(fuzz_args[i], "--output=", 9))
            o = fuzz_args[i] + 9;
        text |= !strcmp(fuzz_args[i], "--help") || !strcmp(fuzz_args[i], "-h") ||
                !strcmp(fuzz_args[i], "--man") || !strcmp(fuzz_args[i], "--version") ||
                !strcmp(fuzz_args[i], "list") || !strcmp(fuzz_args[i], "--method=list");
    }
    char path[8192];
    const int to_stdout =
        !o || !strcmp(o, "-") || !strcmp(o, "/dev/stdout") || !strcmp(o, "/dev/fd/1");
    if (text || (o && !strcmp(o, "/dev/null")) || (code == 3 && !to_stdout))
        return 1;
    if (to_stdout)
        snprintf(path, sizeof path, "%s/stdout", fuzz_capdir);
    else
        snprintf(path, sizeof path, "%s/%s", fuzz_workdir, o);
    return rows_ok(path, why, len);
}
