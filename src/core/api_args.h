/* The argument checks of the library's public functions (src/methods/suslov.h), in one place so
 * that the run drivers refuse the same things with the same words. Not installed: the user sees
 * only their result, a status and report->message. */
#ifndef SUS_API_ARGS_H
#define SUS_API_ARGS_H

#include "driver.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when w is not NULL and both its entries are finite. */
int sus_args_finite2(const double w[2]);
/* 1 when w0 is not 0 and either |w0| (max norm) is below 2^-500 or its energy below the normal
 * doubles: the field is quadratic, so the tolerance-driven methods' series multiply w by w, and
 * (ContDyn)'s coefficients I_ij / |I_m| by w. The largest of those, max(I11, I22) / |I_m| >=
 * 1 / min(I11, I22), is above 2^-512 for any I_m whose determinant a double holds (I11 I22 below
 * 2^1024), so from |w| >= 2^-500 the leading products are normal doubles with 2^10 to spare; below,
 * they are subnormal and lose their bits (or vanish), and the attitude the steps carry with them.
 * taylor-adaptive restores the energy, which must be a normal double for that. The motion is the
 * same in scaled time (c w0 to time T / c), which a caller can use instead. sus_args_tol refuses
 * such a w0. */
int sus_args_tol_underflows(const sus_model *m, const double w0[2]);
/* 1 when lambda of (LagMult) overflows along the motion from w0 (sus_exact_lambda_max), which a
 * start's own check (sus_model_start_overflow) cannot see. First a bound of lambda's terms from
 * the model alone, |w|^2 <= 2E ||I_m^-1|| and |c| <= |b| |w|: below the largest double with room
 * to spare for its roundings (the common case) the closed form is not built, so the check costs
 * a run a few products. 0 for a NULL m or w0. It judges lambda's value, as a row's lambda is
 * formed (a term that overflows is summed scaled: model.h); on a near-singular I_m the largest
 * lambda carries the closed form's cancellation in its last digits, so a start whose lambda comes
 * that close to the limit is refused or not by its roundings. */
int sus_args_lambda_overflows(const sus_model *m, const double w0[2]);
/* 1 when w0 lies off the repelling steady rotation by less than a rounding: c(w0) = I31 w1 + I32 w2
 * is not 0 (to one rounding of itself, sus_cross_diff) but at most 2^-53 (|I31 w1| + |I32 w2|),
 * half of SUS_U: the rounding of c at w0, and c grows from there, c' = g(w) c with g(w0) = c(fA w0)
 * > 0 ((ContDyn)). A method that steps w from w0 cannot tell w0 from that rotation, whose c is 0 to
 * the same rounding: it stays there, or leaves when its roundings say, not when c(w0) says; the
 * closed form (exact.h) follows the motion. 0 for a NULL m or w0. */
int sus_args_start_unresolved(const sus_model *m, const double w0[2]);
/* NULL when the arguments of sus_run (with_stepper = 1) or sus_run_exact (0: no stepper is
 * used) are good (driver.h lists what is checked), else the reason in one line. */
const char *sus_args_run(const sus_run_config *cfg, const double w0[2], sus_emit_fn emit,
                         const sus_run_report *report, int with_stepper);
/* The same for sus_run_tol. */
const char *sus_args_tol(const sus_tol_config *cfg, const double w0[2], sus_emit_fn emit,
                         const sus_run_report *report);
/* A refused run: the report (if any) says why; returns SUS_RUN_BAD_ARGUMENT. */
int sus_args_refuse(sus_run_report *report, const char *why);

#ifdef __cplusplus
}
#endif

#endif
