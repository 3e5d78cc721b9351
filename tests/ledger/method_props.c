#include "method_props.h"

/* The ledger's view of a method, read from what the method's stepper type says of itself. */
method_props method_props_of(const sus_step_method *me)
{
    const sus_stepper_type *t = me->type;
    method_props p = {t->conserves_energy, METHOD_ATT_RECON, t->substeps > 0 ? t->substeps : 1,
                      t->apply_order != NULL};
    if (t->attitude == SUS_ATTITUDE_QUAT)
        p.attitude = METHOD_ATT_QUATERNION;
    return p;
}
