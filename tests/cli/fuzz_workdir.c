/* The fuzzer's work directory (fuzz.c): the files each case starts from, and their state as
 * text, to compare before and after a run. */
#define _GNU_SOURCE
#include "fuzz_workdir.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

char fuzz_workdir[512], fuzz_capdir[512];

static void write_file(const char *name, const char *text, mode_t mode)
{
    char path[8192];
    snprintf(path, sizeof path, "%s/%s", fuzz_workdir, name);
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, mode);
    if (fd >= 0) {
        if (write(fd, text, strlen(text)) < 0)
            perror("fuzz: write");
        close(fd);
    }
}

void fuzz_reset_workdir(void)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd,
             "chmod -R u+w '%s' 2>/dev/null; rm -rf '%s'/* '%s'/.[!.]* 2>/dev/null", fuzz_workdir,
             fuzz_workdir, fuzz_workdir);
    if (system(cmd) != 0) { /* rm may report nothing to remove */
    }
    char path[8192];
    snprintf(path, sizeof path, "%s/sub", fuzz_workdir);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/ro", fuzz_workdir);
    mkdir(path, 0555);
    write_file("keep.csv", "previous contents\n", 0600);
    write_file("rofile.csv", "read-only\n", 0444);
    snprintf(path, sizeof path, "%s/st",
             fuzz_workdir); /* sticky, with another user's (root's) file */
    mkdir(path, 0755);
    chmod(path, 01777);
    write_file("st/other.csv", "root's\n", 0666);
    chmod(path, 01777);
    write_file("target.csv", "link target\n", 0644);
    snprintf(path, sizeof path, "%s/link.csv", fuzz_workdir);
    if (symlink("target.csv", path) != 0)
        perror("fuzz: symlink");
    snprintf(path, sizeof path, "%s/dangling.csv", fuzz_workdir);
    if (symlink("gone.csv", path) != 0)
        perror("fuzz: symlink");
}

/* One line per entry of the directory and of sub/: name, type, mode, size and an FNV-1a hash
 * of the contents (or of the link text). */
void fuzz_snapshot(char *out, size_t len)
{
    const char *dirs[] = {"", "/sub", "/ro", "/st"};
    size_t used = 0;
    out[0] = '\0';
    for (int d = 0; d < 4; d++) {
        char dpath[1024];
        snprintf(dpath, sizeof dpath, "%s%s", fuzz_workdir, dirs[d]);
        struct dirent **names;
        const int n = scandir(dpath, &names, NULL, alphasort);
        for (int i = 0; i < n; i++) {
            char p[2048];
            struct stat sb;
            uint64_t h = 1469598103934665603ULL;
            snprintf(p, sizeof p, "%s/%s", dpath, names[i]->d_name);
            if (lstat(p, &sb) == 0 && strcmp(names[i]->d_name, ".") &&
                strcmp(names[i]->d_name, "..")) {
                char buf[65536];
                ssize_t r = 0;
                if (S_ISLNK(sb.st_mode)) {
                    r = readlink(p, buf, sizeof buf);
                    for (ssize_t j = 0; j < r; j++)
                        h = (h ^ (unsigned char)buf[j]) * 1099511628211ULL;
                } else if (S_ISREG(sb.st_mode)) {
                    const int fd = open(p, O_RDONLY);
                    while (fd >= 0 && (r = read(fd, buf, sizeof buf)) > 0)
                        for (ssize_t j = 0; j < r; j++)
                            h = (h ^ (unsigned char)buf[j]) * 1099511628211ULL;
                    if (fd >= 0)
                        close(fd);
                }
                used += (size_t)snprintf(out + used, used < len ? len - used : 0,
                                         "%s%s/%s %o %lld %016llx\n", dirs[d], "", names[i]->d_name,
                                         (unsigned)sb.st_mode, (long long)sb.st_size,
                                         (unsigned long long)h);
            }
            free(names[i]);
        }
        if (n >= 0)
            free(names);
    }
}

int fuzz_has_temp(char *which, size_t len)
{
    const char *dirs[] = {"", "/sub", "/ro", "/st"};
    for (int d = 0; d < 4; d++) {
        char dpath[1024];
        snprintf(dpath, sizeof dpath, "%s%s", fuzz_workdir, dirs[d]);
        DIR *dir = opendir(dpath);
        struct dirent *e;
        while (dir && (e = readdir(dir)))
            if (strstr(e->d_name, ".tmp.")) {
                snprintf(which, len, "%s/%s", dirs[d], e->d_name);
                closedir(dir);
                return 1;
            }
        if (dir)
            closedir(dir);
    }
    return 0;
}
