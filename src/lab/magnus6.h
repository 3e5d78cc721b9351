/* The sixth-order Magnus method of Blanes, Casas and Ros (three Gauss nodes, two commutators) for
 * the attitude along the closed-form w, q' = 1/2 q (x) (0, w(t)) (reduced.h), at N equal steps:
 * the method a prototype proposed for the loose accuracies. make bench times it on the reduced
 * problem beside the library integrators, as one more peer on the same structure, so that the
 * proposal is judged by the same clock as our methods. */
#ifndef SUS_LAB_MAGNUS6_H
#define SUS_LAB_MAGNUS6_H

#include "exact_fast.h"

#ifdef __cplusplus
extern "C" {
#endif

/* q(T) from q(0) = (1, 0, 0, 0) by N steps of T / N along w (N >= 1). */
void sus_lab_magnus6(const sus_exact_fast *w, double T, long N, double q[4]);

#ifdef __cplusplus
}
#endif

#endif
