/* Output that is all or nothing, and leaves no temporary file behind.
 *
 * A regular file is written unnamed (O_TMPFILE) in the target's directory and linked in
 * under a temporary name, then renamed over the target, only on commit: a process killed
 * even by SIGKILL leaves no file. Where O_TMPFILE is unsupported (or /proc is missing) the
 * file is a named mkstemp temporary, which every catchable fatal signal removes
 * (fatal_cleanup.h). The temporary's name, SUS_SYS_ATOMIC_TMP_PREFIX plus at most
 * SUS_SYS_ATOMIC_TMP_SUFFIX_MAX characters, does not grow with the target's name, so any valid
 * target name can be written. An abort (a failed run) leaves the target as it was.
 *
 * Unix semantics, as a shell redirection where it can be and as cp without -f where not:
 * - no path, or "-", means stdout, written in place and never renamed;
 * - a path that names an open descriptor (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N,
 *   or a link to one) is written in place through that descriptor, at its offset and in its
 *   append mode, whatever file it refers to;
 * - a device or pipe is written in place;
 * - a regular file is replaced atomically: a new file gets 0666 & ~umask, an existing file
 *   keeps its mode but not its owner (the writer owns the new file) and not its hard links
 *   (the other names keep the old contents); a read-only file or directory is refused (one the
 *   caller may not write, or whose owner may not: mode u-w, which root's access() ignores), and
 *   so is the root of a mount (a bind-mounted file), which no rename can replace;
 * - a symbolic link, or a chain of them, is written through: the file at the chain's end is
 *   replaced, or created when the chain dangles (l1 -> l2 -> missing.csv creates missing.csv),
 *   and the links stay links. */
#ifndef SUS_SYS_ATOMIC_FILE_H
#define SUS_SYS_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SUS_SYS_ATOMIC_TMP_PREFIX ".tmp."
#define SUS_SYS_ATOMIC_TMP_SUFFIX_MAX 24 /* "XXXXXX" or "PID.I": a pid and a counter below 1000 */

typedef struct {
    FILE *fp;
    const char *path;  /* as given, NULL for stdout */
    char target[4096]; /* the file replaced on commit: path, or the end of its chain of links */
    char tmp[4096];    /* named temporary path, empty when unnamed or writing directly */
    int unnamed;       /* 1: an O_TMPFILE file, named only on commit */
    int in_place;      /* 1: stdout, a descriptor, a device or a pipe: never renamed */
    int existed;       /* 1: the target existed when opened (an abort leaves it as it was) */
    int slot;          /* its entry in the signal-cleanup table, or -1 */
} sus_sys_atomic_file;

/* Checks, leaving nothing behind, every condition of a later commit that can be checked now:
 * the path is non-empty and not a directory; for a descriptor, device or pipe, that it can be
 * written; for a regular file, that its chain of links ends within 40 links, that it is not
 * read-only nor the root of a mount, that its directory exists, is writable and not read-only,
 * that the temporary's name fits (NAME_MAX, PATH_MAX), that the rename is permitted (a sticky
 * directory lets only the owner of the file or directory replace it), and last, by creating
 * one, that a file can be created in the directory (an unnamed O_TMPFILE file, or where the
 * filesystem has none a named temporary, each removed at once).
 * Returns 0, or -1 with a one-line reason in err. */
int sus_sys_atomic_file_check(const char *path, char *err, size_t errlen);
/* Returns 0, or -1 with a one-line reason in err and errno its cause (nothing is left behind). */
int sus_sys_atomic_file_open(sus_sys_atomic_file *af, const char *path, char *err, size_t errlen);
/* Flushes, closes and renames into place. Returns 0, or -1 with a reason. */
int sus_sys_atomic_file_commit(sus_sys_atomic_file *af, char *err, size_t errlen);
/* Closes and removes the temporary file; the final path is left untouched (in place: what was
 * written stays written). */
void sus_sys_atomic_file_abort(sus_sys_atomic_file *af);
/* Removes every named temporary now open; async-signal-safe, for a program that handles a
 * signal itself (its handler then takes precedence over this file's). */
void sus_sys_atomic_file_remove_temporaries(void);

#ifdef __cplusplus
}
#endif

#endif
