/* The fuzzer's checks on what a run wrote (fuzz.c). */
#ifndef SUSLOV_FUZZ_OUTPUT_H
#define SUSLOV_FUZZ_OUTPUT_H

#include <stddef.h>

/* The lines of a file (an unterminated last line counts; -1 when it cannot be read), its first
 * line in first when first is not NULL. */
long fuzz_count_lines(const char *path, char *first, size_t flen);
/* 1 when the rows the case's argv wrote, to stdout or to its --output file, are complete and
 * finite; else 0, with the reason in why. */
int fuzz_output_ok(int code, char *why, size_t len);

#endif
