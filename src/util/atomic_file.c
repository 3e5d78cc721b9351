#define _GNU_SOURCE /* O_TMPFILE, AT_EMPTY_PATH */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- named temporaries removed on a fatal signal ---- */

enum { SLOTS = 8 };
static const int CLEANUP_SIGNALS[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
static char slot_name[SLOTS][4096];
static volatile sig_atomic_t slot_used[SLOTS];

/* Async-signal-safe: unlink, sigaction and raise only. The signal is blocked while its
 * handler runs, so raise() leaves it pending; it is delivered with the default action on
 * return and the process ends with the conventional status 128 + signo. */
static void cleanup_and_die(int sig)
{
    for (int i = 0; i < SLOTS; i++)
        if (slot_used[i])
            unlink(slot_name[i]);
    struct sigaction dfl;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);
}

static void install_handlers(void)
{
    static int installed;
    if (installed)
        return;
    installed = 1;
    for (size_t i = 0; i < sizeof CLEANUP_SIGNALS / sizeof CLEANUP_SIGNALS[0]; i++) {
        struct sigaction old, sa;
        /* Leave a signal that is ignored or already handled alone (nohup, the caller). */
        if (sigaction(CLEANUP_SIGNALS[i], NULL, &old) != 0 || old.sa_handler != SIG_DFL)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = cleanup_and_die;
        sigemptyset(&sa.sa_mask);
        sigaction(CLEANUP_SIGNALS[i], &sa, NULL);
    }
}

static void block_signals(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (size_t i = 0; i < sizeof CLEANUP_SIGNALS / sizeof CLEANUP_SIGNALS[0]; i++)
        sigaddset(&set, CLEANUP_SIGNALS[i]);
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

static void slot_release(int *slot)
{
    if (*slot >= 0)
        slot_used[*slot] = 0;
    *slot = -1;
}

/* ---- paths ---- */

static void dir_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, len, ".");
    else if (slash == path)
        snprintf(dir, len, "/");
    else
        snprintf(dir, len, "%.*s", (int)(slash - path), path);
}

/* The file a write to path replaces: path itself, or where its symbolic link points (a
 * dangling link is followed one level, so that writing creates its target, as a shell
 * redirection does). */
static int resolve_target(const char *path, char *out, size_t len, char *err, size_t errlen)
{
    struct stat lsb;
    if (lstat(path, &lsb) != 0 || !S_ISLNK(lsb.st_mode)) {
        if ((size_t)snprintf(out, len, "%s", path) >= len)
            goto too_long;
        return 0;
    }
    char *real = realpath(path, NULL);
    if (real) {
        const int n = snprintf(out, len, "%s", real);
        free(real);
        if ((size_t)n >= len)
            goto too_long;
        return 0;
    }
    char link[4096], dir[4096];
    const ssize_t n = readlink(path, link, sizeof link - 1);
    if (n < 0) {
        snprintf(err, errlen, "cannot read the link %s: %s", path, strerror(errno));
        return -1;
    }
    link[n] = '\0';
    dir_of(path, dir, sizeof dir);
    if ((size_t)(link[0] == '/' ? snprintf(out, len, "%s", link) : snprintf(out, len, "%s/%s", dir, link)) >= len)
        goto too_long;
    return 0;
too_long:
    snprintf(err, errlen, "output path too long");
    return -1;
}

int atomic_file_check(const char *path, char *err, size_t errlen)
{
    char target[4096], dir[4096];
    struct stat sb;
    if (path == NULL)
        return 0;
    if (path[0] == '\0') {
        snprintf(err, errlen, "the output path is empty");
        return -1;
    }
    if (resolve_target(path, target, sizeof target, err, errlen) != 0)
        return -1;
    if (stat(target, &sb) == 0) {
        if (S_ISDIR(sb.st_mode)) {
            snprintf(err, errlen, "cannot write %s: it is a directory", path);
            return -1;
        }
        if (!S_ISREG(sb.st_mode)) { /* a device or pipe is written in place */
            if (access(target, W_OK) != 0) {
                snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
                return -1;
            }
            return 0;
        }
    } else if (errno != ENOENT) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    dir_of(target, dir, sizeof dir);
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        snprintf(err, errlen, "cannot write %s: directory %s does not exist", path, dir);
        return -1;
    }
    /* The file is created and renamed in its directory: that needs write and search. */
    if (access(dir, W_OK | X_OK) != 0) {
        snprintf(err, errlen, "cannot write %s: directory %s: %s", path, dir, strerror(errno));
        return -1;
    }
    return 0;
}

int atomic_file_open(atomic_file *af, const char *path, char *err, size_t errlen)
{
    struct stat sb;
    af->path = path;
    af->fp = NULL;
    af->target[0] = af->tmp[0] = '\0';
    af->unnamed = 0;
    af->slot = -1;
    if (path == NULL) {
        af->fp = stdout;
        return 0;
    }
    if (atomic_file_check(path, err, errlen) != 0 ||
        resolve_target(path, af->target, sizeof af->target, err, errlen) != 0)
        return -1;
    const int exists = stat(af->target, &sb) == 0;
    if (exists && !S_ISREG(sb.st_mode)) {
        af->target[0] = '\0';
        af->fp = fopen(path, "w");
        if (!af->fp) {
            snprintf(err, errlen, "cannot open %s: %s", path, strerror(errno));
            return -1;
        }
        return 0;
    }
    mode_t mode;
    if (exists) {
        mode = sb.st_mode & 07777;
    } else { /* what open(path, O_CREAT, 0666) would give: umask() is the only way to read it */
        const mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    char dir[4096];
    dir_of(af->target, dir, sizeof dir);
    int fd = -1;
    /* O_TMPFILE needs a way to name the file later: /proc/self/fd (or CAP_DAC_READ_SEARCH
     * for AT_EMPTY_PATH); without /proc use a named temporary from the start. */
    /* SUSLOV_NO_O_TMPFILE (a test hook) forces the fallback, so that tests cover both ways. */
    const char *no_tmpfile = getenv("SUSLOV_NO_O_TMPFILE");
    if (access("/proc/self/fd", X_OK) == 0 && !(no_tmpfile && *no_tmpfile))
        fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    if (fd >= 0) {
        af->unnamed = 1;
    } else { /* the filesystem lacks O_TMPFILE: named temporary, removed on a signal */
        if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s.tmp.XXXXXX", af->target) >= sizeof af->tmp) {
            snprintf(err, errlen, "output path too long");
            af->tmp[0] = '\0';
            return -1;
        }
        install_handlers();
        sigset_t old;
        block_signals(&old);
        fd = mkstemp(af->tmp);
        const int saved = errno;
        if (fd >= 0)
            af->slot = slot_take(af->tmp);
        sigprocmask(SIG_SETMASK, &old, NULL);
        if (fd < 0) {
            snprintf(err, errlen, "cannot create a temporary file next to %s: %s", path, strerror(saved));
            af->tmp[0] = '\0';
            return -1;
        }
    }
    /* fchmod ignores the umask: an existing file keeps exactly its mode. */
    if (fchmod(fd, mode) != 0 || !(af->fp = fdopen(fd, "w"))) {
        snprintf(err, errlen, "cannot create %s: %s", path, strerror(errno));
        close(fd);
        atomic_file_abort(af);
        return -1;
    }
    return 0;
}

/* Gives the unnamed file a temporary name in the target's directory. */
static int link_unnamed(atomic_file *af)
{
    char proc[64];
    const int fd = fileno(af->fp);
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
    for (int i = 0; i < 1000; i++) {
        if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s.tmp.%ld.%d", af->target, (long)getpid(), i) >=
            sizeof af->tmp) {
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

int atomic_file_commit(atomic_file *af, char *err, size_t errlen)
{
    const char *name = af->path ? af->path : "stdout";
    if (af->fp == stdout) {
        if ((fflush(stdout) != 0) | ferror(stdout)) {
            snprintf(err, errlen, "writing stdout failed: %s", strerror(errno));
            return -1;
        }
        return 0;
    }
    sigset_t old;
    int bad = 0, saved = 0;
    const char *what = "writing";
    /* No signal between naming and renaming: a signal arriving now is handled after the
     * commit, and only a SIGKILL in these few microseconds can leave the linked name. */
    block_signals(&old);
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
    if (!bad && af->tmp[0] && rename(af->tmp, af->target) != 0) {
        bad = 1;
        saved = errno;
        what = "renaming into";
    }
    if (bad && af->tmp[0])
        unlink(af->tmp);
    af->tmp[0] = '\0';
    slot_release(&af->slot);
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (bad)
        snprintf(err, errlen, "%s %s failed: %s", what, name, strerror(saved));
    return bad ? -1 : 0;
}

void atomic_file_abort(atomic_file *af)
{
    sigset_t old;
    block_signals(&old);
    if (af->fp && af->fp != stdout)
        fclose(af->fp);
    if (af->tmp[0])
        unlink(af->tmp);
    af->tmp[0] = '\0';
    slot_release(&af->slot);
    af->fp = NULL;
    sigprocmask(SIG_SETMASK, &old, NULL);
}
