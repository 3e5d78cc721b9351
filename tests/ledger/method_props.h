/* What the ledger needs to know about a registered method beyond its step: whether it conserves
 * E, the form its attitude takes, how many substeps a step makes, and whether it is a truncated
 * series with a control one degree short. Read in one place from the stepper type's fields. */
#ifndef SUSLOV_METHOD_PROPS_H
#define SUSLOV_METHOD_PROPS_H

#include "registry.h"

typedef enum {
    METHOD_ATT_RECON,      /* R_{k+1} = R_k tau(...): (algo)'s reconstruction, compensated sum */
    METHOD_ATT_QUATERNION  /* a unit quaternion through the step, R rebuilt from it at every step */
} method_attitude;

typedef struct {
    int conserves_energy;      /* E = 1/2 <I_m w, w> kept to round-off by construction */
    method_attitude attitude;
    int substeps;              /* steps of the underlying map per step (1 but for compositions) */
    int series;                /* a truncated Taylor series (its control: the series one degree short) */
} method_props;

method_props method_props_of(const sus_step_method *me);

#endif
