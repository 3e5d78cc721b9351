/* The local error of one Taylor step of order p (sus_step_taylor_apply_full, any p the adaptive
 * method may pick, odd ones included) falls as h^(p+1), for w against the closed form and for R
 * against the reference increment, on the seeded bodies. A series summed one term short, or with its
 * last term's sign flipped, errs by ~h^p instead: the measured exponent tells the two apart. */
#include "check_body.h"
#include "exact.h"
#include "mat3.h"
#include "refattitude.h"
#include "taylor.h"

#include <math.h>

/* One step of size h from w(0): the distances of w and R from the exact ones. */
static void step_error(const sus_model *m, const sus_exact *ex, int p, double h, double *ew, double *eR)
{
    const double w0[3] = {ex->w0[0], ex->w0[1], 0.0};
    double wn[3], lam, we[2], R[3][3], Re[3][3];
    sus_attitude a;
    sus_attitude_identity(&a);
    sus_stepper_stats st;
    sus_step_taylor_apply_full(p, m, h, &a, w0, wn, &lam, &st);
    sus_exact_omega(ex, h, we);
    sus_attitude_get(&a, R);
    sus_refatt_increment(ex, 0.0, h, Re);
    *ew = hypot(wn[0] - we[0], wn[1] - we[1]);
    *eR = sus_mat3_dist(R, Re);
}

/* The exponent from steps h and h/2, counted where the error at h/2 is above 1e-14 (90 u, so that
 * a few u of round-off move it by under 0.1; a body whose w hardly moves has none, then R alone
 * decides). h is small beside the radius (about
 * 10): the next term shifts the exponent by ~ h/rho, under 0.1 here; p + 1/2 is halfway between right
 * (p + 1) and one term short or with its last sign flipped (p). */
#define NOT_COUNTED " (below 1e-14: not counted)"

static void local_order(const sus_model *m, const sus_exact *ex, const char *name, int p, double h)
{
    double ew1, eR1, ew2, eR2;
    step_error(m, ex, p, h, &ew1, &eR1);
    step_error(m, ex, p, h / 2.0, &ew2, &eR2);
    const double sw = log2(ew1 / ew2), sR = log2(eR1 / eR2);
    const int mw = ew2 >= 1e-14, mR = eR2 >= 1e-14;
    CHECK((mw || mR) && (!mw || sw >= p + 0.5) && (!mR || sR >= p + 0.5),
          "%s: Taylor p = %d, one step h = %g, h/2: local error exponents w %.2f%s, R %.2f%s (>= p + 1/2)",
          name, p, h, sw, mw ? "" : NOT_COUNTED, sR, mR ? "" : NOT_COUNTED);
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        body_get(k, &b);
        sus_model m;
        if (check_body_model(&b, &m) != 0)
            continue;
        sus_exact ex;
        sus_exact_init(&ex, &m, b.w0);
        for (int p = 3; p <= 8; p++)
            local_order(&m, &ex, b.name, p, 0.8);
    }
    return check_summary("test_taylor_local_order");
}
