#include "stability_fn.h"

double suslov_stab_euler(double z) { return 1.0 + z; }

double suslov_stab_rk4(double z)
{
    return 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
}

double suslov_stab_midpoint(double z) { return (1.0 + 0.5 * z) / (1.0 - 0.5 * z); }
