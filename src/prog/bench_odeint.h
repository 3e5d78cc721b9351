/* The Boost.Odeint peers of the benchmark (src/prog/bench_odeint.cpp, C++, built only by make
 * bench): runge_kutta_fehlberg78 through make_controlled, and bulirsch_stoer, both with
 * integrate_adaptive, on the 11-dimensional (w, R), the 6-dimensional (w, q) or w alone (2); and
 * runge_kutta_fehlberg78 on the reduced problem (reduced.h: q alone along the closed-form w, 4). */
#ifndef SUSLOV_BENCH_ODEINT_H
#define SUSLOV_BENCH_ODEINT_H

#include "model.h"
#include "reduced.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { SUSLOV_ODEINT_RKF78 = 0, SUSLOV_ODEINT_BS = 1 };

typedef struct suslov_odeint suslov_odeint;

/* stepper SUSLOV_ODEINT_*, dim 11 ((w1, w2, R row-major)), 6 ((w1, w2, q)) or 2 ((w1, w2)), abs =
 * rel = tol. Returns NULL when out of memory. */
suslov_odeint *suslov_odeint_open(int stepper, int dim, double tol, const sus_model *m);
/* runge_kutta_fehlberg78 on the reduced problem along r (which must outlive it), y = q, with
 * abs tolerance tol and rel tolerance rel. Returns NULL when out of memory. */
suslov_odeint *suslov_odeint_open_reduced(const sus_exact_fast *r, double tol, double rel);
/* Integrates y (dim entries) from 0 to T; returns the number of steps odeint reports. */
long suslov_odeint_run(suslov_odeint *o, double T, double *y);
void suslov_odeint_close(suslov_odeint *o);

#ifdef __cplusplus
}
#endif

#endif
