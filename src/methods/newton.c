#include "newton.h"

#include <math.h>

/* NaN when an entry is NaN (a max that drops NaN would call an overflowed residual 0). The max
 * is a comparison, not fmax: no NaN reaches it, so it is fmax's value without fmax's call. */
static double inf_norm(const double *v, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++) {
        if (isnan(v[i]))
            return NAN;
        r = fabs(v[i]) > r ? fabs(v[i]) : r;
    }
    return r;
}

/* to[0 .. n-1] = from[0 .. n-1]; n = 2 (most equations) without a call to memcpy. */
static void copy_n(double *to, const double *from, int n)
{
    if (n == 2) {
        to[0] = from[0], to[1] = from[1];
        return;
    }
    for (int i = 0; i < n; i++)
        to[i] = from[i];
}

/* The product of the row 1-norms of J: an upper bound on the sum of |terms| of det J's Leibniz
 * expansion (expanding the product gives every term of it and more): the yardstick for the
 * round-off in det J, on the safe side. */
static double row_norm_product(const double *J, int n)
{
    double p = 1.0;
    for (int i = 0; i < n; i++) {
        double r = 0.0;
        for (int j = 0; j < n; j++)
            r += fabs(J[i * n + j]);
        p *= r;
    }
    return p;
}

/* n = 2 by the closed form (the (REGLOC) block, bit for bit as it has always been solved); larger
 * n by Gaussian elimination with partial pivoting, on the stack. Written here rather than taken
 * from GSL: GSL's LU was most of the cost of a gauss4 step (n = 8), and the WebAssembly build of
 * the methods has no GSL. */
int sus_step_linear_solve(int n, double *J, const double *g, double *dx, double *det)
{
    if (n == 2) {
        *det = J[0] * J[3] - J[1] * J[2];
        if (fabs(*det) <= 4.0 * SUS_U * (fabs(J[0] * J[3]) + fabs(J[1] * J[2])))
            return -1;
        dx[0] = (J[3] * g[0] - J[1] * g[1]) / *det;
        dx[1] = (J[0] * g[1] - J[2] * g[0]) / *det;
        return 0;
    }
    const double bound = 4.0 * n * SUS_U * row_norm_product(J, n);
    double b[SUS_MAX_UNKNOWNS];
    for (int i = 0; i < n; i++)
        b[i] = g[i];
    *det = 1.0;
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(J[i * n + k]) > fabs(J[p * n + k]))
                p = i;
        if (p != k) { /* a row swap changes the determinant's sign */
            for (int j = 0; j < n; j++) {
                const double t = J[k * n + j];
                J[k * n + j] = J[p * n + j];
                J[p * n + j] = t;
            }
            const double t = b[k];
            b[k] = b[p];
            b[p] = t;
            *det = -*det;
        }
        *det *= J[k * n + k];
        if (J[k * n + k] == 0.0)
            continue;
        for (int i = k + 1; i < n; i++) {
            const double f = J[i * n + k] / J[k * n + k];
            for (int j = k; j < n; j++)
                J[i * n + j] -= f * J[k * n + j];
            b[i] -= f * b[k];
        }
    }
    if (!(fabs(*det) > bound))
        return -1;
    for (int i = n - 1; i >= 0; i--) {
        double r = b[i];
        for (int j = i + 1; j < n; j++)
            r -= J[i * n + j] * dx[j];
        dx[i] = r / J[i * n + i];
    }
    return 0;
}

/* Records the residual at the accepted x. */
static void fn_final(sus_residual_fn G, int n, const sus_model *m, double eps, const double w[2],
                     const double *x, sus_stepper_stats *st)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS];
    G(m, eps, w, x, g, J, &st->scale);
    st->residual = inf_norm(g, n);
}

typedef struct {
    double x[SUS_MAX_UNKNOWNS], residual, scale;
} newton_point;

static void keep(newton_point *p, const double *x, int n, double residual, double scale)
{
    copy_n(p->x, x, n);
    p->residual = residual;
    p->scale = scale;
}

static void restore(const newton_point *p, double *x, int n, sus_stepper_stats *st)
{
    copy_n(x, p->x, n);
    st->residual = p->residual;
}

/* The state of one solve: the best iterate (for stagnation), the accepted one (for polishing). */
typedef struct {
    newton_point best, ok;
    double prev;
    int polishing, maxit;
} newton_state;

/* One decision after evaluating G at x: returns a SUS_STEPPER_* status to end the solve, or -1 to
 * take the correction. */
static int decide(newton_state *s, double *x, int n, sus_stepper_stats *st)
{
    if (s->polishing) {
        /* The polished x replaces the accepted one unless round-off made it worse. */
        if (!(st->residual <= s->ok.residual)) {
            restore(&s->ok, x, n, st);
            st->scale = s->ok.scale;
        }
        return SUS_STEPPER_OK;
    }
    if (!isfinite(st->residual) || !isfinite(st->scale))
        return SUS_STEPPER_NO_CONVERGENCE;
    if (st->residual < s->best.residual)
        keep(&s->best, x, n, st->residual, st->scale);
    /* Stagnation at the round-off floor: near a large or ill-conditioned Jacobian |G| cannot fall
     * below ~ |J| ulp(x) times a few, which may sit above SUS_STEP_NEWTON_RTOL * scale. When an
     * iteration no longer halves |G| and |G| is within SUS_STEP_NEWTON_STAGNATION * scale, the best
     * iterate is the root to working precision. */
    if (st->residual > SUS_STEP_NEWTON_RTOL * st->scale &&
        st->residual <= SUS_STEP_NEWTON_STAGNATION * st->scale && st->residual > 0.5 * s->prev) {
        restore(&s->best, x, n, st);
        return SUS_STEPPER_OK;
    }
    s->prev = st->residual;
    /* Once the residual is at round-off, one more correction takes x from "within the tolerance"
     * to the round-off floor; without it the tolerance, not round-off, sets a bias that
     * accumulates over many steps. */
    if (st->residual <= SUS_STEP_NEWTON_RTOL * st->scale) {
        s->polishing = 1;
        keep(&s->ok, x, n, st->residual, st->scale);
    } else if (st->iterations == s->maxit) {
        return SUS_STEPPER_NO_CONVERGENCE;
    }
    return -1;
}

/* (REGLOC): Newton on the step equation; the matrix it inverts is, for x = w^{k+1}, the
 * upper-left block of (REGLOC), and a singular one ends the step as a failure. */
/* Newton as described in newton.h from x0 (which may be x), the iterates in x, at most maxit
 * corrections. */
static int newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps, const double w[2],
                        const double *x0, double *x, sus_stepper_stats *st, int maxit)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], dx[SUS_MAX_UNKNOWNS];
    /* Field by field, not an initializer that zeroes both points' SUS_MAX_UNKNOWNS entries on every
     * solve. ok is read only after keep has filled it (polishing); best only by the stagnation
     * test, which needs a finite residual, and decide keeps the first finite one (below infinity)
     * before that test: its x is always filled before it is read. */
    newton_state s;
    s.prev = INFINITY, s.polishing = 0, s.maxit = maxit;
    s.ok.residual = INFINITY, s.ok.scale = 0.0;
    s.best.residual = INFINITY, s.best.scale = 0.0;
    st->iterations = 0;
    st->det = NAN;
    st->last_residual = NAN;
    st->continued = 0;
    for (const double *at = x0;; at = x) {
        G(m, eps, w, at, g, J, &st->scale);
        /* x0 into x after G has read it: the start was just stored (a prediction), and a copy that
         * the compiler makes one wide load would wait here for those stores */
        if (at != x)
            copy_n(x, x0, n);
        st->residual = inf_norm(g, n);
        if (isfinite(st->residual))
            st->last_residual = st->residual;
        int singular = 0;
        if (s.polishing && n == 2) /* decide ends the solve: only det J is read, as solve has it */
            st->det = J[0] * J[3] - J[1] * J[2];
        else
            singular = sus_step_linear_solve(n, J, g, dx, &st->det) != 0;
        const int status = decide(&s, x, n, st);
        if (status >= 0)
            return status;
        /* (REGLOC): the step is defined only where this matrix is invertible. */
        if (singular)
            return s.polishing ? SUS_STEPPER_OK : SUS_STEPPER_SINGULAR;
        for (int i = 0; i < n; i++)
            x[i] -= dx[i];
        st->iterations++;
        /* A correction below the spacing of doubles at x leaves x unchanged: x is the root to
         * working precision even when a large Jacobian keeps |G| above SUS_STEP_NEWTON_RTOL * scale
         * (|G| >= |J| ulp(x) there). */
        if (!s.polishing && inf_norm(dx, n) <= 2.0 * SUS_U * inf_norm(x, n)) {
            fn_final(G, n, m, eps, w, x, st);
            return SUS_STEPPER_OK;
        }
    }
}

int sus_step_newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                          const double w[2], double *x, sus_stepper_stats *st)
{
    return newton_solve(G, n, m, eps, w, x, x, st, SUS_STEP_NEWTON_MAXIT);
}

/* ---- the branch: continuation in eps from the root at eps = 0 ---- */

/* |det J| / |J|_F^2 (n = 2) or |det J|^(2/n) / |J|_F^2: how far J is from singular, scale-free. */
static double regularity(sus_residual_fn G, int n, const sus_model *m, double eps,
                         const double w[2], const double *x)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], dx[SUS_MAX_UNKNOWNS], det,
        sc, f2 = 0.0;
    G(m, eps, w, x, g, J, &sc);
    for (int i = 0; i < n * n; i++)
        f2 += J[i] * J[i];
    sus_step_linear_solve(n, J, g, dx, &det);
    /* pow(|det|, 1) is |det| (a representable exact result): n = 2 skips the call */
    return (n == 2 ? fabs(det) : pow(fabs(det), 2.0 / n)) / f2;
}

/* r at the root x for eps relative to r at eps = 0, at its root guess(0). */
static double relative_regularity(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                                  double eps, const double w[2], const double *x)
{
    double x0[SUS_MAX_UNKNOWNS];
    guess(m, 0.0, w, x0);
    return regularity(G, n, m, eps, w, x) / regularity(G, n, m, 0.0, w, x0);
}

/* The scale of the unknowns (values of w or its increments) from w: the largest |x| on w's energy
 * ellipse, sqrt(2 E(w) / lambda_min(I_m)) (the steps keep E, or nearly), and at least |w|_inf. A
 * near-singular I_m stretches the ellipse by cond(I_m)^(1/2), and the roots with it. */
static double unknowns_scale(const sus_model *m, const double w[2])
{
    const double(*I)[3] = m->I;
    const double tr = 0.5 * (I[0][0] + I[1][1]), dif = 0.5 * (I[0][0] - I[1][1]);
    const double lmax = tr + hypot(dif, I[0][1]), lmin = m->det_m / lmax; /* I_m symmetric, > 0 */
    const double reach = sqrt(2.0 * sus_energy(m, w) / lmin);
    return fmax(fmax(fabs(w[0]), fabs(w[1])), isfinite(reach) ? reach : 0.0);
}

/* Is moved <= BRANCH_JUMP * unknowns_scale(m, w)? unknowns_scale is at least the larger |w_i|
 * (fmax of it and the reach), so a move within BRANCH_JUMP of that answers yes without the energy,
 * the square root and the hypot; a NaN in w makes lo NaN or fmax's value, and the answer the full
 * one. */
static int within_jump(double moved, const sus_model *m, const double w[2])
{
    const double a = fabs(w[0]), b = fabs(w[1]), lo = a > b ? a : b;
    return moved <= BRANCH_JUMP * lo || moved <= BRANCH_JUMP * unknowns_scale(m, w);
}

/* |a - b|_inf over n entries; a NaN difference is dropped, as fmax would drop it. */
static double moved_by(const double *a, const double *b, int n)
{
    double d = 0.0;
    for (int i = 0; i < n; i++) {
        const double e = fabs(a[i] - b[i]);
        d = e > d ? e : d;
    }
    return d;
}

/* One stage of the continuation: Newton at e from the prediction xp; the stage holds when Newton
 * converges within maxit iterations (BRANCH_STAGE_ITS; FAST_ITS from the explicit prediction) to a
 * root with det J > 0 (the sign at e = 0, where J
 * is I_m or blocks of it) no farther than BRANCH_JUMP times the unknowns' scale from xp: a root
 * reached that way is the one the prediction follows, not one of the others (they lie that far
 * away). */
static int stage(sus_residual_fn G, int n, const sus_model *m, double e, const double w[2],
                 double *xp, sus_stepper_stats *st, int *its, int maxit)
{
    double x[SUS_MAX_UNKNOWNS];
    const int rc = newton_solve(G, n, m, e, w, xp, x, st, maxit);
    *its += st->iterations;
    if (rc != SUS_STEPPER_OK || !(st->det > 0.0) || !within_jump(moved_by(x, xp, n), m, w))
        return -1;
    copy_n(xp, x, n);
    return 0;
}

int sus_step_newton_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                           double eps, const double w[2], double *x, sus_stepper_stats *st,
                           double *reg_min)
{
    double prev[SUS_MAX_UNKNOWNS], cur[SUS_MAX_UNKNOWNS], xp[SUS_MAX_UNKNOWNS];
    double e = 0.0, e_prev = 0.0, de = eps / BRANCH_FIRST, reg_last = 1.0;
    int its = 0;
    guess(m, 0.0, w, cur); /* the root at eps = 0 */
    for (int i = 0; i < n; i++)
        prev[i] = cur[i];
    /* Without reg_min, r is wanted only where the stages stop short: there it is computed at the
     * last accepted stage, from the same (e, cur) and the same root at 0, so the same bits. */
    const double reg0 = reg_min ? regularity(G, n, m, 0.0, w, cur) : NAN;
    if (reg_min)
        *reg_min = 1.0;
    for (int stages = 0; e != eps; stages++) {
        if (stages == BRANCH_MAX_STAGES || !(fabs(de) >= BRANCH_MIN_STAGE * fabs(eps))) {
            st->iterations = its;
            st->continued = 1;
            if (!reg_min && e != 0.0) /* e = 0: no stage accepted, r still 1 */
                reg_last = relative_regularity(G, guess, n, m, e, w, cur);
            return reg_last <= BRANCH_FOLD ? SUS_STEPPER_SINGULAR : SUS_STEPPER_NO_CONVERGENCE;
        }
        const double en = fabs(eps - e) <= fabs(de) ? eps : e + de;
        if (e == 0.0) { /* the explicit prediction: accurate for a first stage short enough */
            guess(m, en, w, xp);
            if (!within_jump(moved_by(xp, cur, n), m, w)) {
                de *= BRANCH_SHRINK; /* too long to predict: shorter, without a Newton solve */
                continue;
            }
        } else {
            for (int i = 0; i < n; i++) /* the secant through the last two roots */
                xp[i] = cur[i] + (en - e) / (e - e_prev) * (cur[i] - prev[i]);
        }
        if (stage(G, n, m, en, w, xp, st, &its, BRANCH_STAGE_ITS) != 0) {
            de *= BRANCH_SHRINK;
            continue;
        }
        for (int i = 0; i < n; i++)
            prev[i] = cur[i], cur[i] = xp[i];
        e_prev = e, e = en,
        de *= st->iterations <= BRANCH_EASY_ITS ? BRANCH_GROW_EASY : BRANCH_GROW;
        if (reg_min) {
            reg_last = regularity(G, n, m, e, w, cur) / reg0;
            *reg_min = fmin(*reg_min, reg_last);
        }
    }
    for (int i = 0; i < n; i++)
        x[i] = cur[i];
    st->iterations = its;
    st->continued = 1;
    return SUS_STEPPER_OK;
}

int sus_step_newton_solve_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m,
                                 double eps, const double w[2], double *x, sus_stepper_stats *st)
{
    int its = 0;
    guess(m, eps, w, x);
    if (stage(G, n, m, eps, w, x, st, &its, FAST_ITS) == 0)
        return SUS_STEPPER_OK;
    const int rc = sus_step_newton_branch(G, guess, n, m, eps, w, x, st, NULL);
    st->iterations += its;
    return rc;
}
