/* The one list of methods. Every consumer (the suslov command, the convergence sweep and its
 * figure, the stability map, the bench, the claims ledger) iterates over it, so adding a method
 * is one stepper file plus one line in src/methods/registry.c (its SUS_STEP_METHODS list). What the
 * paper or theory says a method's orders are is NOT here: the ledger keeps that in its own table
 * (tests/ledger/expected_orders.c), so that no expected value comes from the code under test. */
#ifndef SUS_STEP_REGISTRY_H
#define SUS_STEP_REGISTRY_H

#include "reconstruct.h"
#include "stepper.h"

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A registered method: its stepper type (which says what the method is and does: orders, implicit
 * equation, stability function, energy, attitude, substeps, source file) and what the registry
 * adds. family is a display label only: no consumer decides anything from it. */
typedef struct {
    const sus_stepper_type *type;
    const char *family;    /* "paper DSP", "variational", "composition", ... */
    const char *paper_ref; /* \label of the statement it tests; NULL for an extension */
    sus_recon recon;       /* its default reconstruction */
    const char *about;     /* one line for --help */
} sus_step_method;

/* The fixed-step methods are 0 .. sus_step_method_count() - 1 (what every sweep over eps
 * iterates); the tolerance-driven ones (type->tol set) follow, up to sus_step_method_count_all().
 * Lookups by name or type, the names, --help and methods.tsv cover all. */
int sus_step_method_count(void);
int sus_step_method_count_all(void);
const sus_step_method *sus_step_method_get(int i); /* NULL outside 0 .. count_all - 1 */
const sus_step_method *sus_step_method_by_name(const char *name); /* NULL: no such name, or NULL */
/* The index of a method in the registry, or -1 (also for NULL): by name (for user input) and by
 * type. */
int sus_step_method_index(const char *name);
int sus_step_method_index_of(const sus_stepper_type *type);
/* "none", "matrix" or "quaternion": what a method's apply_full carries (stepper.h); "?" for a
 * value that is none of them. */
const char *sus_step_attitude_name(sus_attitude_form form);
/* How results of the method of type t run with reconstruction recon are labelled, from what the
 * type says of itself: "NAME + RECON" when it follows the reconstruction it is given
 * (follows_recon), else "NAME (FORM)" with the attitude form it carries (sus_step_attitude_name),
 * "NAME" when it carries none. Into buf, cut to len - 1 characters; returns buf. NULL (nothing
 * written) for a NULL buf or len 0; NULL and an empty buf for a NULL t or an unknown recon that
 * the label would name. */
const char *sus_step_method_label(const sus_stepper_type *t, sus_recon recon, char *buf,
                                  size_t len);
/* "euler|midpoint|..." into buf: the names for usage lines and error messages, cut to len - 1
 * characters. Returns buf, or NULL (nothing written) for a NULL buf or len 0; a NULL sep is "". */
const char *sus_step_method_names(char *buf, unsigned long len, const char *sep);
/* The registry as a table (build/methods.tsv): a header row, then one row per method with
 * name family order lambda_order implicit unknowns conserves_energy attitude follows_recon substeps
 * stability recon paper_ref source about. Returns 0, or -1 on a write error or a NULL fp. */
int sus_step_methods_write_tsv(FILE *fp);

#ifdef __cplusplus
}
#endif

#endif
