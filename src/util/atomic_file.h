/* Output that is all or nothing, and leaves no temporary file behind.
 *
 * A regular file is written unnamed (O_TMPFILE) in the target's directory and linked in
 * under a temporary name, then renamed over the target, only on commit: a process killed
 * even by SIGKILL leaves no file. Where O_TMPFILE is unsupported (or /proc is missing) the
 * file is a named mkstemp temporary; SIGINT, SIGTERM, SIGHUP and SIGPIPE then remove it
 * before the process dies of the signal (handlers are installed only where the signal has
 * its default action, so e.g. nohup's ignored SIGHUP stays ignored).
 *
 * Unix semantics: a new file gets 0666 & ~umask, an existing file keeps its mode, and a
 * symbolic link is written through (its target is replaced, the link stays). A device or
 * pipe (e.g. /dev/null) is written directly and never renamed over; no path means stdout. */
#ifndef SUSLOV_ATOMIC_FILE_H
#define SUSLOV_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *fp;
    const char *path;     /* as given, NULL for stdout */
    char target[4096];    /* the file replaced on commit: path, or the target of the link */
    char tmp[4096];       /* named temporary path, empty when unnamed or writing directly */
    int unnamed;          /* 1: an O_TMPFILE file, named only on commit */
    int slot;             /* its entry in the signal-cleanup table, or -1 */
} atomic_file;

/* Checks that path can be written (non-empty, not a directory, its directory exists and is
 * writable) without creating anything. Returns 0, or -1 with a one-line reason in err. */
int atomic_file_check(const char *path, char *err, size_t errlen);
/* Returns 0, or -1 with a one-line reason in err (nothing is left behind). */
int atomic_file_open(atomic_file *af, const char *path, char *err, size_t errlen);
/* Flushes, closes and renames into place. Returns 0, or -1 with a reason. */
int atomic_file_commit(atomic_file *af, char *err, size_t errlen);
/* Closes and removes the temporary file; the final path is left untouched. */
void atomic_file_abort(atomic_file *af);

#endif
