#include "expected_orders.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* SO(3) orders: with R_{k+1} = R_k cay(eps w^_k) the reconstruction is first order, so TeoL
 * gives min(1, p); the symmetric reconstructions are second order (the midpoint rule for
 * R' = R w^ on the group), so min(2, p). */
/* Where p and s are stated, in the notation (notation.h). */
#define REF_GENERAL_DSP "\\PaperRefOr{nolabel:proposition-5.2}, order $(p,p)$"
#define TAYLOR "Taylor's theorem; Jorba \\& Zou 2005"

#define SO3(cayley, cayley_mid, exp_mid)                                                           \
    {                                                                                              \
        [SUS_RECON_CAYLEY] = cayley, [SUS_RECON_CAYLEY_MID] = cayley_mid,                          \
        [SUS_RECON_EXP_MID] = exp_mid                                                              \
    }

static const expected_order TABLE[] = {
    /* The general-DSP proposition: explicit Euler is (1, 1), RK4 is (4, 4); the midpoint DSP is
     * (2, 2) (the text once calls it "(2,1)", the proposition gives s = p).
     * docs/explanation/where-methods-fail.md states, from the stability map, that the midpoint
     * and variational step equations keep a root on their branch continued from eps = 0 for
     * every start up to h = 1000 (no fold), and that the map meets a fold of gauss4's. */
    {"euler", 1, 1, SO3(1, 1, 1), REF_GENERAL_DSP, 1, 0, 0},
    {"midpoint", 2, 2, SO3(1, 2, 2), REF_GENERAL_DSP, 0, INFINITY, 0},
    {"rk4", 4, 4, SO3(1, 2, 2), REF_GENERAL_DSP, 1, 0, 0},
    /* PropoFinal: (taudyn) is second order, (taualg) does not converge to lambda. */
    {"variational", 2, -1, SO3(1, 2, 2), "\\PaperRefOr{PropoFinal}", 0, INFINITY, 0},
    /* Extensions. A symmetric composition of a symmetric second-order map has the
     * order its weights are built for (Hairer-Lubich-Wanner, Geometric Numerical Integration,
     * Thm. II.4.1 and Sect. V.3); with a symmetric reconstruction the composed map of (w, R) is
     * such a composition, so the SO(3) order is that order too; with cay(eps w^_k) (first order)
     * it is 1. lambda = lambda(w^{k+1}) from (LagMult) inherits the order of w. */
    {"comp4-s5", 4, 4, SO3(1, 4, 4), "Suzuki 1990 ($s = 5$), HLW V.3", 0, 0, 0},
    {"comp6-kl", 6, 6, SO3(1, 6, 6), "Kahan \\& Li 1997 ($s = 9$), HLW V.3", 0, 0, 0},
    {"comp8-kl", 8, 8, SO3(1, 8, 8), "Kahan \\& Li 1997 ($s = 17$), HLW V.3", 0, 0, 0},
    {"comp10-ss", 10, 10, SO3(1, 10, 10), "Sofroniou \\& Spaletta 2005 ($s = 35$), HLW V.3", 0, 0,
     0},
    /* A Taylor method of degree p has order p (truncation of the exact series); its attitude is
     * the degree-p series of the quaternion, whatever the reconstruction asked for. */
    {"taylor8", 8, 8, SO3(8, 8, 8), TAYLOR, 1, 0, 0},
    {"taylor10", 10, 10, SO3(10, 10, 10), TAYLOR, 1, 0, 0},
    {"taylor12", 12, 12, SO3(12, 12, 12), TAYLOR, 1, 0, 0},
    {"taylor16", 16, 16, SO3(16, 16, 16), TAYLOR, 1, 0, 0},
    /* The 2-stage Gauss-Legendre collocation has order 2s = 4 (Butcher 1964; HLW Thm. II.1.5); with
     * lambda(w^{k+1}) from (LagMult) the general-DSP proposition gives s = p. Its attitude is the
     * same collocation on the quaternion kinematics, order 4 whatever reconstruction is asked. */
    {"gauss4", 4, 4, SO3(4, 4, 4), "Gauss-Legendre $s = 2$ (HLW II.1.3); " REF_GENERAL_DSP, 0, 0,
     1},
};

const expected_order *expected_order_of(const char *method)
{
    for (size_t i = 0; i < sizeof TABLE / sizeof TABLE[0]; i++)
        if (strcmp(TABLE[i].method, method) == 0)
            return &TABLE[i];
    return NULL;
}

/* taylor-adaptive holds each step's estimate to TOL (as Jorba & Zou 2005 and heyoka do);
 * exact-attitude shares TOL out over the run (w and lambda are the closed form, and the flow of
 * R' = R w^ keeps norms, so the local errors add up to a bound of the global one). */
static const expected_tol TOL_TABLE[] = {
    {"taylor-adaptive", "adaptive", TOL_LOCAL, "Jorba & Zou 2005 (the step's estimate)"},
    {"exact-attitude", "exactatt", TOL_GLOBAL, "its step file's top (a budget over the run)"},
};

const expected_tol *expected_tol_of(const char *method)
{
    for (size_t i = 0; i < sizeof TOL_TABLE / sizeof TOL_TABLE[0]; i++)
        if (strcmp(TOL_TABLE[i].method, method) == 0)
            return &TOL_TABLE[i];
    return NULL;
}
