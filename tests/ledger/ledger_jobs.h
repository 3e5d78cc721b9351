/* The ledger's sections on every core: each section a process of its own, forked from the one
 * that made what the sections share, so that a section starts from that state and never from
 * another section's; their lines come back in the order of the list, whatever the order they end
 * in. The ledger is therefore the same, byte for byte, however many run at once; make
 * ledger-inproc (CI) compares it with a run of one section after the other in a single process
 * (claims --in-process, into build/ledger-inproc), which a section leaning on another's state
 * would fail. */
#ifndef SUSLOV_LEDGER_JOBS_H
#define SUSLOV_LEDGER_JOBS_H

typedef struct {
    const char *name; /* for the message when it fails */
    void (*run)(int arg);
    int arg;
} ledger_task;

/* Runs tasks[0..n) on up to jobs processes at once (jobs = 0: one after the other, in this
 * process; 1: one after the other, each in a process of its own) and records their lines, their
 * numbers and their minima (ledger_keep_min) here, in the order of the array. A section that stops
 * (ledger_die) or crashes stops the ledger, exit 2, once the running ones have ended. */
void ledger_run_tasks(const ledger_task *tasks, int n, int jobs);

/* The processors online: the default number of jobs. */
int ledger_jobs_online(void);

#endif
