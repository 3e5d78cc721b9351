#include "magnus4.h"

#include "mat3.h"
#include "so3.h"

#include <math.h>

void suslov_magnus4(const suslov_exact *ex, double t0, double t1, long n, double R[3][3])
{
    const double h = (t1 - t0) / (double)n;
    const double c1 = 0.5 - sqrt(3.0) / 6.0, c2 = 0.5 + sqrt(3.0) / 6.0;
    const double k2 = sqrt(3.0) / 12.0 * h * h;
    for (long i = 0; i < n; i++) {
        const double t = t0 + (double)i * h;
        double a1[3] = {0.0, 0.0, 0.0}, a2[3] = {0.0, 0.0, 0.0}, x[3], om[3], E[3][3], Rn[3][3];
        suslov_exact_omega(ex, t + c1 * h, a1);
        suslov_exact_omega(ex, t + c2 * h, a2);
        vec3_cross(x, a1, a2);
        /* For R' = R A: Omega = h/2 (A1 + A2) + sqrt(3)/12 h^2 [A1, A2], [a^, b^] = (a x b)^. */
        for (int j = 0; j < 3; j++)
            om[j] = 0.5 * h * (a1[j] + a2[j]) + k2 * x[j];
        so3_exp(om, E);
        mat3_mul(Rn, R, E);
        mat3_copy(R, Rn);
    }
}
