/* The attitude over the steady tail of the motion, R(t) = R(t*) exp((t - t*) w_inf^), in closed
 * form and to a few roundings however long the tail: the turn's angle is formed in two doubles,
 * from t - t* exactly and |w_inf| in two doubles (sus_steady_speed). In one
 * double it would be off by u (t - t*) |w_inf|, an error growing with t that the inputs, exact
 * doubles, do not have. Used by the tolerance-driven methods, whose tails are one step. */
#ifndef SUS_STEADY_TURN_H
#define SUS_STEADY_TURN_H

#include "exact.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The angle's error is a few 2^-104 of it (the speed's two-double rounding, times its condition,
 * sus_steady_speed; 2 pi's and the product's, 2^-106 each): below 2^50 radians that is still a
 * few roundings of 2^-53 (u/2) each, the accuracy the methods' tails promise. The methods'
 * max_angle (stepper.h): sus_run_tol refuses longer runs. */
#define SUS_STEADY_TURN_MAX_ANGLE 0x1p50

/* |w_inf|, the speed of the steady rotation the motion of ex tends to (|w0| for a motion that
 * stays where it is), as speed[0] + speed[1], formed in double-double arithmetic from the inputs:
 * |w_inf| = |d| sqrt(<I_m w0, w0> / <I_m d, d>), d = (-I32, I31). Its relative error is a few
 * 2^-104 times the size of the quadratic forms' terms over their values (up to cond(I_m)), so an
 * angle turned at that speed is right to a rounding while that error times the angle stays below
 * 2^-53. Independent of the reference attitude's own speed (refattitude.c, 113 bits), which the
 * tests hold both methods to. */
void sus_steady_speed(const sus_exact *ex, double speed[2]);

/* q <- q (x) exp((t - t0) w_inf / 2), t >= t0 >= 0: the axis w_inf / |w_inf| in double (its error
 * does not grow with t - t0), the angle (t - t0) speed, speed = |w_inf| as speed[0] + speed[1],
 * with t - t0 taken exactly (Fast2Sum: its rounding kept as a second double) and the angle reduced
 * modulo 2 pi to a few roundings whatever its size. */
void sus_steady_turn(const double w_inf[2], const double speed[2], double t0, double t,
                     double q[4]);

#ifdef __cplusplus
}
#endif

#endif
