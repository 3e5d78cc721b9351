/* The attitude over the steady tail of the motion, R(t) = R(t*) exp((t - t*) w_inf^), in closed
 * form and to a few roundings however long the tail: the turn's angle is formed in two doubles,
 * from t - t* exactly (sus_steady_gap_lo) and |w_inf| to 106 bits (refattitude.h's
 * sus_refatt_steady_speed). In one double it would be off by u (t - t*) |w_inf|, an error growing
 * with t that the inputs, exact doubles, do not have. Used by the tolerance-driven methods,
 * whose tails are one step. */
#ifndef SUS_STEADY_TURN_H
#define SUS_STEADY_TURN_H

#ifdef __cplusplus
extern "C" {
#endif

/* What b - a rounded to d = fl(b - a) leaves out, b - a - d, exactly for b >= a >= 0 (Fast2Sum). */
double sus_steady_gap_lo(double b, double a, double d);

/* q <- q (x) exp(tau w_inf / 2) for tau + tau_lo the time turned: the axis w_inf / |w_inf| in
 * double (its error does not grow with tau), the angle (tau + tau_lo) speed, speed = |w_inf| as
 * speed[0] + speed[1], reduced modulo 2 pi to a few roundings whatever its size. */
void sus_steady_turn(const double w_inf[2], const double speed[2], double tau, double tau_lo,
                     double q[4]);

#ifdef __cplusplus
}
#endif

#endif
