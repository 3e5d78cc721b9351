/* fuzz: throws random and hostile argument vectors at `suslov` and checks every promise of its
 * interface (docs/reference/cli.md) on each run:
 *   - the exit status is 0, 2 or 3 (or 128+15 when the fuzzer itself stopped a long run with
 *     SIGTERM); never a crash, a sanitizer report or another status;
 *   - on 2 and 3 stderr is exactly one line "suslov: error: ..."; on 0 stderr is empty or one
 *     "suslov: warning: ..." line (an option that does not apply);
 *   - on 2 nothing is written: stdout is empty and no file in the work directory is created,
 *     changed or removed;
 *   - no temporary file (*.tmp.*) is ever left, whatever the status;
 *   - written rows have 16 fields and no nan/inf (a blow-up is exit 3, never printed), after
 *     the #-comment header lines, which are valid UTF-8 whatever bytes the arguments hold;
 *   - on 3 an --output file is all or nothing: no file in the work directory is created,
 *     changed or removed (rows of a failed run reach only stdout, a device or a pipe).
 * Besides argv it varies: both temporary-file modes; every catchable signal (SIGKILL only with
 * O_TMPFILE) sent mid-run; a run as the unprivileged user nobody (when the fuzzer is root)
 * against another user's files, a read-only file and a sticky directory; outputs to
 * /dev/stdout, /dev/fd/1, "-", a pipe and names of 250 and 256 bytes; huge t for exact and
 * counts whose conversion to an integer would overflow.
 * Usage: fuzz SUSLOV [SECONDS [SEED]]. The seed is printed first, so a failing run can be
 * replayed; the last line is "fuzz: N passed, N failed". */
#define _GNU_SOURCE
#include "monoclock.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

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

/* ---- argument generation ---- */

enum { MAXARGS = 40, ARGLEN = 6000 };
static char argbuf[MAXARGS][ARGLEN];
static char *args[MAXARGS + 1];
static int nargs;

static void add(const char *s)
{
    if (nargs < MAXARGS) {
        snprintf(argbuf[nargs], ARGLEN, "%s", s);
        args[nargs] = argbuf[nargs];
        nargs++;
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

static void generate(void)
{
    nargs = 0;
    args[0] = NULL;
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
    args[nargs] = NULL;
}

/* ---- the work directory and its state ---- */

static char workdir[512], capdir[512];

static void write_file(const char *name, const char *text, mode_t mode)
{
    char path[8192];
    snprintf(path, sizeof path, "%s/%s", workdir, name);
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, mode);
    if (fd >= 0) {
        if (write(fd, text, strlen(text)) < 0)
            perror("fuzz: write");
        close(fd);
    }
}

static void reset_workdir(void)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "chmod -R u+w '%s' 2>/dev/null; rm -rf '%s'/* '%s'/.[!.]* 2>/dev/null", workdir,
             workdir, workdir);
    if (system(cmd) != 0) { /* rm may report nothing to remove */
    }
    char path[8192];
    snprintf(path, sizeof path, "%s/sub", workdir);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/ro", workdir);
    mkdir(path, 0555);
    write_file("keep.csv", "previous contents\n", 0600);
    write_file("rofile.csv", "read-only\n", 0444);
    snprintf(path, sizeof path, "%s/st", workdir); /* sticky, with another user's (root's) file */
    mkdir(path, 0755);
    chmod(path, 01777);
    write_file("st/other.csv", "root's\n", 0666);
    chmod(path, 01777);
    write_file("target.csv", "link target\n", 0644);
    snprintf(path, sizeof path, "%s/link.csv", workdir);
    if (symlink("target.csv", path) != 0)
        perror("fuzz: symlink");
    snprintf(path, sizeof path, "%s/dangling.csv", workdir);
    if (symlink("gone.csv", path) != 0)
        perror("fuzz: symlink");
}

/* One line per entry of the directory and of sub/: name, type, mode, size and an FNV-1a hash
 * of the contents (or of the link text). */
static void snapshot(char *out, size_t len)
{
    const char *dirs[] = {"", "/sub", "/ro", "/st"};
    size_t used = 0;
    out[0] = '\0';
    for (int d = 0; d < 4; d++) {
        char dpath[1024];
        snprintf(dpath, sizeof dpath, "%s%s", workdir, dirs[d]);
        struct dirent **names;
        const int n = scandir(dpath, &names, NULL, alphasort);
        for (int i = 0; i < n; i++) {
            char p[2048];
            struct stat sb;
            uint64_t h = 1469598103934665603ULL;
            snprintf(p, sizeof p, "%s/%s", dpath, names[i]->d_name);
            if (lstat(p, &sb) == 0 && strcmp(names[i]->d_name, ".") &&
                strcmp(names[i]->d_name, "..")) {
                char buf[65536];
                ssize_t r = 0;
                if (S_ISLNK(sb.st_mode)) {
                    r = readlink(p, buf, sizeof buf);
                    for (ssize_t j = 0; j < r; j++)
                        h = (h ^ (unsigned char)buf[j]) * 1099511628211ULL;
                } else if (S_ISREG(sb.st_mode)) {
                    const int fd = open(p, O_RDONLY);
                    while (fd >= 0 && (r = read(fd, buf, sizeof buf)) > 0)
                        for (ssize_t j = 0; j < r; j++)
                            h = (h ^ (unsigned char)buf[j]) * 1099511628211ULL;
                    if (fd >= 0)
                        close(fd);
                }
                used += (size_t)snprintf(out + used, used < len ? len - used : 0,
                                         "%s%s/%s %o %lld %016llx\n", dirs[d], "", names[i]->d_name,
                                         (unsigned)sb.st_mode, (long long)sb.st_size,
                                         (unsigned long long)h);
            }
            free(names[i]);
        }
        if (n >= 0)
            free(names);
    }
}

static int has_temp(char *which, size_t len)
{
    const char *dirs[] = {"", "/sub", "/ro", "/st"};
    for (int d = 0; d < 4; d++) {
        char dpath[1024];
        snprintf(dpath, sizeof dpath, "%s%s", workdir, dirs[d]);
        DIR *dir = opendir(dpath);
        struct dirent *e;
        while (dir && (e = readdir(dir)))
            if (strstr(e->d_name, ".tmp.")) {
                snprintf(which, len, "%s/%s", dirs[d], e->d_name);
                closedir(dir);
                return 1;
            }
        if (dir)
            closedir(dir);
    }
    return 0;
}

/* ---- checks on what a run wrote ---- */

static long count_lines(const char *path, char *first, size_t flen)
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

static const char *suslov_bin;
static long by_status[5];      /* runs that ended 0, 2, 3, stopped after run_limit, killed */
static double run_limit = 3.0; /* seconds before a run is stopped with SIGTERM */

static void print_args(FILE *fp)
{
    for (int i = 0; i < nargs; i++) {
        fputs(" '", fp);
        for (const unsigned char *p = (const unsigned char *)args[i]; *p; p++)
            if (*p < 0x20 || *p >= 0x7f || *p == '\'' || *p == '\\')
                fprintf(fp, "\\x%02x", *p);
            else
                fputc(*p, fp);
        fputc('\'', fp);
    }
    fputc('\n', fp);
}

static int output_ok(int code, char *why, size_t len);

/* How a case is run: the temporary-file mode, a signal sent kill_after seconds into the run
 * (0: none; a run killed by it must have changed nothing and left no temporary), and as the
 * user nobody (only when the fuzzer runs as root). */
typedef struct {
    int no_tmpfile, kill_sig, as_nobody;
    double kill_after;
} run_mode;

static pid_t spawn(const run_mode *rm, const char *out, const char *err)
{
    /* A signal may arrive before the exec: the child must die of it as suslov would, not be
     * caught by a sanitizer's handler that this (possibly sanitized) fuzzer installed; every
     * signal is held until the child has restored the default actions. */
    static const int fault_sigs[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP};
    sigset_t all, old;
    sigfillset(&all);
    sigprocmask(SIG_BLOCK, &all, &old);
    const pid_t pid = fork();
    if (pid != 0) {
        sigprocmask(SIG_SETMASK, &old, NULL);
        return pid;
    }
    for (size_t i = 0; i < sizeof fault_sigs / sizeof fault_sigs[0]; i++)
        signal(fault_sigs[i], SIG_DFL);
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (chdir(workdir) != 0)
        _exit(120);
    const int fo = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fe = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int fi = open("/dev/null", O_RDONLY);
    if (fo < 0 || fe < 0 || fi < 0)
        _exit(121);
    dup2(fi, 0);
    dup2(fo, 1);
    dup2(fe, 2);
    signal(SIGPIPE, SIG_DFL); /* the fuzzer ignores it; suslov must see the default */
    if (rm->no_tmpfile)
        setenv("SUSLOV_NO_O_TMPFILE", "1", 1);
    else
        unsetenv("SUSLOV_NO_O_TMPFILE");
    /* under SAN=1 AddressSanitizer would take SEGV, BUS and FPE for itself: leave them to suslov */
    char asan[4096];
    snprintf(asan, sizeof asan, "%s:handle_segv=0:handle_sigbus=0:handle_sigfpe=0",
             getenv("ASAN_OPTIONS") ? getenv("ASAN_OPTIONS") : "");
    setenv("ASAN_OPTIONS", asan, 1);
    if (rm->as_nobody && (setgroups(0, NULL) != 0 || setgid(65534) != 0 || setuid(65534) != 0))
        _exit(123);
    execv(suslov_bin, args);
    _exit(122);
}

/* Waits, sending the case's signal when due and SIGTERM after run_limit. The exit status as
 * a shell gives it (128 + n for a signal); *stopped and *sent say what the fuzzer did. */
static int wait_run(pid_t pid, const run_mode *rm, int *stopped, int *sent)
{
    int status = 0;
    const double t0 = sus_sys_now();
    *stopped = *sent = 0;
    while (waitpid(pid, &status, WNOHANG) != pid) {
        if (rm->kill_sig && !*sent && sus_sys_now() - t0 > rm->kill_after) {
            kill(pid, rm->kill_sig);
            *sent = 1;
        }
        if (!*stopped && sus_sys_now() - t0 > run_limit) {
            kill(pid, SIGTERM);
            *stopped = 1;
        } else if (*stopped && sus_sys_now() - t0 > run_limit + 30.0) {
            kill(pid, SIGKILL);
        }
        usleep(2000);
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* The promises on a finished run's status, stderr, stdout and files. */
static int judge(int code, const char *before, const char *first, long errlines, long outlines,
                 char *why, size_t len)
{
    char after[65536];
    if (code != 0 && code != 1 && code != 2 && code != 3) {
        snprintf(why, len, "exit status %d; stderr: %.300s", code, first);
        return 0;
    }
    if (code == 0 && errlines != 0 &&
        (errlines != 1 || strncmp(first, "suslov: warning: ", 17) != 0)) {
        snprintf(why, len, "exit 0 with %ld stderr lines: %.300s", errlines, first);
        return 0;
    }
    if (code != 0 && (errlines != 1 || strncmp(first, "suslov: error: ", 15) != 0)) {
        snprintf(why, len, "exit %d with %ld stderr lines (want one 'suslov: error:' line): %.300s",
                 code, errlines, first);
        return 0;
    }
    if (code == 1 && !strstr(first, "writing stdout failed")) { /* only stdout can fail here */
        snprintf(why, len, "exit 1: %.300s", first);
        return 0;
    }
    snapshot(after, sizeof after);
    if (code == 2 && (outlines != 0 || strcmp(before, after) != 0)) {
        snprintf(why, len, "exit 2 but something was written (stdout %ld lines; files %s)",
                 outlines, strcmp(before, after) ? "changed" : "unchanged");
        return 0;
    }
    if (code == 3 && strcmp(before, after) != 0) {
        snprintf(why, len,
                 "exit 3 but files in the work directory changed (a failed run writes "
                 "no file)");
        return 0;
    }
    return !((code == 0 || code == 3) && !output_ok(code, why, len));
}

static int run_case(const run_mode *rm, char *why, size_t len)
{
    char before[65536], after[65536], out[8192], err[8192], tmpname[512], first[4096];
    snprintf(out, sizeof out, "%s/stdout", capdir);
    snprintf(err, sizeof err, "%s/stderr", capdir);
    reset_workdir();
    snapshot(before, sizeof before);
    int stopped, sent;
    const int code = wait_run(spawn(rm, out, err), rm, &stopped, &sent);
    const long errlines = count_lines(err, first, sizeof first);
    const long outlines = count_lines(out, NULL, 0);
    if (strstr(first, "Sanitizer") || strstr(first, "runtime error")) {
        snprintf(why, len, "sanitizer report: %.300s", first);
        return 0;
    }
    if (has_temp(tmpname, sizeof tmpname)) {
        snprintf(why, len, "temporary file left: %s (status %d)", tmpname, code);
        return 0;
    }
    if (sent && code == 128 + rm->kill_sig) {
        by_status[4]++;
        snapshot(after, sizeof after);
        /* A signal that arrives during the commit is held until the file is in place (then
         * the file is complete); at any other time nothing may have changed. */
        if (strcmp(before, after) != 0 && !output_ok(0, why, len)) {
            snprintf(why, len, "killed by signal %d, but files were changed", rm->kill_sig);
            return 0;
        }
        return 1;
    }
    by_status[stopped ? 3 : code == 0 ? 0 : code == 2 ? 1 : 2]++;
    if (stopped) {
        if (code != 128 + SIGTERM)
            snprintf(why, len, "stopped with SIGTERM after %.0f s, status %d (want 143)", run_limit,
                     code);
        return code == 128 + SIGTERM;
    }
    return judge(code, before, first, errlines, outlines, why, len);
}

/* Rows that were written, to stdout or to the file named after --output, are complete. A text
 * that is not CSV (--help, --man, --version, --method list) is not judged here, nor the file of a
 * failed run (code 3), which must not exist (judge compares the directory before and after). */
static int output_ok(int code, char *why, size_t len)
{
    const char *o = NULL;
    int text = 0;
    for (int i = 1; i < nargs; i++) {
        if (!strcmp(args[i], "--output") && i + 1 < nargs)
            o = args[i + 1];
        else if (!strncmp(args[i], "--output=", 9))
            o = args[i] + 9;
        text |= !strcmp(args[i], "--help") || !strcmp(args[i], "-h") || !strcmp(args[i], "--man") ||
                !strcmp(args[i], "--version") || !strcmp(args[i], "list") ||
                !strcmp(args[i], "--method=list");
    }
    char path[8192];
    const int to_stdout =
        !o || !strcmp(o, "-") || !strcmp(o, "/dev/stdout") || !strcmp(o, "/dev/fd/1");
    if (text || (o && !strcmp(o, "/dev/null")) || (code == 3 && !to_stdout))
        return 1;
    if (to_stdout)
        snprintf(path, sizeof path, "%s/stdout", capdir);
    else
        snprintf(path, sizeof path, "%s/%s", workdir, o);
    return rows_ok(path, why, len);
}

/* Whether the user nobody can reach and run suslov (not from a private directory). */
static int nobody_can_run(void)
{
    const pid_t pid = fork();
    if (pid == 0)
        _exit(setgroups(0, NULL) == 0 && setgid(65534) == 0 && setuid(65534) == 0 &&
                      access(suslov_bin, X_OK) == 0
                  ? 0
                  : 1);
    int status = 1;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* Seconds for suslov to start and exit (the slowest of three --version runs): a sanitized build on
 * a loaded machine takes seconds, which the per-run limit must allow for. */
static double startup_time(void)
{
    double worst = 0.0;
    for (int i = 0; i < 3; i++) {
        const double t0 = sus_sys_now();
        const pid_t pid = fork();
        if (pid == 0) {
            const int fd = open("/dev/null", O_WRONLY);
            dup2(fd, 1);
            execl(suslov_bin, "suslov", "--version", (char *)NULL);
            _exit(122);
        }
        waitpid(pid, NULL, 0);
        const double dt = sus_sys_now() - t0;
        worst = dt > worst ? dt : worst;
    }
    return worst;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: fuzz SUSLOV [SECONDS [SEED]]\n");
        return 2;
    }
    suslov_bin = argv[1];
    const double seconds = argc > 2 ? atof(argv[2]) : 60.0;
    const uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 0) : 20261122ULL;
    if (access(suslov_bin, X_OK) != 0) {
        fprintf(stderr, "fuzz: cannot run %s\n", suslov_bin);
        return 2;
    }
    char real[4096];
    if (!realpath(suslov_bin, real)) {
        perror("fuzz: realpath");
        return 2;
    }
    suslov_bin = real;
    const char *tmp = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    snprintf(workdir, sizeof workdir, "%s/suslov-fuzz-XXXXXX", tmp);
    snprintf(capdir, sizeof capdir, "%s/suslov-fuzzcap-XXXXXX", tmp);
    if (!mkdtemp(workdir) || !mkdtemp(capdir)) {
        perror("fuzz: mkdtemp");
        return 2;
    }
    signal(SIGPIPE, SIG_IGN);
    run_limit += 4.0 * startup_time();
    /* the permission cases run as nobody, who must reach the work directory and suslov */
    const int root = geteuid() == 0 && nobody_can_run();
    if (root) {
        chmod(workdir, 0777);
        chmod(capdir, 0777);
    }
    printf("fuzz: %s\n",
           root ? "some runs as the user nobody (permission cases)"
                : "SKIP runs as nobody: the fuzzer is not root, or nobody cannot run suslov");
    printf("fuzz: seed %llu, %.0f s, %s (replay: fuzz %s %.0f %llu)\n", (unsigned long long)seed,
           seconds, suslov_bin, argv[1], seconds, (unsigned long long)seed);
    fflush(stdout);
    rng_state = seed ? seed : 1;
    long pass = 0, fail = 0;
    const double start = sus_sys_now();
    for (long id = 0; sus_sys_now() - start < seconds; id++) {
        char why[1024];
        generate();
        run_mode rm = {.no_tmpfile = pick(4) == 0, .as_nobody = root && pick(5) == 0};
        /* every catchable signal whose default ends the process; SIGKILL only with O_TMPFILE:
         * the named fallback cannot clean up after it */
        static const int sigs[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGABRT, SIGUSR1, SIGUSR2,
                                   SIGPIPE, SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ, SIGVTALRM,
                                   SIGPROF, SIGIO,   SIGPWR,  SIGSYS,  SIGSEGV, SIGBUS,
                                   SIGFPE,  SIGILL,  SIGTRAP, 34,      64,      SIGKILL};
        const int nsigs = (int)(sizeof sigs / sizeof sigs[0]);
        rm.kill_sig = pick(10) == 0 ? sigs[pick(rm.no_tmpfile ? nsigs - 1 : nsigs)] : 0;
        rm.kill_after = 0.0005 * pick(60);
        if (run_case(&rm, why, sizeof why)) {
            pass++;
        } else {
            fail++;
            if (fail <= 30) {
                printf("FAIL case %ld%s%s: %s; argv:", id,
                       rm.no_tmpfile ? " (SUSLOV_NO_O_TMPFILE=1)" : "",
                       rm.as_nobody ? " (as nobody)" : "", why);
                print_args(stdout);
                fflush(stdout);
            }
        }
    }
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "chmod -R u+w '%s'; rm -rf '%s' '%s'", workdir, workdir, capdir);
    if (system(cmd) != 0)
        fprintf(stderr, "fuzz: could not remove %s\n", workdir);
    printf("fuzz: runs that exited 0: %ld, 2: %ld, 3: %ld; stopped with SIGTERM after %.0f s: %ld; "
           "killed by a "
           "random signal mid-run: %ld\n",
           by_status[0], by_status[1], by_status[2], run_limit, by_status[3], by_status[4]);
    printf("fuzz: %ld passed, %ld failed\n", pass, fail);
    return fail != 0;
}
