/* Unit quaternions q = (s, v) for attitudes: the rotation of q, and the product with a pure
 * quaternion (0, w) that the kinematics q' = 1/2 q (x) (0, w) needs (R' = R w^ for R = R(q)). */
#ifndef SUS_QUATERNION_H
#define SUS_QUATERNION_H

#include "so3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* p = q (x) (0, w): (-v.w, s w + v x w). */
static inline void sus_quat_mul_pure(double p[4], const double q[4], const double w[3])
{
    p[0] = -(q[1] * w[0] + q[2] * w[1] + q[3] * w[2]);
    p[1] = q[0] * w[0] + q[2] * w[2] - q[3] * w[1];
    p[2] = q[0] * w[1] + q[3] * w[0] - q[1] * w[2];
    p[3] = q[0] * w[2] + q[1] * w[1] - q[2] * w[0];
}

/* p = a (x) b (Hamilton product). */
static inline void sus_quat_mul(double p[4], const double a[4], const double b[4])
{
    p[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    p[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    p[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    p[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* The unit quaternion of a rotation R (Shepperd's method: the largest of 1 + tr R, 1 + 2 R_ii - tr
 * R under the square root, so no cancellation), sign fixed by q0 >= 0. */
void sus_quat_from_rotation(const double R[3][3], double q[4]);

/* R(q/|q|). */
void sus_quat_rotation(const double q[4], double R[3][3]);

/* q / |q|. */
void sus_quat_unit(const double q[4], double u[4]);

/* R(q) for a unit quaternion q (no normalisation). */
void sus_quat_unit_rotation(const double q[4], double R[3][3]);

#ifdef __cplusplus
}
#endif

#endif
