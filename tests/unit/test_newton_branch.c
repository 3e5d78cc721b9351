/* The implicit steps solve for the root on the branch continued in eps from eps = 0 (newton.h):
 *   - where Newton from the explicit prediction fails (the variational step at h = eps k ~ 160, the
 *     midpoint step at h ~ 4, both on the paper's energy ellipse), the step still returns a root,
 *     to round-off, and it is the branch's: it equals the end of an independent continuation (4000
 *     equal stages, each Newton from the last root, det J > 0 all along) to 1e-12 relative; a step
 *     of negative eps (a composition's backward substep) likewise;
 *     and where it lands on another root, which it can where the energy ellipse is long (a
 *     near-singular I_m: the variational step, one start), the step still gives the branch's;
 *   - where the prediction is good (h = 0.145, the paper's eps = 1, and h = 0.5; 200 steps on
 *     every body of the family), the step is Newton from the prediction, bit for bit (the fast
 *     path: the results of the fixed-step experiments at such steps are unchanged);
 *   - a fold: from a state of the stability map where the 2-stage Gauss step's branch turns back,
 *     the continuation reaches 0.99 of the fold's step, not 1.01 of it (SUS_STEPPER_SINGULAR), and
 *     det J vanishes there like (e* - e)^(1/2) (exponent within 0.05: stability.h);
 *   - the stability map classes a run whose step cannot be solved (the variational step from
 *     |w| = 1e150 overflows at its first prediction and along its continuation) as a solver
 *     failure at step 1;
 *   - the stability map skips the rest of a run that has entered a cycle (stability.c): its final
 *     error equals that of the whole run, step by step, bit for bit (midpoint at h = 1000, a
 *     composition and the variational step at h = 100, six starts each); on a made-up step that
 *     walks a cycle of P states, a cycle of up to 16 states is skipped once it has come round
 *     (P steps taken) and a longer one is stepped through, and w_N is the same either way;
 *   - stats.continued: a step says when its root is the continuation's, and then that root is
 *     sus_step_newton_branch's from the same w and eps, bit for bit (the map skips its branch check
 *     on that identity); at h = 0.01 no step continues, at h = 1000 some do (the three implicit
 *     methods, twelve starts each, first steps). */
#include "check_body.h"
#include "exact.h"
#include "implicit_step.h"
#include "newton.h"
#include "registry.h"
#include "stability.h"

#include <math.h>
#include <string.h>

/* The independent continuation: 4000 equal stages from the root at eps = 0; 0 with the root in x,
 * -1 when a stage fails or det J <= 0 on the way. */
static int uniform_continuation(const sus_stepper_type *st, const sus_model *m, double eps,
                                const double w[2], double *x)
{
    enum { STAGES = 4000 };
    st->equation->guess(m, 0.0, w, x);
    for (int j = 1; j <= STAGES; j++) {
        sus_stepper_stats s;
        if (sus_step_newton_solve(st->equation->residual, st->equation->unknowns, m,
                                  eps * j / STAGES, w, x, &s) != SUS_STEPPER_OK ||
            !(s.det > 0.0))
            return -1;
    }
    return 0;
}

/* The state after `steps` steps of the map's run from angle a of na at step h (stability.h). */
static void map_state(const sus_exact *paper, const sus_stepper_type *st, int a, int na, double h,
                      int steps, double w[3])
{
    sus_lab_ellipse_point(paper, 2.0 * 3.14159265358979323846 * a / na + SUS_LAB_STAB_ANGLE0, w);
    w[2] = 0.0;
    for (int k = 0; k < steps; k++) {
        double x[3], lam;
        sus_stepper_stats s;
        st->step->apply(paper->model, h / paper->k, w, x, &lam, &s);
        w[0] = x[0], w[1] = x[1];
    }
}

/* One step: the step returns the branch's root; where `hard`, plain Newton from the prediction
 * fails or ends off the branch there (else the case would not test the continuation). */
static void branch_step(const sus_exact *paper, const char *name, double h, const double w[3],
                        int hard)
{
    const sus_stepper_type *st = sus_step_method_by_name(name)->type;
    const sus_model *m = paper->model;
    const double eps = h / paper->k;
    double x[SUS_MAX_UNKNOWNS], xu[SUS_MAX_UNKNOWNS], wn[3], g[SUS_MAX_UNKNOWNS], J[16], scale;
    sus_stepper_stats s;
    st->equation->guess(m, eps, w, x);
    const int plain =
        sus_step_newton_solve(st->equation->residual, st->equation->unknowns, m, eps, w, x, &s);
    const int cont = uniform_continuation(st, m, eps, w, xu) == 0;
    const int off_branch =
        plain != SUS_STEPPER_OK || !(s.det > 0.0) || hypot(x[0] - xu[0], x[1] - xu[1]) > 1e-6;
    const int rc = sus_step_implicit_solve(st->equation, m, eps, w, wn, &s);
    st->equation->residual(m, eps, w, wn, g, J, &scale);
    const double res = fmax(fabs(g[0]), fabs(g[1])), d = hypot(wn[0] - xu[0], wn[1] - xu[1]);
    CHECK(cont && (off_branch || !hard) && rc == SUS_STEPPER_OK &&
              res <= SUS_STEP_NEWTON_STAGNATION * scale && d <= 1e-12 * hypot(xu[0], xu[1]) &&
              s.det > 0.0,
          "%s at h = %g from (%.4g, %.4g): Newton from the prediction %s; the step: status "
          "%d, |G| = %.2g (scale %.2g), %.2g from the continued branch's root, det J %.3g",
          name, h, w[0], w[1],
          plain != SUS_STEPPER_OK ? "fails"
          : off_branch            ? "lands off the branch"
                                  : "holds",
          rc, res, scale, d, s.det);
}

/* A near-singular I_m (condition near 1e5, the stiff bodies' "cond" kind): its energy ellipse is
 * so long that the variational step's other root lies nearer the explicit prediction than the
 * ellipse's size; at this eps Newton from the prediction reaches that root within the stage's
 * iterations and det J > 0. The step must still give the continued branch's root. */
static void elongated_ellipse(void)
{
    static const double I[9] = {0.88026711676438429, 0.50204113652209859, 0.31474715079768634,
                                0.50204113652209859, 0.2863411520411564,  0.43734859527303876,
                                0.52863521428070659, 0.38428363400701054, 2.4838304300206255};
    const double w[3] = {0.57904027635134869, 0.51602877784210577, 0.0};
    sus_model m;
    sus_exact ex;
    if (sus_model_init(&m, I, NULL, 0) != 0 || sus_exact_init(&ex, &m, w) != 0) {
        CHECK(0, "the elongated body is accepted");
        return;
    }
    branch_step(&ex, "variational", 0.00049476 * ex.k, w, 1);
}

/* Small steps, h = eps k = 0.145 (the paper's eps = 1) and 0.5 on each body: the step is plain
 * Newton from the prediction, bit for bit; and the method's own step, whose Newton has the
 * residual inlined (newton_core.h), is the generic sus_step_implicit_solve, bit for bit. */
static void fast_path(void)
{
    int differ = 0, n = 0;
    const char *names[2] = {"midpoint", "variational"};
    for (int k = 0; k < BODIES_COUNT; k++) {
        body b;
        sus_model m;
        sus_exact ex;
        if (check_body_exact(k, &b, &m, &ex))
            continue;
        for (int i = 0; i < 4; i++) {
            const sus_stepper_type *st = sus_step_method_by_name(names[i % 2])->type;
            const double eps = (i < 2 ? 0.145 : 0.5) / ex.k;
            double w[3] = {b.w0[0], b.w0[1], 0.0};
            for (int j = 0; j < 200; j++, n++) {
                double x[2], wp[2], wn[3], wa[3], lam;
                sus_stepper_stats s;
                st->equation->guess(&m, eps, w, x);
                sus_step_newton_solve(st->equation->residual, 2, &m, eps, w, x, &s);
                st->equation->result(&m, eps, w, x, wp);
                sus_step_implicit_solve(st->equation, &m, eps, w, wn, &s);
                st->step->apply(&m, eps, w, wa, &lam, &s);
                differ += wn[0] != wp[0] || wn[1] != wp[1] || wa[0] != wn[0] || wa[1] != wn[1];
                w[0] = wn[0], w[1] = wn[1];
            }
        }
    }
    CHECK(differ == 0,
          "%d steps of h = eps k = 0.145 and 0.5 (midpoint, variational, %d bodies): the step is "
          "Newton from the prediction bit for bit, and so is the method's step; %d differ",
          n, BODIES_COUNT, differ);
}

static void fold(const sus_exact *paper)
{
    const sus_stepper_type *st = sus_step_method_by_name("gauss4")->type;
    const sus_model *m = paper->model;
    const double h = pow(10.0, -2.0 + 0.2 * 17); /* 25.1: the map's first fold of gauss4 */
    double w[3], e_star = NAN, exponent = NAN, x[SUS_MAX_UNKNOWNS], reg;
    sus_stepper_stats s;
    map_state(paper, st, 29, 36, h, 2, w);
    const int found = sus_lab_fold(m, st, w, h / paper->k, &e_star, &exponent) == 0;
    const int below = sus_step_newton_branch(st->equation->residual, st->equation->guess, 4, m,
                                             0.99 * e_star, w, x, &s, &reg);
    const int above = sus_step_newton_branch(st->equation->residual, st->equation->guess, 4, m,
                                             1.01 * e_star, w, x, &s, &reg);
    CHECK(found && below == SUS_STEPPER_OK && above == SUS_STEPPER_SINGULAR &&
              fabs(exponent - 0.5) <= 0.05,
          "gauss4 from (%.4g, %.4g): its branch folds at e* k = %.4g (reached at 0.99 "
          "e*: %d; at 1.01 e*: status %d, SINGULAR %d); det J ~ (e* - e)^%.4f (1/2)",
          w[0], w[1], e_star * paper->k, below, above, SUS_STEPPER_SINGULAR, exponent);
}

/* A step that cannot be solved: the map's SOLVER class, at step 1. */
static void unsolvable(const sus_exact *paper)
{
    const double w0[2] = {1e150, 1e100};
    sus_exact ex;
    sus_lab_stab_result r;
    sus_exact_init(&ex, paper->model, w0);
    sus_lab_stability_run(&ex, sus_step_method_by_name("variational")->type, 1e-150, 5, 0, &r);
    CHECK(r.cls == SUS_LAB_STAB_SOLVER && r.step == 1,
          "variational from |w| = 1e150: the map's class %s at step "
          "%ld (solver failure at 1)",
          SUS_LAB_STAB_NAMES[r.cls], r.step);
}

/* The whole run by hand against sus_lab_stability_run's, which skips cycles. */
static void cycle_shortcut(const sus_exact *paper)
{
    const char *names[3] = {"midpoint", "comp4-s5", "variational"};
    const double hs[3] = {1000.0, 100.0, 100.0};
    int differ = 0, n = 0;
    for (int i = 0; i < 3; i++) {
        const sus_stepper_type *st = sus_step_method_by_name(names[i])->type;
        const double eps = hs[i] / paper->k;
        const long N = sus_lab_stability_steps(hs[i]);
        for (int a = 0; a < 36; a += 6, n++) {
            double w[3], winf[2];
            sus_exact ex;
            sus_lab_stab_result r;
            sus_lab_ellipse_point(paper,
                                  2.0 * 3.14159265358979323846 * a / 36 + SUS_LAB_STAB_ANGLE0, w);
            w[2] = 0.0;
            sus_exact_init(&ex, paper->model, w);
            sus_exact_limit(&ex, winf);
            sus_lab_stability_run(&ex, st, eps, N, 0, &r);
            for (long k = 0; k < N; k++) {
                double x[3], lam;
                sus_stepper_stats s;
                st->step->apply(paper->model, eps, w, x, &lam, &s);
                w[0] = x[0], w[1] = x[1];
            }
            differ +=
                r.final_err != hypot(w[0] - winf[0], w[1] - winf[1]) / hypot(winf[0], winf[1]);
        }
    }
    CHECK(differ == 0,
          "%d runs of the stability map with their cycles skipped "
          "end as the whole runs do, bit for bit: %d differ",
          n, differ);
}

/* A made-up step that walks P states round a circle about the paper's w0: w = state i goes to
 * state i + 1 mod P (a state it does not know goes to NaN, which the map calls a blow-up). */
enum { WALK_MAX = 32 };
static double walk[WALK_MAX][2];
static int walk_n;
static long walk_calls;

static int walk_apply(const sus_model *m, double eps, const double w[3], double x[3],
                      double *lambda, sus_stepper_stats *st)
{
    (void)m, (void)eps;
    *st = (sus_stepper_stats){0};
    *lambda = 0.0;
    walk_calls++;
    x[0] = x[1] = NAN, x[2] = 0.0;
    for (int i = 0; i < walk_n; i++)
        if (w[0] == walk[i][0] && w[1] == walk[i][1]) {
            x[0] = walk[(i + 1) % walk_n][0], x[1] = walk[(i + 1) % walk_n][1];
            break;
        }
    return SUS_STEPPER_OK;
}

/* The map's cycle skip against the cycle's known period: calls and w_N. */
static void cycle_lengths(const sus_exact *paper)
{
    static const sus_step_ops ops = {.apply = walk_apply};
    const sus_stepper_type walker = {.name = "walk", .step = &ops, .desc = {.substeps = 1}};
    const long N = 1000;
    static const int periods[] = {1, 9, 16, 17};
    for (int k = 0; k < 4; k++) {
        const int P = periods[k];
        walk_n = P;
        for (int i = 0; i < P; i++) {
            const double a = 2.0 * 3.14159265358979323846 * i / P;
            walk[i][0] = paper->w0[0] + 0.01 * cos(a), walk[i][1] = paper->w0[1] + 0.01 * sin(a);
        }
        sus_exact ex;
        sus_lab_stab_result r;
        double winf[2];
        sus_exact_init(&ex, paper->model, walk[0]);
        sus_exact_limit(&ex, winf);
        walk_calls = 0;
        sus_lab_stability_run(&ex, &walker, 1.0, N, 0, &r);
        const double *wN = walk[N % P]; /* w_N of the whole run */
        const int same =
            r.final_err == hypot(wN[0] - winf[0], wN[1] - winf[1]) / hypot(winf[0], winf[1]);
        const long want = P <= 16 ? P : N; /* w_P = w_0 is seen at step P */
        CHECK(same && walk_calls == want,
              "a cycle of period %d: %ld steps taken (%ld), w_N that of the whole run (%s)", P,
              walk_calls, want, same ? "yes" : "no");
    }
}

/* Over the implicit methods and twelve starts on the ellipse: the steps that report a continued
 * root and those that do not, at h = 0.01 and 1000, and how many continued roots differ from the
 * continuation's own. */
static void continued_flag(const sus_exact *paper)
{
    static const char *const NAMES[3] = {"midpoint", "variational", "gauss4"};
    int cont[2] = {0, 0}, steps = 0, differ = 0;
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 2; i++)
            for (int a = 0; a < 36; a += 3) {
                const sus_stepper_type *st = sus_step_method_by_name(NAMES[k])->type;
                const double eps = (i ? 1000.0 : 0.01) / paper->k;
                double w[3], x[3], xc[3], lam, root[SUS_MAX_UNKNOWNS];
                sus_stepper_stats s, sb;
                map_state(paper, st, a, 36, 0.0, 0, w);
                const int rc = st->step->apply(paper->model, eps, w, x, &lam, &s);
                steps++;
                if (rc != SUS_STEPPER_OK || !s.continued)
                    continue;
                cont[i]++;
                const sus_step_equation *eq = st->equation;
                differ +=
                    sus_step_newton_branch(eq->residual, eq->guess, eq->unknowns, paper->model, eps,
                                           w, root, &sb, NULL) != SUS_STEPPER_OK;
                eq->result(paper->model, eps, w, root, xc);
                differ += memcmp(xc, x, 2 * sizeof x[0]) != 0;
            }
    CHECK(
        cont[0] == 0 && cont[1] > 0 && differ == 0,
        "%d first steps (midpoint, variational, gauss4; h = 0.01 and 1000): %d at h = 0.01 and %d "
        "at h = 1000 report a continued root (0 and some); %d of these differ from "
        "sus_step_newton_branch's bit for bit",
        steps, cont[0], cont[1], differ);
}

int main(void)
{
    sus_model m;
    sus_exact paper;
    char err[256];
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0) {
        CHECK(0, "the paper's body: %s", err);
        return check_summary("test_newton_branch");
    }
    sus_exact_init(&paper, &m, SUS_PAPER_OMEGA0);
    double w[3];
    const double h_var = pow(10.0, -2.0 + 0.2 * 21),
                 h_mid = pow(10.0, -2.0 + 0.2 * 13); /* 158, 3.98 */
    map_state(&paper, sus_step_method_by_name("variational")->type, 1, 36, h_var, 3, w);
    branch_step(&paper, "variational", h_var, w, 1);
    map_state(&paper, sus_step_method_by_name("midpoint")->type, 0, 36, h_mid, 0, w);
    branch_step(&paper, "midpoint", h_mid, w, 1);
    branch_step(&paper, "midpoint", -h_mid, w, 0);
    map_state(&paper, sus_step_method_by_name("midpoint")->type, 2, 36, h_mid, 0, w);
    branch_step(&paper, "midpoint", -h_mid, w, 1);
    elongated_ellipse();
    fast_path();
    fold(&paper);
    unsolvable(&paper);
    cycle_shortcut(&paper);
    cycle_lengths(&paper);
    continued_flag(&paper);
    return check_summary("test_newton_branch");
}
