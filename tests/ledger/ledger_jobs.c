#define _POSIX_C_SOURCE 200809L
#include "ledger_jobs.h"

#include "ledger.h"
#include "ledger_rows.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int ledger_jobs_online(void)
{
    const long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

/* A task's results as the child writes them: the counts and the minima, then the new lines and
 * numbers, as they are in memory (the parent is the same program). */
typedef struct {
    int nrows, nextras;
    double mins[LEDGER_MINS];
} task_head;

/* In the child: runs the task and writes what it recorded to out, then ends without running the
 * parent's exit handlers or flushing its inherited buffers again. */
static void run_child(const ledger_task *t, FILE *out)
{
    ledger_state *s = ledger_state_get();
    const int r0 = s->nrows, e0 = s->nextras;
    t->run(t->arg);
    task_head h = {s->nrows - r0, s->nextras - e0, {0}};
    for (int i = 0; i < LEDGER_MINS; i++)
        h.mins[i] = s->mins[i];
    fwrite(&h, sizeof h, 1, out);
    fwrite(s->rows + r0, sizeof s->rows[0], (size_t)h.nrows, out);
    fwrite(s->extras + e0, sizeof s->extras[0], (size_t)h.nextras, out);
    fflush(stdout);
    fflush(stderr);
    _exit(fflush(out) != 0 || ferror(out) ? 3 : 0);
}

/* In the parent: appends a finished task's results to this process's state. */
static int take_results(FILE *in)
{
    ledger_state *s = ledger_state_get();
    task_head h;
    rewind(in);
    if (fread(&h, sizeof h, 1, in) != 1 || h.nrows < 0 || h.nextras < 0 ||
        s->nrows + h.nrows > LEDGER_MAX || s->nextras + h.nextras > LEDGER_MAX)
        return -1;
    if (fread(s->rows + s->nrows, sizeof s->rows[0], (size_t)h.nrows, in) != (size_t)h.nrows ||
        fread(s->extras + s->nextras, sizeof s->extras[0], (size_t)h.nextras, in) !=
            (size_t)h.nextras)
        return -1;
    s->nrows += h.nrows;
    s->nextras += h.nextras;
    for (int i = 0; i < LEDGER_MINS; i++)
        s->mins[i] = fmin(s->mins[i], h.mins[i]);
    return 0;
}

/* Starts task i in a child writing to an unnamed temporary file; 0, or -1 when it cannot. */
static int start(const ledger_task *t, FILE **out, pid_t *pid)
{
    *out = tmpfile();
    if (!*out)
        return -1;
    fflush(NULL); /* nothing buffered is written twice */
    *pid = fork();
    if (*pid == 0)
        run_child(t, *out);
    if (*pid < 0) {
        fclose(*out);
        *out = NULL;
        return -1;
    }
    return 0;
}

/* Waits for one child; the index of its task, or -1 when it failed (said on stderr). */
static int reap(const ledger_task *tasks, const pid_t *pid, int n, int *failed)
{
    int status;
    const pid_t p = wait(&status);
    for (int i = 0; i < n; i++)
        if (pid[i] == p) {
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
                fprintf(stderr, "claims: the section %s (%d) stopped\n", tasks[i].name,
                        tasks[i].arg);
                *failed = 1;
            }
            return i;
        }
    *failed = 1;
    return -1;
}

void ledger_run_tasks(const ledger_task *tasks, int n, int jobs)
{
    if (jobs <= 0) {
        for (int i = 0; i < n; i++)
            tasks[i].run(tasks[i].arg);
        return;
    }
    FILE **out = calloc((size_t)n, sizeof *out);
    pid_t *pid = calloc((size_t)n, sizeof *pid);
    int next = 0, running = 0, failed = 0;
    if (!out || !pid)
        ledger_die("allocating the table of sections");
    while ((next < n && !failed) || running > 0) {
        if (next < n && !failed && running < jobs) {
            if (start(&tasks[next], &out[next], &pid[next]) != 0)
                failed = 1;
            else
                running++, next++;
            continue;
        }
        if (reap(tasks, pid, n, &failed) < 0)
            break; /* no child to wait for: none is left running */
        running--;
    }
    for (int i = 0; i < next && !failed; i++)
        if (take_results(out[i]) != 0)
            failed = 1;
    for (int i = 0; i < next; i++)
        if (out[i])
            fclose(out[i]);
    free(out);
    free(pid);
    if (failed)
        ledger_die("running the ledger's sections");
}
