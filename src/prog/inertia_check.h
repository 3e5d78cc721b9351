/* The suslov command's check of an --inertia value, shared with the browser's module
 * (wasm_api.c) so that the page shows the CLI's own one-line message. */
#ifndef SUSLOV_INERTIA_CHECK_H
#define SUSLOV_INERTIA_CHECK_H

#include <stddef.h>

/* 0 when I (by rows) is a usable body; otherwise -1 and the one-line message in msg, starting
 * with "--inertia: ". */
int suslov_inertia_check(const double I[9], char *msg, size_t len);

#endif
