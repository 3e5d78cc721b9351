#include "method_props.h"

#include "composition.h"
#include "taylor.h"

/* The adapter (see the header). The facts, from the methods' sources: the midpoint DSP keeps
 * the quadratic invariant E (its step is the midpoint rule on f, and <f(w), I_m w> = 0); a
 * composition is midpoint substeps with the attitude carried through them as a quaternion
 * (composition.c); a Taylor step restores E(w^k) and carries a quaternion series. */
method_props method_props_of(const suslov_method *me)
{
    static const struct {
        const suslov_stepper_type *type;
        const suslov_composition *table;
    } comp[] = {{&suslov_comp4_s5_type, &suslov_comp_suzuki4},
                {&suslov_comp6_kl_type, &suslov_comp_kahan_li6},
                {&suslov_comp8_kl_type, &suslov_comp_kahan_li8},
                {&suslov_comp10_ss_type, &suslov_comp_sofroniou10}};
    static const suslov_stepper_type *const taylor[] = {&suslov_taylor8_type, &suslov_taylor10_type,
                                                        &suslov_taylor12_type, &suslov_taylor16_type};
    method_props p = {me->type == &suslov_midpoint_type, METHOD_ATT_RECON, 1, 0};
    for (unsigned i = 0; i < sizeof comp / sizeof comp[0]; i++)
        if (comp[i].type == me->type)
            p = (method_props){1, METHOD_ATT_QUATERNION, suslov_composition_stages(comp[i].table), 0};
    for (unsigned i = 0; i < sizeof taylor / sizeof taylor[0]; i++)
        if (taylor[i] == me->type)
            p = (method_props){1, METHOD_ATT_QUATERNION, 1, 1};
    return p;
}
