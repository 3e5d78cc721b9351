#include "echo.h"

#include <errno.h>
#include <stdio.h>

static int continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

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

size_t sus_sys_utf8_len(const char *s, size_t n)
{
    const unsigned char *u = (const unsigned char *)s;
    /* the sequence's length, and the range of its second byte (RFC 3629's table): the narrow
     * ranges exclude overlong forms, surrogates and code points past U+10FFFF */
    size_t len;
    unsigned char lo = 0x80, hi = 0xBF;
    if (u[0] < 0x80)
        return 1;
    if (u[0] < 0xC2 || u[0] > 0xF4)
        return 0;
    len = u[0] < 0xE0 ? 2 : u[0] < 0xF0 ? 3 : 4;
    if (u[0] == 0xE0)
        lo = 0xA0;
    else if (u[0] == 0xED)
        hi = 0x9F;
    else if (u[0] == 0xF0)
        lo = 0x90;
    else if (u[0] == 0xF4)
        hi = 0x8F;
    if (n < len || u[1] < lo || u[1] > hi)
        return 0;
    for (size_t i = 2; i < len; i++)
        if (!continuation(u[i]))
            return 0;
    return len;
}
