/* The bench's peers (src/lab/peers.c): a run repeated on the same configuration, as the bench's
 * timed runs repeat it, must give the state and step count of a run on a fresh configuration.
 * GSL's driver keeps the step a run ended with unless it is reset to hstart, and the bench
 * records the error of one run while it times the others: they must be the same run. And the
 * reduced problem the peers are given (src/lab/reduced.h): its cheap w(t) (exact_fast.h) is the
 * closed form's on every body, and its right-hand side is the attitude's kinematics along it. */
#include "bodies.h"
#include "check.h"
#include "exact.h"
#include "peers.h"
#include "reduced.h"
#include "refattitude.h"
#include "so3.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <string.h>

/* A tolerance where the step carried over from a previous run changes the result (the step
 * controller's first decisions depend on hstart), on the paper's problem. */
#define TOL 1.8e-5
#define T_END 50.0

/* dim 4: the reduced problem along red, abs = rel = TOL. */
static int open_peer(sus_lab_peer *p, const sus_model *m, const sus_exact_fast *red,
                     const gsl_odeiv2_step_type *type, size_t dim, sus_lab_peer_api api,
                     double hstart)
{
    return dim == 4 ? sus_lab_peer_open_reduced(p, red, type, api, TOL, TOL, hstart)
                    : sus_lab_peer_open(p, m, type, dim, api, TOL, TOL, hstart);
}

static int same_run(const sus_model *m, const sus_exact_fast *red, const gsl_odeiv2_step_type *type,
                    size_t dim, sus_lab_peer_api api, double hstart)
{
    const double w0[2] = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]};
    sus_lab_peer fresh, used;
    double y0[11], y1[11], y2[11];
    long n0 = 0, n1 = 0, n2 = 0;
    if (open_peer(&fresh, m, red, type, dim, api, hstart) ||
        open_peer(&used, m, red, type, dim, api, hstart))
        return 0;
    const int s0 = sus_lab_peer_run(&fresh, w0, T_END, y0, &n0);
    /* a run to another end time leaves the configuration with another step size */
    const int s1 = sus_lab_peer_run(&used, w0, 0.37 * T_END, y1, &n1);
    const int s2 = sus_lab_peer_run(&used, w0, T_END, y2, &n2);
    sus_lab_peer_close(&fresh);
    sus_lab_peer_close(&used);
    return s0 == GSL_SUCCESS && s1 == GSL_SUCCESS && s2 == GSL_SUCCESS && n0 == n2 &&
           memcmp(y0, y2, dim * sizeof(double)) == 0;
}

/* The largest |w_cheap - w_closed| over t in [0, 50] and at long times, in units of the rounding
 * yardstick u S_i of each component: S_1 = r / l22 and S_0 = (r + |l21| S_1) / l11 bound the
 * terms w is summed from (|cos psi|, |sin psi| <= 1). Both sides share s; E, sech and tanh
 * (its 1 - E^2 loses relative, not absolute, accuracy near s = 0) carry a few roundings each,
 * M's entries and the product with it a few more: about 10 u S_i in all. */
static double omega_rounding_ratio(const sus_exact *ex, const sus_exact_fast *red)
{
    const double S1 = ex->r / ex->l22, S0 = (ex->r + fabs(ex->l21) * S1) / ex->l11;
    double worst = 0.0;
    for (int i = 0; i <= 1000; i++) {
        const double t = i <= 500 ? 0.1 * i : 50.0 * pow(1e4 / 50.0, (i - 500) / 500.0);
        double a[2], b[2];
        sus_exact_omega(ex, t, a);
        sus_exact_fast_omega(red, t, b);
        worst = fmax(worst, fmax(fabs(a[0] - b[0]) / S0, fabs(a[1] - b[1]) / S1) / DBL_EPSILON);
    }
    return worst;
}

/* rk8pd on the reduced problem at tolerance 1e-12 against the long-double reference at t = 50:
 * the flow of R' = R w^ keeps norms, so the global error is at most the sum of the local ones,
 * each held near the tolerance, over fewer than 1e4 steps: 1e-8. A wrong sign or row of M, or of
 * the kinematics, moves R(50) by O(1). */
static double reduced_error(const sus_model *m, const sus_exact *ex, const sus_exact_fast *red)
{
    sus_lab_peer p;
    double y[4], w[2], R[3][3], Rref[3][3];
    long n = 0;
    if (sus_lab_peer_open_reduced(&p, red, gsl_odeiv2_step_rk8pd, SUS_LAB_PEER_DRIVER, 1e-12, 1e-12,
                                  1e-2) != 0)
        return INFINITY;
    const int st = sus_lab_peer_run(&p, ex->w0, T_END, y, &n);
    sus_lab_peer_close(&p);
    sus_lab_peer_attitude(4, y, R);
    sus_refatt_precise(m, ex->w0, T_END, w, Rref);
    return st == GSL_SUCCESS && n < 10000 ? sus_so3_dist(R, Rref) : INFINITY;
}

static void check_reduced(void)
{
    for (int k = 0; k < BODIES_COUNT; k++) {
        body bd;
        sus_model m;
        sus_exact ex;
        sus_exact_fast red;
        char err[256];
        body_get(k, &bd);
        if (sus_model_init(&m, bd.I, err, sizeof err) != 0 || sus_exact_init(&ex, &m, bd.w0) != 0 ||
            sus_exact_fast_init(&red, &ex) != 0) {
            CHECK(0, "%s: the model, closed form and reduced problem set up (%s)", bd.name, err);
            continue;
        }
        const double r = omega_rounding_ratio(&ex, &red);
        CHECK(r <= 32.0,
              "%s: the reduced problem's w(t) is the closed form's within 32 u of its "
              "terms, t in [0, 1e4]: %.3g u",
              bd.name, r);
        const double e = reduced_error(&m, &ex, &red);
        CHECK(e <= 1e-8,
              "%s: rk8pd (tol 1e-12) on the reduced problem ends within 1e-8 of the "
              "reference attitude at t = 50: %.3g",
              bd.name, e);
    }
}

/* The full problem's error control: abs = rel = TOL, or (rel 0) the absolute error alone. |y| is
 * of order one, so GSL's tolerance D = abs + rel |y| about halves without rel and the run takes
 * more steps: a rel that did not reach GSL would give the same run. */
static void check_abs_only(const sus_model *m)
{
    long steps[2] = {0, 0};
    for (int c = 0; c < 2; c++) {
        sus_lab_peer p;
        double y[11];
        if (sus_lab_peer_open(&p, m, gsl_odeiv2_step_rk8pd, 6, SUS_LAB_PEER_DRIVER, TOL,
                              c ? 0.0 : TOL, 1.0) == 0)
            sus_lab_peer_run(&p, SUS_PAPER_OMEGA0, T_END, y, &steps[c]);
        sus_lab_peer_close(&p);
    }
    CHECK(steps[0] > 0 && steps[1] > steps[0],
          "GSL rk8pd (w,q) driver: the absolute error alone takes more steps (%ld) than abs = rel "
          "(%ld)",
          steps[1], steps[0]);
}

int main(void)
{
    gsl_set_error_handler_off();
    sus_model m;
    sus_exact ex;
    sus_exact_fast red;
    char err[256];
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0 ||
        sus_exact_init(&ex, &m, SUS_PAPER_OMEGA0) != 0 || sus_exact_fast_init(&red, &ex) != 0)
        return 1;
    const gsl_odeiv2_step_type *types[2] = {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkck};
    const size_t dims[4] = {11, 6, 2, 4};
    const double hstarts[4] = {1e-3, 1e-2, 0.1, 1.0};
    for (int k = 0; k < 2; k++)
        for (int api = 0; api < 2; api++)
            for (int d = 0; d < 4; d++)
                for (int h = 0; h < 4; h++)
                    CHECK(same_run(&m, &red, types[k], dims[d], (sus_lab_peer_api)api, hstarts[h]),
                          "GSL %s dim %zu %s hstart %g: a repeated "
                          "run equals a fresh run, bit for bit",
                          types[k]->name, dims[d], api ? "evolve" : "driver", hstarts[h]);
    check_reduced();
    check_abs_only(&m);
    return check_summary("test_peers");
}
