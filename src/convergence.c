#include "convergence.h"

#include "consistency.h"
#include "magnus4.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"
#include "stepper.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Substeps of the Magnus check per increment: h <= 1/256 makes its O(h^4) error negligible. */
#define MAGNUS_SUBSTEPS 256
#define MAGNUS_GLOBAL_STEP 5e-4

int suslov_convergence_run(suslov_convergence *c, const suslov_exact *ex, const double *tk, int ntk,
                           double T)
{
    memset(c, 0, sizeof *c);
    for (int j = 0; j < SUSLOV_CONV_NJ; j++)
        c->eps[j] = ldexp(1.0, -j);

    for (int j = 0; j < SUSLOV_CONV_NJ; j++)
        for (int t = 0; t < ntk; t++) {
            suslov_local_ref ref;
            double M[3][3];
            if (suslov_local_ref_init(&ref, ex, tk[t], c->eps[j]) != 0) {
                fprintf(stderr, "convergence: reference attitude failed at t_k = %g, eps = %g\n", tk[t], c->eps[j]);
                return -1;
            }
            mat3_identity(M);
            suslov_magnus4(ex, tk[t], tk[t] + c->eps[j], MAGNUS_SUBSTEPS, M);
            c->ref_local_err = fmax(c->ref_local_err, so3_dist(ref.Phi, M));
            for (int m = 0; m < SUSLOV_CONV_NMETHOD; m++) {
                suslov_local_err e;
                if (suslov_local_errors(ex->model, suslov_stepper_get(m), &ref, &e) != SUSLOV_STEP_OK) {
                    fprintf(stderr, "convergence: %s step failed at t_k = %g, eps = %g\n",
                            suslov_stepper_get(m)->name, tk[t], c->eps[j]);
                    return -1;
                }
                c->loc_w[m][j] = fmax(c->loc_w[m][j], e.w);
                c->loc_lambda[m][j] = fmax(c->loc_lambda[m][j], e.lambda);
                for (int r = 0; r < 2; r++)
                    c->loc_so3[m][r][j] = fmax(c->loc_so3[m][r][j], e.so3[r]);
            }
        }

    double I3[3][3], Rm[3][3];
    suslov_refatt ra;
    mat3_identity(I3);
    mat3_identity(Rm);
    if (suslov_refatt_init(&ra, ex, 0.0, I3, SUSLOV_REFATT_TOL) != 0 || suslov_refatt_advance(&ra, T, c->R_T) != 0) {
        fprintf(stderr, "convergence: reference attitude failed on [0, %g]\n", T);
        suslov_refatt_free(&ra);
        return -1;
    }
    suslov_refatt_free(&ra);
    suslov_magnus4(ex, 0.0, T, (long)ceil(T / MAGNUS_GLOBAL_STEP), Rm);
    c->ref_global_err = so3_dist(c->R_T, Rm);

    for (int m = 0; m < SUSLOV_CONV_NMETHOD; m++)
        for (int j = 0; j < SUSLOV_CONV_NJ; j++)
            for (int r = 0; r < 2; r++) {
                suslov_global_err g;
                const long N = (long)llround(T / c->eps[j]);
                if (suslov_global_errors(ex, suslov_stepper_get(m), (suslov_recon)r, T, N, c->R_T, &g) != 0) {
                    fprintf(stderr, "convergence: %s failed on [0, %g] with eps = %g\n",
                            suslov_stepper_get(m)->name, T, c->eps[j]);
                    return -1;
                }
                c->glob_w[m][j] = g.w;
                c->glob_lambda[m][j] = g.lambda;
                c->glob_so3[m][r][j] = g.so3;
            }
    return 0;
}
