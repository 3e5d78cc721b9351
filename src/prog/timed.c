/* Runs a command, records how long it took, and shows its progress meanwhile: what make wraps
 * around every long step (the figure programs, the claims ledger, the tests, the bench).
 * Usage: timed [--progress NAME] [--output FILE] TIMEFILE COMMAND [ARG]...
 *   TIMEFILE  gets one line, the wall-clock seconds ("S failed" when the command failed, so that
 *             nothing quotes it as a normal run), written whole or not at all
 *   --progress NAME  progress on stderr (progress.h), for a command that reports none itself: the
 *             estimate is the time TIMEFILE recorded for the last run
 *   --output FILE    the command's stdout and stderr go to FILE, so that the progress stays on
 *             this program's stderr
 * The exit status is the command's (128 + n when a signal n ended it); 2 for bad usage. */
#define _POSIX_C_SOURCE 200809L
#include "monoclock.h"
#include "progress.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static volatile sig_atomic_t child;

/* A signal for this program goes to the command too, and ends this program as it ends the command
 * (make and a terminal signal the whole group anyway; a kill of this process alone must not leave
 * the command running). */
static void pass_on(int sig)
{
    if (child > 0)
        kill((pid_t)child, sig);
}

/* The seconds TIMEFILE holds from the last successful run, or 0. */
static double last_seconds(const char *path)
{
    FILE *fp = fopen(path, "r");
    double s = 0.0;
    char word[32] = "";
    if (!fp)
        return 0.0;
    if (fscanf(fp, "%lf %31s", &s, word) < 1 || word[0] || !(s > 0.0))
        s = 0.0;
    fclose(fp);
    return s;
}

/* TIMEFILE written whole, through a temporary, its directory made when missing (one level:
 * BUILD/timings). */
static int record(const char *path, double seconds, int failed)
{
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *fp = fopen(tmp, "w");
    if (!fp && errno == ENOENT && strrchr(tmp, '/')) {
        *strrchr(tmp, '/') = '\0';
        mkdir(tmp, 0777);
        snprintf(tmp, sizeof tmp, "%s.tmp", path);
        fp = fopen(tmp, "w");
    }
    if (!fp)
        return -1;
    const int bad = fprintf(fp, "%.1f%s\n", seconds, failed ? " failed" : "") < 0;
    if ((fclose(fp) != 0) | bad || rename(tmp, path) != 0) {
        remove(tmp);
        return -1;
    }
    return 0;
}

/* The command in a child, its output to `output` when given; returns its pid, or -1. */
static pid_t start(char **argv, const char *output)
{
    const pid_t pid = fork();
    if (pid != 0)
        return pid;
    if (output) {
        const int fd = open(output, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (fd < 0 || dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) {
            fprintf(stderr, "timed: %s: %s\n", output, strerror(errno));
            _exit(127);
        }
        close(fd);
    }
    execvp(argv[0], argv);
    fprintf(stderr, "timed: %s: %s\n", argv[0], strerror(errno));
    _exit(127);
}

/* Waits for the command, ticking the progress ten times a second (in milliseconds, against the
 * last run's); returns its wait status. */
static int wait_for(pid_t pid, double t0, double last)
{
    int status = 0;
    for (;;) {
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid)
            return status;
        if (r < 0 && errno != EINTR)
            return -1;
        const double dt = sus_sys_now() - t0;
        if (last > 0.0 && dt >= last)
            suslov_progress_tick((long)(1000.0 * dt), "longer than the last run (%.0f s)", last);
        else
            suslov_progress_tick((long)(1000.0 * dt), "%s", "");
        const struct timespec tenth = {0, 100000000L};
        nanosleep(&tenth, NULL);
    }
}

int main(int argc, char **argv)
{
    const char *name = NULL, *output = NULL;
    int i = 1;
    for (; i + 1 < argc && !strncmp(argv[i], "--", 2); i += 2)
        if (!strcmp(argv[i], "--progress"))
            name = argv[i + 1];
        else if (!strcmp(argv[i], "--output"))
            output = argv[i + 1];
        else
            break;
    if (argc - i < 2 || !strncmp(argv[i], "--", 2)) {
        fputs("usage: timed [--progress NAME] [--output FILE] TIMEFILE COMMAND [ARG]...\n", stderr);
        return 2;
    }
    const char *timefile = argv[i];
    const double last = last_seconds(timefile);
    suslov_progress_start(name ? name : "", NULL, (long)(1000.0 * last),
                          name ? PROGRESS_TERMINAL | PROGRESS_LOG : 0);
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t k = 0; k < sizeof sigs / sizeof sigs[0]; k++)
        signal(sigs[k], pass_on);
    const double t0 = sus_sys_now();
    const pid_t pid = start(argv + i + 1, output);
    child = pid;
    const int status = pid < 0 ? -1 : wait_for(pid, t0, last);
    suslov_progress_end();
    const int rc = status < 0          ? 127
                   : WIFEXITED(status) ? WEXITSTATUS(status)
                                       : 128 + WTERMSIG(status);
    if (record(timefile, sus_sys_now() - t0, rc != 0) != 0)
        fprintf(stderr, "timed: cannot write %s: %s\n", timefile, strerror(errno));
    if (status >= 0 && WIFSIGNALED(status)) { /* die of the same signal, as the command did */
        signal(WTERMSIG(status), SIG_DFL);
        raise(WTERMSIG(status));
    }
    return rc;
}
