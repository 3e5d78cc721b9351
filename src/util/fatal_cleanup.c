#define _GNU_SOURCE /* SIGRTMIN, SIGPWR, SIGSTKFLT */
#include "fatal_cleanup.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { SLOTS = 8 };
/* Every catchable signal whose default action ends the process (besides the real-time ones,
 * added in a loop). The synchronous ones (a fault in the program) are handled but blocked only
 * around mkstemp: a fault while blocked would kill without the handler. */
static const int ASYNC_SIGNALS[] = {
    SIGHUP,    SIGINT,  SIGQUIT, SIGABRT,   SIGUSR1, SIGUSR2, SIGPIPE, SIGALRM,
    SIGTERM,   SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGIO,   SIGPWR,
#ifdef SIGSTKFLT
    SIGSTKFLT,
#endif
};
static const int SYNC_SIGNALS[] = {SIGILL, SIGTRAP, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
static char slot_name[SLOTS][4096];
static volatile sig_atomic_t slot_used[SLOTS];

/* Async-signal-safe: unlink only. */
void sus_sys_cleanup_remove_all(void)
{
    for (int i = 0; i < SLOTS; i++)
        if (slot_used[i])
            unlink(slot_name[i]);
}

/* unlink, sigaction and raise only. The signal is blocked while its handler runs, so raise()
 * leaves it pending; it is delivered with the default action on return and the process ends
 * with the conventional status 128 + signo. */
static void cleanup_and_die(int sig)
{
    sus_sys_cleanup_remove_all();
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);
}

static void handle(int sig)
{
    struct sigaction old, sa;
    /* Leave a signal that is ignored or already handled alone (nohup, the caller, a sanitizer). */
    if (sigaction(sig, NULL, &old) != 0 || old.sa_handler != SIG_DFL)
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = cleanup_and_die;
    sigfillset(&sa.sa_mask); /* no second signal in the middle of the cleanup */
    sigaction(sig, &sa, NULL);
}

static void install_handlers(void)
{
    static int installed;
    if (installed)
        return;
    installed = 1;
    for (size_t i = 0; i < COUNT(ASYNC_SIGNALS); i++)
        handle(ASYNC_SIGNALS[i]);
    for (size_t i = 0; i < COUNT(SYNC_SIGNALS); i++)
        handle(SYNC_SIGNALS[i]);
    for (int s = SIGRTMIN; s <= SIGRTMAX; s++)
        handle(s);
}

/* sync: the synchronous ones too, only around mkstemp and the naming of its slot (libc and a copy,
 * nothing of ours that can fault): the temporary exists before its slot names it, and a kill -FPE
 * sent in between would otherwise leave it. */
void sus_sys_cleanup_block(sigset_t *old, int sync)
{
    sigset_t set;
    sigemptyset(&set);
    for (size_t i = 0; i < COUNT(ASYNC_SIGNALS); i++)
        sigaddset(&set, ASYNC_SIGNALS[i]);
    for (size_t i = 0; sync && i < COUNT(SYNC_SIGNALS); i++)
        sigaddset(&set, SYNC_SIGNALS[i]);
    for (int s = SIGRTMIN; s <= SIGRTMAX; s++)
        sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, old);
}

/* With the signals blocked, so that the handler never sees a half-written name. */
static int slot_take(const char *name)
{
    for (int i = 0; i < SLOTS; i++)
        if (!slot_used[i]) {
            snprintf(slot_name[i], sizeof slot_name[i], "%s", name);
            slot_used[i] = 1;
            return i;
        }
    return -1;
}

int sus_sys_cleanup_mkstemp(char *tmpl, int *slot)
{
    install_handlers();
    sigset_t old;
    sus_sys_cleanup_block(&old, 1);
    const int fd = mkstemp(tmpl);
    const int saved = errno;
    if (fd >= 0)
        *slot = slot_take(tmpl);
    else
        tmpl[0] = '\0';
    sigprocmask(SIG_SETMASK, &old, NULL);
    errno = saved;
    return fd;
}

void sus_sys_cleanup_forget(int *slot)
{
    if (*slot >= 0)
        slot_used[*slot] = 0;
    *slot = -1;
}
