/* The runs make bench times, each from the same state every time it runs (so a timed repeat
 * ends bit for bit where the first run did): our methods through the driver, as `suslov` runs
 * them; their w-steps alone; a tolerance-driven method through sus_run_tol; and a GSL odeiv2
 * peer in one configuration (src/lab/peers.c): (w, R) 11 unknowns, (w, q) 6, w alone 2, and the
 * reduced problem, q alone along the closed-form w, 4; and Magnus6 on the reduced problem
 * (magnus6.h) at N steps. */
#ifndef SUS_LAB_BENCH_RUNS_H
#define SUS_LAB_BENCH_RUNS_H

#include "bench.h"
#include "driver.h"

#ifdef __cplusplus
extern "C" {
#endif

/* N steps of eps = T / N with a reconstruction, through sus_run. */
typedef struct {
    const sus_lab_bench_problem *pb;
    const sus_stepper_type *st;
    sus_recon recon;
    long N;
    double T;
    sus_row last;
    sus_run_report rep;
    double sink; /* what a bare loop over the steps ends with, so that no run is optimized away */
} sus_lab_bench_dsp_run;

/* w alone (no attitude): the driver's w-steps without the reconstruction, for a user who needs
 * only w (the peers get the same choice, 2 unknowns), and the per-step cost. */
typedef struct {
    const sus_lab_bench_problem *pb;
    const sus_stepper_type *st;
    long N;
    double T, w[3], newton; /* newton: Newton iterations per step */
    int status;
} sus_lab_bench_w_run;

/* A tolerance-driven method to T through sus_run_tol, one row: the end. */
typedef struct {
    const sus_lab_bench_problem *pb;
    const sus_stepper_type *st;
    double tol, T;
    sus_row last;
    sus_run_report rep;
    int rc;
    double sink;
} sus_lab_bench_tol_run;

/* A GSL peer (sus_lab_peer_open'ed, or sus_lab_peer_open_reduced'ed) to T. */
typedef struct {
    const sus_lab_bench_problem *pb;
    sus_lab_peer p;
    double T, y[11];
    long steps;
    int status;
} sus_lab_bench_peer_run;

/* Magnus6 along the closed-form w to T in N equal steps. */
typedef struct {
    const sus_lab_bench_problem *pb;
    long N;
    double T, q[4];
} sus_lab_bench_magnus6_run;

void sus_lab_bench_dsp_fn(void *ctx);
void sus_lab_bench_w_fn(void *ctx);
void sus_lab_bench_tol_fn(void *ctx);
void sus_lab_bench_peer_fn(void *ctx);
void sus_lab_bench_magnus6_fn(void *ctx);

/* Each with its result and release (free, and the peer's sus_lab_peer_close). */
extern const sus_lab_bench_run_ops SUS_LAB_BENCH_DSP_OPS, SUS_LAB_BENCH_W_OPS,
    SUS_LAB_BENCH_TOL_OPS, SUS_LAB_BENCH_PEER_OPS, SUS_LAB_BENCH_MAGNUS6_OPS;

#ifdef __cplusplus
}
#endif

#endif
