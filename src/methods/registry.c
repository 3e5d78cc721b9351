#include "registry.h"

#include "composition.h"
#include "stability_fn.h"
#include "taylor.h"

#include <stdio.h>
#include <string.h>

static const suslov_method METHODS[] = {
    {&suslov_euler_type, "paper DSP", 0, suslov_stab_euler, "Discretization", SUSLOV_RECON_CAYLEY,
     "(Discretization) with l = I_m f(w^k): explicit Euler"},
    {&suslov_midpoint_type, "paper DSP", 1, suslov_stab_midpoint, "Discretization", SUSLOV_RECON_CAYLEY,
     "(Discretization) with the midpoint l1, l2 (Figures 1-2)"},
    {&suslov_rk4_type, "paper DSP", 0, suslov_stab_rk4, "Discretization", SUSLOV_RECON_CAYLEY,
     "(Discretization) with the classical Runge-Kutta increment"},
    {&suslov_variational_type, "variational", 1, NULL, "PropoFinal", SUSLOV_RECON_CAYLEY,
     "(taudyn) for w^{k+1}, (taualg) for lambda_{k+1}"},
    /* Extensions (issue 11): compositions of the midpoint DSP with a symmetric reconstruction,
     * and Taylor-series methods with a quaternion attitude (its own, whatever --reconstruct).
     * The compositions list no stability function: the composed linear map prod (1 + g_i z/2) /
     * (1 - g_i z/2) has a pole at z = 2/g_i for each negative weight (h = 3.0 for comp4-s5), where
     * a backward substep's linear step equation is singular; measured, a start near the
     * attracting rotation still returns at h ~ 300-700, and from the energy ellipse the Newton
     * solves fail from h ~ 10-40 (figures/stability): the linear function predicts neither. */
    {&suslov_comp4_s5_type, "composition", 1, NULL, NULL, SUSLOV_RECON_EXP_MID,
     "midpoint DSP composed, Suzuki s=5, order 4"},
    {&suslov_comp6_kl_type, "composition", 1, NULL, NULL, SUSLOV_RECON_EXP_MID,
     "midpoint DSP composed, Kahan-Li s=9, order 6"},
    {&suslov_comp8_kl_type, "composition", 1, NULL, NULL, SUSLOV_RECON_EXP_MID,
     "midpoint DSP composed, Kahan-Li s=17, order 8"},
    {&suslov_comp10_ss_type, "composition", 1, NULL, NULL, SUSLOV_RECON_EXP_MID,
     "midpoint DSP composed, Sofroniou-Spaletta s=35, order 10"},
    {&suslov_taylor8_type, "taylor", 0, suslov_stab_taylor8, NULL, SUSLOV_RECON_EXP_MID,
     "Taylor series of order 8, quaternion attitude series (ignores --reconstruct), E restored"},
    {&suslov_taylor10_type, "taylor", 0, suslov_stab_taylor10, NULL, SUSLOV_RECON_EXP_MID,
     "Taylor series of order 10, quaternion attitude series (ignores --reconstruct), E restored"},
    {&suslov_taylor12_type, "taylor", 0, suslov_stab_taylor12, NULL, SUSLOV_RECON_EXP_MID,
     "Taylor series of order 12, quaternion attitude series (ignores --reconstruct), E restored"},
    {&suslov_taylor16_type, "taylor", 0, suslov_stab_taylor16, NULL, SUSLOV_RECON_EXP_MID,
     "Taylor series of order 16, quaternion attitude series (ignores --reconstruct), E restored"},
};
#define NMETHODS ((int)(sizeof METHODS / sizeof METHODS[0]))

int suslov_method_count(void) { return NMETHODS; }

const suslov_method *suslov_method_get(int i)
{
    return i >= 0 && i < NMETHODS ? &METHODS[i] : NULL;
}

int suslov_method_index(const char *name)
{
    for (int i = 0; i < NMETHODS; i++)
        if (strcmp(METHODS[i].type->name, name) == 0)
            return i;
    return -1;
}

const suslov_method *suslov_method_by_name(const char *name)
{
    return suslov_method_get(suslov_method_index(name));
}

const char *suslov_method_names(char *buf, unsigned long len, const char *sep)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < NMETHODS && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? sep : "", METHODS[i].type->name);
    return buf;
}
