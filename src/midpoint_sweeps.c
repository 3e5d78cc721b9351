#include "midpoint_sweeps.h"

void suslov_midpoint_sweeps(const suslov_model *m, double eps, int n, const double w[2], double x[2])
{
    x[0] = w[0];
    x[1] = w[1];
    for (int j = 0; j < n; j++) {
        const double mid[2] = {0.5 * (w[0] + x[0]), 0.5 * (w[1] + x[1])};
        double f[2];
        suslov_contdyn(m, mid, f);  /* I_m^{-1} (l1, l2) at the midpoint */
        x[0] = w[0] + eps * f[0];
        x[1] = w[1] + eps * f[1];
    }
}
