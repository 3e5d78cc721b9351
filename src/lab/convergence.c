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

/* The local errors at every step size and start time tk, worst over the starts; and how far the
 * local reference is from a Magnus check. */
static void local_errors(sus_lab_convergence *c, const sus_exact *ex, const double *tk, int ntk)
{
    for (int j = 0; j < SUS_LAB_CONV_NJ; j++)
        for (int t = 0; t < ntk; t++) {
            sus_lab_local_ref ref;
            double M[3][3];
            sus_lab_local_ref_init(&ref, ex, tk[t], c->eps[j]);
            sus_mat3_identity(M);
            sus_magnus4(ex, tk[t], tk[t] + c->eps[j],
                        (long)ceil(c->eps[j] * MAGNUS_SUBSTEPS_PER_UNIT), M);
            c->ref_local_err = fmax(c->ref_local_err, sus_so3_dist(ref.Phi, M));
            for (int m = 0; m < c->nmethod; m++) {
                const sus_stepper_type *st = sus_step_method_get(m)->type;
                sus_lab_conv_method *cm = &c->m[m];
                sus_lab_local_err e;
                if (sus_lab_local_errors(ex->model, st, &ref, &e) != SUS_STEPPER_OK) {
                    e.w = e.lambda = NAN;
                    for (int r = 0; r < SUS_RECON_COUNT; r++)
                        e.so3[r] = NAN;
                }
                cm->loc_w[j] = fmax_nan(cm->loc_w[j], e.w);
                cm->loc_lambda[j] = fmax_nan(cm->loc_lambda[j], e.lambda);
                for (int r = 0; r < SUS_RECON_COUNT; r++)
                    cm->loc_so3[r][j] = fmax_nan(cm->loc_so3[r][j], e.so3[r]);
            }
        }
}

/* The reference attitude R(T), checked against a Magnus run; then the global errors at T of every
 * method, step size and reconstruction. */
static void global_errors(sus_lab_convergence *c, const sus_exact *ex, double T)
{
    double I3[3][3], Rm[3][3];
    sus_refatt ra;
    sus_mat3_identity(I3);
    sus_mat3_identity(Rm);
    sus_refatt_init(&ra, ex, 0.0, I3);
    sus_refatt_advance(&ra, T, c->R_T);
    sus_magnus4(ex, 0.0, T, (long)ceil(T / MAGNUS_GLOBAL_STEP), Rm);
    c->ref_global_err = sus_so3_dist(c->R_T, Rm);

    for (int m = 0; m < c->nmethod; m++)
        for (int j = 0; j < SUS_LAB_CONV_NJ; j++)
            for (int r = 0; r < SUS_RECON_COUNT; r++) {
                const sus_stepper_type *st = sus_step_method_get(m)->type;
                sus_lab_conv_method *cm = &c->m[m];
                sus_lab_global_err g;
                const long N = llround(T / c->glob_eps[j]);
                if (sus_lab_global_errors(ex, st, (sus_recon)r, T, N, c->R_T, &g) != 0)
                    g.w = g.lambda = g.so3 = NAN;
                cm->glob_w[j] = g.w;
                cm->glob_lambda[j] = g.lambda;
                cm->glob_so3[r][j] = g.so3;
            }
}

int sus_lab_convergence_run(sus_lab_convergence *c, const sus_exact *ex, const double *tk, int ntk,
                            double T)
{
    memset(c, 0, sizeof *c);
    c->nmethod = sus_step_method_count();
    c->m = calloc((size_t)c->nmethod, sizeof *c->m);
    if (!c->m) {
        fprintf(stderr, "convergence: out of memory\n");
        return -1;
    }
    for (int j = 0; j < SUS_LAB_CONV_NJ; j++) {
        c->eps[j] = ldexp(1.0, SUS_LAB_CONV_J0 - j);
        c->glob_eps[j] = T / (double)llround(fmax(1.0, round(T / c->eps[j])));
    }
    local_errors(c, ex, tk, ntk);
    global_errors(c, ex, T);
    return 0;
}

void sus_lab_convergence_free(sus_lab_convergence *c)
{
    free(c->m);
    c->m = NULL;
}
