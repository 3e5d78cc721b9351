/* The inner loop of newton.h's solves, as static inline functions: newton.c builds the public
 * solves from them for any residual, and a step whose residual is known at compile time
 * (step_midpoint.c, which the compositions call for every substep) gets them with its residual
 * inlined: its Newton chain then runs without a call through a pointer. Private to src/methods. */
#ifndef SUS_STEP_NEWTON_CORE_H
#define SUS_STEP_NEWTON_CORE_H

#include "newton.h"

#include <float.h>
#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A step's residual (or guess) defined with this is inlined into the Newton loop that calls it,
 * which the compositions run for every substep; an out-of-line copy remains where its address is
 * taken (the continuation, the stability checks). */
#define NEWTON_INLINE static inline __attribute__((always_inline))

/* n = 2 by the closed form (the (REGLOC) block, bit for bit as it has always been solved). */
static inline int newton_solve_2x2(const double *J, const double *g, double *dx, double *det)
{
    *det = J[0] * J[3] - J[1] * J[2];
    if (fabs(*det) <= 4.0 * SUS_U * (fabs(J[0] * J[3]) + fabs(J[1] * J[2])))
        return -1;
    dx[0] = (J[3] * g[0] - J[1] * g[1]) / *det;
    dx[1] = (J[0] * g[1] - J[2] * g[0]) / *det;
    return 0;
}

/* Is x a normal double (not 0, subnormal, inf or NaN)? */
static inline int in_range(double x) { return fabs(x) >= DBL_MIN && fabs(x) <= DBL_MAX; }

/* The row 1-norms of J into r. Their product bounds the sum of |terms| of det J's Leibniz
 * expansion (expanding the product gives every term of it and more): times 4 n u, the yardstick
 * for the round-off in det J, on the safe side. */
static inline __attribute__((always_inline)) void row_norms(const double *J, const int n, double *r)
{
#pragma GCC unroll 8
    for (int i = 0; i < n; i++) {
        r[i] = 0.0;
#pragma GCC unroll 8
        for (int j = 0; j < n; j++)
            r[i] += fabs(J[i * n + j]);
    }
}

/* P J = L U in place by Gaussian elimination with partial pivoting: U on and above the diagonal,
 * L's multipliers below it (only the condition number reads them), perm[k] the row of J that is
 * row k of P J; the same eliminations applied to b. Returns det P (+-1). */
static inline __attribute__((always_inline)) double lu_factor(const int n, double *J, double *b,
                                                              int *perm)
{
    double sign = 1.0;
#pragma GCC unroll 8
    for (int k = 0; k < n; k++)
        perm[k] = k;
#pragma GCC unroll 8
    for (int k = 0; k < n; k++) {
        int p = k;
#pragma GCC unroll 8
        for (int i = k + 1; i < n; i++)
            if (fabs(J[i * n + k]) > fabs(J[p * n + k]))
                p = i;
        if (p != k) { /* a row swap changes the determinant's sign */
#pragma GCC unroll 8
            for (int j = 0; j < n; j++) {
                const double t = J[k * n + j];
                J[k * n + j] = J[p * n + j];
                J[p * n + j] = t;
            }
            const double t = b[k];
            const int q = perm[k];
            b[k] = b[p], b[p] = t;
            perm[k] = perm[p], perm[p] = q;
            sign = -sign;
        }
        if (J[k * n + k] == 0.0)
            continue;
#pragma GCC unroll 8
        for (int i = k + 1; i < n; i++) {
            const double f = J[i * n + k] / J[k * n + k];
            J[i * n + k] = f;
#pragma GCC unroll 8
            for (int j = k + 1; j < n; j++)
                J[i * n + j] -= f * J[k * n + j];
            b[i] -= f * b[k];
        }
    }
    return sign;
}

/* sus_step_linear_solve's singularity test (newton.h) on the factors of lu_factor; *det as it
 * says. Out of line: newton_solve_lu below settles the common case without it. */
int sus_step_linear_singular(int n, const double *LU, const int *perm, double sign, const double *r,
                             double *det);

/* sus_step_linear_solve for n > 2 by Gaussian elimination with partial pivoting, on the stack;
 * inlined, with n a constant, for gauss4's n = 4 (the out-of-line solve with n a variable was
 * most of its Newton iteration). Where det J and its yardstick are normal doubles and |det J|
 * exceeds the yardstick, J is regular without further test; else sus_step_linear_singular, which
 * forms the same products first, decides. */
static inline __attribute__((always_inline)) int
newton_solve_lu(const int n, double *J, const double *g, double *dx, double *det)
{
    double b[SUS_MAX_UNKNOWNS], r[SUS_MAX_UNKNOWNS];
    int perm[SUS_MAX_UNKNOWNS];
    if (n > SUS_MAX_UNKNOWNS) /* newton.h's bound, for the compiler's unrolled loops */
        __builtin_unreachable();
    row_norms(J, n, r);
#pragma GCC unroll 8
    for (int i = 0; i < n; i++)
        b[i] = g[i];
    const double sign = lu_factor(n, J, b, perm);
    double d = sign, p = 1.0;
#pragma GCC unroll 8
    for (int k = 0; k < n; k++)
        d *= J[k * n + k], p *= r[k];
    const double bound = 4.0 * n * SUS_U * p;
    *det = d;
    if (!(in_range(d) && in_range(bound) && fabs(d) > bound) &&
        sus_step_linear_singular(n, J, perm, sign, r, det))
        return -1;
#pragma GCC unroll 8
    for (int i = n - 1; i >= 0; i--) {
        double s = b[i];
#pragma GCC unroll 8
        for (int j = i + 1; j < n; j++)
            s -= J[i * n + j] * dx[j];
        dx[i] = s / J[i * n + i];
    }
    return 0;
}

/* dx = J^{-1} g: the 2 x 2 closed form and gauss4's 4 x 4 elimination here, so that they inline;
 * other n out of line. */
static inline int newton_linear(int n, double *J, const double *g, double *dx, double *det)
{
    if (n == 2)
        return newton_solve_2x2(J, g, dx, det);
    return n == 4 ? newton_solve_lu(4, J, g, dx, det) : sus_step_linear_solve(n, J, g, dx, det);
}

/* NaN when an entry is NaN (a max that drops NaN would call an overflowed residual 0). The max
 * is a comparison, not fmax: no NaN reaches it, so it is fmax's value without fmax's call. */
static inline double inf_norm(const double *v, int n)
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
static inline void copy_n(double *to, const double *from, int n)
{
    if (n == 2) {
        to[0] = from[0], to[1] = from[1];
        return;
    }
    for (int i = 0; i < n; i++)
        to[i] = from[i];
}

/* Records the residual at the accepted x. */
static inline void fn_final(sus_residual_fn G, int n, const sus_model *m, double eps,
                            const double w[2], const double *x, sus_stepper_stats *st)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS];
    G(m, eps, w, x, g, J, &st->scale);
    st->residual = inf_norm(g, n);
}

typedef struct {
    double x[SUS_MAX_UNKNOWNS], residual, scale;
} newton_point;

static inline void keep(newton_point *p, const double *x, int n, double residual, double scale)
{
    copy_n(p->x, x, n);
    p->residual = residual;
    p->scale = scale;
}

static inline void restore(const newton_point *p, double *x, int n, sus_stepper_stats *st)
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
static inline int decide(newton_state *s, double *x, int n, sus_stepper_stats *st)
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

/* Always inlined: with G known where it is inlined, its residual inlines into the loop. */
static inline int newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                               const double w[2], const double *x0, double *x,
                               sus_stepper_stats *st, int maxit) __attribute__((always_inline));

/* (REGLOC): Newton on the step equation; the matrix it inverts is, for x = w^{k+1}, the
 * upper-left block of (REGLOC), and a singular one ends the step as a failure. Newton as
 * described in newton.h from x0 (which may be x), the iterates in x, at most maxit corrections. */
static inline int newton_solve(sus_residual_fn G, int n, const sus_model *m, double eps,
                               const double w[2], const double *x0, double *x,
                               sus_stepper_stats *st, int maxit)
{
    double g[SUS_MAX_UNKNOWNS], J[SUS_MAX_UNKNOWNS * SUS_MAX_UNKNOWNS], dx[SUS_MAX_UNKNOWNS];
    /* Field by field, not an initializer that zeroes both points' SUS_MAX_UNKNOWNS entries on every
     * solve. ok is read only after keep has filled it (polishing); best only by the stagnation
     * test, which needs a finite residual, and decide keeps the first finite one (below infinity)
     * before that test: its x is always filled before it is read; dx only after a solve. The n
     * entries each are zeroed all the same: inlined with n known, the compiler cannot see that. */
    newton_state s;
    s.prev = INFINITY, s.polishing = 0, s.maxit = maxit;
    s.ok.residual = INFINITY, s.ok.scale = 0.0;
    s.best.residual = INFINITY, s.best.scale = 0.0;
    for (int i = 0; i < n; i++)
        s.ok.x[i] = s.best.x[i] = dx[i] = 0.0;
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
            singular = newton_linear(n, J, g, dx, &st->det) != 0;
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

/* The scale of the unknowns (values of w or its increments) from w: the largest |x| on w's energy
 * ellipse, sqrt(2 E(w) / lambda_min(I_m)) (the steps keep E, or nearly), and at least |w|_inf. A
 * near-singular I_m stretches the ellipse by cond(I_m)^(1/2), and the roots with it. */
static inline double unknowns_scale(const sus_model *m, const double w[2])
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
static inline int within_jump(double moved, const sus_model *m, const double w[2])
{
    const double a = fabs(w[0]), b = fabs(w[1]), lo = a > b ? a : b;
    return moved <= BRANCH_JUMP * lo || moved <= BRANCH_JUMP * unknowns_scale(m, w);
}

/* |a - b|_inf over n entries; a NaN difference is dropped, as fmax would drop it. */
static inline double moved_by(const double *a, const double *b, int n)
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
static inline __attribute__((always_inline)) int stage(sus_residual_fn G, int n, const sus_model *m,
                                                       double e, const double w[2], double *xp,
                                                       sus_stepper_stats *st, int *its, int maxit)
{
    double x[SUS_MAX_UNKNOWNS];
    const int rc = newton_solve(G, n, m, e, w, xp, x, st, maxit);
    *its += st->iterations;
    if (rc != SUS_STEPPER_OK || !(st->det > 0.0) || !within_jump(moved_by(x, xp, n), m, w))
        return -1;
    copy_n(xp, x, n);
    return 0;
}

/* sus_step_newton_solve_branch (newton.h): Newton from guess(eps) within FAST_ITS, else the
 * branch by continuation. */
static inline __attribute__((always_inline)) int
newton_solve_branch(sus_residual_fn G, sus_guess_fn guess, int n, const sus_model *m, double eps,
                    const double w[2], double *x, sus_stepper_stats *st)
{
    int its = 0;
    guess(m, eps, w, x);
    if (stage(G, n, m, eps, w, x, st, &its, FAST_ITS) == 0)
        return SUS_STEPPER_OK;
    const int rc = sus_step_newton_branch(G, guess, n, m, eps, w, x, st, NULL);
    st->iterations += its;
    return rc;
}

/* sus_step_predict (implicit_step.h) without its checks of NULL: the explicit midpoint
 * prediction, inlined where a step's Newton is (the compositions start one every substep). */
NEWTON_INLINE void newton_predict(const sus_model *m, double eps, const double w[2], double x[2])
{
    double f[2], mid[2];
    sus_contdyn(m, w, f);
    mid[0] = w[0] + 0.5 * eps * f[0];
    mid[1] = w[1] + 0.5 * eps * f[1];
    sus_contdyn(m, mid, f);
    x[0] = w[0] + eps * f[0];
    x[1] = w[1] + eps * f[1];
}

/* An implicit w-step's Newton, inlined: w_next = (x1, x2, 0) with x the branch's solution of G = 0
 * in two unknowns from w. */
static inline __attribute__((always_inline)) int
newton_w_step(sus_residual_fn G, sus_guess_fn guess, const sus_model *m, double eps,
              const double w[3], double w_next[3], sus_stepper_stats *st)
{
    double x[2];
    const int status = newton_solve_branch(G, guess, 2, m, eps, w, x, st);
    w_next[0] = x[0], w_next[1] = x[1], w_next[2] = 0.0;
    return status;
}

#ifdef __cplusplus
}
#endif

#endif
