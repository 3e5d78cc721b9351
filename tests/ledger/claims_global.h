/* Global orders on every body of tests/unit/bodies.h (claims_bodies.h): the slope of the error at
 * a fixed phase of the transient against the step, for every method of the registry, w and R;
 * each line reports the body farthest from its claim. */
#ifndef SUSLOV_CLAIMS_GLOBAL_H
#define SUSLOV_CLAIMS_GLOBAL_H

/* The reference attitude that judges them, on every body. */
void global_reference_claims(void);
/* The lines of the i-th registered method. */
void global_order_claims_of(int i);

#endif
