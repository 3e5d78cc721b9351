/* The bench's Magnus6 peer on the reduced problem (src/lab/magnus6.c). Expected values from
 * theory: a sixth-order method's global error falls by 2^6 = 64 when the step halves; the window
 * [32, 128] allows the next order's term on either side, while a slip in a commutator's sign or
 * weight leaves order 2 or 4 (a ratio of 4 or 16). Along a constant w the Magnus vector is T w
 * exactly, so the steps compose to the exact rotation up to rounding. */
#include "bodies.h"
#include "check.h"
#include "magnus6.h"
#include "quaternion.h"
#include "refattitude.h"
#include "so3.h"

#include <math.h>

#define T_RUN 10.0
#define LEVEL 1e-5 /* first N whose error is below this: asymptotic, far above round-off */
#define RATIO_LO 32.0
#define RATIO_HI 128.0

static double error_at(const sus_exact_fast *f, const double Rref[3][3], long N)
{
    double q[4], R[3][3];
    sus_lab_magnus6(f, T_RUN, N, q);
    sus_quat_rotation(q, R);
    return sus_so3_dist(R, Rref);
}

/* The error ratio between N and 2N steps at the first N = 2^j whose error is below LEVEL. */
static double order_ratio(const sus_model *m, const double w0[2], long *N_out)
{
    sus_exact ex;
    sus_exact_fast f;
    double w[2], Rref[3][3];
    if (sus_exact_init(&ex, m, w0) || sus_exact_fast_init(&f, &ex))
        return NAN;
    sus_refatt_precise(m, w0, T_RUN, w, Rref);
    long N = 4;
    while (N < 4096 && !(error_at(&f, Rref, N) < LEVEL))
        N *= 2;
    *N_out = N;
    return error_at(&f, Rref, N) / error_at(&f, Rref, 2 * N);
}

static void check_order(const body *b)
{
    sus_model m;
    char err[128];
    if (sus_model_init(&m, b->I, err, sizeof err)) {
        CHECK(0, "%s: model refused: %s", b->name, err);
        return;
    }
    long N = 0;
    const double r = order_ratio(&m, b->w0, &N);
    CHECK(r >= RATIO_LO && r <= RATIO_HI, "%s: error(N = %ld) / error(2N) = %.1f in [%g, %g]",
          b->name, N, r, RATIO_LO, RATIO_HI);
}

/* LONG_N steps (past the re-anchoring of E every 64 steps): the error is at most twice the sixth-
 * order extrapolation from N steps, plus the roundings of LONG_N steps (a few u each, 64 u a step
 * allowed); a factor E carried wrongly would leave an error of the size of w's change. */
#define LONG_N 300

static void check_many_steps(const sus_model *m, const double w0[2], const sus_exact_fast *f,
                             long N)
{
    double w[2], Rref[3][3];
    sus_refatt_precise(m, w0, T_RUN, w, Rref);
    const double eN = error_at(f, Rref, N), eL = error_at(f, Rref, LONG_N);
    const double bound = 2.0 * eN * pow((double)N / LONG_N, 6.0) + 64.0 * LONG_N * 0x1p-53;
    CHECK(eL <= bound, "%d steps: error %.2g <= %.2g (sixth order from %ld steps, + round-off)",
          LONG_N, eL, bound, N);
}

/* A motion through s = 0 (the incremental E re-anchored where s changes sign): the paper's body
 * from a w0 whose s0 < 0 < s0 + ks T. */
static void check_sign_change(void)
{
    sus_model m;
    char err[128];
    sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err);
    for (double a = 0.05; a < 3.2; a += 0.05) {
        const double w0[2] = {0.6 * cos(a), 0.6 * sin(a)};
        sus_exact ex;
        sus_exact_fast f;
        if (sus_exact_init(&ex, &m, w0) || sus_exact_fast_init(&f, &ex) || ex.fixed)
            continue;
        if (!(f.s0 < 0.0 && f.s0 + f.ks * T_RUN > 0.0 && f.ks > 0.0))
            continue;
        long N = 0;
        const double r = order_ratio(&m, w0, &N);
        CHECK(r >= RATIO_LO && r <= RATIO_HI,
              "through s = 0 (w0 at angle %.2f, s from %.2f to %.2f): error(N = %ld) / "
              "error(2N) = %.1f in [%g, %g]",
              a, f.s0, f.s0 + f.ks * T_RUN, N, r, RATIO_LO, RATIO_HI);
        check_many_steps(&m, w0, &f, N);
        return;
    }
    CHECK(0, "no w0 on the circle of radius 0.6 crosses s = 0 within T");
}

/* I31 = I32 = 0: w stays w0, and three steps give exp(T w0^) up to rounding (a few u per step). */
static void check_constant_w(void)
{
    const double I[9] = {1.0, 0.1, 0.0, 0.1, 1.0, 0.0, 0.0, 0.0, 1.0}, w0[2] = {0.4, 0.5};
    sus_model m;
    sus_exact ex;
    sus_exact_fast f;
    char err[128];
    sus_model_init(&m, I, err, sizeof err);
    sus_exact_init(&ex, &m, w0);
    sus_exact_fast_init(&f, &ex);
    const double n = hypot(w0[0], w0[1]), c = cos(0.5 * T_RUN * n), s = sin(0.5 * T_RUN * n);
    const double qe[4] = {c, s * w0[0] / n, s * w0[1] / n, 0.0};
    double q[4], d = 0.0;
    sus_lab_magnus6(&f, T_RUN, 3, q);
    for (int i = 0; i < 4; i++)
        d = fmax(d, fabs(q[i] - qe[i]));
    CHECK(d <= 64.0 * 0x1p-53, "constant w: 3 steps give exp(T w^) to %.2g (<= 64 u)", d);
}

int main(void)
{
    for (int k = 0; k < 1 + BODIES_GENERAL; k++) {
        body b;
        body_get(k, &b);
        check_order(&b);
    }
    check_sign_change();
    check_constant_w();
    return check_summary("test_magnus6");
}
