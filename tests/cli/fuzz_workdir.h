/* The fuzzer's work directory (fuzz.c), where each case runs, and the directory that captures
 * the run's stdout and stderr. */
#ifndef SUSLOV_FUZZ_WORKDIR_H
#define SUSLOV_FUZZ_WORKDIR_H

#include <stddef.h>

/* Made by main (mkdtemp) before the first case. */
extern char fuzz_workdir[512], fuzz_capdir[512];

/* Empties the work directory and lays out its cases: a kept file, a read-only file and
 * directory, a sticky directory with another user's file, a link and a dangling link. */
void fuzz_reset_workdir(void);
/* The work directory's state as text, one line per entry (see fuzz_workdir.c). */
void fuzz_snapshot(char *out, size_t len);
/* 1 when a temporary file (*.tmp.*) is left, its name in which. */
int fuzz_has_temp(char *which, size_t len);

#endif
