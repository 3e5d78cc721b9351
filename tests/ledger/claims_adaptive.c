/* The tolerance-driven methods of the registry (stepper.h, sus_tol_ops) against their tolerance
 * and their structure, on the paper's body and the general and stiff bodies of tests/unit/bodies.h.
 * What a method's TOL bounds, and the key of its lines, come from tests/ledger/expected_orders.c
 * (expected_tol_of): TOL_LOCAL (each step's own estimate; taylor-adaptive) or TOL_GLOBAL (R's
 * global error; exact-attitude).
 *
 * TOL_LOCAL. Error against TOL at t = T_ERR: w and R against the long-double reference
 * (sus_refatt_precise, good to ~1e-17), for TOL = 10^-4 ... 10^-14, one a decade. What theory says:
 *   - each accepted step's estimated error is at most TOL, and the global error at t is a sum of
 *     N such local errors carried by the flow, so err <= F N TOL with F = 10, the factor by which
 *     the last-two-terms estimate may undershoot a tail whose ratio r is up to 0.9 (true tail
 *     T_{p+1} / (1 - r));
 *   - the controller aims each step at SAFETY^{p+1} TOL >= 0.9^21 TOL ~ 0.1 TOL, so a method that
 *     uses its tolerance lands within two decades below it: err(R) >= 1e-2 TOL (the textbook rule
 *     lands 10-100x below, which is what this line is to catch);
 *   - proportionality: the slope of log err(R) against log TOL is 1 - 1/(p+1) at one order (N
 *     grows like TOL^{-1/(p+1)}) and 1 when N does not change: in [0.86, 1] for p = 6 ... 20,
 *     widened by 0.15 each way for the order changing with TOL and the estimate's scatter: the band
 *     [0.7, 1.15]. Each edge is a line (the steepest body against the upper, the shallowest
 *     against the lower). The 0.15 is an allowance, not an estimate: theory does not fix it. Two
 *     of its parts can be estimated, and the estimates are not the line's threshold: the
 *     controller's SAFETY^{p+1} falls by 12 log10(1/0.9) = 0.55 decades as p goes from 8 to 20
 *     over the ten decades (+0.055 of slope), and an estimate whose undershoot varies within
 *     [1, F] moves a least-squares slope over 11 evenly spaced decades by at most log10(F) 15/110
 *     = 0.14 (0.17 over the 9 left above round-off on some bodies). Together they can exceed the
 *     allowance, so the upper-edge line prints where its verdict turns and how many bodies lie
 *     inside the one-order theory alone;
 *   - points within 100 N u of round-off (the rounding of N steps, a hundredfold) are left out
 *     of the slope and of the lower ratio bound (as in the order fits, claims_highorder.c).
 * w gets only the upper bound: its local errors decay on the attracting rotation, far below the
 * tolerance its steps spend, so no lower bound and no slope follow from the estimate. Its bound
 * is the theory's and far above w's error, so it cannot see a weak w estimate; it does catch a w
 * far from the reference (a broken step or reference: the mutants of refattitude.c's w are killed
 * by it). u is SUS_U = 2^-52 in every bound of this file.
 * Every body runs in its own time: t k = T k_paper (t = T on the paper's body), the same phase of
 * its transient and the same number of its time scales 1/k.
 * Structure at T = 1e4 (every step's row): w3 = 0 exactly; |R^T R - I| <= 1e-14 (R is built afresh
 * from a unit quaternion: one rounding per entry, whatever N); |E - E0| <= 8 u e, e the sum of
 * |terms| of E (E0 itself where none cancels; far more on a near-singular I_m) (every step
 * scales w onto E(w_0) itself, so the rounding does not accumulate). *
 * TOL_GLOBAL, from theory (each body in its own time, as above):
 *   - dist(R, R_ref)(t k = 50 k_paper) <= TOL + (34 N + 32 sum h |w|) u for TOL = 10^-4 ... 10^-14:
 * the method's estimates of its N steps sum to at most TOL (its file's top); each step rounds |q|
 * by about 12 u (the quaternion product, the series' sum, the normalisation), dist <= 2 sqrt2 |dq|:
 *     34 u a step; and a step that turns R by theta = h |w| computes that angle in double, about u
 *     theta (32: tests/unit/test_exact_attitude.c counts it), h |w| taken as h max(|w|) at its
 * ends;
 *   - |w - w_ref| <= 64 u r |L^{-1}|_F at the same time: w is the closed form, w = L^{-T} u with
 *     |u| = r, whose parameters (s0, k, r, beta, L) and evaluation carry some 16 roundings, each
 *     moving w by at most about u times that scale (|d(sech s, tanh s)/ds| <= 1, |s| e^{-|s|} <=
 * 1/e);
 *   - structure to T k = 1e4 k_paper, the steady tail included: w3 = 0 exactly; |R^T R - I| <=
 *     1e-14 (R from a unit quaternion); |E - E0| <= (32 kappa E0 + 6 e) u, kappa = |L|_F
 *     |L^{-1}|_F: E = |u|^2 / 2 with u = L^T w, and w's roundings (16 u r |L^{-1}|_F, as in the
 *     tests of the closed form) reach E through L^T, 2 r |L|_F 16 u r |L^{-1}|_F = 32 u kappa E0;
 *     and E's own evaluation at w and at w0 rounds each by 3 u of its terms' size e (the largest
 *     over the rows, e = 1/2 sum |w_i I_ij w_j|), which on a near-singular I_m is up to kappa^2 E0
 *     where the terms cancel.
 * Two hard bodies (HARD_BODIES), where N local errors of at most TOL do not bound R's: a TOL_LOCAL
 * method's line states that its error exceeds N TOL there (what --help says it may do), a
 * TOL_GLOBAL method's that its bound holds there too.
 *   - slow: a general body that starts near its repelling rotation and leaves it slowly, one of an
 *     independent check's random family. An error in w there moves the rest of the transient in
 *     time, and the attitude integrates the shift.
 *   - sing: I_m nearly singular (|I_m| = 2e-9) with a third row of size 1, so |w| grows to 4.5e4
 *     along I_m's soft axis; the Taylor series' proved radius (step_taylor.c) shrinks with |I_m|
 *     and holds every step far below what TOL would allow, and the roundings of many short steps
 *     add up.
 */
#include "claims_adaptive.h"

#include "claims_bodies.h"
#include "driver.h"
#include "exact.h"
#include "expected_orders.h"
#include "ledger.h"
#include "notation.h"
#include "orderfit.h"
#include "refattitude.h"
#include "registry.h"
#include "so3.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define U SUS_U
#define T_ERR 50.0
#define T_STRUCT 1e4
#define TOL_STRUCT 1e-10
#define NTOL 11 /* 1e-4 ... 1e-14 */
#define F_UNDERSHOOT 10.0
#define RATIO_LO 1e-2
#define SLOPE_P6                                                                                   \
    (6.0 / 7.0) /* 1 - 1/(p+1) at the lowest order, p = 6: the one-order theory's lower end */
#define SLOPE_MID 0.925 /* the band [0.7, 1.15] */
#define SLOPE_HALF 0.225
#define ORTH_BOUND 1e-14
#define ROUND_STEP 34.0 /* TOL_GLOBAL: round-off per step, in u (above) */
#define ROUND_TURN 32.0 /* and per radian turned */
#define ROUND_W 64.0
/* |E - E0|: w's share and E's own evaluation (the top of the file) */
#define ENERGY_KAPPA 32.0
#define ENERGY_EVAL 6.0
/* The attitude's share of the tolerance. A step is as long as the jet's largest coefficients
 * allow: w's scale as (h k)^n (its rate of approach), the attitude's as (h |w|)^n (its rate of
 * turn). Where |w| < k the attitude's truncation error lies a factor (|w| / k)^(p+1) below the
 * tolerance each step spends, so R's error tells nothing of how the tolerance is used: such a
 * body (|w| / k below RATE_RATIO_MIN, |w| the largest along the motion) enters only the upper
 * bounds, and the lines name it. 1 is where the argument turns: below it the factor, which
 * shrinks as p grows with falling TOL (by ln(10) / 2 a decade), steepens R's slope by
 * 1.15 log10(k / |w|) and takes its ratio out of the two decades the lower bound allows. */
#define RATE_RATIO_MIN 1.0
/* The hard bodies (the top of the file): inertia by rows, w0, the time, the tolerance, and what
 * the line says of the body and of each kind of method. */
typedef struct {
    const char *key; /* the line's id: KEY-<key>-body-R */
    double I[9], w0[2], T, tol;
    const char *body, *local, *global;
} hard_body;

static const hard_body HARD_BODIES[] = {
    {"slow",
     {3.7607657312547844, -1.8500477600547198, -9.98946566513876, -1.8500477600547198,
      2.0012376008313595, 4.178285727568296, -9.98946566513876, 4.178285727568296,
      41.54591882545439},
     {0.005464358177027481, 0.013316269712168134},
     1e3,
     1e-8,
     "a general body that starts near its repelling rotation and leaves it slowly",
     "an error in $\\omega$ shifts the rest of the transient in time, the attitude carries the "
     "shift, and the error exceeds $N$ local errors of at most TOL, as the command's help says it "
     "may",
     "its bound holds where an error in $\\omega$ would shift the transient, as $\\omega$ is the "
     "closed form"},
    {"sing",
     {1.0, 1.0 - 1e-9, 0.0, 1.0 - 1e-9, 1.0, 0.0, -1.0, -1.0, 1.0},
     {1.0, 1.0},
     1e-2,
     1e-12,
     "a body with a nearly singular $I_m$ ($I_{12} = 1 - 10^{-9}$, $I_{11} = I_{22} = 1$, third "
     "row $(-1, -1)$, $\\omega_0 = (1, 1)$)",
     "its steps are held short by the series' proved radius, which shrinks with $|I_m|$, and "
     "their roundings add up past $N$ TOL, as the command's help says",
     "its bound holds there too, as $\\omega$ is the closed form"},
};

typedef struct {
    const sus_model *m;
    double e0;
    long steps;
    double w[3], R[3][3];
    double w3, orth, energy; /* the largest over the rows */
    double eterms;           /* the largest sum of |terms| of E(w) over the rows */
    double t, turn; /* the last row's time; the sum of h max(|w|) over the steps (TOL_GLOBAL) */
} track_ctx;

static int track(void *vctx, const sus_row *r)
{
    track_ctx *c = vctx;
    if (r->k > 0)
        c->turn += (r->t - c->t) * fmax(hypot(c->w[0], c->w[1]), hypot(r->w[0], r->w[1]));
    c->t = r->t;
    c->steps = r->k;
    for (int i = 0; i < 3; i++)
        c->w[i] = r->w[i];
    double R[3][3]; /* a local copy: GCC's -fsanitize build misjudges the size of r->R */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c->R[i][j] = R[i][j] = r->R[i][j];
    c->w3 = fmax(c->w3, fabs(r->w[2]));
    c->orth = fmax(c->orth, sus_so3_orth_defect(R));
    c->energy = fmax(c->energy, fabs(sus_energy(c->m, r->w) - c->e0));
    c->eterms = fmax(c->eterms, claims_energy_terms(c->m, r->w));
    return 0;
}

static int run(const sus_stepper_type *type, const sus_model *m, const double w0[2], double tol,
               double T, track_ctx *c)
{
    *c = (track_ctx){.m = m, .e0 = sus_energy(m, w0)};
    const sus_tol_config cfg = {m, type, tol, T, 0.0, 0};
    sus_run_report rep;
    return sus_run_tol(&cfg, w0, track, c, &rep);
}

/* A tolerance-driven method under test and what the ledger's table says of it. */
typedef struct {
    const sus_stepper_type *type;
    const expected_tol *eo;
} tol_method;

/* "KEY" + suffix as a TeX macro name (letters only, the first one capital): "adaptive" ->
 * "AdaptiveSlopeRMin". */
static void macro_of(const char *key, const char *suffix, char *out, size_t len)
{
    size_t n = 0;
    for (const char *c = key; *c && n + 1 < len; c++) {
        if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z')))
            continue;
        out[n] = n == 0 && *c >= 'a' ? (char)(*c - 'a' + 'A') : *c;
        n++;
    }
    out[n] = '\0';
    snprintf(out + n, len - n, "%s", suffix);
}

static void key_number(const tol_method *tm, const char *suffix, double value)
{
    char name[64];
    macro_of(tm->eo->key, suffix, name, sizeof name);
    ledger_number(name, value);
}

/* The times and tolerances the lines name, in the notation. */
#define T50 "$t k = 50\\,k_\\mathrm{paper}$"
#define T1E4 "$T k = 10^4\\,k_\\mathrm{paper}$"
#define TOLS "$\\mathrm{TOL} = 10^{-4}, \\dots, 10^{-14}$"

/* A run of the method, or the claims program stops (ledger_die) naming it. */
static void run_or_die(const tol_method *tm, const sus_model *m, const double w0[2], double tol,
                       double T, track_ctx *c)
{
    char what[96];
    if (run(tm->type, m, w0, tol, T, c) == SUS_RUN_OK)
        return;
    snprintf(what, sizeof what, "a %s run to t = %g", tm->type->name, T);
    ledger_die(what);
}

/* ---- TOL_LOCAL: each step's estimate at most TOL ---- */

typedef struct {
    double slope, slope_min, ratio_lo,
        ratio_hi; /* over bodies: steepest and shallowest slope, err/TOL, err/(N TOL) */
    char slope_body[16], lo_body[16], hi_body[16]; /* copies: each body is gone after its turn */
    char slow[160]; /* bodies whose attitude turns slower than w settles, with |w| / k */
    int points, fitted;
    int bodies,
        in_theory; /* bodies fitted; of them, slopes inside the one-order theory [SLOPE_P6, 1] */
} tol_summary;

/* The worst-so-far bookkeeping of one body's measurements of one quantity; a body whose R error is
 * not what its tolerance controls (rate = |w| / k below RATE_RATIO_MIN) enters the upper bound
 * only. */
static void summary_add(tol_summary *s, const char *name, double rate, double slope,
                        const double *ratio, const double *per_step, int n)
{
    for (int j = 0; j < NTOL; j++)
        if (!s->hi_body[0] || !(per_step[j] <= s->ratio_hi))
            s->ratio_hi = per_step[j], snprintf(s->hi_body, sizeof s->hi_body, "%s", name);
    if (rate < RATE_RATIO_MIN) {
        const size_t len = strlen(s->slow);
        snprintf(s->slow + len, sizeof s->slow - len, "%s%s $%s$", len ? ", " : "", name,
                 notation_g(rate, 2).s);
        return;
    }
    if (!s->slope_body[0] || !(slope <= s->slope))
        s->slope = slope, snprintf(s->slope_body, sizeof s->slope_body, "%s", name);
    if (!(slope >= s->slope_min) || s->slope_min == 0.0)
        s->slope_min = slope;
    s->bodies++;
    s->in_theory += slope >= SLOPE_P6 && slope <= 1.0;
    for (int j = 0; j < n; j++) {
        if (!s->lo_body[0] || ratio[j] < s->ratio_lo)
            s->ratio_lo = ratio[j], snprintf(s->lo_body, sizeof s->lo_body, "%s", name);
    }
}

/* A time of the paper's body carried to body d's own time: the same t k, the same phase of the
 * transient (t itself on the paper's body). */
static double body_time(const claims_body *d, double t)
{
    return t * (claims_body_get(0)->ex.k / d->ex.k);
}

/* One body's errors over the tolerances, for w (q = 0) and R (q = 1), at t k = T_ERR k_paper. */
static void body_errors(const tol_method *tm, const claims_body *d, tol_summary s[2])
{
    const body *b = &d->b;
    const sus_model *m = &d->m;
    const double T = body_time(d, T_ERR);
    double w_ref[2], R_ref[3][3], tols[2][NTOL], e[2][NTOL], ratio[2][NTOL], per_step[2][NTOL];
    sus_refatt_precise(m, b->w0, T, w_ref, R_ref);
    int n[2] = {0, 0};
    for (int j = 0; j < NTOL; j++) {
        const double tol = pow(10.0, -4.0 - j);
        track_ctx c;
        run_or_die(tm, m, b->w0, tol, T, &c);
        const double er[2] = {hypot(c.w[0] - w_ref[0], c.w[1] - w_ref[1]),
                              sus_so3_dist(R_ref, c.R)};
        const double size[2] = {hypot(w_ref[0], w_ref[1]), 1.0};
        for (int q = 0; q < 2; q++) {
            per_step[q][j] = er[q] / (tol * (double)c.steps);
            if (er[q] <= 100.0 * (double)c.steps * U * size[q])
                continue; /* at round-off: neither in the slope nor in the lower bound */
            tols[q][n[q]] = tol;
            e[q][n[q]] = er[q];
            ratio[q][n[q]++] = er[q] / tol;
        }
    }
    for (int q = 0; q < 2; q++) {
        sus_lab_order_fit fit = {.slope = NAN};
        if (sus_lab_fit_order(tols[q], e[q], n[q], 1.0, 0.0, &fit) != 0)
            fit.slope = NAN;
        const double rate = q == 1 ? d->size_w / d->ex.k : INFINITY; /* w: only its upper bound */
        summary_add(&s[q], b->name, rate, fit.slope, ratio[q], per_step[q], n[q]);
        if (rate < RATE_RATIO_MIN)
            continue;
        s[q].fitted += n[q];
        s[q].points += NTOL;
    }
}

static void local_claims(const tol_method *tm)
{
    const char *name = tm->type->name, *key = tm->eo->key;
    tol_summary s[2] = {{.points = 0}, {.points = 0}};
    for (int k = 0; k < BODIES_COUNT; k++)
        body_errors(tm, claims_body_get(k), s);
    char text[1024], slow[320], id[96];
    snprintf(
        slow, sizeof slow,
        "without: %s ($|\\omega|/k < %g$: the attitude turns slower than $\\omega$ settles, its "
        "error is not what TOL controls)",
        s[1].slow[0] ? s[1].slow : "none", RATE_RATIO_MIN);
    key_number(tm, "SlopeRMin", s[1].slope_min);
    key_number(tm, "SlopeRMax", s[1].slope);
    /* the band's two edges, each a line: the steepest body against the upper, the shallowest
     * against the lower (the verdict moves with an edge only if it crosses these two slopes) */
    snprintf(
        text, sizeof text,
        "steepest slope of $\\log \\mathrm{dist}(R, R_\\mathrm{ref})$ at " T50 " against $\\log "
        "\\mathrm{TOL}$, " TOLS " above $100\\,N u$ (%d of %d points), %s, %d of %d bodies (%s): "
        "$\\le %.2f$, the upper edge of the band $[%.2f, %.2f]$ fixed before "
        "measuring; the verdict turns at an edge of %.3f, and %d of %d "
        "bodies lie inside the one-order theory $[%.2f, 1]$; %s",
        s[1].fitted, s[1].points, name, s[1].bodies, BODIES_COUNT, s[1].slope_body,
        SLOPE_MID + SLOPE_HALF, SLOPE_MID - SLOPE_HALF, SLOPE_MID + SLOPE_HALF, s[1].slope,
        s[1].in_theory, s[1].bodies, SLOPE_P6, slow);
    snprintf(id, sizeof id, "%s-tol-slope-R", key);
    ledger_add_bound(id, "(extension)", text, s[1].slope, SLOPE_MID + SLOPE_HALF, 0,
                     LEDGER_EXTENSION);
    snprintf(text, sizeof text,
             "shallowest slope of $\\log \\mathrm{dist}(R, R_\\mathrm{ref})$ at " T50
             " against $\\log "
             "\\mathrm{TOL}$, as above, %d of %d bodies: $\\ge %.2f$, the lower edge of the band "
             "$[%.2f, %.2f]$; %s",
             s[1].bodies, BODIES_COUNT, SLOPE_MID - SLOPE_HALF, SLOPE_MID - SLOPE_HALF,
             SLOPE_MID + SLOPE_HALF, slow);
    snprintf(id, sizeof id, "%s-tol-slope-R-min", key);
    ledger_add_bound(id, "(extension)", text, s[1].slope_min, SLOPE_MID - SLOPE_HALF, 1,
                     LEDGER_EXTENSION);
    snprintf(text, sizeof text,
             "smallest $\\mathrm{dist}(R, R_\\mathrm{ref})/\\mathrm{TOL}$ at " T50 ", " TOLS
             " above $100\\,N u$, %s, %d of %d bodies (%s): "
             "$\\ge %g$ (within two decades below TOL); %s",
             name, s[1].bodies, BODIES_COUNT, s[1].lo_body, RATIO_LO, slow);
    snprintf(id, sizeof id, "%s-tol-ratio-lo-R", key);
    ledger_add_bound(id, "(extension)", text, s[1].ratio_lo, RATIO_LO, 1, LEDGER_EXTENSION);
    static const char *const what[2] = {"$|\\omega - \\omega_\\mathrm{ref}|$",
                                        "$\\mathrm{dist}(R, R_\\mathrm{ref})$"},
                             *const wr[2] = {"w", "R"};
    for (int q = 0; q < 2; q++) {
        snprintf(id, sizeof id, "%s-tol-ratio-hi-%s", key, wr[q]);
        snprintf(text, sizeof text,
                 "largest %s at " T50 " over $N\\,\\mathrm{TOL}$, " TOLS
                 " ($N$ accepted steps), %s, %d bodies (%s): $\\le %g$ ($N$ "
                 "local errors of at most TOL, estimate within $%g\\times$)",
                 what[q], name, BODIES_COUNT, s[q].hi_body, F_UNDERSHOOT, F_UNDERSHOOT);
        ledger_add_bound(id, "(extension)", text, s[q].ratio_hi, F_UNDERSHOOT, 0, LEDGER_EXTENSION);
    }
}

/* ---- TOL_GLOBAL: R's global error at most TOL ---- */

/* |L^{-1}|_F r, the scale of w, and kappa = |L|_F |L^{-1}|_F, from the closed form's Cholesky
 * factor of I_m (exact.h). */
static void closed_form_scales(const sus_exact *ex, double *w_scale, double *kappa)
{
    const double a = 1.0 / ex->l11, b = 1.0 / ex->l22, c = ex->l21 / (ex->l11 * ex->l22);
    const double inv = sqrt(a * a + b * b + c * c);
    *w_scale = inv * ex->r;
    *kappa = inv * sqrt(ex->l11 * ex->l11 + ex->l21 * ex->l21 + ex->l22 * ex->l22);
}

/* TOL_GLOBAL's bound on dist(R, R_ref) after a run (the top of the file), and how the lines
 * write it (with ROUND_STEP, ROUND_TURN). */
static double global_bound(double tol, const track_ctx *c)
{
    return tol + (ROUND_STEP * (double)c->steps + ROUND_TURN * c->turn) * U;
}
#define GLOBAL_BOUND_TEX "$\\mathrm{TOL} + (%g N + %g \\sum h |\\omega|) u$"

typedef struct {
    double R, w;                 /* the worst ratios to the bounds */
    char R_body[16], w_body[16]; /* where */
} global_worst;

/* One body's errors at t k = T_ERR k_paper over the tolerances, as ratios to the bounds (the top
 * of the file). */
static void global_body(const tol_method *tm, const claims_body *d, global_worst *g)
{
    const double T = body_time(d, T_ERR);
    double w_ref[2], R_ref[3][3], scale, kappa;
    closed_form_scales(&d->ex, &scale, &kappa);
    sus_refatt_precise(&d->m, d->b.w0, T, w_ref, R_ref);
    for (int j = 0; j < NTOL; j++) {
        const double tol = pow(10.0, -4.0 - j);
        track_ctx c;
        run_or_die(tm, &d->m, d->b.w0, tol, T, &c);
        const double r = sus_so3_dist(R_ref, c.R) / global_bound(tol, &c);
        const double v = hypot(c.w[0] - w_ref[0], c.w[1] - w_ref[1]) / (ROUND_W * U * scale);
        if (!g->R_body[0] || !(r <= g->R))
            g->R = r, snprintf(g->R_body, sizeof g->R_body, "%s", d->b.name);
        if (!g->w_body[0] || !(v <= g->w))
            g->w = v, snprintf(g->w_body, sizeof g->w_body, "%s", d->b.name);
    }
}

static void global_claims(const tol_method *tm)
{
    const char *name = tm->type->name, *key = tm->eo->key;
    global_worst g = {.R = 0.0};
    char id[96], text[640];
    for (int k = 0; k < BODIES_COUNT; k++)
        global_body(tm, claims_body_get(k), &g);
    key_number(tm, "TolRatioR", g.R);
    snprintf(
        text, sizeof text,
        "largest $\\mathrm{dist}(R, R_\\mathrm{ref})$ at " T50 " over " GLOBAL_BOUND_TEX ", " TOLS
        " ($N$ accepted steps), %s, %d bodies (%s): $\\le 1$ (step "
        "estimates summing to at most TOL; round-off of the steps and of the angles they turn)",
        ROUND_STEP, ROUND_TURN, name, BODIES_COUNT, g.R_body);
    snprintf(id, sizeof id, "%s-tol-R", key);
    ledger_add_bound(id, "(extension)", text, g.R, 1.0, 0, LEDGER_EXTENSION);
    snprintf(
        text, sizeof text,
        "largest $|\\omega - \\omega_\\mathrm{ref}| / (%g\\,u\\,r |L^{-1}|_F)$ over the same runs, "
        "%s, %d bodies (%s): $\\le 1$ ($\\omega$ is the closed form: its roundings alone)",
        ROUND_W, name, BODIES_COUNT, g.w_body);
    snprintf(id, sizeof id, "%s-tol-w", key);
    ledger_add_bound(id, "(extension)", text, g.w, 1.0, 0, LEDGER_EXTENSION);
}

/* ---- both: w3, |R^T R - I| and |E - E0| over every step to T k = 1e4 k_paper, worst of the
 * bodies; E against the size of its terms (TOL_LOCAL) or kappa E0 (TOL_GLOBAL, the top of the file)
 */

static void energy_line(const tol_method *tm, double en)
{
    char id[96], text[640];
    if (tm->eo->bounds == TOL_GLOBAL)
        snprintf(
            text, sizeof text,
            "$\\max |E - E_0| / ((%g \\kappa E_0 + %g e) u)$, $\\kappa = |L|_F |L^{-1}|_F$ "
            "($I_m = L L^\\top$), $e = \\max \\frac{1}{2} \\sum |\\omega_i I_{ij} \\omega_j|$, "
            "over every step to " T1E4 ", %s at $\\mathrm{TOL} = %s$, %d bodies: $\\le 1$ "
            "($\\omega$ is the closed form, $|L^\\top \\omega| = r$: its roundings reach $E$ "
            "through $L^\\top$; $E$'s own evaluation rounds by a few $u e$)",
            ENERGY_KAPPA, ENERGY_EVAL, tm->type->name, notation_g(TOL_STRUCT, 6).s, BODIES_COUNT);
    else
        snprintf(
            text, sizeof text,
            "$\\max |E - E_0| / (u e)$ over every step to " T1E4 ", %s at $\\mathrm{TOL} = %s$, "
            "%d bodies, $e = \\max \\frac{1}{2} \\sum |\\omega_i I_{ij} \\omega_j|$ (the terms of "
            "$E$, $E_0$ when none cancels); bound 8 (each step scales $\\omega$ onto $E_0$ itself: "
            "no accumulation)",
            tm->type->name, notation_g(TOL_STRUCT, 6).s, BODIES_COUNT);
    snprintf(id, sizeof id, "%s-energy", tm->eo->key);
    ledger_add_bound(id, "(extension)", text, en, tm->eo->bounds == TOL_GLOBAL ? 1.0 : 8.0, 0,
                     LEDGER_EXTENSION);
}

static void structure_claims(const tol_method *tm)
{
    const char *name = tm->type->name, *key = tm->eo->key;
    double w3 = 0.0, orth = 0.0, en = 0.0;
    long steps = 0;
    for (int k = 0; k < BODIES_COUNT; k++) {
        const claims_body *d = claims_body_get(k);
        double scale, kappa;
        track_ctx c;
        closed_form_scales(&d->ex, &scale, &kappa);
        run_or_die(tm, &d->m, d->b.w0, TOL_STRUCT, body_time(d, T_STRUCT), &c);
        w3 = fmax(w3, c.w3);
        orth = fmax(orth, c.orth);
        en = fmax(en, c.energy / (U * (tm->eo->bounds == TOL_GLOBAL
                                           ? ENERGY_KAPPA * kappa * c.e0 + ENERGY_EVAL * c.eterms
                                           : c.eterms)));
        steps += c.steps;
    }
    char id[96], text[640];
    key_number(tm, "StructSteps", (double)steps / BODIES_COUNT);
    snprintf(text, sizeof text,
             "$\\max |\\omega_3|$ over every step to " T1E4
             ", %s at $\\mathrm{TOL} = %s$, %d bodies: exactly 0",
             name, notation_g(TOL_STRUCT, 6).s, BODIES_COUNT);
    /* the method writes w3 = 0.0 at every step: a check of the code, not evidence */
    snprintf(id, sizeof id, "%s-w3", key);
    ledger_add(id, "(extension)", text, w3, 0.0, 0.0, LEDGER_BY_CONSTRUCTION);
    snprintf(text, sizeof text,
             "$\\max |R^\\top R - I|$ over every step to " T1E4 ", %s at $\\mathrm{TOL} = %s$, %d "
             "bodies; round-off bound $%s$ ($R$ from a unit quaternion at each step)",
             name, notation_g(TOL_STRUCT, 6).s, BODIES_COUNT, notation_g(ORTH_BOUND, 6).s);
    snprintf(id, sizeof id, "%s-orth", key);
    ledger_add_bound(id, "(extension)", text, orth, ORTH_BOUND, 0, LEDGER_EXTENSION);
    energy_line(tm, en);
}

/* A hard body (the top of the file): R's error at T against N TOL (TOL_LOCAL: at least, as --help
 * says it may be) or against the run's bound (TOL_GLOBAL: at most). */
static void hard_body_claim(const tol_method *tm, const hard_body *hb)
{
    sus_model m;
    sus_exact ex;
    double w_ref[2], R_ref[3][3];
    track_ctx c;
    if (sus_model_init(&m, hb->I, NULL, 0) != 0 || sus_exact_init(&ex, &m, hb->w0) != 0)
        ledger_die("a hard body of claims_adaptive.c");
    sus_refatt_precise(&m, hb->w0, hb->T, w_ref, R_ref);
    run_or_die(tm, &m, hb->w0, hb->tol, hb->T, &c);
    const int local = tm->eo->bounds != TOL_GLOBAL;
    const double dist = sus_so3_dist(R_ref, c.R);
    const double x = local ? dist / (hb->tol * (double)c.steps) : dist / global_bound(hb->tol, &c);
    char id[96], text[1024], bound[96];
    snprintf(bound, sizeof bound, GLOBAL_BOUND_TEX, ROUND_STEP, ROUND_TURN);
    snprintf(text, sizeof text,
             "$\\mathrm{dist}(R, R_\\mathrm{ref})$ at $T = %s$ over %s, %s at $\\mathrm{TOL} = %s$ "
             "($N = %ld$ steps), on %s ($s_0 = %s$, $k = %s$, $|\\omega_0| = %s$): %s: %s",
             notation_g(hb->T, 6).s, local ? "$N\\,\\mathrm{TOL}$" : bound, tm->type->name,
             notation_g(hb->tol, 6).s, c.steps, hb->body, notation_g(ex.s0, 2).s,
             notation_g(ex.k, 2).s, notation_g(hypot(hb->w0[0], hb->w0[1]), 2).s,
             local ? "$\\ge 1$" : "$\\le 1$", local ? hb->local : hb->global);
    snprintf(id, sizeof id, "%s-%s-body-R", tm->eo->key, hb->key);
    ledger_add_bound(id, "(extension)", text, x, 1.0, local, LEDGER_EXTENSION);
}

/* Every tolerance-driven method of the registry; one the table does not know fails a line. */
void adaptive_claims(void)
{
    for (int i = sus_step_method_count(); i < sus_step_method_count_all(); i++) {
        const sus_stepper_type *type = sus_step_method_get(i)->type;
        const tol_method tm = {type, expected_tol_of(type->name)};
        if (!tm.eo) {
            char id[64];
            snprintf(id, sizeof id, "expected-tol-known-%s", type->name);
            ledger_add_bound(
                id, "\\texttt{tests/ledger/expected\\_orders.c}",
                "the tolerance-driven method has a stated meaning of TOL to test: 1 when it does",
                0.0, 1.0, 1, LEDGER_EXTENSION);
            continue;
        }
        if (tm.eo->bounds == TOL_GLOBAL)
            global_claims(&tm);
        else
            local_claims(&tm);
        for (size_t j = 0; j < sizeof HARD_BODIES / sizeof HARD_BODIES[0]; j++)
            hard_body_claim(&tm, &HARD_BODIES[j]);
        structure_claims(&tm);
    }
}
