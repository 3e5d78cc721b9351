/* The fuzzer's argument vectors (fuzz.c): a seeded generator, the tables of valid, boundary and
 * hostile values per option, and the random argv built from them. */
#include "fuzz_args.h"

#include <string.h>

static uint64_t rng_state;

static uint64_t rnd(void) /* xorshift64*: small, fast, and the same sequence on every libc */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ULL;
}

static int pick(int n) { return (int)(rnd() % (uint64_t)n); }
#define PICK(a) (a[pick((int)(sizeof a / sizeof a[0]))])

void fuzz_seed(uint64_t seed) { rng_state = seed ? seed : 1; }

int fuzz_pick(int n) { return pick(n); }

enum { ARGLEN = 6000 };
static char argbuf[FUZZ_MAXARGS][ARGLEN];
char *fuzz_args[FUZZ_MAXARGS + 1];
int fuzz_nargs;

static void add(const char *s)
{
    if (fuzz_nargs < FUZZ_MAXARGS) {
        snprintf(argbuf[fuzz_nargs], ARGLEN, "%s", s);
        fuzz_args[fuzz_nargs] = argbuf[fuzz_nargs];
        fuzz_nargs++;
    }
}

static const char *const METHODS[] = {"exact",    "euler",    "midpoint", "rk4",  "variational",
                                      "comp4-s5", "taylor12", "RK4",      "rk4 ", "",
                                      "exact\n",  "leapfrog", "-"};
static const char *const RECONS[] = {"cayley", "cayley-mid", "exp-mid", "exp", "", "cayley\t"};
static const char *const NUMBERS[] = {
    "0.1",   "1",      "0.5",      "1e-3",      "2",
    "0.25",  "1000",   "1e7",      "1e308",     "1.7976931348623157e308",
    "-1",    "0",      "-0",       "nan",       "inf",
    "-inf",  "1e-320", "4.9e-324", "0x1p-1022", "2.2250738585072014e-308",
    "1e400", "0.1x",   "",         "  1",       " ",
    "+1",    "1e",     "e5",       "0x10",      "1,5",
    "3",     "17",     "100",      "-1e308",    "1e-300",
    "4,5",   "1e300",  "1e155",    "1e19",      "1e150"};
static const char *const INTEGERS[] = {"2.0000000000000001",
                                       "9007199254740993e0",
                                       "0x1.8p1",
                                       "0x1.8p0",
                                       "1.5e1",
                                       "1e-400",
                                       "1e400",
                                       ".5e1",
                                       "1",
                                       "2",
                                       "3",
                                       "7",
                                       "10",
                                       "100",
                                       "1000",
                                       "0",
                                       "-1",
                                       "2.5",
                                       "9223372036854775807",
                                       "9223372036854775808",
                                       "-9223372036854775808",
                                       "1e3",
                                       "",
                                       " 5",
                                       "5 ",
                                       "0x10",
                                       "007",
                                       "4611686018427387904",
                                       "1e19",
                                       "9.2233720368547758e18",
                                       "9.2233720368547748e18",
                                       "1e6",
                                       "2e0",
                                       "1.5e1",
                                       "-0",
                                       "inf",
                                       "nan",
                                       "0x1p63"};
static const char *const HOSTILE[] = {
    "\n", "a\nb",   "\x1b[31mred", "%s%n%x%d", "\t", "\r", "\x7f", "--",   "-",
    "=",  "--eps=", "\xff\xfe",    "\xc3\xa9", ",",  ",,", "1,,2", ",1,2,"};
static const char *const OPTIONS[] = {
    "--method", "--eps",    "--steps",     "--time",    "--omega0", "--inertia", "--reconstruct",
    "--every",  "--output", "--quiet",     "--help",    "--frob",   "-h",        "--EPS",
    "--steps=", "--header", "--no-header", "--version", "--man",    "--"};
#define X50 "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx"
#define LONG250 X50 X50 X50 X50 X50
#define LONG256 X50 X50 X50 X50 X50 "xxxxxx"
static const char *const OUTPUTS[] = {
    "out.csv",      "keep.csv",   "sub/x.csv",  "missing/x.csv", "",
    "sub",          "/dev/null",  "link.csv",   "dangling.csv",  ".",
    "sub/",         "ro/x.csv",   "-",          "/dev/stdout",   "/dev/fd/1",
    "st/other.csv", "st/new.csv", "rofile.csv", LONG250,         LONG256,
    "\xff\xfe.csv", "a\nb'\\.csv"};

static void random_number(char *buf, size_t len)
{
    switch (pick(4)) {
        case 0:
            snprintf(buf, len, "%.17g", (double)(int64_t)rnd() * 1e-18 * (double)(1 + pick(1000)));
            break;
        case 1: { /* a random exponent from 1e-330 to 1e330 */
            snprintf(buf, len, "%de%d", pick(19) - 9, pick(661) - 330);
            break;
        }
        default: snprintf(buf, len, "%s", PICK(NUMBERS));
    }
}

static void random_list(char *buf, size_t len, int want)
{
    const int n = pick(5) ? want : pick(12);
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < n && used + 64 < len; i++) {
        char num[128];
        random_number(num, sizeof num);
        if (pick(8) == 0)
            num[0] = '\0'; /* an empty field */
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? "," : "", num);
    }
    if (pick(10) == 0 && used + 2 < len)
        strcat(buf, pick(2) ? "," : "\n");
}

static void random_value(const char *opt, char *buf, size_t len)
{
    if (pick(12) == 0) {
        snprintf(buf, len, "%s", PICK(HOSTILE));
        return;
    }
    if (pick(40) == 0) { /* a very long argument */
        const size_t n = (size_t)(100 + pick(5000)) < len ? (size_t)(100 + pick(5000)) : len - 1;
        memset(buf, '1', n);
        buf[n] = '\0';
        return;
    }
    if (!strcmp(opt, "--method"))
        snprintf(buf, len, "%s", PICK(METHODS));
    else if (!strcmp(opt, "--reconstruct"))
        snprintf(buf, len, "%s", PICK(RECONS));
    else if (!strcmp(opt, "--steps") || !strcmp(opt, "--every"))
        pick(2) ? snprintf(buf, len, "%d", 1 + pick(2000))
                : snprintf(buf, len, "%s", PICK(INTEGERS));
    else if (!strcmp(opt, "--omega0"))
        random_list(buf, len, 2);
    else if (!strcmp(opt, "--inertia"))
        random_list(buf, len, 9);
    else if (!strcmp(opt, "--output"))
        snprintf(buf, len, "%s", PICK(OUTPUTS));
    else
        random_number(buf, len);
}

static void add_option(const char *opt)
{
    char val[ARGLEN - 64];
    random_value(opt, val, sizeof val);
    if (!strcmp(opt, "--quiet") || !strcmp(opt, "--help") || !strcmp(opt, "-h") ||
        !strcmp(opt, "--header") || !strcmp(opt, "--no-header") || !strcmp(opt, "--version") ||
        !strcmp(opt, "--man") || !strcmp(opt, "--")) {
        add(opt);
    } else if (pick(6) == 0) { /* --opt=value */
        char both[ARGLEN];
        snprintf(both, sizeof both, "%s=%s", opt, val);
        add(both);
    } else {
        add(opt);
        if (pick(30))
            add(val); /* sometimes the value is missing */
    }
}

void fuzz_generate(void)
{
    fuzz_nargs = 0;
    fuzz_args[0] = NULL;
    add("suslov");
    if (pick(10) < 6) { /* mostly a valid run, then mutations: reaches the run paths */
        char v[64];
        add("--method");
        add(pick(3) ? PICK(METHODS) : "rk4");
        add("--eps");
        snprintf(v, sizeof v, "%.6g",
                 pick(2) ? 0.001 * (1 + pick(1000)) : (double)(1 + pick(3000)));
        add(v);
        if (pick(5)) {
            add("--steps");
            snprintf(v, sizeof v, "%d", 1 + pick(3000));
        } else {
            add("--time");
            snprintf(v, sizeof v, "%d", 1 + pick(500));
        }
        add(v);
        if (pick(2)) {
            add("--output");
            add(PICK(OUTPUTS));
        }
        for (int i = pick(4); i > 0; i--)
            add_option(PICK(OPTIONS));
    } else {
        for (int i = pick(10); i > 0; i--) {
            if (pick(10) == 0)
                add(PICK(HOSTILE));
            else
                add_option(PICK(OPTIONS));
        }
    }
    fuzz_args[fuzz_nargs] = NULL;
}

void fuzz_print_args(FILE *fp)
{
    for (int i = 0; i < fuzz_nargs; i++) {
        fputs(" '", fp);
        for (const unsigned char *p = (const unsigned char *)fuzz_args[i]; *p; p++)
            if (*p < 0x20 || *p >= 0x7f || *p == '\'' || *p == '\\')
                fprintf(fp, "\\x%02x", *p);
            else
                fputc(*p, fp);
        fputc('\'', fp);
    }
    fputc('\n', fp);
}
