#define _GNU_SOURCE /* O_TMPFILE, AT_EMPTY_PATH */
#include "atomic_file.h"

#include "echo.h"
#include "fatal_cleanup.h"
#include "path_resolve.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void sus_sys_atomic_file_remove_temporaries(void) { sus_sys_cleanup_remove_all(); }

/* A path as a message shows it (echo.h): at most PATH_ECHO_MAX characters, so that the two a
 * message may name and its reason fit the 1024 bytes callers give it. */
enum { PATH_ECHO_MAX = 100 };
static const char *shown(const char *path)
{
    return sus_sys_echo_ring(path, strlen(path), PATH_ECHO_MAX, 0);
}

static int is_stdout(const char *path) { return path == NULL || strcmp(path, "-") == 0; }

/* A one-line reason in err; returns -1. */
static int fail(char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return -1;
}

/* The file a write to path replaces: path itself, or the end of its chain of symbolic links
 * (path_resolve.h; a dangling chain ends in the name that writing creates, as a shell
 * redirection does). */
static int resolve_target(const char *path, char *out, size_t len, char *err, size_t errlen)
{
    if (sus_sys_link_target(path, out, len) == 0)
        return 0;
    if (errno == ENAMETOOLONG)
        return fail(err, errlen, "output path too long");
    return fail(err, errlen, "cannot write %s: %s", shown(path), strerror(errno));
}
/* The target's name and the temporary's must fit the directory's limits. */
static int check_names(const char *path, const char *target, const char *dir, char *err,
                       size_t errlen)
{
    const char *base = strrchr(target, '/') ? strrchr(target, '/') + 1 : target;
    const long name_max = pathconf(dir, _PC_NAME_MAX);
    const size_t tmp_len =
        strlen(dir) + 1 + strlen(SUS_SYS_ATOMIC_TMP_PREFIX) + SUS_SYS_ATOMIC_TMP_SUFFIX_MAX;
    if (name_max > 0 && strlen(base) > (size_t)name_max)
        return fail(err, errlen, "cannot write %s: its name is longer than the directory allows",
                    shown(path));
    if (strlen(target) >= PATH_MAX || tmp_len >= PATH_MAX ||
        tmp_len >= sizeof((sus_sys_atomic_file *)0)->tmp)
        return fail(err, errlen, "cannot write %s: the path (or its temporary in %s) is too long",
                    shown(path), shown(dir));
    return 0;
}

/* Read-only, for everyone: the owner's write bit clear (chmod u-w, mode 444). root's access()
 * succeeds whatever the mode, so the bit is read as well; a file or directory its owner may not
 * write is then refused to root as to any other user. */
static int owner_may_write(const struct stat *sb) { return (sb->st_mode & S_IWUSR) != 0; }

/* Replacing an existing regular file: not the root of a mount (a bind-mounted file: the rename
 * would fail with EBUSY after the run; it is refused rather than written in place, which would
 * break all-or-nothing), not a read-only one (as cp without -f; owner_may_write), and in a
 * sticky directory only as the owner of the file or of the directory (else the rename fails). */
static int check_replace(const char *path, const char *target, const struct stat *fsb,
                         const char *dir, char *err, size_t errlen)
{
    struct stat dsb;
    if (sus_sys_is_mount_root(target, dir))
        return fail(err, errlen,
                    "cannot replace %s: it is a mount point (a bind-mounted file), "
                    "which no rename can replace; to write it in place, redirect stdout: "
                    "--output - > FILE",
                    shown(path));
    if (access(target, W_OK) != 0)
        return fail(err, errlen,
                    "%s is read-only (%s): not replaced; remove it or make it writable first",
                    shown(path), strerror(errno));
    if (!owner_may_write(fsb))
        return fail(
            err, errlen,
            "%s is read-only (mode %03o): not replaced; remove it or make it writable first",
            shown(path), (unsigned)(fsb->st_mode & 07777));
    const uid_t me = geteuid();
    if (stat(dir, &dsb) == 0 && (dsb.st_mode & S_ISVTX) && me != 0 && me != fsb->st_uid &&
        me != dsb.st_uid)
        return fail(err, errlen,
                    "cannot replace %s: directory %s is sticky and neither it nor the file is "
                    "yours, so the rename would be refused",
                    shown(path), shown(dir));
    return 0;
}

/* A file can be created in dir: tried, since neither access() (always yes for root) nor the
 * mode tells where a pseudo filesystem (/proc, /sys) refuses every new file. An unnamed
 * O_TMPFILE file, closed at once, leaves nothing; where the filesystem has no O_TMPFILE, a named
 * temporary, removed at once (and on a fatal signal meanwhile), as the open would make. Only a
 * refusal of the path is found here; a lack of resources (no space or inode, I/O) is not the
 * path's fault and is met, and reported as such, by the open. */
static int probe_create(const char *path, const char *dir, char *err, size_t errlen)
{
    char tmp[4096];
    int slot = -1, fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
    if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
        snprintf(tmp, sizeof tmp, "%s/%sXXXXXX", dir, SUS_SYS_ATOMIC_TMP_PREFIX);
        if ((fd = sus_sys_cleanup_mkstemp(tmp, &slot)) >= 0) {
            unlink(tmp);
            sus_sys_cleanup_forget(&slot);
        }
    }
    if (fd >= 0)
        return close(fd), 0;
    const int why = errno; /* ENOENT in a directory that exists: no file can be created there */
    if (why != EACCES && why != EPERM && why != EROFS && why != ENOENT)
        return 0;
    return fail(err, errlen, "cannot create a temporary file next to %s: %s%s", shown(path),
                strerror(why), why == ENOENT ? " (its filesystem creates no files)" : "");
}

int sus_sys_atomic_file_check(const char *path, char *err, size_t errlen)
{
    char target[4096], dir[4096];
    struct stat sb;
    if (is_stdout(path))
        return 0;
    if (path[0] == '\0')
        return fail(err, errlen, "the output path is empty");
    const int fd = sus_sys_fd_of_path(path);
    if (fd >= 0) {
        const int fl = fcntl(fd, F_GETFL);
        if (fl < 0 || (fl & O_ACCMODE) == O_RDONLY)
            return fail(err, errlen, "cannot write %s: its descriptor is not open for writing",
                        shown(path));
        return 0;
    }
    if (resolve_target(path, target, sizeof target, err, errlen) != 0)
        return -1;
    const int exists = stat(target, &sb) == 0;
    if (!exists && errno != ENOENT)
        return fail(err, errlen, "cannot write %s: %s", shown(path), strerror(errno));
    if (exists && S_ISDIR(sb.st_mode))
        return fail(err, errlen, "cannot write %s: it is a directory", shown(path));
    if (exists && !S_ISREG(sb.st_mode)) /* a device or pipe is written in place */
        return access(target, W_OK) == 0
                   ? 0
                   : fail(err, errlen, "cannot write %s: %s", shown(path), strerror(errno));
    sus_sys_dir_of(target, dir, sizeof dir);
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return fail(err, errlen, "cannot write %s: directory %s does not exist", shown(path),
                    shown(dir));
    /* The file is created and renamed in its directory: that needs write and search. */
    if (access(dir, W_OK | X_OK) != 0) {
        snprintf(err, errlen, "cannot write %s: directory %s: %s", shown(path), shown(dir),
                 strerror(errno));
        return -1;
    }
    if (!owner_may_write(&sb))
        return fail(err, errlen, "cannot write %s: directory %s is read-only (mode %03o)",
                    shown(path), shown(dir), (unsigned)(sb.st_mode & 07777));
    if (check_names(path, target, dir, err, errlen) != 0)
        return -1;
    if (exists && stat(target, &sb) == 0 && check_replace(path, target, &sb, dir, err, errlen))
        return -1;
    return probe_create(path, dir, err, errlen);
}

/* stdout, a descriptor, a device or a pipe: written where it is. */
static int open_in_place(sus_sys_atomic_file *af, const char *path, int fd, char *err,
                         size_t errlen)
{
    af->in_place = 1;
    af->target[0] = '\0';
    if (is_stdout(path)) {
        af->fp = stdout;
        return 0;
    }
    const int mine = fd >= 0 ? fcntl(fd, F_DUPFD_CLOEXEC, 3) : open(path, O_WRONLY | O_CLOEXEC);
    if (mine < 0 || !(af->fp = fdopen(mine, "w"))) {
        const int saved = errno;
        snprintf(err, errlen, "cannot open %s: %s", shown(path), strerror(saved));
        if (mine >= 0)
            close(mine);
        errno = saved;
        return -1;
    }
    return 0;
}

/* A named temporary in dir, registered for removal on a signal. */
static int open_named(sus_sys_atomic_file *af, const char *dir)
{
    /* the length was checked by check_names */
    if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s/%sXXXXXX", dir, SUS_SYS_ATOMIC_TMP_PREFIX) >=
        sizeof af->tmp) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return sus_sys_cleanup_mkstemp(af->tmp, &af->slot);
}

static mode_t mode_for(int exists, const struct stat *sb)
{
    if (exists)
        return sb->st_mode & 07777;
    /* what open(path, O_CREAT, 0666) would give: umask() is the only way to read it */
    const mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

int sus_sys_atomic_file_open(sus_sys_atomic_file *af, const char *path, char *err, size_t errlen)
{
    struct stat sb;
    *af = (sus_sys_atomic_file){.path = is_stdout(path) ? NULL : path, .slot = -1};
    if (sus_sys_atomic_file_check(path, err, errlen) != 0)
        return -1;
    const int dfd = is_stdout(path) ? -1 : sus_sys_fd_of_path(path);
    if (is_stdout(path) || dfd >= 0)
        return open_in_place(af, path, dfd, err, errlen);
    if (resolve_target(path, af->target, sizeof af->target, err, errlen) != 0)
        return -1;
    const int exists = stat(af->target, &sb) == 0;
    af->existed = exists;
    if (exists && !S_ISREG(sb.st_mode))
        return open_in_place(af, path, -1, err, errlen);
    const mode_t mode = mode_for(exists, &sb);
    char dir[4096];
    sus_sys_dir_of(af->target, dir, sizeof dir);
    int fd = -1;
    /* O_TMPFILE needs a way to name the file later: /proc/self/fd (or CAP_DAC_READ_SEARCH
     * for AT_EMPTY_PATH); without /proc use a named temporary from the start.
     * SUSLOV_NO_O_TMPFILE (a test hook) forces the fallback, so that tests cover both ways. */
    const char *no_tmpfile = getenv("SUSLOV_NO_O_TMPFILE");
    if (access("/proc/self/fd", X_OK) == 0 && !(no_tmpfile && *no_tmpfile))
        fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    af->unnamed = fd >= 0;
    if (fd < 0 && (fd = open_named(af, dir)) < 0) {
        snprintf(err, errlen, "cannot create a temporary file next to %s: %s", shown(path),
                 strerror(errno));
        return -1;
    }
    /* fchmod ignores the umask: an existing file keeps exactly its mode. */
    if (fchmod(fd, mode) != 0 || !(af->fp = fdopen(fd, "w"))) {
        const int saved = errno; /* for the caller, past the cleanup */
        snprintf(err, errlen, "cannot create %s: %s", shown(path), strerror(saved));
        close(fd);
        sus_sys_atomic_file_abort(af);
        errno = saved;
        return -1;
    }
    return 0;
}

/* Gives the unnamed file a temporary name in the target's directory. */
static int link_unnamed(sus_sys_atomic_file *af)
{
    char proc[64], dir[4096];
    const int fd = fileno(af->fp);
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
    sus_sys_dir_of(af->target, dir, sizeof dir);
    for (int i = 0; i < 1000; i++) {
        if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s/%s%ld.%d", dir, SUS_SYS_ATOMIC_TMP_PREFIX,
                             (long)getpid(), i) >= sizeof af->tmp) {
            errno = ENAMETOOLONG;
            break;
        }
        if (linkat(AT_FDCWD, proc, AT_FDCWD, af->tmp, AT_SYMLINK_FOLLOW) == 0 ||
            (errno != EEXIST && linkat(fd, "", AT_FDCWD, af->tmp, AT_EMPTY_PATH) == 0))
            return 0;
        if (errno != EEXIST)
            break;
    }
    af->tmp[0] = '\0';
    return -1;
}

static int commit_in_place(sus_sys_atomic_file *af, char *err, size_t errlen)
{
    const char *name = af->path ? af->path : "stdout";
    int bad = (fflush(af->fp) != 0) | ferror(af->fp);
    int saved = errno;
    if (af->fp != stdout && fclose(af->fp) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    af->fp = NULL;
    if (bad)
        snprintf(err, errlen, "writing %s failed: %s", shown(name), strerror(saved));
    return bad ? -1 : 0;
}

int sus_sys_atomic_file_commit(sus_sys_atomic_file *af, char *err, size_t errlen)
{
    if (af->in_place)
        return commit_in_place(af, err, errlen);
    sigset_t old;
    int bad = 0, saved = 0;
    const char *what = "writing";
    /* No signal between naming and renaming: a signal arriving now is handled after the
     * commit, and only a SIGKILL in these few microseconds can leave the linked name. */
    sus_sys_cleanup_block(&old, 0);
    if ((fflush(af->fp) != 0) | ferror(af->fp)) {
        bad = 1;
        saved = errno;
    }
    if (!bad && af->unnamed && link_unnamed(af) != 0) {
        bad = 1;
        saved = errno;
        what = "naming the temporary for";
    }
    if (fclose(af->fp) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    af->fp = NULL;
    if (!bad && rename(af->tmp, af->target) != 0) {
        bad = 1;
        saved = errno;
        what = "renaming into";
    }
    if (bad && af->tmp[0])
        unlink(af->tmp);
    af->tmp[0] = '\0';
    sus_sys_cleanup_forget(&af->slot);
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (bad)
        snprintf(err, errlen, "%s %s failed: %s", what, shown(af->path), strerror(saved));
    return bad ? -1 : 0;
}

void sus_sys_atomic_file_abort(sus_sys_atomic_file *af)
{
    sigset_t old;
    sus_sys_cleanup_block(&old, 0);
    if (af->fp && af->fp != stdout)
        fclose(af->fp);
    if (af->tmp[0])
        unlink(af->tmp);
    af->tmp[0] = '\0';
    sus_sys_cleanup_forget(&af->slot);
    af->fp = NULL;
    sigprocmask(SIG_SETMASK, &old, NULL);
}
