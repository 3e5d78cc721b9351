/* A body of the family (bodies.h) and its model, for the unit tests: a body the model refuses is a
 * failed check, never a test run on a model left uninitialized. */
#ifndef SUSLOV_CHECK_BODY_H
#define SUSLOV_CHECK_BODY_H

#include "bodies.h"
#include "check.h"

/* 0, or nonzero after a FAIL line naming the body and the model's reason. */
static inline int check_body_model(const body *b, sus_model *m)
{
    char err[256];
    if (sus_model_init(m, b->I, err, sizeof err) == 0)
        return 0;
    CHECK(0, "%s: the model refuses the body: %s", b->name, err);
    return -1;
}

#endif
