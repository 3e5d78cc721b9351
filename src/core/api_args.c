#include "api_args.h"

#include "exact.h"

#include <float.h>
#include <math.h>
#include <string.h>

int sus_args_finite2(const double w[2]) { return w && isfinite(w[0]) && isfinite(w[1]); }

int sus_args_tol_underflows(const sus_model *m, const double w0[2])
{
    const double size = fmax(fabs(w0[0]), fabs(w0[1]));
    return size > 0.0 && !(size >= 0x1p-500 && sus_energy(m, w0) >= DBL_MIN);
}

int sus_args_start_unresolved(const sus_model *m, const double w0[2])
{
    if (!m || !w0)
        return 0;
    const double c = sus_c_accurate(m, w0);
    const double terms = fabs(m->b[0] * w0[0]) + fabs(m->b[1] * w0[1]);
    return c != 0.0 && fabs(c) <= 0x1p-53 * terms && sus_contdyn_rate(m, w0) > 0.0;
}

int sus_args_lambda_overflows(const sus_model *m, const double w0[2])
{
    if (!m || !w0)
        return 0;
    const double(*I)[3] = m->I, w2 = 2.0 * sus_energy(m, w0) * m->norm_fA;
    const double rows = fabs(I[1][0]) + fabs(I[1][1]) + fabs(I[0][0]) + fabs(I[0][1]);
    const double o0 = m->norm_b * fabs(m->inv_det_m) * (fabs(m->o0c[0]) + fabs(m->o0c[1]));
    if ((rows + o0) * w2 <= 0x1p-8 * DBL_MAX) /* 2^-8: far more than these few roundings */
        return 0;
    sus_exact ex;
    return sus_exact_init(&ex, m, w0) == 0 && isinf(sus_exact_lambda_max(&ex));
}

/* The pointers and the model every run needs. */
static const char *common(const void *cfg, const sus_model *model, const double w0[2],
                          sus_emit_fn emit, const sus_run_report *report)
{
    if (!report)
        return "report is NULL";
    if (!cfg)
        return "cfg is NULL";
    if (!emit)
        return "emit is NULL";
    if (!w0)
        return "w0 is NULL";
    if (!sus_args_finite2(w0))
        return "w0 is not finite";
    /* as the command refuses it: a subnormal has lost its precision, and w^2 vanishes */
    if ((w0[0] != 0.0 && fabs(w0[0]) < DBL_MIN) || (w0[1] != 0.0 && fabs(w0[1]) < DBL_MIN))
        return "w0 has a subnormal entry (nonzero, below 2^-1022): too small to be served";
    if (!sus_model_sealed(model))
        return "cfg->model is NULL, or not a model sus_model_init filled, or changed since";
    /* the first row's E and lambda (sus_model_start_overflow), refused as the CLI refuses them */
    const char *what = sus_model_start_overflow(model, w0);
    if (what)
        return strcmp(what, "energy") == 0
                   ? "the energy at w0 overflows with this inertia"
                   : "the multiplier lambda at w0 overflows with this inertia";
    /* and lambda along the motion, as the CLI refuses it */
    if (sus_args_lambda_overflows(model, w0))
        return "the multiplier lambda overflows along the motion from w0 with this inertia";
    return NULL;
}

static const char *fixed_stepper(const sus_stepper_type *st, sus_recon recon)
{
    if (!st)
        return "cfg->stepper is NULL";
    if (st->tol)
        return "cfg->stepper chooses its own steps: run it with sus_run_tol";
    if (!st->step)
        return "cfg->stepper has no step interface (cfg->stepper->step is NULL)";
    if (!st->step->apply && !st->step->apply_full)
        return "cfg->stepper->step has neither apply nor apply_full";
    if ((int)recon < 0 || (int)recon >= SUS_RECON_COUNT)
        return "cfg->recon is not one of sus_recon's values";
    return NULL;
}

const char *sus_args_run(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit,
                         const sus_run_report *report, int with_stepper)
{
    const char *why = common(cfg, cfg ? cfg->model : NULL, w0, emit, report);
    if (!why && with_stepper)
        why = fixed_stepper(cfg->stepper, cfg->recon);
    if (why)
        return why;
    if (!(cfg->eps > 0.0) || !isfinite(cfg->eps))
        return "cfg->eps is not a finite step > 0";
    if (cfg->steps < 0)
        return "cfg->steps is negative";
    if (cfg->every < 1)
        return "cfg->every is below 1";
    if (!isfinite((double)cfg->steps * cfg->eps)) /* the last row's time */
        return "cfg->steps * cfg->eps overflows";
    return NULL;
}

static const char *tol_stepper(const sus_stepper_type *st, double every_time)
{
    if (!st)
        return "cfg->stepper is NULL";
    if (!st->tol)
        return "cfg->stepper is a fixed-step method: run it with sus_run";
    if (!st->tol->alloc || !st->tol->step || !st->tol->free)
        return "cfg->stepper->tol lacks alloc, step or free";
    if (every_time > 0.0 && !st->tol->dense)
        return "cfg->stepper->tol has no dense output for every_time > 0";
    return NULL;
}

const char *sus_args_tol(const sus_tol_config *cfg, const double w0[2], sus_emit_fn emit,
                         const sus_run_report *report)
{
    const char *why = common(cfg, cfg ? cfg->model : NULL, w0, emit, report);
    if (!why)
        why = tol_stepper(cfg->stepper, cfg->every_time);
    if (why)
        return why;
    /* from 1 on, an error bound of an attitude (|dq| <= 2) says nothing: the CLI's --tol refuses
     * it too; a tol below the rounding of the state is the methods' to refuse, at their first
     * step (SUS_STEPPER_REJECTED) */
    if (!(cfg->tol > 0.0 && cfg->tol < 1.0))
        return "cfg->tol is not in (0, 1)";
    if (!(cfg->t_end >= 0.0) || !isfinite(cfg->t_end))
        return "cfg->t_end is not a finite time >= 0";
    if (!(cfg->every_time >= 0.0) || !isfinite(cfg->every_time))
        return "cfg->every_time is not a finite interval >= 0";
    /* the driver counts the rows every_time apart in a long */
    if (cfg->every_time > 0.0 && !(cfg->t_end / cfg->every_time < 0x1p62))
        return "cfg->t_end / cfg->every_time: more rows than a long counts";
    if (cfg->max_steps < 0)
        return "cfg->max_steps is negative";
    if (sus_args_tol_underflows(cfg->model, w0))
        return "w0: below 2^-500, or its energy below the normal doubles, where the "
               "tolerance-driven methods' series, products of w and w, lose their bits: scale w0 "
               "up and t_end down alike";
    return NULL;
}

int sus_args_refuse(sus_run_report *report, const char *why)
{
    if (report)
        *report = (sus_run_report){.status = SUS_STEPPER_OK, .message = why};
    return SUS_RUN_BAD_ARGUMENT;
}
