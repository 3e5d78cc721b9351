#!/bin/sh
# suslov --tol's two ways to stop short of --time, each exit 3 with one line saying where:
# 1. The retries run out. Body I_m = I, (I31, I32) = (1.2, 0), w0 = (1.3e154, 0): E = 8.45e307 is
#    finite, and so is lambda along the motion, I31^2 w1 w2 <= 1.44 1.69e308 / 2 = 1.2e308 (the
#    input is valid), but the series' first term c_0 U_0 = I31 w1^2 (0, 1) is 2.03e308, which
#    overflows whatever the step; the estimate is never a number, so every retry is rejected and
#    the step fails after the bounded tries (step_taylor_adaptive.c's MAX_TRIES, 12).
#    T = 1e-140: the steady rotation, |w_inf| = 1.56e154, turns the body by 1.6e14 radians by
#    then, below the method's max_angle (a longer run is refused as bad input).
# 2. The step budget (SUSLOV_TOL_MAX_STEPS, 10^6) is spent: |w0| = 1.3e154 needs steps near
#    1e-163 (the tolerance is absolute), so T = 1e-140 (an angle of 1.3e14 radians) would take
#    about 1e23 steps (the timeout: without the budget this run would not end).
# Either way stdout keeps the rows before the failure and a last "# incomplete" line, and an
# --output file is left as it was (the convention of every exit-3 path, suslov --help, OUTPUT).
# Usage: test_cli_tol_failures.sh BUILD_DIR. Last line: "test_cli_tol_failures: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
one_line() { [ "$(wc -l <"$1")" -eq 1 ]; }
no_nan() { ! grep -qi 'nan\|inf' "$1"; }

"$S" --method taylor-adaptive --tol 1e-10 --time 1e-140 --inertia 1,0,0,0,1,0,1.2,0,1 --omega0 1.3e154,0 \
    >"$T/over.csv" 2>"$T/over.err"
rc=$?
check "retries run out: exit 3 (got $rc)" [ $rc -eq 3 ]
check "retries run out: one line on stderr" one_line "$T/over.err"
check "retries run out: it names step 1, t = 0 and the 12 tries" \
    grep -q 'step 1 (t = 0) failed: its error estimate was not a finite number .* after 12 tries' "$T/over.err"
check "retries run out: no NaN printed" no_nan "$T/over.err"
check "retries run out: the output holds row 0 and the incomplete line" \
    sh -c "grep -c '^0,0,1.2999999999999999e+154,0,0,' '$T/over.csv' | grep -qx 1 && tail -1 '$T/over.csv' | grep -q '^# incomplete'"

echo previous >"$T/kept.csv"
timeout 60 "$S" --method taylor-adaptive --tol 1e-10 --time 1e-140 --omega0 1.3e154,0 --every-time 1 \
    --output "$T/kept.csv" 2>"$T/kept.err"
rc_kept=$?
timeout 60 "$S" --method taylor-adaptive --tol 1e-10 --time 1e-140 --omega0 1.3e154,0 --every-time 1 \
    >"$T/long.csv" 2>"$T/long.err"
rc=$?
check "step budget: exit 3 (got $rc)" [ $rc -eq 3 ]
check "step budget: one line on stderr" one_line "$T/long.err"
check "step budget: it names the step, t and the limit" \
    grep -q 'stopped before step 1000001 at t = [0-9.e+-]*: a --tol run takes at most 1000000 steps' "$T/long.err"
check "step budget: the output ends with the incomplete line" sh -c "tail -1 '$T/long.csv' | grep -q '^# incomplete'"
check "step budget with --output: exit $rc_kept, the file left as it was ($(cat "$T/kept.err"))" \
    sh -c "test $rc_kept = 3 -a \"\$(cat '$T/kept.csv')\" = previous && grep -q 'is left as it was\$' '$T/kept.err'"
# the paper's body to T = 1e4 (the long run, a few thousand steps) stays far inside the budget
"$S" --method taylor-adaptive --tol 2.3e-16 --time 1e4 --every-time 1e4 --no-header >"$T/ok.csv"
rc=$?
check "T = 1e4 at the tightest tolerance ends normally (exit $rc)" [ $rc -eq 0 ]
done_tests test_cli_tol_failures
