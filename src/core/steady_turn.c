#include "steady_turn.h"

#include "quaternion.h"
#include "so3.h"

#include <math.h>
#include <string.h>

double sus_steady_gap_lo(double b, double a, double d) { return (b - d) - a; }

/* Half the angle (tau + tau_lo) |w_inf| reduced to [-pi, pi]: the product in two parts (fma gives
 * the first's rounding error exactly), the multiple of 2 pi (as hi + lo) taken off the high part by
 * fma, which is exact there. */
static double half_angle(const double speed[2], double tau, double tau_lo)
{
    const double two_pi = 6.283185307179586, two_pi_lo = 2.4492935982947064e-16;
    const double p = tau * speed[0];
    const double e = fma(tau, speed[0], -p) + (tau * speed[1] + tau_lo * speed[0]);
    const double k = nearbyint(0.5 * p / two_pi);
    return fma(-k, two_pi, 0.5 * p) - k * two_pi_lo + 0.5 * e;
}

void sus_steady_turn(const double w_inf[2], const double speed[2], double tau, double tau_lo,
                     double q[4])
{
    const double n = hypot(w_inf[0], w_inf[1]);
    double s, c, p[4];
    sus_so3_sincos(half_angle(speed, tau, tau_lo), &s, &c);
    const double f = n > 0.0 ? s / n : 0.5 * tau; /* sin(tau |w_inf| / 2) / |w_inf| */
    const double dq[4] = {c, f * w_inf[0], f * w_inf[1], 0.0};
    sus_quat_mul(p, q, dq);
    memcpy(q, p, sizeof p);
}
