/* The library's guards and bounds, checked against their definitions on the seeded general bodies:
 * the model's rounded-up norms |b|_2 and ||fA||_2 (model.h: bounds, so |c(v) fA u| <= K |v| |u|)
 * and the driver's finiteness check of a row (driver.h: every field of t, w, lambda, R looked at).
 * These are what the Taylor radius and the blow-up report stand on, and no value a program prints
 * moves when they are slightly off, so they are checked here directly. */
#include "bodies.h"
#include "check.h"
#include "driver.h"
#include "model.h"

#include <math.h>

/* A rounded-up bound is at least the exact value and at most a few roundings above it: 1e-13
 * relative is 450 u, far above the few ulps of a closed form of four terms. */
#define UP 1e-13

/* ||M||_2 of a 2x2 matrix from the eigenvalues of the symmetric M M^T = [[p, r], [r, q]]:
 * s^2 = (p + q + sqrt((p - q)^2 + 4 r^2)) / 2 (a different closed form from the library's). */
static double norm2_ref(double a, double b, double c, double d)
{
    const double p = a * a + b * b, q = c * c + d * d, r = a * c + b * d;
    return sqrt(0.5 * (p + q + sqrt((p - q) * (p - q) + 4.0 * r * r)));
}

static void norm_checks(const body *bd, const sus_model *m)
{
    const double *I = bd->I, det = I[0] * I[4] - I[1] * I[3];
    /* (ContDyn) as f = c(w) fA w: fA = [[-I12, -I22], [I11, I21]] / |I_m| */
    const double s = norm2_ref(-I[1] / det, -I[4] / det, I[0] / det, I[3] / det);
    CHECK(m->norm_fA >= s && m->norm_fA <= s * (1.0 + UP), "%s: ||fA||_2 %.17g, a bound tight to %.0e of %.17g",
          bd->name, m->norm_fA, UP, s);
    const double nb = sqrt(I[6] * I[6] + I[7] * I[7]);
    CHECK(m->norm_b >= nb && m->norm_b <= nb * (1.0 + UP), "%s: |b|_2 %.17g, a bound tight to %.0e of %.17g",
          bd->name, m->norm_b, UP, nb);
}

/* A row with every field finite is finite; one non-finite field, whichever, makes it not. */
static void row_finite_checks(void)
{
    sus_row r = {.k = 3, .t = 0.5, .w = {0.1, -0.2, 0.0}, .lambda = 0.3,
                 .R = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    CHECK(sus_row_finite(&r), "a finite row is finite");
    double *field[15] = {&r.t, &r.w[0], &r.w[1], &r.w[2], &r.lambda};
    for (int i = 0; i < 9; i++)
        field[5 + i] = &r.R[i / 3][i % 3];
    int missed = 0;
    for (int f = 0; f < 14; f++) {
        const double keep = *field[f];
        *field[f] = f % 2 ? NAN : INFINITY;
        missed += sus_row_finite(&r) != 0;
        *field[f] = keep;
    }
    CHECK(missed == 0, "a row with one non-finite field (each of the 14 in turn) is not finite: %d missed",
          missed);
}

int main(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body bd;
        body_get(k, &bd);
        sus_model m;
        char err[128];
        if (sus_model_init(&m, bd.I, err, sizeof err) != 0) {
            CHECK(0, "%s: %s", bd.name, err);
            continue;
        }
        norm_checks(&bd, &m);
    }
    row_finite_checks();
    return check_summary("test_guards");
}
