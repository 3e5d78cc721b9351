/* The settings of ours that the recorded bench run recommends at each accuracy level
 * (data/bench-recorded/what_to_use.tsv), run again by suslov on the paper's body to t = 50 and
 * checked at that level. */
#ifndef SUSLOV_CLAIMS_RECOMMENDED_H
#define SUSLOV_CLAIMS_RECOMMENDED_H

#include "model.h"

/* The file the lines read, relative to the checkout (the ledger runs from its top, as make does).
 */
#define RECOMMENDED_TSV "data/bench-recorded/what_to_use.tsv"

/* The suslov program the lines run: the one beside the claims program, whose argv[0] this is
 * (both are built into one directory). Call before recommended_claims. */
void recommended_program(const char *argv0);

/* One line per setting (and one on E for a fixed-step series), against w_T = w(50) from the
 * closed form and R_T = R(50) from the reference, at w0 the paper's start on the body m. */
void recommended_claims(const sus_model *m, const double w0[2], const double w_T[2],
                        const double R_T[3][3]);

#endif
