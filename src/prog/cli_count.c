/* A count read exactly from its text, in the grammar of every number (suslov_cli_number): a double
 * would round --steps 2.0000000000000001 to 2 and 9007199254740993e0 to 9007199254740992. The
 * text's value is kept as a digit string and an exponent, M base^e, and judged whole and in range
 * before any arithmetic, so no rounding can happen. */
#include "cli_options.h"

#include <limits.h>
#include <string.h>

/* Exponents beyond this are saturated: no text of a count is that long, so the verdict (zero,
 * not whole, out of range) is the same as for the true exponent. */
#define EXP_CAP 100000000L

typedef struct {
    int neg, hex;
    const char *first, *last; /* the first and last nonzero digit of the mantissa, or NULL */
    long point_shift;         /* digits of the mantissa after `last` (a '.' not counted), less the
                                 fraction's length: value = M base^point_shift R^exp */
    long exp;                 /* the written exponent (e: powers of 10; p: powers of 2) */
} exact_text;

static int is_digit(char c, int hex)
{
    return (c >= '0' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
}

static int digit_value(char c) { return c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10; }

/* [+-]? digits [. digits] ([eE] [+-]? digits)?, or 0x hexdigits [. hexdigits] ([pP] [+-]? digits)?,
 * with at least one mantissa digit. Returns 0 when s is of that form, whole. */
static int scan(const char *s, exact_text *x)
{
    *x = (exact_text){.neg = *s == '-'};
    s += *s == '-' || *s == '+';
    x->hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    s += 2 * x->hex;
    int digits = 0, in_frac = 0;
    long frac = 0, after_last = 0;
    for (; is_digit(*s, x->hex) || (*s == '.' && !in_frac); s++) {
        if (*s == '.') {
            in_frac = 1;
            continue;
        }
        digits++, frac += in_frac, after_last++;
        if (*s != '0') {
            x->first = x->first ? x->first : s;
            x->last = s;
            after_last = 0;
        }
    }
    x->point_shift = after_last - frac;
    if (!digits)
        return -1;
    if (*s == (x->hex ? 'p' : 'e') || *s == (x->hex ? 'P' : 'E')) {
        const int eneg = *++s == '-';
        s += *s == '-' || *s == '+';
        if (!is_digit(*s, 0))
            return -1;
        for (; is_digit(*s, 0); s++)
            x->exp = x->exp >= EXP_CAP ? EXP_CAP : 10 * x->exp + (*s - '0');
        x->exp = eneg ? -x->exp : x->exp;
    }
    return *s == '\0' ? 0 : -1;
}

/* The mantissa's significant digits from first to end (last, or the digit before it), skipping a
 * '.', into *m; 0, or -1 when more than max_digits. */
static int mantissa(const exact_text *x, const char *end, int max_digits, unsigned long long *m)
{
    int n = 0;
    *m = 0;
    for (const char *p = x->first; p <= end; p++)
        if (*p != '.') {
            if (++n > max_digits)
                return -1;
            *m = *m * (x->hex ? 16u : 10u) + (unsigned)digit_value(*p);
        }
    return 0;
}

/* The number of significant digits first..last. */
static long sig_digits(const exact_text *x)
{
    const char *dot = memchr(x->first, '.', (size_t)(x->last - x->first));
    return (long)(x->last - x->first) + 1 - (dot != NULL);
}

/* M 10^e: whole when e >= 0 (M ends in a nonzero digit, so 10 does not divide it). */
static long decimal_count(const char *opt, const char *s, const exact_text *x)
{
    const long e = x->point_shift + x->exp, n = sig_digits(x);
    unsigned long long m;
    if (e < 0)
        suslov_cli_die("%s: %s is not a whole number", opt, suslov_cli_quote(s));
    if (n + e > 19 || mantissa(x, x->last, 19, &m) != 0) /* 10^19 > 2^63 - 1 */
        suslov_cli_die("%s: %s is out of range (at most %ld)", opt, suslov_cli_quote(s), LONG_MAX);
    for (long i = 0; i < e; i++)
        m *= 10u; /* at most 19 digits: below 2^64 */
    if (m > (unsigned long long)LONG_MAX)
        suslov_cli_die("%s: %s is out of range (at most %ld)", opt, suslov_cli_quote(s), LONG_MAX);
    return (long)m;
}

/* M 2^b with b = 4 point_shift + exp; M's last hex digit h has t trailing zero bits, so the value
 * is (M / 2^t) 2^(b + t) with M / 2^t odd: whole when b + t >= 0. */
static long hex_count(const char *opt, const char *s, const exact_text *x)
{
    const int h = digit_value(*x->last), t = !(h & 1) + !(h & 3) + !(h & 7);
    const long b = 4 * x->point_shift + x->exp + t;
    const int top = digit_value(*x->first);
    const int top_bits = top >= 8 ? 4 : top >= 4 ? 3 : top >= 2 ? 2 : 1;
    if (b < 0)
        suslov_cli_die("%s: %s is not a whole number", opt, suslov_cli_quote(s));
    /* bits of the value: those of M, less the t zero bits, plus b */
    if (4 * (sig_digits(x) - 1) + top_bits - t + b > 63)
        suslov_cli_die("%s: %s is out of range (at most %ld)", opt, suslov_cli_quote(s), LONG_MAX);
    unsigned long long p; /* M without its last digit: at most 16 hex digits, by the check above */
    mantissa(x, x->last - 1, 16, &p);
    return (long)((p << (4 - t) | (unsigned long long)(h >> t)) << b);
}

long suslov_cli_count(const char *opt, const char *s)
{
    exact_text x;
    if (scan(s, &x) != 0) {
        suslov_cli_number(opt, s); /* its message: not a number, not finite, ... */
        suslov_cli_die("%s: %s is not a whole number", opt, suslov_cli_quote(s));
    }
    if (!x.first || x.neg)
        suslov_cli_die("%s must be positive, got %s", opt, suslov_cli_quote(s));
    return x.hex ? hex_count(opt, s, &x) : decimal_count(opt, s, &x);
}
