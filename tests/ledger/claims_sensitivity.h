/* Figure 2's four statements over eps = 2^-3 .. 2^3, the bodies of tests/unit/bodies.h and
 * SUS_LAB_SENS_NSTATE initial states each (src/lab/sensitivity.h): the companion's sensitivity
 * table (sensitivity.tex beside the claims file), the regularity conditions (RegCond) and (REGLOC)
 * along every run the paper's steps allow, and the energy statement that theory decides. */
#ifndef SUSLOV_CLAIMS_SENSITIVITY_H
#define SUSLOV_CLAIMS_SENSITIVITY_H

/* tsv: the claims file; the table is written beside it, whole or not at all. */
void sensitivity_claims(const char *tsv);

#endif
