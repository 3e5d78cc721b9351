/* Exact products of doubles for the tests' yardsticks, by Dekker's algorithm with Veltkamp's
 * splitting (no fma, so independent of the library's sus_cross_diff): a b = p + e exactly, p = fl(a
 * b). With them a b - c d, the form of |I_m| and of O_0's coefficients, is known to far below a
 * rounding however much the two products cancel, so a near-singular I_m can be checked to its last
 * bit. Valid away from overflow and underflow (entries of size 2^-400 .. 2^400); the build's
 * -ffp-contract=off keeps the splitting's products and sums apart. */
#ifndef SUSLOV_CHECK_EXACT_H
#define SUSLOV_CHECK_EXACT_H

/* a = hi + lo with hi holding the upper 26 bits: Veltkamp's splitting by 2^27 + 1. */
static inline void check_split(double a, double *hi, double *lo)
{
    const double t = 134217729.0 * a;
    *hi = t - (t - a);
    *lo = a - *hi;
}

/* a b = *p + *e exactly (Dekker), *p = fl(a b). */
static inline void check_two_product(double a, double b, double *p, double *e)
{
    double ah, al, bh, bl;
    *p = a * b;
    check_split(a, &ah, &al);
    check_split(b, &bh, &bl);
    *e = ((ah * bh - *p) + ah * bl + al * bh) + al * bl;
}

/* a + b = *s + *e exactly (Knuth's two-sum), *s = fl(a + b). */
static inline void check_two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    const double bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* a b - c d = (p1 - p2) + (e1 - e2) with p1 - p2 = s + t exactly: the only roundings are of the
 * small remainder t + e1 - e2 (two, each 2^-53 of a number at most 2^-52 (|a b| + |c d|)) and of
 * the final sum into long double, so the result is within 2^-64 |a b - c d| + 2^-104 (|a b| + |c
 * d|) of it. */
static inline long double check_cross_diff_exact(double a, double b, double c, double d)
{
    double p1, e1, p2, e2, s, t;
    check_two_product(a, b, &p1, &e1);
    check_two_product(c, d, &p2, &e2);
    check_two_sum(p1, -p2, &s, &t);
    return (long double)s + (long double)((t + e1) - e2);
}

#endif
