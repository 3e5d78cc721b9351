/* make bench's analysis of the timed points: the fastest point at an accuracy, the peers' lower
 * envelopes, the floor of our explicit methods (fewest steps x cost per step), and the verdicts
 * of the targets. which = 0 for the w error, 1 for the attitude error. */
#ifndef SUS_LAB_BENCH_FLOOR_H
#define SUS_LAB_BENCH_FLOOR_H

#include "bench.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double sec;
    int series, point; /* -1 when none */
} sus_lab_bench_best;

/* A peer on the full problem (any formulation, w alone included), a peer on the reduced one. */
int sus_lab_bench_is_peer(const sus_lab_bench_series *s);
int sus_lab_bench_is_reduced_peer(const sus_lab_bench_series *s);
int sus_lab_bench_is_ours_preserving(const sus_lab_bench_series *s);

/* The fastest point reaching error <= level among the series selected by want (sec = INFINITY
 * and series = -1 if none). */
sus_lab_bench_best sus_lab_bench_fastest(const sus_lab_bench *b, double level, int which,
                                         int (*want)(const sus_lab_bench_series *));

/* b->env[0] and b->env[1] (the full problem's peers), b->env[2] (the reduced problem's, attitude)
 * and b->env[3] (ours, attitude), from the timed points. */
void sus_lab_bench_envelopes(sus_lab_bench *b);

/* The floor at a level: the fewest steps any of our explicit structure-preserving methods needs
 * to reach it, times that method's measured cost per step; INFINITY when none reaches it. */
double sus_lab_bench_floor_seconds(const sus_lab_bench *b, double level, int which);

/* The comparisons at the accuracy levels: the attitude against the peers on the full problem and
 * against those on the reduced one (each with its targets), w against the full problem's peers
 * (information: no target, since the closed form gives w in one evaluation). */
typedef enum {
    SUS_LAB_BENCH_ATT_FULL = 0,
    SUS_LAB_BENCH_ATT_REDUCED = 1,
    SUS_LAB_BENCH_W_INFO = 2,
    SUS_LAB_BENCH_NCOMP = 3
} sus_lab_bench_comparison;

/* The verdict at accuracy level l: ours (the fastest preserving method) against the best peer. */
typedef struct {
    sus_lab_bench_best ours, peer;
    double floor; /* sus_lab_bench_floor_seconds, when ours reach the level */
    /* the peer's seconds over ours: 0 when ours do not reach it, inf when no peer does */
    double ratio;
    /* the same by the fastest rounds: each side's fastest point by its fastest round, over that
     * round's seconds. A second estimate of the ratio from the same run, with no threshold of
     * its own: where it falls on the other side of the target the verdict is undecided. */
    double ratio_fast;
    double target; /* NAN: information only */
    int pass;      /* ratio >= target */
    int decided;   /* ratio_fast gives the verdict pass gives (always, when there is no target) */
} sus_lab_bench_level;
sus_lab_bench_level sus_lab_bench_level_verdict(const sus_lab_bench *b, sus_lab_bench_comparison c,
                                                int l);
/* The verdict's word: "PASS", "MISS", "UNDECIDED" (the two estimates disagree) or "info". */
const char *sus_lab_bench_level_word(const sus_lab_bench_level *v);
/* "attitude", "attitude-reduced" or "omega": the comparison's name in the data files. */
const char *sus_lab_bench_comparison_name(sus_lab_bench_comparison c);

/* The per-step targets: GSL's rk4 step over ours, and an implicit step over our rk4's. */
double sus_lab_bench_rk4_speedup(const sus_lab_bench *b);
double sus_lab_bench_implicit_ratio(const sus_lab_bench *b, int m);
/* Whether the implicit step is held to its target (a composition's is not: many substeps). */
int sus_lab_bench_implicit_target(const sus_step_method *me);
/* 1 when the implicit step m costs at most SUS_LAB_BENCH_IMPLICIT_TARGET rk4 steps. */
int sus_lab_bench_implicit_step_pass(const sus_lab_bench *b, int m);
/* 1 when every implicit step held to its target passes it. */
int sus_lab_bench_implicit_pass(const sus_lab_bench *b);

#ifdef __cplusplus
}
#endif

#endif
