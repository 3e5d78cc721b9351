#include "stepper.h"

#include "api_args.h"

#include <math.h>

int sus_stepper_full(const sus_stepper_type *st, const sus_model *m, double eps, sus_recon recon,
                     sus_attitude *att, const double w[3], double w_next[3], double *lambda_next,
                     sus_stepper_stats *stats)
{
    if (!stats)
        return SUS_STEPPER_BAD_ARGUMENT;
    /* Cheap checks only: the driver calls this every step (and checked the model once). */
    if (!st || st->tol || !st->step || !(st->step->apply || st->step->apply_full) || !m ||
        !isfinite(eps) || (int)recon < 0 || (int)recon >= SUS_RECON_COUNT || !att || !w_next ||
        !lambda_next || !sus_args_finite2(w)) {
        *stats = (sus_stepper_stats){.last_residual = NAN};
        return SUS_STEPPER_BAD_ARGUMENT;
    }
    if (st->step->apply_full)
        return st->step->apply_full(m, eps, recon, att, w, w_next, lambda_next, stats);
    const int status = st->step->apply(m, eps, w, w_next, lambda_next, stats);
    if (status == SUS_STEPPER_OK)
        sus_reconstruct(recon, eps, att, w, w_next);
    return status;
}

double sus_step_end(double t, double h, double stop)
{
    if (!(t >= 0.0 && h > 0.0 && stop > t)) /* outside its contract, or a NaN: no end */
        return NAN;
    if (!(h < stop - t))
        return stop;
    double end = t + h;
    if (end - t > h) /* rounded up: h' > h could leave the radius or the tolerance the step met */
        end = nextafter(end, t);
    return end < stop ? end : stop;
}
