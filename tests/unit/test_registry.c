/* The registry and what each stepper type says of itself (src/core/stepper.h): the fields consumers
 * decide from are checked against the steps themselves, on a general body (not the paper's), so
 * that a wrong flag fails here rather than silently steering a figure, the bench or the ledger. */
#include "check.h"
#include "composition.h"
#include "exact.h"
#include "registry.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* A general body: no symmetry, every coupling of (RGB2) present. */
static const double BODY[9] = {1.3, 0.17, 0.31, 0.17, 0.8, -0.23, 0.29, -0.12, 1.1};

static const double W0[3] = {0.45, -0.3, 0.0};

/* max |E - E0| over n steps of eps from W0, or NAN when a step fails. */
static double energy_drift(const sus_model *m, const sus_stepper_type *st, double eps, int n)
{
    double w[3] = {W0[0], W0[1], 0.0}, x[3], lam, drift = 0.0;
    const double e0 = sus_energy(m, w);
    for (int k = 0; k < n; k++) {
        sus_stepper_stats ss;
        if (st->step->apply(m, eps, w, x, &lam, &ss) != SUS_STEPPER_OK)
            return NAN;
        drift = fmax(drift, fabs(sus_energy(m, x) - e0));
        w[0] = x[0];
        w[1] = x[1];
    }
    return drift;
}

/* max |R_a - R_b| over the entries after one whole step with two different reconstructions. */
static double recon_effect(const sus_model *m, const sus_stepper_type *st, double eps)
{
    double x[3], lam, Ra[3][3], Rb[3][3];
    sus_attitude a, b;
    sus_stepper_stats ss;
    sus_attitude_identity(&a);
    sus_attitude_identity(&b);
    sus_stepper_full(st, m, eps, SUS_RECON_CAYLEY, &a, W0, x, &lam, &ss);
    sus_stepper_full(st, m, eps, SUS_RECON_EXP_MID, &b, W0, x, &lam, &ss);
    sus_attitude_get(&a, Ra);
    sus_attitude_get(&b, Rb);
    double d = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(Ra[i][j] - Rb[i][j]));
    return d;
}

/* max over a few starts on the exact motion of the local multiplier error |lambda_{k+1} -
 * lambda(w(t + eps))| of one step from w(t). */
static double lambda_error(const sus_model *m, const sus_stepper_type *st, double eps)
{
    sus_exact ex;
    sus_exact_init(&ex, m, W0);
    double e = 0.0;
    for (int k = 0; k < 4; k++) {
        double w[3] = {0.0, 0.0, 0.0}, we[2], x[3], lam;
        sus_stepper_stats ss;
        sus_exact_omega(&ex, 2.5 * k, w);
        sus_exact_omega(&ex, 2.5 * k + eps, we);
        if (st->step->apply(m, eps, w, x, &lam, &ss) != SUS_STEPPER_OK)
            return NAN;
        e = fmax(e, fabs(lam - sus_lagmult(m, we)));
    }
    return e;
}

/* Consistency of the multiplier as the type states it (Definition RedConsis): with s >= 1 the
 * local error is O(eps^{s+1}), so halving eps divides it by 4 or more (3 leaves room for the next
 * term); with s = -1 (inconsistent) it tends to a nonzero O_0, and halving divides it by less than
 * 2. Read at the first eps of 1/2, 1/4, 1/8, 1, 2 (asymptotic ones first) where both errors stand
 * above round-off (1000 u times |lambda| <= 0.04); a method at round-off at all of them is said
 * so and not judged. */
static void check_lambda(const sus_model *m, const sus_stepper_type *st)
{
    static const double EPS[] = {0.5, 0.25, 0.125, 1.0, 2.0};
    const double floor = 1000.0 * SUS_U * 0.04;
    for (int i = 0; i < 5; i++) {
        const double e1 = lambda_error(m, st, EPS[i]), e2 = lambda_error(m, st, 0.5 * EPS[i]);
        if (!(e2 > floor))
            continue;
        CHECK(st->desc.lambda_order >= 1 ? e1 / e2 >= 3.0 : e1 / e2 < 2.0,
              "%s: lambda_order = %d; local multiplier error "
              "%.2e at eps = %g, %.2e at %g (ratio %.2f)",
              st->name, st->desc.lambda_order, e1, EPS[i], e2, 0.5 * EPS[i], e1 / e2);
        return;
    }
    printf("NOTE %s: local multiplier error at round-off for every eps <= 2: not judged\n",
           st->name);
}

static void check_type(const sus_model *m, const sus_stepper_type *st)
{
    check_lambda(m, st);
    const sus_step_equation *eq = st->equation;
    const sus_stepper_desc *ds = &st->desc;
    const int n = eq ? eq->unknowns : 0, hooks = eq && eq->residual && eq->guess && eq->result;
    CHECK(!eq || (n >= 1 && n <= SUS_MAX_UNKNOWNS && hooks && ds->implicit),
          "%s: equation %s, %d unknowns, implicit %d, hooks %s", st->name, eq ? "set" : "NULL", n,
          ds->implicit, hooks ? "set" : "unset");
    CHECK(ds->source && access(ds->source, R_OK) == 0 && strncmp(ds->source, "src/", 4) == 0,
          "%s: its source file %s exists", st->name, ds->source ? ds->source : "(null)");
    CHECK(st->step && st->step->apply && !st->tol && ds->substeps >= 1 &&
              (ds->attitude == SUS_ATTITUDE_NONE) == (st->step->apply_full == NULL),
          "%s: step interface with apply, no tolerance interface, %d substeps; attitude form %d "
          "with%s apply_full",
          st->name, ds->substeps, (int)ds->attitude, st->step && st->step->apply_full ? "" : "out");
    /* 200 steps of eps = 0.5: a method that conserves E drifts by round-off, at most a few u E per
     * substep (4 u E0 each, a worst case that never cancels); one that does not drifts by its
     * truncation error, many orders above that at this step. */
    const double e0 = sus_energy(m, W0);
    const double drift = energy_drift(m, st, 0.5, 200),
                 yard = 200.0 * st->desc.substeps * 4.0 * SUS_U * e0;
    CHECK(st->desc.conserves_energy ? drift <= yard : drift > 100.0 * yard,
          "%s: conserves_energy = %d; |E - E0| over 200 steps "
          "of eps = 0.5: %.2e (round-off yardstick %.1e)",
          st->name, st->desc.conserves_energy, drift, yard);
    /* cayley against exp-mid differ at O(eps^2) per step; a method that ignores the request gives
     * the same R bit for bit. */
    const double d = recon_effect(m, st, 0.5);
    CHECK(st->desc.follows_recon ? d > 1e-6 : d == 0.0,
          "%s: follows_recon = %d; R after cayley vs exp-mid: %.2e", st->name,
          st->desc.follows_recon, d);
}

/* A method's label says what its type says of itself: the reconstruction only when it follows
 * one, else the attitude form it carries (a matrix-attitude method is no quaternion one). */
static void check_labels(void)
{
    static const struct {
        int follows_recon;
        sus_attitude_form attitude;
        const char *expected;
    } cases[] = {{1, SUS_ATTITUDE_NONE, "m + exp-mid"},
                 {1, SUS_ATTITUDE_QUAT, "m + exp-mid"},
                 {0, SUS_ATTITUDE_QUAT, "m (quaternion)"},
                 {0, SUS_ATTITUDE_MATRIX, "m (matrix)"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const sus_stepper_type t = {
            .name = "m",
            .desc = {.follows_recon = cases[i].follows_recon, .attitude = cases[i].attitude}};
        char label[64];
        sus_step_method_label(&t, SUS_RECON_EXP_MID, label, sizeof label);
        CHECK(strcmp(label, cases[i].expected) == 0,
              "label of a method with follows_recon = %d, attitude %s: \"%s\" (expected \"%s\")",
              cases[i].follows_recon, sus_step_attitude_name(cases[i].attitude), label,
              cases[i].expected);
    }
}

/* build/methods.tsv: a header and one row per method, each found again by index. */
static void check_tsv(void)
{
    FILE *fp = tmpfile();
    int rows = -1, ok = fp && sus_step_methods_write_tsv(fp) == 0;
    char line[1024];
    if (fp) {
        rewind(fp);
        while (fgets(line, sizeof line, fp)) {
            const sus_step_method *me = sus_step_method_get(rows);
            ok &= rows < 0 ? strncmp(line, "name\tfamily\torder\t", 18) == 0
                           : me && strncmp(line, me->type->name, strlen(me->type->name)) == 0;
            rows++;
        }
        fclose(fp);
    }
    CHECK(ok && rows == sus_step_method_count_all(),
          "methods.tsv: a header and %d rows for %d methods", rows, sus_step_method_count_all());
    /* a device that takes no byte: the error surfaces when the buffer is flushed, within the call
     */
    FILE *full = fopen("/dev/full", "w");
    if (full) {
        CHECK(sus_step_methods_write_tsv(full) == -1, "methods.tsv to /dev/full: -1");
        fclose(full);
    }
}

int main(void)
{
    char err[256];
    sus_model m;
    if (sus_model_init(&m, BODY, err, sizeof err) != 0) {
        fprintf(stderr, "test_registry: %s\n", err);
        return 1;
    }
    for (int i = 0; i < sus_step_method_count(); i++)
        check_type(&m, sus_step_method_get(i)->type);
    check_labels();

    /* Each composition's substeps are its table's stages. */
    const struct {
        const sus_stepper_type *type;
        const sus_step_composition *table;
    } comp[] = {{&sus_step_comp4_s5_type, &sus_step_comp_suzuki4},
                {&sus_step_comp6_kl_type, &sus_step_comp_kahan_li6},
                {&sus_step_comp8_kl_type, &sus_step_comp_kahan_li8},
                {&sus_step_comp10_ss_type, &sus_step_comp_sofroniou10}};
    for (size_t i = 0; i < sizeof comp / sizeof comp[0]; i++)
        CHECK(comp[i].type->desc.substeps == sus_step_composition_stages(comp[i].table),
              "%s: %d substeps = %d stages", comp[i].type->name, comp[i].type->desc.substeps,
              sus_step_composition_stages(comp[i].table));

    check_tsv();
    /* The fixed-step methods first, each with a step of given eps; the tolerance-driven ones after;
     * each has exactly one of the two interfaces. */
    for (int i = 0; i < sus_step_method_count_all(); i++) {
        const sus_stepper_type *t = sus_step_method_get(i)->type;
        CHECK((i < sus_step_method_count()) == (t->tol == NULL) &&
                  (t->step == NULL) == (t->tol != NULL),
              "%s: listed with the %s methods; step interface %s, tolerance interface %s", t->name,
              t->tol ? "tolerance-driven" : "fixed-step", t->step ? "set" : "NULL",
              t->tol ? "set" : "NULL");
    }
    for (int i = 0; i < sus_step_method_count_all(); i++)
        CHECK(sus_step_method_index_of(sus_step_method_get(i)->type) == i, "%s found by its type",
              sus_step_method_get(i)->type->name);
    return check_summary("test_registry");
}
