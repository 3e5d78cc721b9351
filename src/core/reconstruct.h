/* Discrete reconstruction, step 3 of Algorithm (algo): R_{k+1} = R_k cay(eps w^_k), and the
 * symmetric variant cayley-mid (our extension): R_{k+1} = R_k cay(eps (w^_k + w^_{k+1})/2), and
 * exp-mid (our extension): R_{k+1} = R_k exp(eps (w^_k + w^_{k+1})/2), Rodrigues' formula. Both
 * symmetric ones are second order alone and keep the order of a symmetric composition; exp's
 * error constant is the smaller (it is exact when w is constant over the step).
 *
 * The product is accumulated as R_{k+1} = R_k + R_k (cay - I) with R_k carried as an unevaluated
 * sum hi + lo (Kahan's compensated summation). In exact arithmetic this is the same map; in
 * floating point the plain product R_k cay drifts off SO(3) linearly, by ~u/2 per step
 * (1e-10 after 10^6 steps: correlated rounding once the motion is a steady rotation), while
 * the compensated sum stays near 1e-14. The claims ledger measures both. */
#ifndef SUS_RECONSTRUCT_H
#define SUS_RECONSTRUCT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    SUS_RECON_CAYLEY = 0,
    SUS_RECON_CAYLEY_MID = 1,
    SUS_RECON_EXP_MID = 2,
    SUS_RECON_COUNT
} sus_recon;

/* The --reconstruct names and one-line descriptions, indexed by sus_recon. */
extern const char *const SUS_RECON_NAMES[SUS_RECON_COUNT];
extern const char *const SUS_RECON_ABOUT[SUS_RECON_COUNT];

typedef struct {
    double hi[3][3], lo[3][3]; /* R = hi + lo */
    /* A unit quaternion of R, valid when has_q: methods that carry the attitude as a quaternion
     * (quaternion.h) keep it here so that it is not recovered from R at every step. The matrix
     * reconstructions clear has_q. */
    double q[4];
    int has_q;
    /* hi and lo are not built yet: R is R(q), made when asked for (sus_attitude_get), so a
     * method that carries q builds no matrix on the steps whose rows nobody reads. */
    int r_stale;
} sus_attitude;

/* A method that carries its attitude as a quaternion (the Taylor methods, the compositions):
 * q of R_k, and R_{k+1} = R(q/|q|) written back (lo = 0). The orthogonality defect is then one
 * rounding of R(q), whatever the number of steps: nothing accumulates. For the methods' steps,
 * which pass their own attitude: no argument checks. */
void sus_quat_of_attitude(const sus_attitude *a, double q[4]);
void sus_quat_to_attitude(const double q[4], sus_attitude *a);

/* Every function below writes nothing where its output is NULL, and NaN where an input is NULL or
 * kind is not a sus_recon (an attitude so advanced is NaN, which the runs report as a blow-up). */
void sus_attitude_identity(sus_attitude *a);
void sus_attitude_get(const sus_attitude *a, double R[3][3]);

/* (algo), step 3: advances a from R_k to R_{k+1}. */
void sus_reconstruct(sus_recon kind, double eps, sus_attitude *a, const double w[3],
                     const double w_next[3]);
/* The same map on a quaternion q of R_k: q <- q (x) dq with dq the quaternion of cay(xi^)
 * ((1, xi/2) normalised) or of exp(xi^) ((cos |xi|/2, sin(|xi|/2) xi/|xi|)). Methods that
 * carry their attitude as a quaternion through many substeps use it (src/methods/composition.c). */
void sus_reconstruct_quat(sus_recon kind, double eps, double q[4], const double w[3],
                          const double w_next[3]);
/* R <- R (I + D), accumulated with the compensated sum above: D = tau(xi) - I, small. */
void sus_attitude_increment(sus_attitude *a, const double D[3][3]);
/* 0 with *kind set, or -1 for an unknown name or a NULL argument. */
int sus_recon_by_name(const char *name, sus_recon *kind);

#ifdef __cplusplus
}
#endif

#endif
