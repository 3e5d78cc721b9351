/* A run recorded into arrays for the figures and the figure claims: t, w, lambda, E and the
 * constraint of the reconstructed velocity, for every row the driver emits. Storage is
 * allocated once, before the run: the integrator loop itself allocates nothing. */
#ifndef SUS_LAB_SERIES_H
#define SUS_LAB_SERIES_H

#include "driver.h"
#include "exact.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t n, cap;
    double *t, *w1, *w2, *w3, *lambda, *energy;
    double *mu; /* <e3, vee(R_k^T R_k w^_k)>: the unreduced constraint of step 6 of (algo) */
} sus_lab_series;

/* Room for the rows of a run of `steps` steps written every `every` steps. Returns 0 or -1. */
int sus_lab_series_init(sus_lab_series *s, long steps, long every);
void sus_lab_series_free(sus_lab_series *s);
/* As sus_run, recording the rows. */
int sus_lab_series_run(sus_lab_series *s, const sus_run_config *cfg, const double w0[2],
                       sus_run_report *report);
/* The closed form at t_i = i dt, i = 0 .. n-1 (at most the capacity; mu = 0). */
void sus_lab_series_exact(sus_lab_series *s, const sus_exact *ex, double dt, size_t n);

/* max_k |a_k - b_k| over two series of the same rows, for one field (offsetof in the struct). */
double sus_lab_series_maxdiff(const sus_lab_series *a, const sus_lab_series *b, size_t field);
/* max_k |v_k - v_0| of one field. */
double sus_lab_series_maxdrift(const sus_lab_series *s, size_t field);

#ifdef __cplusplus
}
#endif

#endif
