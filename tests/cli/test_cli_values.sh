#!/bin/sh
# Absolute values that `suslov` prints, against numbers worked out BY HAND below from the
# printed formulas of the paper (never from the code under test), for the paper's body
#   I = [[1, 0.1, 0.2], [0.1, 1, 0.2], [0.2, 0.1, 1]], w0 = (0.4, 0.5).
#
# Energy E(w) = 1/2 <I_m w, w> = 1/2 (w1^2 + 2 (0.1) w1 w2 + w2^2):
#   E(w0) = 1/2 (0.16 + 0.04 + 0.25) = 0.225.
# (LagMult) lambda(w) = w1 (I2i wi) - w2 (I1i wi)
#                       + (I3i wi)/|I_m| ((I32 I21 - I31 I22) w2 + (I32 I11 - I31 I12) w1),
#   |I_m| = 1 - 0.01 = 0.99, I32 I21 - I31 I22 = 0.01 - 0.2 = -0.19, I32 I11 - I31 I12 = 0.1 - 0.02 = 0.08:
#   lambda(w) = w1 (0.1 w1 + w2) - w2 (w1 + 0.1 w2) + (0.2 w1 + 0.1 w2) (0.08 w1 - 0.19 w2) / 0.99.
#   At w0: 0.4 (0.54) - 0.5 (0.45) = -0.009; c = 0.13, 0.08 (0.4) - 0.19 (0.5) = -0.063,
#   so lambda(w0) = -0.009 - 0.13 (0.063) / 0.99 = -(0.00891 + 0.00819) / 0.99 = -19/1100.
# The steady rotation w_inf: c(w) = 0.2 w1 + 0.1 w2 = 0, so w2 = -2 w1, on E = 0.225:
#   1/2 (1 - 0.4 + 4) w1^2 = 2.3 w1^2 = 0.225; lambda(w_inf) = w1 (0.1 w1 - 2 w1) + 2 w1 (w1 - 0.2 w1)
#   = -0.3 w1^2 = -0.3 (0.225 / 2.3) = -27/920 (either sign of w1).
# Usage: test_cli_values.sh BUILD_DIR. Last line: "test_cli_values: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
tmp=$T
result() { # result OK MESSAGE
    if [ "$1" = 1 ]; then pass=$((pass + 1)); echo "PASS $2"; else fail=$((fail + 1)); echo "FAIL $2"; fi
}
# near A B TOL: |A - B| <= TOL, A a printed number (NaN or missing fails)
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t) }' && echo 1 || echo 0; }

# Row 0 of every method: lambda(w0) = -19/1100 and E(w0) = 0.225. Both are sums of a few
# products of size <= 0.25: round-off a few u, so 1e-15.
for m in exact euler midpoint rk4 variational; do
    "$S" --no-header --method "$m" --eps 0.5 --steps 1 >"$tmp/$m.csv" 2>"$tmp/err" || true
    lam="" E="" # row 0's fields 6 and 7, read by the shell itself
    { read -r _ && IFS=, read -r _ _ _ _ _ lam E _; } <"$tmp/$m.csv"
    result "$(near "$lam" -0.017272727272727273 1e-15)" "$m: row 0 lambda = $lam, by hand -19/1100"
    result "$(near "$E" 0.225 1e-15)" "$m: row 0 energy = $E, by hand 0.225"
done

# Row 0 is w0 as given, for every method (exact included: not its closed form evaluated at
# t = 0, an ulp or so off), so the whole row, E and lambda from that w0, is one row for all.
for w0 in 0.4,0.5 1,1e-15; do
    want=$(awk -v w="$w0" 'BEGIN { split(w, x, ","); printf "0,0,%.17g,%.17g,0", x[1], x[2] }')
    rows=""
    for mo in exact:- $("$S" --method list | tail -n +3 | cut -f1,3 | tr '\t' :); do
        m=${mo%:*} args="--eps 0.5 --steps 1"
        [ "${mo#*:}" = tol ] && args="--tol 1e-10 --time 0.5" # a tolerance-driven method
        "$S" --no-header --method "$m" $args --omega0 "$w0" >"$tmp/row0.csv"
        r="" # row 0
        { read -r _ && read -r r; } <"$tmp/row0.csv"
        rows="$rows$r
"
    done
    distinct=$(printf '%s' "$rows" | sort -u | wc -l)
    first=$(printf '%s' "$rows" | head -1 | cut -d, -f1-5)
    result "$([ "$distinct" = 1 ] && [ "$first" = "$want" ] && echo 1 || echo 0)" \
        "w0 = ($w0): row 0 begins $want and is the same row for every method ($distinct distinct)"
done

# --method exact on [0, 60]: every row's lambda and energy against the formulas above at the
# printed w (terms <= 0.3; the printed 17 digits and the sums: 2e-15), and the energy conserved.
"$S" --no-header --method exact --eps 0.5 --time 60 >"$tmp/exact.csv" 2>"$tmp/err"
res=$(awk -F, 'NR > 1 {
        w1 = $3; w2 = $4
        lam = w1 * (0.1 * w1 + w2) - w2 * (w1 + 0.1 * w2) + (0.2 * w1 + 0.1 * w2) * (0.08 * w1 - 0.19 * w2) / 0.99
        E = 0.5 * (w1 * w1 + 0.2 * w1 * w2 + w2 * w2)
        dl = lam - $6; if (dl < 0) dl = -dl; if (dl > ml) ml = dl
        de = E - $7; if (de < 0) de = -de; if (de > me) me = de
        d0 = $7 - 0.225; if (d0 < 0) d0 = -d0; if (d0 > m0) m0 = d0
        n++
    } END { printf "%d %.3g %.3g %.3g\n", n, ml + 0, me + 0, m0 + 0 }' "$tmp/exact.csv")
set -- $res
result "$([ "$1" = 121 ] && echo 1 || echo 0)" "exact, eps 0.5, t in [0, 60]: $1 rows (121 expected)"
result "$(near "$2" 0 2e-15)" "exact: printed lambda = (LagMult) at the printed w, worst difference $2"
result "$(near "$3" 0 2e-15)" "exact: printed energy = 1/2 <I_m w, w> at the printed w, worst difference $3"
result "$(near "$4" 0 2e-15)" "exact: energy stays 0.225 (a first integral), worst difference $4"

# At t = 200 the exact w is e^{-200 k} ~ 3e-13 (k = 0.145) from w_inf; dlambda/dw ~ 1: 1e-11.
"$S" --no-header --method exact --eps 1 --steps 200 >"$tmp/exact200.csv" 2>"$tmp/err"
lam=$(tail -n 1 "$tmp/exact200.csv" | cut -d, -f6)
result "$(near "$lam" -0.029347826086956522 1e-11)" "exact: lambda(t = 200) = $lam, by hand lambda(w_inf) = -27/920"

# A motion whose rate k = r |v| / det L underflows (here 1e-360) is fixed to far below a rounding
# over any final time (exact.h): exit 0 and every row w = w0, lambda = 0 (c(w0) = 1e-360 is 0).
"$S" --no-header --method exact --eps 0.05 --steps 3 --inertia 1,0,0,0,1,0,1e-200,0,1 \
    --omega0 1e-160,0 >"$tmp/under.csv" 2>"$tmp/err"
rc=$?
bad=$(awk -F, 'NR > 1 && !($3 == 1e-160 && $4 == 0 && $6 == 0) { n++ } END { print n + 0 }' \
    "$tmp/under.csv")
rows=$(($(wc -l <"$tmp/under.csv") - 1))
result "$([ "$rc" = 0 ] && [ "$rows" = 4 ] && [ "$bad" = 0 ] && echo 1 || echo 0)" \
    "exact, k underflows (I31 = 1e-200, w0 = (1e-160, 0)): exit $rc, $rows rows (4), $bad not at w0"

# exact-attitude's lambda takes c(t) from the closed form too: on I_m = diag(1, 1e-12), I31, I32 =
# 8, 4 the motion is at once the steady rotation w2 = -2 w1 (c = 0), where (LagMult) is
# 2 w1^2 (1 - 1e-12); terms of size 4 rounded a few times: 1e-14 (c(w) at the rounded w, divided
# by |I_m| = 1e-12, was off by 4e-3).
"$S" --no-header --method exact-attitude --tol 1e-10 --time 1 --every-time 1 \
    --inertia 1,0,0,0,1e-12,0,8,4,1 --omega0 1,1 >"$tmp/ea_sing.csv" 2>"$tmp/err"
ea=$(tail -n 1 "$tmp/ea_sing.csv")
ea_w1=$(echo "$ea" | cut -d, -f3) ea_lam=$(echo "$ea" | cut -d, -f6)
ea_hand=$(awk -v a="$ea_w1" 'BEGIN { printf "%.17g", 2 * a * a * (1 - 1e-12) }')
result "$(near "$ea_lam" "$ea_hand" 1e-14)" \
    "exact-attitude, I_m = diag(1, 1e-12): lambda(1) = $ea_lam, by hand 2 w1^2 (1 - 1e-12) = $ea_hand"

# The explicit DSPs print lambda_{k+1} = lambda(w^{k+1}) by (Discretization): check each row.
for m in euler rk4 midpoint; do
    "$S" --no-header --method "$m" --eps 0.25 --steps 40 >"$tmp/$m.csv" 2>"$tmp/err"
    worst=$(awk -F, 'NR > 1 { w1 = $3; w2 = $4
        lam = w1 * (0.1 * w1 + w2) - w2 * (w1 + 0.1 * w2) + (0.2 * w1 + 0.1 * w2) * (0.08 * w1 - 0.19 * w2) / 0.99
        d = lam - $6; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g\n", m + 0 }' "$tmp/$m.csv")
    result "$(near "$worst" 0 2e-15)" "$m: printed lambda_k = (LagMult) at the printed w_k on every row, worst difference $worst"
done

# --every K: rows k = 0, K, 2K, ... and always the last step (the integrators and exact).
for m in rk4 exact; do
    "$S" --no-header --method $m --eps 0.1 --steps 10 --every 3 >"$tmp/every.csv" 2>"$tmp/err"
    ks=$(awk -F, 'NR > 1 { printf "%s ", $1 }' "$tmp/every.csv")
    result "$([ "$ks" = "0 3 6 9 10 " ] && echo 1 || echo 0)" "$m --steps 10 --every 3 writes rows k = $ks(expected 0 3 6 9 10)"
    dt=$(awk -F, 'NR > 1 { d = $2 - 0.1 * $1; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.3g\n", m + 0 }' "$tmp/every.csv")
    result "$(near "$dt" 0 1e-15)" "$m --every 3: each row at t = k eps, worst difference $dt"
done

# Row k does not depend on which rows are written: exact's reference attitude is carried on a
# grid of its own, not from one written row to the next (before t_s ~ 272 and across it).
for run in "--eps 0.1 --steps 100" "--eps 1 --steps 400"; do
    "$S" --no-header --method exact $run >"$tmp/all.csv"
    "$S" --no-header --method exact $run --every 7 >"$tmp/some.csv"
    differ=$(awk -F, 'NR == FNR { row[$1] = $0; next } FNR > 1 && row[$1] != $0 { n++ } END { print n + 0 }' \
        "$tmp/all.csv" "$tmp/some.csv")
    result "$([ "$differ" = 0 ] && echo 1 || echo 0)" \
        "exact $run --every 7: every row written equals that row of --every 1 ($differ differ)"
done

echo "test_cli_values: $pass passed, $fail failed"
[ "$fail" = 0 ]
