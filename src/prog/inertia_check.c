#include "inertia_check.h"

#include "paper_ref.h"

#include <stdio.h>

int suslov_inertia_model(sus_model *m, const double I[9], char *msg, size_t len)
{
    char err[512], said[512];
    if (sus_model_init(m, I, err, sizeof err) == 0)
        return 0;
    /* the model cites the paper by labels; the reader gets numbers */
    snprintf(msg, len, "--inertia: %s", sus_paper_numbered(err, said, sizeof said));
    return -1;
}
