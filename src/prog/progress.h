/* A progress line on stderr while a long run lasts: only when stderr is a terminal and the rows
 * do not go to the same terminal, only after the run has lasted a second, redrawn four times a
 * second on one line and erased at the end, so that scripts and the one-line error contract
 * never see it. Under TERM=dumb or NO_COLOR it uses no escape sequence (carriage return and
 * spaces only). */
#ifndef SUSLOV_PROGRESS_H
#define SUSLOV_PROGRESS_H

/* on: whether to show it at all (the caller's --quiet and terminal test). */
void progress_start(int on, long total);
/* Cheap unless a redraw is due; call with the row just computed. */
void progress_tick(long k, double t);
void progress_erase(void);

#endif
