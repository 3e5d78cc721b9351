/* A Taylor method of order p applied to w' = a w takes w to (sum_{n<=p} (a eps)^n / n!) w, so its
 * linear stability function is the truncated exponential. Checked for every registered Taylor order
 * (through the stepper's own stability pointer) and for p = 1 .. 32 (through the run-time form)
 * against the sum in long double, on z in [-8, 2]: within 8 u e^{|z|}, the rounding of p + 1 terms
 * whose absolute sum is at most e^{|z|}. A scaled first term or a wrong denominator moves R by
 * far more (1e-6 (e^z - 1) for a first term scaled by 1 + 1e-6). */
#include "check.h"
#include "taylor.h"

#include <math.h>

extern const sus_stepper_type sus_step_taylor8_type, sus_step_taylor10_type, sus_step_taylor12_type,
    sus_step_taylor16_type;

static long double truncated_exp(int p, long double z)
{
    long double r = 1.0L, t = 1.0L;
    for (int n = 1; n <= p; n++)
        r += (t = t * z / n);
    return r;
}

/* max over the z grid of |R(z) - sum| / (8 u e^{|z|}); R is either stab (if set) or the run-time
 * form */
static double worst_ratio(int p, double (*stab)(double))
{
    double worst = 0.0;
    for (int i = 0; i <= 200; i++) {
        const double z = -8.0 + 10.0 * i / 200.0;
        const double r = stab ? stab(z) : sus_step_taylor_stability(p, z);
        const double d = (double)fabsl(r - truncated_exp(p, z)) / (8.0 * 0x1p-53 * exp(fabs(z)));
        worst = d > worst || isnan(d) ? d : worst;
    }
    return worst;
}

int main(void)
{
    const sus_stepper_type *ty[4] = {&sus_step_taylor8_type, &sus_step_taylor10_type,
                                     &sus_step_taylor12_type, &sus_step_taylor16_type};
    for (int i = 0; i < 4; i++) {
        const double w =
            ty[i]->desc.stability ? worst_ratio(ty[i]->desc.order, ty[i]->desc.stability) : NAN;
        CHECK(w <= 1.0,
              "%s: R(z) is the truncated exponential of degree %d on [-8, 2] (error / 8 u e^|z| "
              "%.2g, at most 1)",
              ty[i]->name, ty[i]->desc.order, w);
    }
    double worst = 0.0;
    for (int p = 1; p <= 32; p++)
        worst = fmax(worst, worst_ratio(p, NULL));
    CHECK(worst <= 1.0,
          "sus_step_taylor_stability(p, z) for p = 1 .. 32 is the truncated exponential on "
          "[-8, 2] (error / 8 u e^|z| %.2g, at most 1)",
          worst);
    return check_summary("test_taylor_stability");
}
