#include "quaternion.h"

#include <math.h>

void sus_quat_unit(const double q[4], double u[4])
{
    const double n = 1.0 / sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int i = 0; i < 4; i++)
        u[i] = q[i] * n;
}

/* R(s, v) = I + 2 s v^ + 2 v^ v^ for a unit quaternion, written out entry by entry. */
void sus_quat_unit_rotation(const double u[4], double R[3][3])
{
    const double s = u[0], x = u[1], y = u[2], z = u[3];
    R[0][0] = 1.0 - 2.0 * (y * y + z * z);
    R[0][1] = 2.0 * (x * y - s * z);
    R[0][2] = 2.0 * (x * z + s * y);
    R[1][0] = 2.0 * (x * y + s * z);
    R[1][1] = 1.0 - 2.0 * (x * x + z * z);
    R[1][2] = 2.0 * (y * z - s * x);
    R[2][0] = 2.0 * (x * z - s * y);
    R[2][1] = 2.0 * (y * z + s * x);
    R[2][2] = 1.0 - 2.0 * (x * x + y * y);
}

void sus_quat_rotation(const double q[4], double R[3][3])
{
    double u[4];
    sus_quat_unit(q, u);
    sus_quat_unit_rotation(u, R);
}

void sus_quat_from_rotation(const double R[3][3], double q[4])
{
    const double tr = R[0][0] + R[1][1] + R[2][2];
    int k = -1; /* -1: the trace is the largest */
    double best = tr;
    for (int i = 0; i < 3; i++)
        if (R[i][i] > best) {
            best = R[i][i];
            k = i;
        }
    if (k < 0) {
        const double r = sqrt(1.0 + tr), f = 0.5 / r;
        q[0] = 0.5 * r;
        q[1] = f * (R[2][1] - R[1][2]);
        q[2] = f * (R[0][2] - R[2][0]);
        q[3] = f * (R[1][0] - R[0][1]);
    } else {
        const int i = k, j = (k + 1) % 3, l = (k + 2) % 3;
        const double r = sqrt(1.0 + 2.0 * R[i][i] - tr), f = 0.5 / r;
        q[1 + i] = 0.5 * r;
        q[1 + j] = f * (R[j][i] + R[i][j]);
        q[1 + l] = f * (R[l][i] + R[i][l]);
        q[0] = f * (R[l][j] - R[j][l]);
        if (q[0] < 0.0)
            for (int m = 0; m < 4; m++)
                q[m] = -q[m];
    }
}
