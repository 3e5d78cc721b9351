/* Small dense 3x3 helpers shared by the SO(3) tools and the integrators.
 * Matrices are row-major double[3][3]; everything is inline and allocation-free. */
#ifndef SUS_MAT3_H
#define SUS_MAT3_H

#include <math.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

static inline void sus_mat3_identity(double A[3][3])
{
    memset(A, 0, 9 * sizeof(double));
    A[0][0] = A[1][1] = A[2][2] = 1.0;
}

static inline void sus_mat3_copy(double D[3][3], const double A[3][3])
{
    memcpy(D, A, 9 * sizeof(double));
}

/* C = A B; C may not alias A or B. */
static inline void sus_mat3_mul(double C[3][3], const double A[3][3], const double B[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
}

/* C = A B^T; C may not alias A or B. */
static inline void sus_mat3_mul_bt(double C[3][3], const double A[3][3], const double B[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = A[i][0] * B[j][0] + A[i][1] * B[j][1] + A[i][2] * B[j][2];
}

/* C = A^T B; C may not alias A or B. */
static inline void sus_mat3_mul_at(double C[3][3], const double A[3][3], const double B[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[i][j] = A[0][i] * B[0][j] + A[1][i] * B[1][j] + A[2][i] * B[2][j];
}

static inline void sus_mat3_vec(double y[3], const double A[3][3], const double x[3])
{
    for (int i = 0; i < 3; i++)
        y[i] = A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
}

/* Frobenius norm, the "Euclidean metric for square matrices" of (Groudist). */
static inline double sus_mat3_frobenius(const double A[3][3])
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            s += A[i][j] * A[i][j];
    return sqrt(s);
}

/* |A - B| in the Frobenius norm. */
static inline double sus_mat3_dist(const double A[3][3], const double B[3][3])
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            s += (A[i][j] - B[i][j]) * (A[i][j] - B[i][j]);
    return sqrt(s);
}

static inline double sus_mat3_det(const double A[3][3])
{
    return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
           A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

/* Ainv = A^{-1} by cofactors; returns -1 (Ainv untouched) when det A is 0 or not a number. */
static inline int sus_mat3_inverse(const double A[3][3], double Ainv[3][3])
{
    const double d = sus_mat3_det(A);
    if (!(fabs(d) > 0.0))
        return -1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            Ainv[i][j] = (A[i1][j1] * A[i2][j2] - A[i1][j2] * A[i2][j1]) / d;
        }
    return 0;
}

static inline void sus_vec3_cross(double c[3], const double a[3], const double b[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double sus_vec3_norm(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

#ifdef __cplusplus
}
#endif

#endif
