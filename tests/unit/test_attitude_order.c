/* The local orders of every registered fixed-step method, on SO(3) with every reconstruction and
 * of w, in a fraction of a second: the claims ledger fits the same orders over windows of steps
 * in about a minute, so a contributor's mutant that breaks a method dies here first.
 *
 * One step of the whole state (sus_stepper_full, as the driver takes it) from a general attitude
 * R_k and the exact w(t0), against the closed form w(t0 + eps) and R_k times the reference
 * increment R(t0)^{-1} R(t0 + eps) (sus_refatt_increment) in the (MetMat) distance; the largest
 * error over three starts t0 in the transient, so that an error constant passing near zero at
 * one start does not bend the curve. A tolerance-driven method has no fixed step to take an
 * order in: it is named with a SKIP line (test_taylor_adaptive and test_exact_attitude hold its
 * error to its tolerance).
 * Steps eps = 8 ... 2^-7 times the body's own time (check_body_time: eps k = 1.16 ... 0.0011 on
 * every body), on every body of tests/unit/bodies.h, stiff ones included.
 *
 * Reading an order. An order q gives errors C eps^{q+1}, so the slope log2(e(eps) / e(eps/2)) - 1
 * is q; it is read at the smallest pair of steps whose errors both stand above the round-off
 * floor (the most asymptotic pair round-off leaves clean). w(t) is analytic in the strip
 * |Im t| < pi / (2k) (refattitude.h), so where the larger step has eps k <= pi/8 (a quarter of
 * that distance) a geometric majorant of the series moves the halving's slope by at most
 * log2((1 - 1/8) / (1 - 1/4)) = 0.22: there the slope is asserted within SLOPE_TOL of q. Where
 * only larger steps stand above the floor (a high order, or a stiff body whose attitude turns
 * little in its own time), the slope is a lower estimate, asserted >= q / 2 as the ledger does:
 * that cannot tell q from q - 1 (the ledger's long-run lines can), but a mutant that breaks
 * consistency (order 0) or a symmetric method's symmetry (order 1) falls below q / 2 wherever
 * q >= 3. A body whose errors are at round-off at every step is not judged, and each line says on
 * how many bodies each reading was made; a line with no reading at all fails. The SO(3) order is
 * TeoL's min(r, p): the attitude's measured r, and p as theory states it. Every expected order is
 * the theory's (tests/ledger/ expected_orders.c), never the stepper's own description. */
#include "check_body.h"
#include "expected_orders.h"
#include "mat3.h"
#include "quaternion.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#define NEPS 16 /* eps = 8 ... 2^-7 in the paper's time */
#define NT 3
#define NQ (1 + SUS_RECON_COUNT) /* w, then R with each reconstruction */
/* Orders are whole numbers: half an order tells q from q - 1 (what a broken coefficient, sign or
 * reconstruction leaves) and holds the 0.22 of the asymptotic pair's bias above. */
#define SLOPE_TOL 0.5
/* A slope is asymptotic where the octave above agrees with it: the next term of the error moves
 * the slope of the pair at eps by b(eps) ~ eps, so the pair at 2 eps reads twice that bias, and
 * slopes that agree to SETTLED leave the lower one within about SETTLED of q. */
#define SETTLED 0.25
#define PI_8 0.39269908169872415 /* pi/8: the largest reach of an asymptotic pair (see the top) */
/* A step rounds R (entries of size 1) by a few u per substep, and w by a few u |w| per substep,
 * times cond(I_m) where a Newton solve's correction is I_m^{-1} times a residual at round-off
 * (an implicit step); the reference is within 2^-51 of the exact increment. 100 times that keeps
 * round-off under 1% of an error read, which moves a slope by under 0.03. */
#define FLOOR_FACTOR (100.0 * 4.0 * SUS_U)

static const double T0_PAPER[NT] = {3.0, 7.0, 12.0}; /* starts in the transient, paper's time */

typedef struct {
    body b;
    sus_model m;
    double s;            /* the body's own time (check_body_time) */
    double rate_s;       /* max(k, |w|) s: the fastest rate of the motion, of w or of R */
    double size_w, cond; /* the largest |w| at 0 and the starts; cond(I_m) */
    double w[NT][3];     /* w(t0) */
    double w_exact[NT][NEPS][2];
    double Phi[NT][NEPS][3][3]; /* R(t0)^{-1} R(t0 + eps_j) */
} body_ref;

static double eps_paper(int j) { return ldexp(8.0, -j); }

/* The condition number of I_m (symmetric positive definite). */
static double cond_m(const sus_model *m)
{
    const double tr = 0.5 * (m->I[0][0] + m->I[1][1]), dif = 0.5 * (m->I[0][0] - m->I[1][1]);
    const double lmax = tr + hypot(dif, m->I[0][1]);
    return lmax * lmax / m->det_m;
}

/* Body k, its model and its exact data; 0, or -1 after a FAIL line. */
static int body_ref_init(int k, body_ref *r)
{
    body_get(k, &r->b);
    if (check_body_model(&r->b, &r->m) != 0)
        return -1;
    sus_exact ex;
    sus_exact_init(&ex, &r->m, r->b.w0);
    r->s = check_body_time(&r->m, r->b.w0);
    r->cond = cond_m(&r->m);
    r->size_w = hypot(r->b.w0[0], r->b.w0[1]);
    for (int i = 0; i < NT; i++) {
        const double t0 = T0_PAPER[i] * r->s;
        sus_exact_omega(&ex, t0, r->w[i]);
        r->w[i][2] = 0.0;
        r->size_w = fmax(r->size_w, hypot(r->w[i][0], r->w[i][1]));
        for (int j = 0; j < NEPS; j++) {
            const double t1 = t0 + eps_paper(j) * r->s;
            sus_exact_omega(&ex, t1, r->w_exact[i][j]);
            sus_refatt_increment(&ex, t0, t1, r->Phi[i][j]);
        }
    }
    r->rate_s = fmax(ex.k, r->size_w) * r->s;
    return 0;
}

/* The start's attitude: a rotation about no axis of the frame, so that an increment multiplied
 * on the wrong side (R_k Phi for Phi R_k) or about a permuted axis shows, as from R_k = I it
 * would not. */
static const double Q0[4] = {0.9, 0.3, -0.2, 0.25};

/* The error of one step of st on body r with reconstruction rc from start i at step j: of R
 * against R_k R(t0)^{-1} R(t0 + eps), and of w in *dw; NAN when the step fails. */
static double step_error(const sus_stepper_type *st, const body_ref *r, int rc, int i, int j,
                         double *dw)
{
    double wn[3], lam, R[3][3], R0[3][3], want[3][3], q[4];
    sus_attitude att;
    sus_stepper_stats ss;
    sus_quat_unit(Q0, q);
    sus_quat_to_attitude(q, &att);
    sus_attitude_get(&att, R0);
    const double eps = eps_paper(j) * r->s;
    if (sus_stepper_full(st, &r->m, eps, (sus_recon)rc, &att, r->w[i], wn, &lam, &ss) !=
        SUS_STEPPER_OK)
        return *dw = NAN;
    sus_attitude_get(&att, R);
    sus_mat3_mul(want, R0, r->Phi[i][j]);
    *dw = hypot(wn[0] - r->w_exact[i][j][0], wn[1] - r->w_exact[i][j][1]);
    return sus_so3_dist(want, R);
}

/* The errors e[q][j] of one method on one body, the largest over the starts; NAN where a step
 * fails (fmax would drop it). w does not depend on the reconstruction: it is read with the
 * first. */
static void local_errors(const sus_stepper_type *st, const body_ref *r, double e[NQ][NEPS])
{
    for (int j = 0; j < NEPS; j++) {
        for (int q = 0; q < NQ; q++)
            e[q][j] = 0.0;
        for (int rc = 0; rc < SUS_RECON_COUNT; rc++)
            for (int i = 0; i < NT; i++) {
                double dw;
                const double dr = step_error(st, r, rc, i, j, &dw);
                e[1 + rc][j] = isnan(dr) || isnan(e[1 + rc][j]) ? NAN : fmax(e[1 + rc][j], dr);
                if (rc == 0)
                    e[0][j] = isnan(dw) || isnan(e[0][j]) ? NAN : fmax(e[0][j], dw);
            }
    }
}

/* A slope read off one curve: 2 asymptotic, 1 a lower estimate, 0 none (at round-off). */
typedef struct {
    int tier;
    double slope;
} reading;

/* reach: eps_paper times it is the step's reach eps r s (see the top). */
static reading read_order(const double e[NEPS], double floor, double reach)
{
    for (int j = NEPS - 1; j >= 1; j--)
        if (e[j] > floor && e[j - 1] > floor) { /* a NaN is not above the floor */
            const double slope = log2(e[j - 1] / e[j]) - 1.0;
            const double above = j >= 2 && e[j - 2] > floor ? log2(e[j - 2] / e[j - 1]) - 1.0 : NAN;
            const int asym = eps_paper(j - 1) * reach <= PI_8 && fabs(above - slope) <= SETTLED;
            return (reading){asym ? 2 : 1, slope};
        }
    return (reading){0, NAN};
}

/* What the readings of one quantity over the bodies came to. */
typedef struct {
    int n[3];          /* bodies per tier */
    int bad;           /* readings off their expectation */
    double worst;      /* the asymptotic slope farthest from q */
    double least;      /* the smallest lower estimate */
    const char *where; /* the body of the first bad reading */
} tally;

static void tally_add(tally *t, reading rd, int q, const char *bname)
{
    t->n[rd.tier]++;
    int ok = 1;
    if (rd.tier == 2) {
        if (!(fabs(rd.slope - q) <= fabs(t->worst - q)))
            t->worst = rd.slope;
        ok = fabs(rd.slope - q) <= SLOPE_TOL;
    } else if (rd.tier == 1) {
        t->least = fmin(t->least, rd.slope);
        ok = rd.slope >= 0.5 * q;
    }
    if (!ok && !t->bad++)
        t->where = bname;
}

static void tally_check(const tally *t, const char *method, const char *what, int q,
                        const char *ref)
{
    char asym[64] = "", low[64] = "", off[64] = "";
    if (t->n[2])
        snprintf(asym, sizeof asym, " (farthest %.2f, within %.1f)", t->worst, SLOPE_TOL);
    if (t->n[1])
        snprintf(low, sizeof low, " (least %.2f, >= %d/2)", t->least, q);
    if (t->bad)
        snprintf(off, sizeof off, "; %d off, first on %s", t->bad, t->where);
    CHECK(t->bad == 0 && t->n[1] + t->n[2] > 0,
          "%s, %s: local order %d expected (%s): asymptotic on %d bodies%s, a lower estimate on "
          "%d%s, at round-off on %d%s",
          method, what, q, ref, t->n[2], asym, t->n[1], low, t->n[0], off);
}

static void check_method(const sus_stepper_type *st, const body_ref *refs, int nb)
{
    const expected_order *eo = expected_order_of(st->name);
    if (!eo) {
        CHECK(0, "%s: its orders are in tests/ledger/expected_orders.c", st->name);
        return;
    }
    tally t[NQ];
    for (int q = 0; q < NQ; q++)
        t[q] = (tally){.worst = NAN, .least = INFINITY};
    for (int b = 0; b < nb; b++) {
        const body_ref *r = &refs[b];
        double e[NQ][NEPS];
        local_errors(st, r, e);
        const double floor_r = FLOOR_FACTOR * st->desc.substeps;
        const double floor_w = floor_r * r->size_w * (st->desc.implicit ? r->cond : 1.0);
        const double reach = r->rate_s * st->desc.substeps;
        tally_add(&t[0], read_order(e[0], floor_w, reach), eo->p, r->b.name);
        for (int rc = 0; rc < SUS_RECON_COUNT; rc++) {
            reading rd = read_order(e[1 + rc], floor_r, reach);
            rd.slope = fmin(rd.slope, eo->p); /* TeoL: min(r, p) */
            tally_add(&t[1 + rc], rd, eo->so3[rc], r->b.name);
        }
    }
    tally_check(&t[0], st->name, "w", eo->p, eo->ref);
    for (int rc = 0; rc < SUS_RECON_COUNT; rc++) {
        char what[64];
        snprintf(what, sizeof what, "SO(3) with %s, min(r, p)", SUS_RECON_NAMES[rc]);
        tally_check(&t[1 + rc], st->name, what, eo->so3[rc], eo->ref);
    }
}

int main(void)
{
    static body_ref refs[BODIES_COUNT];
    int nb = 0;
    gsl_set_error_handler_off();
    for (int k = 0; k < BODIES_COUNT; k++)
        nb += body_ref_init(k, &refs[nb]) == 0;
    for (int i = 0; i < sus_step_method_count(); i++)
        check_method(sus_step_method_get(i)->type, refs, nb);
    for (int i = sus_step_method_count(); i < sus_step_method_count_all(); i++)
        printf("SKIP %s: tolerance-driven, no fixed step to read a local order at\n",
               sus_step_method_get(i)->type->name);
    return check_summary("test_attitude_order");
}
