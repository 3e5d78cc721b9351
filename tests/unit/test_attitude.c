/* The attitude's contract (reconstruct.h), checked directly: the identity attitude is R = I with
 * lo = 0, and its quaternion is the unit quaternion (1, 0, 0, 0), the one a method carrying q
 * starts from. A q off unit length by a relative d is normalised away at the first step, so no
 * row a program prints moves by more than a rounding: it is checked here, where it is exact. */
#include "check.h"
#include "quaternion.h"
#include "reconstruct.h"

#include <math.h>
#include <string.h>

static void identity_checks(void)
{
    sus_attitude a;
    memset(&a, 0x7f, sizeof a);  /* no field may keep what was there before */
    sus_attitude_identity(&a);
    double R[3][3], q[4];
    sus_attitude_get(&a, R);
    sus_quat_of_attitude(&a, q);
    int off = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            off += a.hi[i][j] != (i == j) || a.lo[i][j] != 0.0 || R[i][j] != (i == j);
    CHECK(off == 0, "the identity attitude: R = hi + lo = I, lo = 0 exactly (%d entries off)", off);
    CHECK(a.has_q && q[0] == 1.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 0.0,
          "the identity attitude's quaternion is (1, 0, 0, 0) exactly: (%.17g, %g, %g, %g), has_q %d", q[0],
          q[1], q[2], q[3], a.has_q);
}

/* R = hi + lo (reconstruct.h): lo holds the compensated sum's low parts. Here each is a few
 * ulps of its hi entry, so that hi + lo and hi - lo are exact and differ: sus_attitude_get must
 * return hi + lo bit for bit. */
static void sum_checks(void)
{
    sus_attitude a;
    sus_attitude_identity(&a);
    a.has_q = 0;
    int off = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            a.hi[i][j] = (i == j) ? 0.75 : 0.5 - 0.25 * j;
            a.lo[i][j] = ldexp(1.0 + i + 3 * j, -52);  /* nine different small parts */
        }
    double R[3][3];
    sus_attitude_get(&a, R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            off += R[i][j] != a.hi[i][j] + a.lo[i][j];
    CHECK(off == 0, "R = hi + lo, entry by entry (%d entries off)", off);
}

int main(void)
{
    identity_checks();
    sum_checks();
    return check_summary("test_attitude");
}
