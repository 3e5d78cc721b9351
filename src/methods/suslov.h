/* The library's public interface, the one header a program includes: `make install` puts it and
 * the headers it includes (and no other) in PREFIX/include/suslov/, so a program writes
 *     #include <suslov/suslov.h>
 * and builds with `cc prog.c $(pkg-config --cflags --libs suslov)` (C17, or C++: every header
 * declares C linkage). The library, libsuslov.a, holds the core and the methods and needs only
 * libm.
 *
 * What a program uses:
 *   the body       sus_model, sus_model_init, sus_model_sealed (model.h)
 *   the methods    the registry: sus_step_method_by_name, _get, _count_all (registry.h)
 *   the runs       sus_run (fixed step), sus_run_tol (tolerance-driven), sus_run_exact (the
 *                  closed form), each handing rows (sus_row) to a callback (driver.h,
 *                  exact_run.h)
 *   the solution   sus_exact_init, sus_exact_omega, sus_exact_limit (exact.h)
 *
 * The contract: every function declared in these headers checks its arguments and never
 * crashes, loops or returns a made-up number on bad ones:
 *   - the runs return SUS_RUN_BAD_ARGUMENT before emitting any row, with report->message
 *     naming the argument (driver.h lists what they check: NULL pointers, a model that
 *     sus_model_init did not make, a non-finite or subnormal entry of w0, a w0 whose energy or
 *     lambda overflows, eps <= 0, steps < 0, every < 1, a method of the wrong kind, a tolerance
 *     or times that are not finite and positive, a final time by which the steady rotation
 *     turns the body past what the attitude serves (exact_run.h, sus_exact_turn_angle), a
 *     tolerance-driven run from a w0 not 0 with |w0| below 2^-500 or an energy below the normal
 *     doubles, where its series lose their bits);
 *   - functions returning int return a negative value (sus_model_init, sus_exact_init,
 *     sus_recon_by_name, sus_step_method_index, sus_step_methods_write_tsv) or a
 *     documented status (sus_stepper_full: SUS_STEPPER_BAD_ARGUMENT);
 *   - those returning a pointer return NULL; sus_exact_reference_steps returns -1;
 *   - those returning or writing numbers write NaN for a NULL input, and nothing where the
 *     output is NULL; NaN in gives NaN out.
 * A stepper's own function pointers (the members of sus_stepper_type) are the drivers'
 * interface, called once per step: call them through the run functions. */
#ifndef SUS_SUSLOV_H
#define SUS_SUSLOV_H

#include "driver.h"
#include "exact.h"
#include "exact_run.h"
#include "model.h"
#include "registry.h"

#endif
