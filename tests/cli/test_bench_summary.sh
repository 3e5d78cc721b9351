#!/bin/sh
# tools/bench_summary.sh on made-up bench runs: the misses for the software note (misses mode:
# every MISS and UNDECIDED line of bench.txt said short, with its measured value and its target,
# LaTeX's special characters escaped in a line of a shape it does not know, and the count of the
# targets),
# and the Markdown summary's tables printing each ratio as the TSV files hold it (not rounded a
# second time: 10.3 as 10.3, not 10.30). Needs no build.
# Usage: test_bench_summary.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S=tools/bench_summary.sh
mkdir -p "$T/m" "$T/md"
# one MISS line of every shape src/render/bench_report.c and tools/bench.sh print, with PASS,
# info, (peer) and CHECK lines that are no target or no miss
cat >"$T/m/bench.txt" <<'TXT'
Targets:
  PASS our rk4 step is >= 5x faster than GSL rk4 through gsl_odeiv2_driver_apply_fixed_step: 5.3x
  MISS our rk4 step is >= 5x faster than GSL rk4 through gsl_odeiv2_driver_apply_fixed_step: 4.8x
  MISS an implicit midpoint step costs <= 3x our rk4 step: 3.05x (1.89 Newton iterations per step)
  MISS the driver adds <= 10 % to a taylor8 step (114.8 ns in a bare loop, fastest rounds): +12.4 %
  MISS the driver (sus_run_tol, one row) adds <= 10 % to a tolerance-driven run to t = 50, summed over its TOL grid (fastest rounds): +11.5 %
  MISS attitude accuracy 1e-04: no floor (none of our explicit methods reaches it)
  MISS attitude accuracy 1e-06: our best 2.67e-06 s is within 1.15x of the floor 2.18e-06 s (an estimate: fewest steps x cost per step, timed apart): 1.22x
  MISS attitude accuracy 1e-04 at t = 50: ours 1.96e-06 s (taylor10 (quaternion), eps 4.167) vs best peer on the full problem 2.22e-06 s (GSL rkck (w,q) driver h0 1, tol 0.00032, its timed runs' error 6.1e-05): 1.13x (target 1.8x; fastest rounds 1.16x)
  UNDECIDED attitude accuracy 1e-10 at t = 50: ours 5.06e-06 s (taylor-adaptive (quaternion), tol 1e-10) vs best peer on the full problem 1.57e-05 s (GSL rk8pd (w,q) evolve abs h0 1, tol 1e-10, its timed runs' error 8.8e-11): 3.10x (target 3x; fastest rounds 2.95x)
  MISS attitude (reduced problem) accuracy 1e-14 at t = 50: ours 7.07e-06 s (taylor-adaptive (quaternion), tol 5.623e-14) vs best peer on the reduced problem 8.6e-06 s (Boost rkf78 reduced (q) abs, tol 3.2e-15, its timed runs' error 8.3e-15): 1.21x (target 1.5x; fastest rounds 1.19x)
  MISS attitude (reduced problem) accuracy 1e-12 at t = 50: none of our structure-preserving methods reaches it
  info w accuracy 1e-04 at t = 50: ours 6.09e-07 s (taylor8 (w only), eps 5.556) vs best peer 7.93e-07 s (GSL rkck (w) evolve h0 1, tol 0.00056, its timed runs' error 9.7e-05): 1.30x (no target: the closed form gives w(t) in 28.3 ns)
  MISS T = 1e4, comp6-kl + exp-mid: |R^T R - I| = 2.7e-13, |E - E0| = 4e-12, |w3| = 0 (targets 1e-14, 1e-13, 0); |E - E0| by T/2: 2e-12
  (peer) T = 1e4, GSL rk8pd (w,R) driver h0 0.001 at the tolerance reaching 1e-10 at t = 50: |R^T R - I| = 2.6e-08, |E - E0| = 1.3e-15
  MISS T = 1e4 at equal error (attitude <= 1e-09): ours taylor-adaptive (quaternion) is 18.50x faster than GSL rk8pd (w,q) (target 20x)
  MISS T = 1e4 at equal error: none of our explicit own-attitude methods reaches attitude 1e-09 there
  MISS cost at T = 1e6 <= 1.5x the cost at T = 1e4: taylor-adaptive (quaternion) (tol 1.778e-10) 2.1e-05 s against 1.27e-05 s: 1.65x
  CHECK ok: 14 of 14 "ours" rows re-run with build/suslov give the same results (suslov_args in bench.csv, longruns.tsv)
Wall-clock targets (this machine, as loaded as it was):
  MISS figure_stability on 2 cores in 10.9 s (target <= 10 s)
  MISS figure_stability on 2 cores in nan s (target <= 10 s)
  MISS make -j2 figures (every figure program and the animation, built, two at a time) in 26.1 s (target <= 25 s)
  MISS make check (the tests and the claims ledger run afresh, built; the median of 3 runs, 39.8 to 43.0 s) in 41.0 s (target <= 40 s)
  MISS make check (the tests and the claims ledger run afresh, built): a test failed after 12.0 s, so there is no time to judge (the logs: build/tests/)
  MISS a target of a new_shape: 50% & #1 {x} ~^\
TXT
# what each of them must read, in order
cat >"$T/m/want" <<'TXT'
our RK4 step, $4.8$ times as fast as GSL's \cmd{rk4} (target~$\ge 5$)
the \cmd{midpoint} step, $3.05$ RK4 steps (target~$\le 3$)
the driver on a \cmd{taylor8} step, $+12.4\,\%$ (target~$\le 10\,\%$)
the driver on tolerance-driven runs, $+11.5\,\%$ (target~$\le 10\,\%$)
the attitude to $10^{-4}$: none of our explicit methods reaches it
our best time to the attitude to $10^{-6}$, $1.22$ times the floor (target~$\le 1.15$)
the attitude to $10^{-4}$, $1.13$ times as fast as the best peer, $1.16$ by the fastest rounds (target~$\ge 1.8$)
the attitude to $10^{-14}$ on the reduced problem, $1.21$ times as fast as the best peer, $1.19$ by the fastest rounds (target~$\ge 1.5$)
the attitude to $10^{-12}$ on the reduced problem: none of our structure-preserving methods reaches it
\cmd{comp6-kl + exp-mid} at $T=10^{4}$, $|R^{\mathsf T}R-I|=2.7\times10^{-13}$ (target~$\le 10^{-14}$) and $|E-E_0|=4\times10^{-12}$ (target~$\le 10^{-13}$), $2\times10^{-12}$ already by $T/2$
at $T=10^{4}$ and equal attitude error, \cmd{taylor-adaptive (quaternion)} $18.50$ times as fast as \cmd{rk8pd} (target~$\ge 20$)
at $T=10^{4}$, none of our explicit own-attitude methods reaches the attitude error $10^{-9}$
the cost to $T=10^{6}$, $1.65$ times that to $T=10^{4}$ (target~$\le 1.5$)
\cmd{figure\_stability} on $2$ cores, $10.9$\,s (target~$\le 10$\,s)
\cmd{figure\_stability} on $2$ cores did not finish (target~$\le 10$\,s)
\cmd{make -j2 figures}, $26.1$\,s (target~$\le 25$\,s)
\cmd{make check}, $41.0$\,s (target~$\le 40$\,s)
\cmd{make check}: a test failed, so no time to judge
a target of a new\_shape: 50\% \& \#1 \{x\} \textasciitilde{}\textasciicircum{}\textbackslash{}
TXT
sh "$S" "$T/m" misses >"$T/m/out" 2>"$T/m/err"
rc=$?
check "misses: exit $rc (0), nothing on stderr" test "$rc" = 0 -a ! -s "$T/m/err"
check "misses: 21 targets (the PASS, MISS and UNDECIDED lines), 19 misses, 1 undecided" \
    sh -c "grep -qx '\\\\newcommand{\\\\BenchTargetCount}{21}' '$T/m/out' &&
           grep -qx '\\\\newcommand{\\\\BenchMissCount}{19}' '$T/m/out' &&
           grep -qx '\\\\newcommand{\\\\BenchUndecidedCount}{1}' '$T/m/out'"
check "misses: the undecided line said short, with both estimates and its target" \
    grep -qxF '\newcommand{\BenchUndecided}{the attitude to $10^{-10}$, $3.10$ times as fast as the best peer, $2.95$ by the fastest rounds (target~$\ge 3$)}' "$T/m/out"
sed -n 's/^\\newcommand{\\BenchMisses}{\(.*\)}$/\1/p' "$T/m/out" | sed 's/; /\n/g' >"$T/m/got"
check "misses: each miss said short, with its value and its target ($(diff "$T/m/want" "$T/m/got" | head -3 | tr '\n' ' '))" \
    cmp -s "$T/m/want" "$T/m/got"
printf 'Targets:\n  PASS a: 1x\n' >"$T/m/bench.txt"
sh "$S" "$T/m" misses >"$T/m/out"
check "misses: a run that misses nothing gives a count of 0 and an empty list" \
    sh -c "grep -qx '\\\\newcommand{\\\\BenchMissCount}{0}' '$T/m/out' &&
           grep -qx '\\\\newcommand{\\\\BenchMisses}{}' '$T/m/out'"
sh "$S" "$T/md" misses >"$T/m/out" 2>"$T/m/err"
rc=$?
check "misses without a bench.txt: exit $rc (2), one line, nothing on stdout" \
    test "$rc" = 2 -a "$(wc -l <"$T/m/err")" = 1 -a ! -s "$T/m/out"
# the recorded run: as many misses listed as it has MISS lines
R=data/bench-recorded
n=$(grep -c '^  MISS ' "$R/bench.txt")
sh "$S" "$R" misses >"$T/rec"
got=$(sed -n 's/^\\newcommand{\\BenchMisses}{\(.*\)}$/\1/p' "$T/rec" | sed 's/; /\n/g' | grep -c .)
check "the recorded run: its $n MISS lines counted and listed ($got)" \
    sh -c "grep -qx '\\\\newcommand{\\\\BenchMissCount}{$n}' '$T/rec' && test '$got' = '$n'"
# tex mode: machine.txt's text through the one escaper (tools/latex.sh, tools/latex_esc.awk) that
# the misses use too: every special character escaped once (the braces of \textbackslash{} are
# braces), the same as the misses' line of an unknown shape above
printf '%s\n' 'date: 2000-01-01' 'commit: 0123456789abcdef' 'cpu: 50% & #1 {x} ~^\ a_b $' \
    'cores: 2' 'note: run_1' >"$T/md/machine.txt"
sh "$S" "$T/md" tex >"$T/md/tex" 2>"$T/md/err"
rc=$?
check "tex: exit $rc (0); \\BenchRunCPU and \\BenchRunNote escaped ($(grep -E 'CPU|Note' "$T/md/tex" | tr '\n' ' '))" \
    sh -c "test $rc = 0 -a ! -s '$T/md/err' &&
        grep -qxF '\\newcommand{\\BenchRunCPU}{50\\% \\& \\#1 \\{x\\} \\textasciitilde{}\\textasciicircum{}\\textbackslash{} a\\_b \\\$}' '$T/md/tex' &&
        grep -qxF '\\newcommand{\\BenchRunNote}{; run\\_1}' '$T/md/tex'"
# summary.md: the ratios as the TSV files hold them
printf 'date: d\ncommit: c\n' >"$T/md/machine.txt"
printf 'Targets:\n' >"$T/md/bench.txt"
printf 'section,method\n' >"$T/md/bench.csv"
tab=$(printf '\t')
{
    echo "quantity${tab}level${tab}ours${tab}ours_seconds${tab}peer${tab}peer_parameter_name${tab}peer_parameter${tab}peer_seconds${tab}ratio${tab}target${tab}verdict${tab}suslov_args"
    echo "attitude-reduced${tab}1e-14${tab}ours${tab}7.069e-06${tab}peer${tab}tol${tab}3.2e-15${tab}7.312e-05${tab}10.3${tab}1.5${tab}PASS${tab}--method taylor8"
    echo "attitude-reduced${tab}1e-04${tab}ours${tab}1.91e-06${tab}fixed peer${tab}eps${tab}2.2${tab}2.304e-06${tab}1.21${tab}1.5${tab}MISS${tab}--method taylor10"
} >"$T/md/what_to_use.tsv"
{
    echo "row${tab}ours${tab}parameter_name${tab}parameter${tab}T${tab}seconds${tab}attitude_error${tab}peer${tab}peer_tol${tab}peer_seconds${tab}peer_error${tab}ratio${tab}target${tab}verdict${tab}reduced_tol${tab}reduced_seconds${tab}reduced_error${tab}reduced_ratio${tab}suslov_args"
    echo "equal-error${tab}ours${tab}tol${tab}1.778e-10${tab}10000${tab}1.666e-05${tab}1.05e-10${tab}rk8pd${tab}3.2e-12${tab}0.004152${tab}7.54e-10${tab}249.14${tab}20${tab}PASS${tab}3.2e-12${tab}0.007298${tab}9.06e-10${tab}437.90${tab}--method x"
} >"$T/md/longruns.tsv"
sh "$S" "$T/md" md >"$T/md/out" 2>"$T/md/err"
check "summary.md prints the ratios as the TSV holds them (10.3, not 10.30; 249.14, 437.90), each peer's parameter by its name (tol, eps), and the long run's numbers too (1.666e-05, 1.05e-10, 0.004152)" \
    sh -c "grep -q '| 10.3× |' '$T/md/out' && grep -q '| 249.14× |' '$T/md/out' &&
           grep -q '| peer, tol 3.2e-15 |' '$T/md/out' && grep -q '| fixed peer, eps 2.2 |' '$T/md/out' &&
           grep -q '| 437.90× |' '$T/md/out' && grep -q '| 1.666e-05 | 1.05e-10 | 3.2e-12, 0.004152 |' '$T/md/out'"
done_tests test_bench_summary
