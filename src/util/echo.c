#include "echo.h"

#include <errno.h>
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

const char *sus_sys_echo_ring(const char *s, size_t n, size_t max, char quote)
{
    static char buf[SUS_SYS_ECHO_RING][4 * SUS_SYS_ECHO_RING_MAX + 48];
    static unsigned next;
    const int saved = errno;
    if (max > SUS_SYS_ECHO_RING_MAX)
        max = SUS_SYS_ECHO_RING_MAX;
    const char *e = sus_sys_echo(buf[next++ % SUS_SYS_ECHO_RING], sizeof buf[0], s, n, max, quote);
    errno = saved;
    return e;
}
