#include "convergence.h"

#include "consistency.h"
#include "magnus4.h"
#include "mat3.h"
#include "refattitude.h"
#include "so3.h"
#include "registry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Substeps of the Magnus check per unit time: h <= 1/256 makes its O(h^4) error negligible. */
#define MAGNUS_SUBSTEPS_PER_UNIT 256
#define MAGNUS_GLOBAL_STEP 5e-4

/* The larger of a and b, NaN when either is: one failed start fails the point. */
static double fmax_nan(double a, double b) { return isnan(a) || isnan(b) ? NAN : fmax(a, b); }

int suslov_convergence_run(suslov_convergence *c, const suslov_exact *ex, const double *tk, int ntk,
                           double T)
{
    memset(c, 0, sizeof *c);
    c->nmethod = suslov_method_count();
    c->m = calloc((size_t)c->nmethod, sizeof *c->m);
    if (!c->m) {
        fprintf(stderr, "convergence: out of memory\n");
        return -1;
    }
    for (int j = 0; j < SUSLOV_CONV_NJ; j++) {
        c->eps[j] = ldexp(1.0, SUSLOV_CONV_J0 - j);
        c->glob_eps[j] = T / (double)llround(fmax(1.0, round(T / c->eps[j])));
    }

    for (int j = 0; j < SUSLOV_CONV_NJ; j++)
        for (int t = 0; t < ntk; t++) {
            suslov_local_ref ref;
            double M[3][3];
            suslov_local_ref_init(&ref, ex, tk[t], c->eps[j]);
            mat3_identity(M);
            suslov_magnus4(ex, tk[t], tk[t] + c->eps[j], (long)ceil(c->eps[j] * MAGNUS_SUBSTEPS_PER_UNIT), M);
            c->ref_local_err = fmax(c->ref_local_err, so3_dist(ref.Phi, M));
            for (int m = 0; m < c->nmethod; m++) {
                const suslov_stepper_type *st = suslov_method_get(m)->type;
                suslov_conv_method *cm = &c->m[m];
                suslov_local_err e;
                if (suslov_local_errors(ex->model, st, &ref, &e) != SUSLOV_STEP_OK) {
                    e.w = e.lambda = NAN;
                    for (int r = 0; r < SUSLOV_RECON_COUNT; r++)
                        e.so3[r] = NAN;
                }
                cm->loc_w[j] = fmax_nan(cm->loc_w[j], e.w);
                cm->loc_lambda[j] = fmax_nan(cm->loc_lambda[j], e.lambda);
                for (int r = 0; r < SUSLOV_RECON_COUNT; r++)
                    cm->loc_so3[r][j] = fmax_nan(cm->loc_so3[r][j], e.so3[r]);
            }
        }

    double I3[3][3], Rm[3][3];
    suslov_refatt ra;
    mat3_identity(I3);
    mat3_identity(Rm);
    suslov_refatt_init(&ra, ex, 0.0, I3);
    suslov_refatt_advance(&ra, T, c->R_T);
    suslov_magnus4(ex, 0.0, T, (long)ceil(T / MAGNUS_GLOBAL_STEP), Rm);
    c->ref_global_err = so3_dist(c->R_T, Rm);

    for (int m = 0; m < c->nmethod; m++)
        for (int j = 0; j < SUSLOV_CONV_NJ; j++)
            for (int r = 0; r < SUSLOV_RECON_COUNT; r++) {
                const suslov_stepper_type *st = suslov_method_get(m)->type;
                suslov_conv_method *cm = &c->m[m];
                suslov_global_err g;
                const long N = llround(T / c->glob_eps[j]);
                if (suslov_global_errors(ex, st, (suslov_recon)r, T, N, c->R_T, &g) != 0)
                    g.w = g.lambda = g.so3 = NAN;
                cm->glob_w[j] = g.w;
                cm->glob_lambda[j] = g.lambda;
                cm->glob_so3[r][j] = g.so3;
            }
    return 0;
}

void suslov_convergence_free(suslov_convergence *c)
{
    free(c->m);
    c->m = NULL;
}
