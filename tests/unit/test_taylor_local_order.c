/* The local error of one Taylor step of order p (sus_step_taylor_apply_full, any p the adaptive
 * method may pick, odd ones included) falls as h^(p+1), for w against the closed form and for R
 * against the reference increment, on the seeded bodies. A series summed one term short, or with
 * its last term's sign flipped, errs by ~h^p instead: the measured exponent tells the two apart. */
#include "check_body.h"
#include "exact.h"
#include "mat3.h"
#include "refattitude.h"
#include "taylor.h"

#define NOT_COUNTED " (below the floor: not counted)"

#include <math.h>

/* One step of size h from w(0): the distances of w and R from the exact ones; -1 if the step
 * refuses. */
static int step_error(const sus_model *m, const sus_exact *ex, int p, double h, double *ew,
                      double *eR)
{
    const double w0[3] = {ex->w0[0], ex->w0[1], 0.0};
    double wn[3], lam, we[2], R[3][3], Re[3][3];
    sus_attitude a;
    sus_attitude_identity(&a);
    sus_stepper_stats st;
    if (sus_step_taylor_apply_full(p, m, h, &a, w0, wn, &lam, &st) != SUS_STEPPER_OK)
        return -1;
    sus_exact_omega(ex, h, we);
    sus_attitude_get(&a, R);
    sus_refatt_increment(ex, 0.0, h, Re);
    *ew = hypot(wn[0] - we[0], wn[1] - we[1]);
    *eR = sus_mat3_dist(R, Re);
    return 0;
}

/* The exponent from steps h and h/2, counted where the error at h/2 is above the round-off floor,
 * 64 u |w0| for w and 1e-14 (90 u) for R, so that a few u of round-off move it by under 0.1 (a body
 * whose w hardly moves has none, then R alone decides). p + 1/2 is halfway between right (p + 1)
 * and one term short or with its last sign flipped (p). The step starts where the paper's 0.8 does
 * in the body's time (h k = 0.116) and doubles until an error is counted, within limits fixed
 * beforehand: half the proved radius (taylor.h), h k <= 0.46 (the closed form's radius is at least
 * pi / 2k, so the next term shifts the exponent by under 0.2) and |w0| h <= 1 (R's series: its next
 * term is under a tenth of the last). Where no step within them shows an error above the floor, the
 * order cannot be measured in double: a NOTE says so; returns 1 if measured, 0 if not. */
static int local_order(const sus_model *m, const sus_exact *ex, const char *name, int p, double h0)
{
    const double wn = hypot(ex->w0[0], ex->w0[1]), floor_w = 64.0 * SUS_U * wn;
    const double hmax = fmin(0.5 * sus_step_taylor_radius(m, ex->w0), fmin(0.46 / ex->k, 1.0 / wn));
    double h = fmin(h0, hmax), ew1, eR1, ew2, eR2;
    int rc;
    for (;;) {
        rc = step_error(m, ex, p, h, &ew1, &eR1) | step_error(m, ex, p, h / 2.0, &ew2, &eR2);
        if (rc != 0 || ew2 >= floor_w || eR2 >= 1e-14 || 2.0 * h > hmax)
            break;
        h *= 2.0;
    }
    const double sw = log2(ew1 / ew2), sR = log2(eR1 / eR2);
    const int mw = rc == 0 && ew2 >= floor_w, mR = rc == 0 && eR2 >= 1e-14;
    if (rc == 0 && !mw && !mR) {
        printf("NOTE %s: Taylor p = %d: local error below round-off (w %.2g, R %.2g at h = %.3g, "
               "the longest step within the limits): the order cannot be measured in double\n",
               name, p, ew1, eR1, h);
        return 0;
    }
    CHECK(rc == 0 && (!mw || sw >= p + 0.5) && (!mR || sR >= p + 0.5),
          "%s: Taylor p = %d, one step h = %.3g (h k = %.3g), h/2: "
          "local error exponents w %.2f%s, R %.2f%s (>= p + 1/2)",
          name, p, h, h * ex->k, sw, mw ? "" : NOT_COUNTED, sR, mR ? "" : NOT_COUNTED);
    return 1;
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        const double h0 = 0.8 * check_body_time(&m, b.w0);
        int low = 0;
        for (int p = 3; p <= 8; p++) {
            const int measured = local_order(&m, &ex, b.name, p, h0);
            low += p <= 5 && measured;
        }
        /* the low orders' errors, ~ |w| (h k)^(p+1) >= 1e-7 |w| at h0, are measurable on every body
         */
        CHECK(low == 3, "%s: the local order measured for p = 3, 4, 5 at least (%d of 3)", b.name,
              low);
    }
    return check_summary("test_taylor_local_order");
}
