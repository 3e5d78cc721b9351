/* The suslov command's check of an --inertia value, shared with the browser's module
 * (wasm_api.c) so that the page shows the CLI's own one-line message. The check itself is the
 * library's (sus_model_init), so that the library refuses what the command refuses, in the same
 * words. */
#ifndef SUSLOV_INERTIA_CHECK_H
#define SUSLOV_INERTIA_CHECK_H

#include "model.h"

#include <stddef.h>

/* sus_model_init(m, I): 0 when I (by rows) is a usable body; otherwise -1 and its one-line
 * message in msg, starting with "--inertia: ", the paper cited by its printed numbers. */
int suslov_inertia_model(sus_model *m, const double I[9], char *msg, size_t len);

#endif
