#define _GNU_SOURCE /* O_TMPFILE, AT_EMPTY_PATH */
#include "atomic_file.h"

#include "echo.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- named temporaries removed on a fatal signal ---- */

enum { SLOTS = 8 };
/* Every catchable signal whose default action ends the process (besides the real-time ones,
 * added in a loop). The synchronous ones (a fault in the program) are handled but blocked only
 * around mkstemp (block_signals): a fault while blocked would kill without the handler. */
static const int ASYNC_SIGNALS[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGABRT, SIGUSR1, SIGUSR2,   SIGPIPE, SIGALRM,
                                    SIGTERM, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGIO, SIGPWR,
#ifdef SIGSTKFLT
                                    SIGSTKFLT,
#endif
};
static const int SYNC_SIGNALS[] = {SIGILL, SIGTRAP, SIGBUS, SIGFPE, SIGSEGV, SIGSYS};
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
static char slot_name[SLOTS][4096];
static volatile sig_atomic_t slot_used[SLOTS];

/* Async-signal-safe: unlink, sigaction and raise only. The signal is blocked while its
 * handler runs, so raise() leaves it pending; it is delivered with the default action on
 * return and the process ends with the conventional status 128 + signo. */
void sus_sys_atomic_file_remove_temporaries(void)
{
    for (int i = 0; i < SLOTS; i++)
        if (slot_used[i])
            unlink(slot_name[i]);
}

static void cleanup_and_die(int sig)
{
    sus_sys_atomic_file_remove_temporaries();
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
static void block_signals(sigset_t *old, int sync)
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

/* N when s is "/dev/fd/N" or "/proc/self/fd/N" (or /dev/stdout, /dev/stderr), else -1. */
static int fd_named(const char *s)
{
    static const char *const PREFIX[] = {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/"};
    if (strcmp(s, "/dev/stdout") == 0)
        return 1;
    if (strcmp(s, "/dev/stderr") == 0)
        return 2;
    for (size_t i = 0; i < COUNT(PREFIX); i++) {
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

/* The descriptor a path names, following its chain of symbolic links textually (readlink on
 * the descriptor's own magic link would jump to the file, losing the descriptor), or -1. */
static int fd_of_path(const char *path)
{
    char cur[4096], link[4096], dir[4096];
    snprintf(cur, sizeof cur, "%s", path);
    for (int hops = 0; hops < 40; hops++) {
        const int fd = fd_named(cur);
        if (fd >= 0)
            return fd;
        const ssize_t n = readlink(cur, link, sizeof link - 1);
        if (n < 0)
            return -1;
        link[n] = '\0';
        dir_of(cur, dir, sizeof dir);
        if (link[0] == '/')
            snprintf(cur, sizeof cur, "%s", link);
        else if ((size_t)snprintf(cur, sizeof cur, "%s/%s", dir, link) >= sizeof cur)
            return -1;
    }
    return -1;
}

/* A path as a message shows it (echo.h): at most PATH_ECHO_MAX characters, so that the two a
 * message may name and its reason fit the 1024 bytes callers give it. */
enum { PATH_ECHO_MAX = 100 };
static const char *shown(const char *path)
{
    return sus_sys_echo_ring(path, strlen(path), PATH_ECHO_MAX, 0);
}

static int is_stdout(const char *path)
{
    return path == NULL || strcmp(path, "-") == 0;
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
        snprintf(err, errlen, "cannot read the link %s: %s", shown(path), strerror(errno));
        return -1;
    }
    link[n] = '\0';
    dir_of(path, dir, sizeof dir);
    if ((size_t)(link[0] == '/' ? snprintf(out, len, "%s", link) : snprintf(out, len, "%s/%s", dir, link)) >=
        len)
        goto too_long;
    return 0;
too_long:
    snprintf(err, errlen, "output path too long");
    return -1;
}

/* A one-line reason in err; returns -1. */
static int fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return -1;
}

/* The target's name and the temporary's must fit the directory's limits. */
static int check_names(const char *path, const char *target, const char *dir, char *err, size_t errlen)
{
    const char *base = strrchr(target, '/') ? strrchr(target, '/') + 1 : target;
    const long name_max = pathconf(dir, _PC_NAME_MAX);
    const size_t tmp_len =
        strlen(dir) + 1 + strlen(SUS_SYS_ATOMIC_TMP_PREFIX) + SUS_SYS_ATOMIC_TMP_SUFFIX_MAX;
    if (name_max > 0 && strlen(base) > (size_t)name_max)
        return fail(err, errlen, "cannot write %s: its name is longer than the directory allows",
                    shown(path));
    if (strlen(target) >= PATH_MAX || tmp_len >= PATH_MAX || tmp_len >= sizeof((sus_sys_atomic_file *)0)->tmp)
        return fail(err, errlen, "cannot write %s: the path (or its temporary in %s) is too long",
                    shown(path), shown(dir));
    return 0;
}

/* Replacing an existing regular file: not a read-only one (as cp without -f), and in a sticky
 * directory only as the owner of the file or of the directory (else the rename fails). */
static int check_replace(const char *path, const char *target, const struct stat *fsb, const char *dir,
                         char *err, size_t errlen)
{
    struct stat dsb;
    if (access(target, W_OK) != 0)
        return fail(err, errlen, "%s is read-only (%s): not replaced; remove it or make it writable first",
                    shown(path), strerror(errno));
    const uid_t me = geteuid();
    if (stat(dir, &dsb) == 0 && (dsb.st_mode & S_ISVTX) && me != 0 && me != fsb->st_uid && me != dsb.st_uid)
        return fail(err, errlen, "cannot replace %s: directory %s is sticky and neither it nor the file is "
                    "yours, so the rename would be refused", shown(path), shown(dir));
    return 0;
}

int sus_sys_atomic_file_check(const char *path, char *err, size_t errlen)
{
    char target[4096], dir[4096];
    struct stat sb;
    if (is_stdout(path))
        return 0;
    if (path[0] == '\0')
        return fail(err, errlen, "the output path is empty");
    const int fd = fd_of_path(path);
    if (fd >= 0) {
        const int fl = fcntl(fd, F_GETFL);
        if (fl < 0 || (fl & O_ACCMODE) == O_RDONLY)
            return fail(err, errlen, "cannot write %s: its descriptor is not open for writing", shown(path));
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
    dir_of(target, dir, sizeof dir);
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return fail(err, errlen, "cannot write %s: directory %s does not exist", shown(path), shown(dir));
    /* The file is created and renamed in its directory: that needs write and search. */
    if (access(dir, W_OK | X_OK) != 0) {
        snprintf(err, errlen, "cannot write %s: directory %s: %s", shown(path), shown(dir),
                 strerror(errno));
        return -1;
    }
    if (check_names(path, target, dir, err, errlen) != 0)
        return -1;
    return exists && stat(target, &sb) == 0 ? check_replace(path, target, &sb, dir, err, errlen) : 0;
}

/* stdout, a descriptor, a device or a pipe: written where it is. */
static int open_in_place(sus_sys_atomic_file *af, const char *path, int fd, char *err, size_t errlen)
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
    install_handlers();
    sigset_t old;
    block_signals(&old, 1);
    const int fd = mkstemp(af->tmp);
    const int saved = errno;
    if (fd >= 0)
        af->slot = slot_take(af->tmp);
    else
        af->tmp[0] = '\0';
    sigprocmask(SIG_SETMASK, &old, NULL);
    errno = saved;
    return fd;
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
    const int dfd = is_stdout(path) ? -1 : fd_of_path(path);
    if (is_stdout(path) || dfd >= 0)
        return open_in_place(af, path, dfd, err, errlen);
    if (resolve_target(path, af->target, sizeof af->target, err, errlen) != 0)
        return -1;
    const int exists = stat(af->target, &sb) == 0;
    if (exists && !S_ISREG(sb.st_mode))
        return open_in_place(af, path, -1, err, errlen);
    const mode_t mode = mode_for(exists, &sb);
    char dir[4096];
    dir_of(af->target, dir, sizeof dir);
    int fd = -1;
    /* O_TMPFILE needs a way to name the file later: /proc/self/fd (or CAP_DAC_READ_SEARCH
     * for AT_EMPTY_PATH); without /proc use a named temporary from the start.
     * SUSLOV_NO_O_TMPFILE (a test hook) forces the fallback, so that tests cover both ways. */
    const char *no_tmpfile = getenv("SUSLOV_NO_O_TMPFILE");
    if (access("/proc/self/fd", X_OK) == 0 && !(no_tmpfile && *no_tmpfile))
        fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    af->unnamed = fd >= 0;
    if (fd < 0 && (fd = open_named(af, dir)) < 0) {
        snprintf(err, errlen, "cannot create a temporary file next to %s: %s", shown(path), strerror(errno));
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
    dir_of(af->target, dir, sizeof dir);
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
    block_signals(&old, 0);
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
    slot_release(&af->slot);
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (bad)
        snprintf(err, errlen, "%s %s failed: %s", what, shown(af->path), strerror(saved));
    return bad ? -1 : 0;
}

void sus_sys_atomic_file_abort(sus_sys_atomic_file *af)
{
    sigset_t old;
    block_signals(&old, 0);
    if (af->fp && af->fp != stdout)
        fclose(af->fp);
    if (af->tmp[0])
        unlink(af->tmp);
    af->tmp[0] = '\0';
    slot_release(&af->slot);
    af->fp = NULL;
    sigprocmask(SIG_SETMASK, &old, NULL);
}
