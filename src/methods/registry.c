#include "registry.h"

#include <stdio.h>
#include <string.h>

/* One line per method: its stepper type (sus_step_ID_type, defined in its stepper file), a display
 * family, the \label of the statement it tests (NULL for an extension), its default
 * reconstruction, and one line for --help. Everything else a consumer needs is in the type. */
#define SUS_STEP_METHODS(M)                                                                        \
    M(euler, "paper DSP", "Discretization", CAYLEY,                                                \
      "(Discretization) with l = I_m f(w^k): explicit Euler")                                      \
    M(midpoint, "paper DSP", "Discretization", CAYLEY,                                             \
      "(Discretization) with the midpoint l1, l2 (Figures 1-2)")                                   \
    M(rk4, "paper DSP", "Discretization", CAYLEY,                                                  \
      "(Discretization) with the classical Runge-Kutta increment")                                 \
    M(variational, "variational", "PropoFinal", CAYLEY,                                            \
      "(taudyn) for w^{k+1}, (taualg) for lambda_{k+1}")                                           \
    M(comp4_s5, "composition", NULL, EXP_MID, "midpoint DSP composed, Suzuki s=5, order 4")        \
    M(comp6_kl, "composition", NULL, EXP_MID, "midpoint DSP composed, Kahan-Li s=9, order 6")      \
    M(comp8_kl, "composition", NULL, EXP_MID, "midpoint DSP composed, Kahan-Li s=17, order 8")     \
    M(comp10_ss, "composition", NULL, EXP_MID,                                                     \
      "midpoint DSP composed, Sofroniou-Spaletta s=35, order 10")                                  \
    M(taylor8, "taylor", NULL, EXP_MID, TAYLOR_ABOUT(8))                                           \
    M(taylor10, "taylor", NULL, EXP_MID, TAYLOR_ABOUT(10))                                         \
    M(taylor12, "taylor", NULL, EXP_MID, TAYLOR_ABOUT(12))                                         \
    M(taylor16, "taylor", NULL, EXP_MID, TAYLOR_ABOUT(16))                                         \
    M(gauss4, "collocation", NULL, EXP_MID,                                                        \
      "2-stage Gauss-Legendre collocation, order 4, conserves E")

/* Tolerance-driven methods (stepper.h, sus_tol_ops): after the fixed-step ones, outside
 * sus_step_method_count(), so that the sweeps over eps do not meet them. */
#define SUS_STEP_TOL_METHODS(M)                                                                    \
    M(taylor_adaptive, "taylor", NULL, EXP_MID,                                                    \
      "Taylor series, order and steps from --tol, rows by dense output (--every-time)")            \
    M(exact_attitude, "closed form", NULL, EXP_MID,                                                \
      "w from the closed form, attitude series with steps from --tol, the steady tail in one "     \
      "step")

#define TAYLOR_ABOUT(P) "Taylor series of order " #P ", quaternion attitude series, E restored"

#define DECLARE(ID, FAMILY, REF, RECON, ABOUT) extern const sus_stepper_type sus_step_##ID##_type;
SUS_STEP_METHODS(DECLARE)
SUS_STEP_TOL_METHODS(DECLARE)
#define ENTRY(ID, FAMILY, REF, RECON, ABOUT)                                                       \
    {&sus_step_##ID##_type, FAMILY, REF, SUS_RECON_##RECON, ABOUT},
#define ONE(ID, FAMILY, REF, RECON, ABOUT) +1
static const sus_step_method METHODS[] = {SUS_STEP_METHODS(ENTRY) SUS_STEP_TOL_METHODS(ENTRY)};
enum { NFIXED = 0 SUS_STEP_METHODS(ONE) };
#define NMETHODS ((int)(sizeof METHODS / sizeof METHODS[0]))

int sus_step_method_count(void) { return NFIXED; }
int sus_step_method_count_all(void) { return NMETHODS; }

const sus_step_method *sus_step_method_get(int i)
{
    return i >= 0 && i < NMETHODS ? &METHODS[i] : NULL;
}

int sus_step_method_index(const char *name)
{
    if (!name)
        return -1;
    for (int i = 0; i < NMETHODS; i++)
        if (strcmp(METHODS[i].type->name, name) == 0)
            return i;
    return -1;
}

int sus_step_method_index_of(const sus_stepper_type *type)
{
    for (int i = 0; i < NMETHODS; i++)
        if (METHODS[i].type == type)
            return i;
    return -1;
}

const sus_step_method *sus_step_method_by_name(const char *name)
{
    return sus_step_method_get(sus_step_method_index(name));
}

const char *sus_step_method_names(char *buf, unsigned long len, const char *sep)
{
    size_t used = 0;
    if (!buf || len == 0)
        return NULL;
    if (!sep)
        sep = "";
    buf[0] = '\0';
    for (int i = 0; i < NMETHODS && used < len; i++)
        used +=
            (size_t)snprintf(buf + used, len - used, "%s%s", i ? sep : "", METHODS[i].type->name);
    return buf;
}

const char *sus_step_attitude_name(sus_attitude_form form)
{
    static const char *const NAMES[] = {"none", "matrix", "quaternion"};
    return form >= SUS_ATTITUDE_NONE && form <= SUS_ATTITUDE_QUAT ? NAMES[form] : "?";
}

const char *sus_step_method_label(const sus_stepper_type *t, sus_recon recon, char *buf, size_t len)
{
    if (!buf || len == 0)
        return NULL;
    if (!t || !t->name ||
        (t->desc.follows_recon && ((int)recon < 0 || (int)recon >= SUS_RECON_COUNT))) {
        buf[0] = '\0';
        return NULL;
    }
    if (t->desc.follows_recon)
        snprintf(buf, len, "%s + %s", t->name, SUS_RECON_NAMES[recon]);
    else if (t->desc.attitude != SUS_ATTITUDE_NONE)
        snprintf(buf, len, "%s (%s)", t->name, sus_step_attitude_name(t->desc.attitude));
    else
        snprintf(buf, len, "%s", t->name);
    return buf;
}

int sus_step_methods_write_tsv(FILE *fp)
{
    if (!fp)
        return -1;
    fprintf(fp,
            "name\tfamily\torder\tlambda_order\timplicit\tunknowns\tconserves_energy\tattitude\t"
            "follows_recon\tsubsteps\tstability\trecon\tpaper_ref\tsource\tabout\n");
    for (int i = 0; i < NMETHODS; i++) {
        const sus_step_method *me = &METHODS[i];
        const sus_stepper_type *t = me->type;
        fprintf(fp, "%s\t%s\t%d\t%d\t%d\t%d\t%d\t%s\t%d\t%d\t%d\t%s\t%s\t%s\t%s\n", t->name,
                me->family, t->desc.order, t->desc.lambda_order, t->desc.implicit,
                (t->equation ? t->equation->unknowns : 0), t->desc.conserves_energy,
                sus_step_attitude_name(t->desc.attitude), t->desc.follows_recon, t->desc.substeps,
                t->desc.stability != NULL, SUS_RECON_NAMES[me->recon],
                me->paper_ref ? me->paper_ref : "-", t->desc.source, me->about);
    }
    /* flushed first: a write that fails in the buffer sets the error only when it reaches fp */
    return fflush(fp) != 0 || ferror(fp) ? -1 : 0;
}
