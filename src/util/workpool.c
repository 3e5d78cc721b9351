#define _POSIX_C_SOURCE 200809L
#include "workpool.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_WORKERS 256

typedef struct {
    pid_t pid;
    int cmd, res; /* the parent's ends: job numbers out, results in (-1 once closed) */
    int job;      /* the job it is running, or -1 */
} worker;

int sus_sys_pool_cores(void)
{
    const long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > MAX_WORKERS ? MAX_WORKERS : (int)n;
}

static int job_at(const sus_sys_pool *p, int k) { return p->order ? p->order[k] : k; }

/* ---- both sides: whole reads and writes on a pipe ---- */

/* 1 when all n bytes came, 0 at end of file before any, -1 otherwise. */
static int read_full(int fd, void *buf, size_t n)
{
    size_t got = 0;
    while (got < n) {
        const ssize_t r = read(fd, (char *)buf + got, n - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return r == 0 && got == 0 ? 0 : -1;
        got += (size_t)r;
    }
    return 1;
}

static int write_full(int fd, const void *buf, size_t n)
{
    size_t put = 0;
    while (put < n) {
        const ssize_t w = write(fd, (const char *)buf + put, n - put);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        put += (size_t)w;
    }
    return 0;
}

static void close_fd(int *fd)
{
    if (*fd >= 0)
        close(*fd);
    *fd = -1;
}

/* ---- the worker ---- */

/* A handler the parent installed (a temporary file's removal, say) is the parent's business: the
 * worker dies of a signal as a plain process does. Ignored signals stay ignored. */
static void default_handlers(void)
{
    for (int s = 1; s < 32; s++) {
        struct sigaction old;
        if (s == SIGKILL || s == SIGSTOP || sigaction(s, NULL, &old) != 0)
            continue;
        if (old.sa_handler != SIG_DFL && old.sa_handler != SIG_IGN)
            signal(s, SIG_DFL);
    }
}

static void worker_main(const sus_sys_pool *p, int cmd, int res)
{
    void *buf = malloc(p->size ? p->size : 1);
    int job;
    default_handlers();
    if (!buf)
        _exit(1);
    while (read_full(cmd, &job, sizeof job) == 1) {
        if (job < 0 || job >= p->njobs)
            _exit(1);
        memset(buf, 0, p->size); /* a struct's padding too: the same bytes as in the parent */
        p->run(job, buf, p->ctx);
        if (write_full(res, &job, sizeof job) != 0 || write_full(res, buf, p->size) != 0)
            _exit(1);
    }
    _exit(0);
}

/* ---- the parent ---- */

/* Stops every worker still there and waits for it. */
static void stop_all(worker *w, int n)
{
    for (int i = 0; i < n; i++) {
        close_fd(&w[i].cmd);
        close_fd(&w[i].res);
        if (w[i].pid > 0) {
            kill(w[i].pid, SIGTERM);
            waitpid(w[i].pid, NULL, 0);
        }
    }
}

/* Forks worker i; the child closes every pipe end but its own two. Returns 0 or -1. */
static int start_worker(const sus_sys_pool *p, worker *w, int i)
{
    int cmd[2], res[2];
    if (pipe(cmd) != 0)
        return -1;
    if (pipe(res) != 0) {
        close(cmd[0]), close(cmd[1]);
        return -1;
    }
    fflush(NULL); /* nothing buffered is written twice */
    const pid_t pid = fork();
    if (pid == 0) {
        for (int j = 0; j < i; j++)
            close(w[j].cmd), close(w[j].res);
        close(cmd[1]), close(res[0]);
        worker_main(p, cmd[0], res[1]);
    }
    close(cmd[0]), close(res[1]);
    w[i] = (worker){.pid = pid, .cmd = cmd[1], .res = res[0], .job = -1};
    if (pid < 0) {
        close_fd(&w[i].cmd), close_fd(&w[i].res);
        return -1;
    }
    return 0;
}

/* The next job to worker i, or its pipe closed when none is left. */
static int hand_out(const sus_sys_pool *p, worker *wk, int *next)
{
    if (*next >= p->njobs) {
        close_fd(&wk->cmd);
        return 0;
    }
    wk->job = job_at(p, (*next)++);
    return write_full(wk->cmd, &wk->job, sizeof wk->job);
}

/* Takes worker i's finished job in. Returns 0, or -1 for a worker that died or sent another job. */
static int take_in(const sus_sys_pool *p, worker *wk)
{
    int job;
    if (read_full(wk->res, &job, sizeof job) != 1 || job != wk->job ||
        read_full(wk->res, (char *)p->results + (size_t)job * p->size, p->size) != 1)
        return -1;
    wk->job = -1;
    if (p->done)
        p->done(job, p->ctx);
    return 0;
}

/* Waits for a result from any busy worker and takes it in; the index of a failed worker in
 * *failed (-1 when none failed). Returns the number of results taken in, or -1. */
static int collect(const sus_sys_pool *p, worker *w, int n, int *next, int *failed)
{
    struct pollfd fds[MAX_WORKERS];
    int idx[MAX_WORKERS], m = 0, took = 0;
    for (int i = 0; i < n; i++)
        if (w[i].job >= 0)
            fds[m] = (struct pollfd){.fd = w[i].res, .events = POLLIN}, idx[m++] = i;
    if (poll(fds, (nfds_t)m, -1) < 0)
        return errno == EINTR ? 0 : -1;
    for (int k = 0; k < m; k++) {
        if (!fds[k].revents)
            continue;
        worker *wk = &w[idx[k]];
        *failed = idx[k];
        if (take_in(p, wk) != 0 || hand_out(p, wk, next) != 0)
            return -1;
        took++;
    }
    *failed = -1;
    return took;
}

/* Every worker's exit status: 0 when all left normally. */
static int wait_all(worker *w, int n)
{
    int bad = 0;
    for (int i = 0; i < n; i++) {
        int status = 0;
        close_fd(&w[i].cmd);
        close_fd(&w[i].res);
        if (waitpid(w[i].pid, &status, 0) != w[i].pid || !WIFEXITED(status) || WEXITSTATUS(status))
            bad++;
        w[i].pid = -1;
    }
    return bad;
}

static int run_here(const sus_sys_pool *p)
{
    for (int k = 0; k < p->njobs; k++) {
        const int job = job_at(p, k);
        p->run(job, (char *)p->results + (size_t)job * p->size, p->ctx);
        if (p->done)
            p->done(job, p->ctx);
    }
    return 0;
}

static int fail(worker *w, int n, char *err, size_t errlen, const char *what, int job)
{
    const int e = errno;
    stop_all(w, n);
    if (job >= 0)
        snprintf(err, errlen, "a worker process died or garbled its result (job %d)", job);
    else
        snprintf(err, errlen, "%s: %s", what, strerror(e));
    return -1;
}

int sus_sys_pool_run(const sus_sys_pool *p, char *err, size_t errlen)
{
    int n = p->workers < p->njobs ? p->workers : p->njobs;
    if (n > MAX_WORKERS)
        n = MAX_WORKERS;
    if (n <= 1)
        return run_here(p);
    worker w[MAX_WORKERS];
    int next = 0, done = 0, failed = -1;
    struct sigaction ign = {.sa_handler = SIG_IGN}, old_pipe;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGPIPE, &ign, &old_pipe); /* a dead worker shows as a failed write, not a kill */
    for (int i = 0; i < n; i++) {
        if (start_worker(p, w, i) != 0) {
            sigaction(SIGPIPE, &old_pipe, NULL);
            return fail(w, i, err, errlen, "cannot start a worker process", -1);
        }
        if (hand_out(p, &w[i], &next) != 0) {
            sigaction(SIGPIPE, &old_pipe, NULL);
            return fail(w, i + 1, err, errlen, "", w[i].job);
        }
    }
    while (done < p->njobs) {
        const int took = collect(p, w, n, &next, &failed);
        if (took < 0) {
            sigaction(SIGPIPE, &old_pipe, NULL);
            return failed >= 0 ? fail(w, n, err, errlen, "", w[failed].job)
                               : fail(w, n, err, errlen, "waiting for the workers", -1);
        }
        done += took;
    }
    sigaction(SIGPIPE, &old_pipe, NULL);
    if (wait_all(w, n) != 0) {
        snprintf(err, errlen, "a worker process did not exit normally");
        return -1;
    }
    return 0;
}
