#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int atomic_file_open(atomic_file *af, const char *path, char *err, size_t errlen)
{
    struct stat sb;
    af->path = path;
    af->tmp[0] = '\0';
    if (path == NULL) {
        af->fp = stdout;
        return 0;
    }
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        af->fp = fopen(path, "w");
        if (!af->fp) {
            snprintf(err, errlen, "cannot open %s: %s", path, strerror(errno));
            return -1;
        }
        return 0;
    }
    if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s.tmp.XXXXXX", path) >= sizeof af->tmp) {
        snprintf(err, errlen, "output path too long");
        af->tmp[0] = '\0';
        return -1;
    }
    const int fd = mkstemp(af->tmp);
    if (fd < 0 || !(af->fp = fdopen(fd, "w"))) {
        snprintf(err, errlen, "cannot create a temporary file next to %s: %s", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(af->tmp);
        }
        af->tmp[0] = '\0';
        return -1;
    }
    fchmod(fd, 0644);
    return 0;
}

int atomic_file_commit(atomic_file *af, char *err, size_t errlen)
{
    const int bad = ferror(af->fp) | (af->fp == stdout ? fflush(af->fp) : fclose(af->fp));
    if (bad) {
        snprintf(err, errlen, "writing %s failed: %s", af->path ? af->path : "stdout", strerror(errno));
        if (af->tmp[0])
            unlink(af->tmp);
        return -1;
    }
    if (af->tmp[0] && rename(af->tmp, af->path) != 0) {
        snprintf(err, errlen, "cannot rename into %s: %s", af->path, strerror(errno));
        unlink(af->tmp);
        return -1;
    }
    return 0;
}

void atomic_file_abort(atomic_file *af)
{
    if (af->fp && af->fp != stdout)
        fclose(af->fp);
    if (af->tmp[0])
        unlink(af->tmp);
    af->fp = NULL;
}
