#!/bin/sh
# suslov --sweeps N: the midpoint rule's implicit equation solved by N fixed-point sweeps
# (Figure 2's readings), against values worked out by hand from (ContDyn) and (LagMult), and
# against Newton's solution, which the sweeps converge to.
# Paper's body, w0 = (0.4, 0.5): c = I31 w1 + I32 w2 = 0.13, (l1, l2) = (-w2 c, w1 c) =
# (-0.065, 0.052), I_m^-1 = [[1, -0.1], [-0.1, 1]] / 0.99, so f(w0) = (-0.0702, 0.0585) / 0.99.
# One sweep from x = w0 has its midpoint at w0: explicit Euler, w1 = w0 + eps f(w0), which at
# eps = 1 is (3.62, 6.15) / 11. lambda(w) as in test_cli_values.sh.
# Usage: test_cli_sweeps.sh BUILD_DIR. Last line: "test_cli_sweeps: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
# near A B TOL: |A - B| <= TOL, A a printed number (missing fails)
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t) }'; }

"$S" --no-header --method midpoint --sweeps 1 --eps 1 --steps 1 >"$T/s1.csv" 2>"$T/err"
row=$(sed -n 3p "$T/s1.csv")
w1=$(echo "$row" | cut -d, -f3) w2=$(echo "$row" | cut -d, -f4) lam=$(echo "$row" | cut -d, -f6)
lam_hand=$(awk -v a="$w1" -v b="$w2" 'BEGIN { printf "%.17g", a * (0.1 * a + b) - b * (a + 0.1 * b) \
    + (0.2 * a + 0.1 * b) * (0.08 * a - 0.19 * b) / 0.99 }')
# a few operations on numbers below 1: round-off a few u, so 1e-15
both_near() { near "$w1" 0.32909090909090909 1e-15 && near "$w2" 0.55909090909090909 1e-15; }
check "--sweeps 1, one step of eps 1: w = ($w1, $w2), by hand (3.62, 6.15)/11" both_near
check "--sweeps 1: lambda_1 = $lam, (LagMult) at w_1 by hand $lam_hand" near "$lam" "$lam_hand" 1e-15

# Eight sweeps at eps = 0.1 contract by about (eps/2) |Df| < 0.05 each: their fixed point is
# Newton's to far below round-off, so 10 steps agree with --method midpoint to a few u per step.
"$S" --no-header --method midpoint --sweeps 8 --eps 0.1 --steps 10 >"$T/s8.csv"
"$S" --no-header --method midpoint --eps 0.1 --steps 10 >"$T/newton.csv"
worst=$(paste -d, "$T/s8.csv" "$T/newton.csv" | awk -F, 'NR > 1 { for (c = 3; c <= 16; c++) {
    d = $c - $(c + 16); if (d < 0) d = -d; if (d > m) m = d } } END { printf "%.3g", m + 0 }')
check "--sweeps 8 at eps 0.1: every column of 10 steps within 1e-14 of Newton's midpoint ($worst)" \
    near "$worst" 0 1e-14

# bad input: one line, exit 2
for args in "--method rk4 --sweeps 2" "--method midpoint --sweeps 9" "--method midpoint --sweeps 0" \
            "--method exact --sweeps 1"; do
    # shellcheck disable=SC2086
    "$S" $args --eps 0.1 --steps 1 >"$T/out" 2>"$T/err"; rc=$?
    check "$args: exit 2 with one line ($(head -1 "$T/err"))" test "$rc" = 2 -a "$(wc -l <"$T/err")" = 1
done
done_tests test_cli_sweeps
