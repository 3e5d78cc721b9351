/* The bench's peers (src/exp/peers.c): a run repeated on the same configuration, as the bench's
 * timed runs repeat it, must give the state and step count of a run on a fresh configuration.
 * GSL's driver keeps the step a run ended with unless it is reset to hstart, and the bench
 * records the error of one run while it times the others: they must be the same run. */
#include "check.h"
#include "exact.h"
#include "peers.h"

#include <gsl/gsl_errno.h>
#include <string.h>

/* A tolerance where the step carried over from a previous run changes the result (the step
 * controller's first decisions depend on hstart), on the paper's problem. */
#define TOL 1.8e-5
#define T_END 50.0

static int same_run(const sus_model *m, const gsl_odeiv2_step_type *type, size_t dim, sus_exp_peer_api api,
                    double hstart)
{
    const double w0[2] = {SUS_PAPER_OMEGA0[0], SUS_PAPER_OMEGA0[1]};
    sus_exp_peer fresh, used;
    double y0[11], y1[11], y2[11];
    long n0 = 0, n1 = 0, n2 = 0;
    if (sus_exp_peer_open(&fresh, m, type, dim, api, TOL, hstart) ||
        sus_exp_peer_open(&used, m, type, dim, api, TOL, hstart))
        return 0;
    const int s0 = sus_exp_peer_run(&fresh, w0, T_END, y0, &n0);
    /* a run to another end time leaves the configuration with another step size */
    const int s1 = sus_exp_peer_run(&used, w0, 0.37 * T_END, y1, &n1);
    const int s2 = sus_exp_peer_run(&used, w0, T_END, y2, &n2);
    sus_exp_peer_close(&fresh);
    sus_exp_peer_close(&used);
    return s0 == GSL_SUCCESS && s1 == GSL_SUCCESS && s2 == GSL_SUCCESS && n0 == n2
        && memcmp(y0, y2, dim * sizeof(double)) == 0;
}

int main(void)
{
    gsl_set_error_handler_off();
    sus_model m;
    char err[256];
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0)
        return 1;
    const gsl_odeiv2_step_type *types[2] = {gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkck};
    const size_t dims[3] = {11, 6, 2};
    const double hstarts[4] = {1e-3, 1e-2, 0.1, 1.0};
    for (int k = 0; k < 2; k++)
        for (int api = 0; api < 2; api++)
            for (int d = 0; d < 3; d++)
                for (int h = 0; h < 4; h++)
                    CHECK(same_run(&m, types[k], dims[d], (sus_exp_peer_api)api, hstarts[h]),
                          "GSL %s dim %zu %s hstart %g: a repeated run equals a fresh run, bit for bit",
                          types[k]->name, dims[d], api ? "evolve" : "driver", hstarts[h]);
    return check_summary("test_peers");
}
