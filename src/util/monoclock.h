/* Seconds on the monotonic clock, for timing the benchmark and the renderer. */
#ifndef SUS_SYS_MONOCLOCK_H
#define SUS_SYS_MONOCLOCK_H

#include <time.h>

#ifdef __cplusplus
extern "C" {
#endif

static inline double sus_sys_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#ifdef __cplusplus
}
#endif

#endif
