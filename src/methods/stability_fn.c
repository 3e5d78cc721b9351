#include "stability_fn.h"

double sus_step_stab_euler(double z) { return 1.0 + z; }

double sus_step_stab_rk4(double z)
{
    return 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
}

double sus_step_stab_midpoint(double z) { return (1.0 + 0.5 * z) / (1.0 - 0.5 * z); }
