#include "echo.h"

#include <stdio.h>

static int continuation(unsigned char c)
{
    return (c & 0xC0) == 0x80;
}

char *sus_sys_echo(char *buf, size_t len, const char *s, size_t n, size_t max, char quote)
{
    size_t chars = 0, cut = n;
    for (size_t i = 0; i < n; i++) {
        if (continuation((unsigned char)s[i]))
            continue;
        if (chars++ == max)
            cut = i;
    }
    const char q[2] = {quote, '\0'};
    if (cut == n)
        snprintf(buf, len, "%s%.*s%s", q, (int)n, s, q);
    else
        snprintf(buf, len, "%s%.*s...%s (%zu characters)", q, (int)cut, s, q, chars);
    return buf;
}
