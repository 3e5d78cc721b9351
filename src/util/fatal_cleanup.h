/* Named temporary files removed when a fatal signal ends the process. Every catchable signal
 * whose default action ends the process gets a handler that unlinks the registered names and
 * dies of the same signal (status 128 + n); handlers are installed only where the signal has
 * its default action, so that e.g. nohup's ignored SIGHUP stays ignored. */
#ifndef SUS_SYS_FATAL_CLEANUP_H
#define SUS_SYS_FATAL_CLEANUP_H

#include <signal.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Blocks the asynchronous fatal signals (and with sync the synchronous ones, SIGSEGV and its
 * kind, too), saving the old mask in *old for sigprocmask(SIG_SETMASK, old, NULL). */
void sus_sys_cleanup_block(sigset_t *old, int sync);
/* mkstemp(tmpl) with its name registered for removal, atomically as far as any catchable
 * signal can tell. Returns the descriptor and *slot, or -1 (errno; tmpl emptied). */
int sus_sys_cleanup_mkstemp(char *tmpl, int *slot);
/* Forgets the name in *slot (the file was renamed or removed); *slot becomes -1. */
void sus_sys_cleanup_forget(int *slot);
/* Unlinks every registered name now; async-signal-safe, for a program's own handler. */
void sus_sys_cleanup_remove_all(void);

#ifdef __cplusplus
}
#endif

#endif
