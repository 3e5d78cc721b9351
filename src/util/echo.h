/* Text from the user (an argument, a path) as a one-line message quotes it: whole when short,
 * else cut, so that the message's reason, which follows the text, always fits its line. */
#ifndef SUS_SYS_ECHO_H
#define SUS_SYS_ECHO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The first n bytes of s, whole when they hold at most max characters, else their first max
 * characters, "..." and their length: '0.000...' (2103 characters). Characters are counted as
 * UTF-8 (a continuation byte is no character of its own), so a cut never splits one. quote: the
 * quote character around the text, or 0 for none. Writes at most len bytes into buf (4 max + 48
 * holds any echo) and returns buf. */
char *sus_sys_echo(char *buf, size_t len, const char *s, size_t n, size_t max, char quote);

/* The same into one of SUS_SYS_ECHO_RING static buffers, used in turn (one message may quote that
 * many texts), for max <= SUS_SYS_ECHO_RING_MAX; errno is kept, for a strerror beside the text. */
#define SUS_SYS_ECHO_RING 4
#define SUS_SYS_ECHO_RING_MAX 100
const char *sus_sys_echo_ring(const char *s, size_t n, size_t max, char quote);

/* The length (1 to 4) of the well-formed UTF-8 character that the n > 0 bytes at s begin with, or
 * 0 when they begin none: a stray continuation byte, a bad lead byte (0xC0, 0xC1, 0xF5-0xFF), a
 * truncated sequence, an overlong form, a surrogate or a code point beyond U+10FFFF. */
size_t sus_sys_utf8_len(const char *s, size_t n);

#ifdef __cplusplus
}
#endif

#endif
