/* Where an output path leads, found without opening it: the descriptor it names, the file at
 * the end of its chain of symbolic links (existing or not), and whether that file is the root of
 * a mount (a bind-mounted file, which no rename can replace). */
#ifndef SUS_SYS_PATH_RESOLVE_H
#define SUS_SYS_PATH_RESOLVE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The directory part of path: "." for a bare name, "/" for a name in the root. */
void sus_sys_dir_of(const char *path, char *dir, size_t len);

/* The descriptor a path names (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, or a chain of
 * links ending in one), followed textually: readlink on the descriptor's own magic link would
 * jump to its file, losing the descriptor. Else -1. */
int sus_sys_fd_of_path(const char *path);

/* The name a write to path creates or replaces, as the kernel's open(O_CREAT) finds it: path
 * itself, or the last name of its chain of symbolic links, each relative link text read from
 * the directory of the link that holds it. The chain may end in a name that does not exist (a
 * dangling link, or a dangling chain l1 -> l2 -> missing.csv): that name is created. Returns 0,
 * or -1 with errno: ELOOP (more than 40 links), ENAMETOOLONG, or readlink's error. */
int sus_sys_link_target(const char *path, char *out, size_t len);

/* 1 when the existing file at path is the root of a mount (mount --bind FILE path), whose
 * directory entry a rename cannot replace (EBUSY); 0 otherwise or when it cannot be told. Asks
 * statx for the mount-root attribute, else compares the mount ids (or the devices) of the file
 * and of dir. */
int sus_sys_is_mount_root(const char *path, const char *dir);

#ifdef __cplusplus
}
#endif

#endif
