#define _GNU_SOURCE /* statx */
#include "path_resolve.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* As the kernel allows on one path (MAXSYMLINKS). */
enum { MAX_LINKS = 40 };

void sus_sys_dir_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, len, ".");
    else if (slash == path)
        snprintf(dir, len, "/");
    else
        snprintf(dir, len, "%.*s", (int)(slash - path), path);
}

/* N when s is "/dev/fd/N" or "/proc/self/fd/N" (or /dev/stdout, /dev/stderr), else -1. */
static int fd_named(const char *s)
{
    static const char *const PREFIX[] = {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/"};
    if (strcmp(s, "/dev/stdout") == 0)
        return 1;
    if (strcmp(s, "/dev/stderr") == 0)
        return 2;
    for (size_t i = 0; i < sizeof PREFIX / sizeof PREFIX[0]; i++) {
        const size_t n = strlen(PREFIX[i]);
        char *end;
        if (strncmp(s, PREFIX[i], n) != 0 || s[n] < '0' || s[n] > '9')
            continue;
        errno = 0;
        const long fd = strtol(s + n, &end, 10);
        if (*end == '\0' && errno == 0 && fd <= INT_MAX)
            return (int)fd;
    }
    return -1;
}

/* One hop along a chain: cur becomes what the link cur points to. Returns 1 after a hop, 0 when
 * cur is no link (or cannot be read), -1 when the new path is too long (errno ENAMETOOLONG). */
static int hop(char *cur, size_t len)
{
    char link[PATH_MAX], dir[PATH_MAX];
    const ssize_t n = readlink(cur, link, sizeof link - 1);
    if (n < 0) /* no link, or no file: a later stat says why, if it matters */
        return 0;
    link[n] = '\0';
    sus_sys_dir_of(cur, dir, sizeof dir);
    const int w =
        link[0] == '/' ? snprintf(cur, len, "%s", link) : snprintf(cur, len, "%s/%s", dir, link);
    if (w < 0 || (size_t)w >= len) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return 1;
}

int sus_sys_fd_of_path(const char *path)
{
    char cur[PATH_MAX];
    if ((size_t)snprintf(cur, sizeof cur, "%s", path) >= sizeof cur)
        return -1;
    for (int hops = 0; hops <= MAX_LINKS; hops++) {
        const int fd = fd_named(cur);
        if (fd >= 0)
            return fd;
        if (hop(cur, sizeof cur) != 1)
            return -1;
    }
    return -1;
}

int sus_sys_link_target(const char *path, char *out, size_t len)
{
    if ((size_t)snprintf(out, len, "%s", path) >= len) {
        errno = ENAMETOOLONG;
        return -1;
    }
    for (int hops = 0; hops <= MAX_LINKS; hops++) {
        const int r = hop(out, len);
        if (r <= 0)
            return r;
    }
    errno = ELOOP;
    return -1;
}

/* Devices differ: a mount from another filesystem (all that can be told without statx). */
static int other_device(const char *path, const char *dir)
{
    struct stat fs, ds;
    return stat(path, &fs) == 0 && stat(dir, &ds) == 0 && fs.st_dev != ds.st_dev;
}

int sus_sys_is_mount_root(const char *path, const char *dir)
{
#ifdef STATX_ATTR_MOUNT_ROOT /* Linux 5.8; a bind mount from the same filesystem keeps st_dev */
    struct statx f, d;
    if (statx(AT_FDCWD, path, 0, STATX_BASIC_STATS | STATX_MNT_ID, &f) != 0)
        return other_device(path, dir); /* no statx: an old kernel, a filter */
    if (f.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT)
        return (f.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
    if (statx(AT_FDCWD, dir, 0, STATX_BASIC_STATS | STATX_MNT_ID, &d) == 0 &&
        (f.stx_mask & STATX_MNT_ID) && (d.stx_mask & STATX_MNT_ID))
        return f.stx_mnt_id != d.stx_mnt_id;
#endif
    return other_device(path, dir);
}
