/* SO(3) tools of Sections 4.1-4.2 and 5.5 of the paper: the hat map (Isom), the Cayley
 * retraction (caypart) with its trivialized derivative and inverse, (cayinver) as printed,
 * the exponential map, the distance (MetMat) and the orthogonality defect. */
#ifndef SUS_SO3_H
#define SUS_SO3_H

#ifdef __cplusplus
extern "C" {
#endif

void sus_so3_hat(const double w[3], double W[3][3]);
void sus_so3_vee(const double W[3][3], double w[3]);
void sus_so3_cay(const double w[3], double R[3][3]);
void sus_so3_cay_minus_identity(const double w[3], double D[3][3]);
void sus_so3_cay_inv(const double R[3][3], double w[3]);
void sus_so3_dcay(const double w[3], double D[3][3]);
void sus_so3_dcay_inv(const double w[3], double D[3][3]);
void sus_so3_cayinver_printed(double eps, const double w[2], double D[3][3]);
void sus_so3_exp_minus_identity(const double w[3], double D[3][3]);
void sus_so3_exp(const double w[3], double R[3][3]);
double sus_so3_dist(const double R1[3][3], const double R2[3][3]);
double sus_so3_orth_defect(const double R[3][3]);
/* sin t, cos t and sin t / t by the project's own reduction and polynomials (so3_trig.c): the
 * same bits in every build (CLI and WebAssembly), within about 2 u of the true values. */
void sus_so3_sincos(double t, double *s, double *c);
double sus_so3_sinc(double t);

#ifdef __cplusplus
}
#endif

#endif
