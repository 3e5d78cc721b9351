/* The sections of the claims program on the paper's own body (claims_consistency.c,
 * claims_multiplier.c, claims_preserve.c), and what they share, made once before they run
 * (claims.c): the body, its closed form, and the convergence sweep of the registered methods in
 * the paper's window. */
#ifndef SUSLOV_CLAIMS_PAPER_H
#define SUSLOV_CLAIMS_PAPER_H

#include "convergence.h"
#include "exact.h"
#include "model.h"

typedef struct {
    sus_model m;
    sus_exact ex;
    sus_lab_convergence conv;
} claims_paper;

/* The starts t_k of the local errors, in the transient (the motion settles on the steady
 * rotation within t ~ 5/k ~ 35); the error at eps is the largest over them. */
#define PAPER_NTK 5
extern const double PAPER_TK[PAPER_NTK];
#define PAPER_T_GLOBAL 10.0 /* the global errors' end */

/* ledger_keep_min's slots: the smallest SO(3) error that entered an order fit, global and local
 * (the reference attitude must be far more accurate than these). */
enum { CLAIMS_MIN_SO3_GLOBAL, CLAIMS_MIN_SO3_LOCAL };

/* Consistency orders of the paper's methods (the general-DSP proposition, Proposition 5.1,
 * 5.3, 4.1), local and global; (36) as printed; the multiplier with (36) corrected. */
void consistency_local_claims(const claims_paper *p);
void consistency_global_claims(const claims_paper *p);
void consistency_unreduced_claims(const claims_paper *p);
void consistency_multiplier_claims(const claims_paper *p);
void consistency_cayinver_claims(void);

/* Proposition 5.3's limit of the variational multiplier, lambda - O_0, on every body. */
void multiplier_limit_claims(const claims_paper *p);

/* The constraint and the group kept over 10^6 steps by one registered method, and the negative
 * controls that show the measurement can fail. */
void preserve_claims(const claims_paper *p, int method);
void preserve_control_claims(const claims_paper *p);

#endif
