/* Gauss4's linear stability function is the (2,2) Pade approximant of exp (Hairer & Wanner II,
 * IV.3): R(z) = (1 + z/2 + z^2/12) / (1 - z/2 + z^2/12), checked from its defining property,
 * R(z) R(-z) = 1 and R(z) = exp(z) + O(z^5) with the error constant 1/720, on real z. */
#include "check.h"
#include "registry.h"

#include <math.h>

extern const sus_stepper_type sus_step_gauss4_type;

int main(void)
{
    double (*R)(double) = sus_step_gauss4_type.desc.stability;
    double worst = 0.0;
    const double z[6] = {-8.0, -3.0, -0.7, 0.4, 1.5, 2.5};
    for (int i = 0; i < 6; i++)
        worst = fmax(worst, fabs(R(z[i]) * R(-z[i]) - 1.0));
    /* a product of two quotients of three terms: a few ulps; 1e-14 is 45 u */
    CHECK(R != NULL && worst <= 1e-14, "gauss4: R(z) R(-z) = 1 to %.1e (bound 1e-14)", worst);
    /* exp(z) - R(z) = z^5/720 + O(z^6) for small z: the leading error constant of the (2,2) Pade
     * approximant; at z = 1e-2 the next term is 1e-2 of it and rounding ~1e-16 / 1.4e-13 */
    const double h = 1e-2, c = (exp(h) - R(h)) / pow(h, 5) * 720.0;
    CHECK(fabs(c - 1.0) <= 0.05, "gauss4: (exp(z) - R(z)) 720 / z^5 = %.4f at z = 1e-2 (1 to 0.05)",
          c);
    return check_summary("test_gauss4_pade");
}
