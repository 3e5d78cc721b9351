/* Output that is all or nothing: a regular file is written through a temporary file in the
 * same directory and renamed into place on commit; a device or pipe (e.g. /dev/null) is
 * written directly and never renamed over; no path means stdout. */
#ifndef SUSLOV_ATOMIC_FILE_H
#define SUSLOV_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *fp;
    const char *path;  /* final path, NULL for stdout */
    char tmp[4096];    /* temporary path, empty when writing directly */
} atomic_file;

/* Returns 0, or -1 with a one-line reason in err. */
int atomic_file_open(atomic_file *af, const char *path, char *err, size_t errlen);
/* Flushes, closes and renames into place. Returns 0, or -1 with a reason. */
int atomic_file_commit(atomic_file *af, char *err, size_t errlen);
/* Closes and removes the temporary file; the final path is left untouched. */
void atomic_file_abort(atomic_file *af);

#endif
