/* Independent jobs on every core: a pool of forked worker processes, each handed the next job as
 * it finishes one, whose results come back through pipes into a caller's array at the job's own
 * index. So the results, and whatever is written from them, are the same bytes whichever process
 * ran which job and in whichever order they finished: each job is a pure function of its index,
 * computed by the same code in the same binary (IEEE arithmetic gives the same bits in a child as
 * in the parent). Processes, not threads: nothing a job touches needs to be thread-safe, and a
 * job that crashes cannot corrupt the others' results.
 *
 * The parent hands the jobs out in the caller's order (the longest first keeps the cores busy to
 * the end) and reports each finished job (a progress line). A worker reads job numbers until its
 * pipe closes; it leaves by _exit, so no atexit handler of the parent (a temporary file's
 * removal) runs twice. A worker that dies, or a job's result that comes back short, fails the run:
 * the other workers are stopped (their pipes closed, SIGTERM) and waited for, and the call returns
 * -1 with one line saying which job. If the parent dies its workers read end of file and leave. */
#ifndef SUS_SYS_WORKPOOL_H
#define SUS_SYS_WORKPOOL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Job `job` (0 <= job < njobs): writes its size-byte result to `result`. */
typedef void (*sus_sys_job_fn)(int job, void *result, void *ctx);
/* Called in the parent as job `job` has come back (its result in place). */
typedef void (*sus_sys_done_fn)(int job, void *ctx);

typedef struct {
    int njobs;
    const int
        *order;    /* the jobs in the order to hand them out (a permutation), or NULL: 0, 1, ... */
    size_t size;   /* bytes of one result */
    void *results; /* njobs * size bytes: job j's result at j * size */
    int workers;   /* processes; <= 1 runs every job in this process, in `order` */
    sus_sys_job_fn run;
    sus_sys_done_fn done; /* or NULL */
    void *ctx;
} sus_sys_pool;

/* The cores available to this process (sysconf), at least 1. */
int sus_sys_pool_cores(void);

/* Runs every job. Returns 0; or -1 with a one-line reason in err (a fork or pipe that failed, a
 * worker that died) and the results undefined. */
int sus_sys_pool_run(const sus_sys_pool *p, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
