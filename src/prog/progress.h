/* The progress report of a long run, on stderr: the one mechanism of every program that runs for
 * more than a few seconds (suslov, the figure programs, and through build/timed the ledger and
 * whatever else make runs). On a terminal: one line, redrawn four times a second once the run has
 * lasted a second, erased at the end (without escape sequences under TERM=dumb or NO_COLOR). Off a
 * terminal (a log, CI): a line every ten seconds. Each line says how far the run is, how long it
 * has taken and an estimate of what is left. The caller's --quiet or the environment variable
 * NO_PROGRESS (set and not empty) turns it off. */
#ifndef SUSLOV_PROGRESS_H
#define SUSLOV_PROGRESS_H

/* The ways a caller allows it to show (OR them; 0: never, as under --quiet). Only one applies,
 * by whether stderr is a terminal. */
enum {
    PROGRESS_TERMINAL = 1, /* stderr a terminal: the redrawn line */
    PROGRESS_LOG = 2       /* stderr not a terminal: a line every ten seconds */
};

/* The modes a program allows: none when its arguments hold --quiet, which is taken out of them
 * (*argc and argv shortened), else both. */
int suslov_progress_modes(int *argc, char **argv);
/* who: the line's first word (the program). unit: what total counts, printed as "UNIT k of N"
 * with a rate in UNITs/s; NULL prints the fraction done only (work counted in uneven units).
 * total <= 0: unknown, so no fraction and no estimate. */
void suslov_progress_start(const char *who, const char *unit, long total, int modes);
/* done of total so far; detail (printf format, may be NULL) is formatted only when a line is
 * due, so a call is cheap otherwise. */
void suslov_progress_tick(long done, const char *detail, ...) __attribute__((format(printf, 2, 3)));
/* The end of the run: the terminal's line erased (a log's lines stay). */
void suslov_progress_end(void);

#endif
