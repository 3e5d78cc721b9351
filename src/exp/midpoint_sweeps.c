#include "midpoint_sweeps.h"

void sus_exp_midpoint_sweeps(const sus_model *m, double eps, int n, const double w[2], double x[2])
{
    x[0] = w[0];
    x[1] = w[1];
    for (int j = 0; j < n; j++) {
        const double mid[2] = {0.5 * (w[0] + x[0]), 0.5 * (w[1] + x[1])};
        double f[2];
        sus_contdyn(m, mid, f);  /* I_m^{-1} (l1, l2) at the midpoint */
        x[0] = w[0] + eps * f[0];
        x[1] = w[1] + eps * f[1];
    }
}

void sus_exp_midpoint_sweeps_run(const sus_model *m, double eps, int n, const double w0[2], long N,
                                double *energy, double wN[2])
{
    double w[2] = {w0[0], w0[1]};
    energy[0] = sus_energy(m, w);
    for (long k = 0; k < N; k++) {
        double x[2];
        sus_exp_midpoint_sweeps(m, eps, n, w, x);
        w[0] = x[0];
        w[1] = x[1];
        energy[k + 1] = sus_energy(m, w);
    }
    wN[0] = w[0];
    wN[1] = w[1];
}
