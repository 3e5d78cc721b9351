/* The checks of suslov's options that need several of them (suslov_cli.c parses each alone): the
 * run's kind, its steps, the body, the start, the method and its reconstruction, the output. */
#define _POSIX_C_SOURCE 200809L
#include "suslov_cli_checks.h"

#include "api_args.h"
#include "atomic_file.h"
#include "cli_options.h"
#include "dsp.h"
#include "exact_run.h"
#include "inertia_check.h"
#include "midpoint_sweeps.h"
#include "stepper.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The reference attitude of --method exact (refattitude.h) costs one long-double Taylor step of
 * order SUS_REFATT_ORDER = P per step h: its Cauchy products sum P (P + 1) / 2 = 406 terms of
 * about 20 long-double operations each, some 1e4 operations, about 1e-5 s at 1e9 operations a
 * second (x87; several times slower where long double is a software quad). A row's partial step
 * costs at most that: its order falls with its length (refattitude.c). A run is refused
 * beyond a budget of ten minutes, and one beyond a few seconds (the guide's threshold for a
 * progress report) is announced on stderr, since its rows may come minutes apart. */
#define EXACT_STEP_SECONDS 1e-5
#define EXACT_MAX_SECONDS 600.0
#define EXACT_NOTE_SECONDS 5.0

/* The nearest final time to n steps, written as briefly as it is still accepted. */
static void time_choice(char *buf, size_t len, double n, double eps)
{
    const double T = n * eps;
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(buf, len, "--time %.*g", digits, T);
        const double back = strtod(buf + 7, NULL);
        if (fabs(round(back / eps) * eps - back) <= 2.0 * DBL_EPSILON * back)
            return;
    }
}

/* N = T/H when that is a whole number to within the rounding of T, H and their quotient:
 * |N H - T| <= 4u T (u = DBL_EPSILON / 2), so that the last row is at T up to those roundings;
 * else refused. The rows print t = k H, the time the steps reach, so the last may differ from T
 * in its last digits (0.1 and 0.3: 3 H = 0.30000000000000004): a step shortened to end at T
 * would change the method's last step, and a t printed as T would not be the time reached. */
static long steps_for_time(double T, double eps)
{
    const double n = round(T / eps); /* T / eps may be inf: caught below */
    char lo[64], hi[64];
    if (!(n >= 1.0)) {
        time_choice(hi, sizeof hi, 1.0, eps);
        suslov_cli_die(
            "--time %.17g with --eps %.17g gives %.17g steps; need at least 1: the shortest is %s",
            T, eps, n + 0.0, hi); /* + 0.0: the count of --time -0 is 0, not -0 */
    }
    if (!(n < 0x1p63)) /* (long)n is defined only below 2^63 = LONG_MAX + 1 */
        suslov_cli_die("--time %.17g with --eps %.17g gives %.17g steps, more than %ld", T, eps, n,
                       LONG_MAX);
    if (fabs(n * eps - T) > 2.0 * DBL_EPSILON * T) {
        const double f = floor(T / eps);
        time_choice(lo, sizeof lo, f, eps);
        time_choice(hi, sizeof hi, f + 1.0, eps);
        suslov_cli_die(
            "--time %.17g is not a whole number of steps of --eps %.17g; nearest: %s%s%s", T, eps,
            f >= 1.0 ? lo : "", f >= 1.0 ? " or " : "", hi);
    }
    return (long)n;
}

/* An unknown method first: the other checks depend on the kind of run it names. */
static void check_method_name(const suslov_args_given *g)
{
    char names[1024];
    if (g->method && strcmp(g->method, "exact") != 0 && !sus_step_method_by_name(g->method))
        suslov_cli_die("unknown method %s (exact, %s; or list)", suslov_cli_quote(g->method),
                       sus_step_method_names(names, sizeof names, ", "));
}

/* Returns 1 when --reconstruct is given to a method that ignores it (a warning, given once every
 * check has passed, so that bad input still gets exactly one line). */
static int resolve_method(suslov_args *a, const suslov_args_given *g)
{
    char names[1024];
    const int exact = g->method && strcmp(g->method, "exact") == 0;
    a->method = exact || !g->method ? NULL : sus_step_method_by_name(g->method);
    a->recon = a->method ? a->method->recon : SUS_RECON_CAYLEY;
    if (!g->recon)
        return 0;
    if (sus_recon_by_name(g->recon, &a->recon) != 0) {
        size_t len = 0;
        for (int r = 0; r < SUS_RECON_COUNT; r++)
            len += (size_t)snprintf(names + len, sizeof names - len, "%s%s", r ? ", " : "",
                                    SUS_RECON_NAMES[r]);
        suslov_cli_die("unknown reconstruction %s (%s)", suslov_cli_quote(g->recon), names);
    }
    if (!g->method) /* --help without --method: the name alone can be checked */
        return 0;
    if (exact)
        suslov_cli_die(
            "--reconstruct does not apply to --method exact (its R is the reference attitude)");
    return !a->method->type->desc.follows_recon;
}

/* --sweeps replaces the midpoint rule's Newton solve, so it needs that method. */
static void check_sweeps(suslov_args *a, const suslov_args_given *g)
{
    a->stepper = a->method ? a->method->type : NULL;
    if (!g->sweeps)
        return;
    if (g->method && (!a->method || a->method->type != sus_step_midpoint))
        suslov_cli_die(
            "--sweeps applies only to --method midpoint (it solves the midpoint rule's equation)");
    if (g->sweeps > SUS_LAB_MAX_SWEEPS)
        suslov_cli_die("--sweeps must be at most %d, got %ld", SUS_LAB_MAX_SWEEPS, g->sweeps);
    a->sweeps = (int)g->sweeps;
    a->stepper = sus_lab_midpoint_sweeps_type(a->sweeps);
}

/* A tolerance-driven method: --tol and --time, no fixed step. The smallest TOL is one rounding
 * unit of 1: a step's estimate cannot be resolved below the rounding of the state it corrects.
 * Under --help (g->show) an option that is missing is not asked for; one given is checked. */
static void check_tol_run(suslov_args *a, const suslov_args_given *g)
{
    if (isnan(g->tol) && !g->show)
        suslov_cli_die("--method %s chooses its steps from --tol, which is required", g->method);
    if (!isnan(g->tol) && !(g->tol >= DBL_EPSILON && g->tol < 1.0))
        suslov_cli_die("--tol must be in [2^-52, 1), got %.17g", g->tol);
    if (!isnan(g->eps) || g->steps > 0)
        suslov_cli_die("a tolerance-driven run chooses its steps from --tol: give --time, not "
                       "--eps or --steps");
    if (g->every_given)
        suslov_cli_die(
            "--every counts fixed steps; with --tol rows come at each step or by --every-time");
    if (isnan(g->T) ? !g->show : !(g->T > 0.0))
        suslov_cli_die("--tol needs a final time --time T > 0");
    if (!isnan(g->every_time) && !(g->every_time > 0.0))
        suslov_cli_die("--every-time must be positive, got %.17g", g->every_time);
    /* The rows' count: below 2^62, as the library counts them (driver.h, sus_run_tol), so that a
     * count it refuses is refused here, as bad input, not met later as a failed run. */
    if (!isnan(g->every_time) && !isnan(g->T) && !(g->T / g->every_time < 0x1p62))
        suslov_cli_die("--time %.17g with --every-time %.17g asks for %.3g rows, 2^62 or more",
                       g->T, g->every_time, g->T / g->every_time);
    a->tol = g->tol;
    a->t_end = isnan(g->T) ? 0.0 : g->T; /* 0: --help without --time, no run to size */
    a->every_time = isnan(g->every_time) ? 0.0 : g->every_time;
}

static void check_fixed_steps(suslov_args *a, const suslov_args_given *g)
{
    if (!isnan(g->tol) || !isnan(g->every_time))
        suslov_cli_die("%s applies to a tolerance-driven method (--method list: order tol)",
                       isnan(g->tol) ? "--every-time" : "--tol");
    if (isnan(g->eps) && !g->show)
        suslov_cli_die("--eps is required");
    if (!isnan(g->eps) && !(g->eps > 0.0))
        suslov_cli_die("--eps must be positive, got %.17g", g->eps);
    const int lengths = (g->steps > 0) + !isnan(g->T);
    if (lengths == 2 || (lengths == 0 && !g->show))
        suslov_cli_die("give exactly one of --steps and --time");
    if (isnan(g->eps) || lengths == 0) /* --help without them: no run to size, t_end 0 */
        return;
    a->eps = g->eps;
    a->steps = isnan(g->T) ? g->steps : steps_for_time(g->T, g->eps);
    /* Every t_k = k eps <= N eps must be a finite number. */
    if (!isfinite((double)a->steps * a->eps))
        suslov_cli_die("--steps %ld with --eps %.17g: the final time N H overflows", a->steps,
                       a->eps);
    a->t_end = (double)a->steps * a->eps;
}

/* E and lambda at w0 must be finite numbers (row 0 prints them), and lambda along the motion (every
 * row prints it; sus_args_lambda_overflows). They depend on w0 and the body alike, so the message
 * names the options that were given: the default of the other is not the user's doing. */
static void check_start(const suslov_args *a, const suslov_args_given *g)
{
    const char *what = sus_model_start_overflow(&a->model, g->w0), *where = "at";
    if (!what && sus_args_lambda_overflows(&a->model, g->w0)) {
        what = "multiplier lambda";
        where = "along the motion from";
    }
    if (!what)
        return;
    const char *opts =
        g->inertia_given ? (g->omega0_given ? "--omega0 and --inertia" : "--inertia") : "--omega0";
    suslov_cli_die("%s: the %s %s w0 = (%.17g, %.17g) overflows with %s inertia", opts, what, where,
                   g->w0[0], g->w0[1], g->inertia_given ? "this" : "the paper's (default)");
}

/* A start the tolerance-driven methods cannot serve (api_args.h): refused as the library refuses
 * it, with what to do instead. */
static void check_tol_start(const suslov_args *a, const suslov_args_given *g)
{
    if (!a->method || !a->method->type->tol || !sus_args_tol_underflows(&a->model, g->w0))
        return;
    suslov_cli_die(
        "--omega0: w0 = (%.17g, %.17g), with energy %.3g, is too small for the --tol "
        "methods, which need |w0| >= 2^-500 (%.3g) and an energy of at least %.3g (a "
        "normal double): their series multiply w by w, and lose their bits below; scale "
        "w0 up by a factor and --time down by it (the motion is the same in scaled time)",
        g->w0[0], g->w0[1], sus_energy(&a->model, g->w0), 0x1p-500, DBL_MIN);
}

/* A start within a rounding of the repelling steady rotation (api_args.h): a run is still made,
 * since it is right up to the time the motion leaves, but a method that steps w stays there. */
static void check_unresolved_start(const suslov_args *a, const suslov_args_given *g)
{
    if (!a->method || a->method->type->desc.w_closed_form ||
        !sus_args_start_unresolved(&a->model, g->w0))
        return;
    suslov_cli_warn("--omega0: c(w0) = I31 w1 + I32 w2 = %.3g is below the rounding of its terms, "
                    "so to %s w0 is the repelling steady rotation: it stays there, or leaves when "
                    "its roundings say, not when c(w0) says; exact and exact-attitude follow the "
                    "closed form",
                    sus_c_accurate(&a->model, g->w0), a->method->type->name);
}

/* The angle the steady rotation turns the body by at the final time, against the largest the
 * run's attitude forms to its stated accuracy (exact_run.h, the method's max_angle): the library
 * refuses the run, so it is refused here first, as bad input that says how far is possible. */
static void check_angle(const suslov_args *a, const suslov_args_given *g, int exact)
{
    const sus_tol_ops *tol = a->method ? a->method->type->tol : NULL;
    if (!exact && !tol)
        return; /* a fixed-step method's error at any angle is what it computes */
    const double limit = exact ? SUS_EXACT_MAX_ANGLE : tol->max_angle;
    const double angle = sus_exact_turn_angle(&a->model, g->w0, a->t_end);
    if (angle <= limit)
        return;
    /* the longest final time, rounded down to four digits so that the one suggested is taken */
    const double longest = a->t_end * (limit / angle), unit = pow(10.0, floor(log10(longest)) - 3);
    double suggest = floor(longest / unit) * unit;
    if (sus_exact_turn_angle(&a->model, g->w0, suggest) > limit)
        suggest -= unit;
    suslov_cli_die("%s: by t = %.17g the steady rotation turns the body by %.7g radians, more "
                   "than the %.7g (2^%d) to which its attitude keeps its accuracy: ask for a final "
                   "time of at most %.4g",
                   exact ? "--method exact" : a->method->type->name, a->t_end, angle, limit,
                   ilogb(limit), suggest);
}

void suslov_args_check(suslov_args *a, const suslov_args_given *g)
{
    char err[1024];
    check_method_name(g);
    const sus_step_method *me = g->method ? sus_step_method_by_name(g->method) : NULL;
    /* --help without --method: the options given say which kind of run they describe */
    if (me ? me->type->tol != NULL : !g->method && (!isnan(g->tol) || !isnan(g->every_time)))
        check_tol_run(a, g);
    else
        check_fixed_steps(a, g);
    if (suslov_inertia_model(&a->model, g->inertia, err, sizeof err) != 0)
        suslov_cli_die("%s", err);
    check_start(a, g);
    const int ignored = resolve_method(a, g);
    check_sweeps(a, g);
    const int exact = g->method && !a->method;
    check_tol_start(a, g);
    check_angle(a, g, exact);
    const sus_run_config cfg = {&a->model, NULL, a->recon, a->eps, a->steps, g->every};
    const double cost = exact && a->t_end > 0.0 ? sus_exact_reference_steps(&cfg, g->w0) : 0.0;
    if (!(cost * EXACT_STEP_SECONDS <= EXACT_MAX_SECONDS))
        suslov_cli_die("--method exact: the reference attitude needs %.3g Taylor steps (to the "
                       "steady tail or the final time, and one for each row before the tail), "
                       "roughly %.2g hours (at most %.3g, ten minutes): ask for a shorter final "
                       "time, or fewer rows (--every)",
                       cost, cost * EXACT_STEP_SECONDS / 3600.0,
                       EXACT_MAX_SECONDS / EXACT_STEP_SECONDS);
    if (sus_sys_atomic_file_check(g->output, err, sizeof err) != 0)
        suslov_cli_die("--output: %s", err);
    if (g->show) /* --help, --man, --version: no run, so no warning or note about it */
        return;
    if (ignored)
        suslov_cli_warn("--reconstruct %s is ignored: %s carries its own attitude", g->recon,
                        a->method->type->name);
    check_unresolved_start(a, g);
    const char *np = getenv("NO_PROGRESS");
    if (cost * EXACT_STEP_SECONDS > EXACT_NOTE_SECONDS && !g->quiet && !(np && *np))
        suslov_cli_note("--method exact: the reference attitude needs %.3g Taylor steps, roughly "
                        "%.0f s",
                        cost, cost * EXACT_STEP_SECONDS);
}
