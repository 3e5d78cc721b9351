/* The fuzzer's argument vectors (fuzz.c): one seeded sequence of random numbers, the same on
 * every libc, from which each case's argv and run mode are drawn, so that a seed replays a run. */
#ifndef SUSLOV_FUZZ_ARGS_H
#define SUSLOV_FUZZ_ARGS_H

#include <stdint.h>
#include <stdio.h>

enum { FUZZ_MAXARGS = 40 };

/* The case's argv, NULL-terminated: "suslov" and up to FUZZ_MAXARGS - 1 arguments. */
extern char *fuzz_args[FUZZ_MAXARGS + 1];
extern int fuzz_nargs;

/* Starts the sequence (a seed of 0 counts as 1: xorshift never leaves 0). */
void fuzz_seed(uint64_t seed);
/* The next number of the sequence, in [0, n). */
int fuzz_pick(int n);
/* A new argv: mostly a valid run with random changes, else random options and hostile bytes. */
void fuzz_generate(void);
/* The argv as one line of quoted, printable arguments (\xNN for other bytes), for a replay. */
void fuzz_print_args(FILE *fp);

#endif
