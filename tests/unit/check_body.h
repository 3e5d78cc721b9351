/* A body of the family (bodies.h) and its model, for the unit tests: a body the model refuses is a
 * failed check, never a test run on a model left uninitialized. */
#ifndef SUSLOV_CHECK_BODY_H
#define SUSLOV_CHECK_BODY_H

#include "bodies.h"
#include "check.h"
#include "exact.h"
#include "refattitude.h"

/* 0, or nonzero after a FAIL line naming the body and the model's reason. */
static inline int check_body_model(const body *b, sus_model *m)
{
    char err[256];
    if (sus_model_init(m, b->I, err, sizeof err) == 0)
        return 0;
    CHECK(0, "%s: the model refuses the body: %s", b->name, err);
    return -1;
}

/* Body k of the family, its model and its closed form: 0, or nonzero after a FAIL line (a body is
 * never skipped quietly). */
static inline int check_body_exact(int k, body *b, sus_model *m, sus_exact *ex)
{
    body_get(k, b);
    if (check_body_model(b, m))
        return -1;
    if (sus_exact_init(ex, m, b->w0) == 0)
        return 0;
    CHECK(0, "%s: no closed form for its w0", b->name);
    return -1;
}

/* The body's own time against the paper's: k_paper / k, k the rate at which the motion from w0
 * nears its steady rotation (exact.h), the time scale of (ContDyn) on that body. A step or a span
 * fixed on the paper's body, times this, has the same h k on every body (the stiff ones' k reaches
 * 1e7). */
static inline double check_body_time(const sus_model *m, const double w0[2])
{
    sus_exact paper, ex;
    sus_model mp;
    sus_model_init(&mp, SUS_PAPER_INERTIA, NULL, 0);
    sus_exact_init(&paper, &mp, SUS_PAPER_OMEGA0);
    sus_exact_init(&ex, m, w0);
    return paper.k / ex.k;
}

/* The paper's body altered to stress a step rule (test_exact_attitude, test_attitude_series):
 * "slow" (slow 1) with a third row a tenth of the paper's, so k is ten times smaller and a step
 * long in time; "fast" (slow 0) with w0 eight times the paper's, so k and the rotation are eight
 * times larger. */
static inline void check_body_paper_variant(int slow, body *b)
{
    body_get(0, b);
    if (slow) {
        b->I[6] *= 0.1;
        b->I[7] *= 0.1;
        snprintf(b->name, sizeof b->name, "slow");
    } else {
        b->w0[0] *= 8.0;
        b->w0[1] *= 8.0;
        snprintf(b->name, sizeof b->name, "fast");
    }
}

/* The slow body: I_m = I, I31 = I32 = 1e-5, w0 = (1000, -999), whose k is far below |w0|, so a
 * run to SLOW_T is a slow transient on a fast rotation, many steps long for any method. Its model
 * and closed form, and the long-double reference attitude at SLOW_T (R(0) = I): 0, or nonzero
 * after a FAIL line. */
#define SLOW_T 50.0
static inline int check_slow_body(sus_model *m, sus_exact *ex, double w0[2], double R_T[3][3])
{
    const double I[9] = {1, 0, 0, 0, 1, 0, 1e-5, 1e-5, 1},
                 I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    sus_refatt ra;
    w0[0] = 1000.0, w0[1] = -999.0;
    if (sus_model_init(m, I, NULL, 0) != 0 || sus_exact_init(ex, m, w0) != 0) {
        CHECK(0, "the slow body");
        return -1;
    }
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, SLOW_T, R_T);
    return 0;
}

#endif
