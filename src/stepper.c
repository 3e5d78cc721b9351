#include "stepper.h"

#include <string.h>

const suslov_stepper_type *suslov_stepper_get(int i)
{
    const suslov_stepper_type *all[] = {suslov_step_euler, suslov_step_midpoint,
                                        suslov_step_rk4, suslov_step_variational};
    return i >= 0 && i < (int)(sizeof all / sizeof all[0]) ? all[i] : NULL;
}

const suslov_stepper_type *suslov_stepper_by_name(const char *name)
{
    const suslov_stepper_type *s;
    for (int i = 0; (s = suslov_stepper_get(i)) != NULL; i++)
        if (strcmp(s->name, name) == 0)
            return s;
    return NULL;
}

void suslov_predict(const suslov_model *m, double eps, const double w[2], double x[2])
{
    double f[2], mid[2];
    suslov_contdyn(m, w, f);
    mid[0] = w[0] + 0.5 * eps * f[0];
    mid[1] = w[1] + 0.5 * eps * f[1];
    suslov_contdyn(m, mid, f);
    x[0] = w[0] + eps * f[0];
    x[1] = w[1] + eps * f[1];
}
