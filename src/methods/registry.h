/* The one list of methods. Every consumer (the suslov command, the convergence sweep and its
 * figure, the stability map, the bench, the claims ledger) iterates over it, so adding a method
 * is one stepper file plus one line in src/methods/registry.c. What the paper or theory says a method's
 * orders are is NOT here: the ledger keeps that in its own table (tests/ledger/expected_orders.c), so
 * that no expected value comes from the code under test. */
#ifndef SUSLOV_REGISTRY_H
#define SUSLOV_REGISTRY_H

#include "reconstruct.h"
#include "stepper.h"

typedef struct {
    const suslov_stepper_type *type;
    const char *family;             /* "paper DSP", "variational", "composition", ... */
    int implicit;                   /* 1 when a step solves an equation */
    /* The linear stability function R(z) of the w-step for real z = eps * eigenvalue (the
     * transverse eigenvalue at the attracting rotation is real, -k); NULL when the step has
     * none (the variational step is not a linear one-step map of f). */
    double (*stability)(double z);
    const char *paper_ref;          /* \label of the statement it tests; NULL for an extension */
    suslov_recon recon;             /* its default reconstruction */
    const char *about;              /* one line for --help */
} suslov_method;

int suslov_method_count(void);
const suslov_method *suslov_method_get(int i);          /* NULL past the end */
const suslov_method *suslov_method_by_name(const char *name);
/* The index of a method in the registry, or -1. */
int suslov_method_index(const char *name);
/* "euler|midpoint|..." into buf: the names for usage lines and error messages. */
const char *suslov_method_names(char *buf, unsigned long len, const char *sep);

#endif
