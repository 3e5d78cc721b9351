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
#include "fuzz_args.h"
#include "fuzz_output.h"
#include "fuzz_workdir.h"
#include "monoclock.h"

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

static const char *suslov_bin;
static long by_status[5];      /* runs that ended 0, 2, 3, stopped after run_limit, killed */
static double run_limit = 3.0; /* seconds before a run is stopped with SIGTERM */

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
    if (chdir(fuzz_workdir) != 0)
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
    execv(suslov_bin, fuzz_args);
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
    fuzz_snapshot(after, sizeof after);
    if (code == 2 && (outlines != 0 || strcmp(before, after) != 0)) {
        snprintf(why, len, "exit 2 but something was written (stdout %ld lines; files %s)",
                 outlines, strcmp(before, after) ? "changed" : "unchanged");
        return 0;
    }
    if (code == 3 && strcmp(before, after) != 0) {
        snprintf(why, len,
                 "exit 3 but files in the work directory changed (a failed run writes no file)");
        return 0;
    }
    return !((code == 0 || code == 3) && !fuzz_output_ok(code, why, len));
}

static int run_case(const run_mode *rm, char *why, size_t len)
{
    char before[65536], after[65536], out[8192], err[8192], tmpname[512], first[4096];
    snprintf(out, sizeof out, "%s/stdout", fuzz_capdir);
    snprintf(err, sizeof err, "%s/stderr", fuzz_capdir);
    fuzz_reset_workdir();
    fuzz_snapshot(before, sizeof before);
    int stopped, sent;
    const int code = wait_run(spawn(rm, out, err), rm, &stopped, &sent);
    const long errlines = fuzz_count_lines(err, first, sizeof first);
    const long outlines = fuzz_count_lines(out, NULL, 0);
    if (strstr(first, "Sanitizer") || strstr(first, "runtime error")) {
        snprintf(why, len, "sanitizer report: %.300s", first);
        return 0;
    }
    if (fuzz_has_temp(tmpname, sizeof tmpname)) {
        snprintf(why, len, "temporary file left: %s (status %d)", tmpname, code);
        return 0;
    }
    if (sent && code == 128 + rm->kill_sig) {
        by_status[4]++;
        fuzz_snapshot(after, sizeof after);
        /* A signal that arrives during the commit is held until the file is in place (then
         * the file is complete); at any other time nothing may have changed. */
        if (strcmp(before, after) != 0 && !fuzz_output_ok(0, why, len)) {
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

/* Resolves SUSLOV and makes the work and capture directories under TMPDIR: 0, or 2 (said). */
static int prepare(const char *bin, char real[4096])
{
    if (access(bin, X_OK) != 0) {
        fprintf(stderr, "fuzz: cannot run %s\n", bin);
        return 2;
    }
    if (!realpath(bin, real)) {
        perror("fuzz: realpath");
        return 2;
    }
    suslov_bin = real;
    const char *tmp = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    snprintf(fuzz_workdir, sizeof fuzz_workdir, "%s/suslov-fuzz-XXXXXX", tmp);
    snprintf(fuzz_capdir, sizeof fuzz_capdir, "%s/suslov-fuzzcap-XXXXXX", tmp);
    if (!mkdtemp(fuzz_workdir) || !mkdtemp(fuzz_capdir)) {
        perror("fuzz: mkdtemp");
        return 2;
    }
    return 0;
}

/* Whether some runs go as the user nobody: only when the fuzzer is root and nobody can reach the
 * work directory and suslov (the permission cases). */
static int permission_cases(void)
{
    const int root = geteuid() == 0 && nobody_can_run();
    if (root) {
        chmod(fuzz_workdir, 0777);
        chmod(fuzz_capdir, 0777);
    }
    printf("fuzz: %s\n",
           root ? "some runs as the user nobody (permission cases)"
                : "SKIP runs as nobody: the fuzzer is not root, or nobody cannot run suslov");
    return root;
}

/* A case's run mode, drawn after its argv. */
static run_mode draw_mode(int root)
{
    run_mode rm = {.no_tmpfile = fuzz_pick(4) == 0, .as_nobody = root && fuzz_pick(5) == 0};
    /* every catchable signal whose default ends the process; SIGKILL only with O_TMPFILE:
     * the named fallback cannot clean up after it */
    static const int sigs[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGABRT, SIGUSR1, SIGUSR2,
                               SIGPIPE, SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ, SIGVTALRM,
                               SIGPROF, SIGIO,   SIGPWR,  SIGSYS,  SIGSEGV, SIGBUS,
                               SIGFPE,  SIGILL,  SIGTRAP, 34,      64,      SIGKILL};
    const int nsigs = (int)(sizeof sigs / sizeof sigs[0]);
    rm.kill_sig = fuzz_pick(10) == 0 ? sigs[fuzz_pick(rm.no_tmpfile ? nsigs - 1 : nsigs)] : 0;
    rm.kill_after = 0.0005 * fuzz_pick(60);
    return rm;
}

/* Case id: a new argv and run mode, run and judged; 1 when it passed. The first 30 failures
 * (failed_before counts the earlier ones) are printed with their argv, for a replay. */
static int one_case(long id, int root, long failed_before)
{
    char why[1024];
    fuzz_generate();
    const run_mode rm = draw_mode(root);
    if (run_case(&rm, why, sizeof why))
        return 1;
    if (failed_before < 30) {
        printf("FAIL case %ld%s%s: %s; argv:", id, rm.no_tmpfile ? " (SUSLOV_NO_O_TMPFILE=1)" : "",
               rm.as_nobody ? " (as nobody)" : "", why);
        fuzz_print_args(stdout);
        fflush(stdout);
    }
    return 0;
}

/* Removes both directories and prints how the runs ended. */
static void finish(void)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "chmod -R u+w '%s'; rm -rf '%s' '%s'", fuzz_workdir, fuzz_workdir,
             fuzz_capdir);
    if (system(cmd) != 0)
        fprintf(stderr, "fuzz: could not remove %s\n", fuzz_workdir);
    printf("fuzz: runs that exited 0: %ld, 2: %ld, 3: %ld; stopped with SIGTERM after %.0f s: %ld; "
           "killed by a random signal mid-run: %ld\n",
           by_status[0], by_status[1], by_status[2], run_limit, by_status[3], by_status[4]);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: fuzz SUSLOV [SECONDS [SEED]]\n");
        return 2;
    }
    const double seconds = argc > 2 ? atof(argv[2]) : 60.0;
    const uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 0) : 20261122ULL;
    char real[4096];
    if (prepare(argv[1], real) != 0)
        return 2;
    signal(SIGPIPE, SIG_IGN);
    run_limit += 4.0 * startup_time();
    const int root = permission_cases();
    printf("fuzz: seed %llu, %.0f s, %s (replay: fuzz %s %.0f %llu)\n", (unsigned long long)seed,
           seconds, suslov_bin, argv[1], seconds, (unsigned long long)seed);
    fflush(stdout);
    fuzz_seed(seed);
    long pass = 0, fail = 0;
    const double start = sus_sys_now();
    for (long id = 0; sus_sys_now() - start < seconds; id++)
        if (one_case(id, root, fail))
            pass++;
        else
            fail++;
    finish();
    printf("fuzz: %ld passed, %ld failed\n", pass, fail);
    return fail != 0;
}
