#!/bin/sh
# The suslov command's interface: CSV format, rows, exit statuses, all-or-nothing output,
# solver failures, constant memory. Usage: test_cli.sh BUILD_DIR
set -u
B=${1:-build}
S="$B/suslov"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { echo "PASS $*"; pass=$((pass + 1)); }
ko() { echo "FAIL $*"; fail=$((fail + 1)); }
check() { # check DESCRIPTION COMMAND...
    d=$1; shift
    if "$@"; then ok "$d"; else ko "$d"; fi
}
HEADER='k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33'

# --help documents every option and exits 0
"$S" --help >"$T/help" 2>&1; rc=$?
missing=""
for o in --method --eps --steps --time --omega0 --inertia --reconstruct --every --output --help \
         exact euler midpoint rk4 variational cayley cayley-mid; do
    grep -q -- "$o" "$T/help" || missing="$missing $o"
done
check "--help exits 0 and documents every option and value${missing:+ (missing:$missing)}" \
    test "$rc" = 0 -a -z "$missing"

# exact header, row count with --every and the last row, %.17g numbers, 16 fields
for m in exact euler midpoint rk4 variational; do
    "$S" --method $m --eps 0.1 --steps 25 --every 10 >"$T/$m.csv" 2>"$T/err"; rc=$?
    rows=$(tail -n +2 "$T/$m.csv" | cut -d, -f1 | tr '\n' ' ')
    nf=$(awk -F, 'NR > 1 && NF != 16 { bad++ } END { print bad + 0 }' "$T/$m.csv")
    check "$m: exit 0, exact header, rows k = 0 10 20 25, 16 fields" \
        test "$rc" = 0 -a "$(head -1 "$T/$m.csv")" = "$HEADER" -a "$rows" = "0 10 20 25 " -a "$nf" = 0
done
check "numbers are printed with %.17g (t = 2.5 at k = 25, w1(0) = 0.40000000000000002)" \
    grep -q '^25,2.5,' "$T/rk4.csv"
check "row 0 of a DSP has w1 = 0.40000000000000002, R = I" \
    grep -q '^0,0,0.40000000000000002,0.5,0,.*,1,0,0,0,1,0,0,0,1$' "$T/midpoint.csv"

# --time T gives N = round(T/H)
"$S" --method euler --eps 0.3 --time 1 | tail -1 | cut -d, -f1 >"$T/n"
check "--time 1 --eps 0.3 gives N = round(3.33) = 3 steps" test "$(cat "$T/n")" = 3

# deterministic: the same command gives the same bytes
"$S" --method variational --eps 0.5 --steps 200 --reconstruct cayley-mid >"$T/a.csv"
"$S" --method variational --eps 0.5 --steps 200 --reconstruct cayley-mid >"$T/b.csv"
check "the same command gives identical output" cmp -s "$T/a.csv" "$T/b.csv"

# bad input: one line "suslov: error: ...", exit 2, no output file created or truncated
echo "keep me" >"$T/keep.csv"
bad() { # bad DESCRIPTION ARGS...
    d=$1; shift
    rm -f "$T/new.csv"
    "$S" "$@" --output "$T/new.csv" >"$T/out" 2>"$T/err"; rc1=$?
    "$S" "$@" --output "$T/keep.csv" >/dev/null 2>&1; rc2=$?
    lines=$(wc -l <"$T/err")
    if [ "$rc1" = 2 ] && [ "$rc2" = 2 ] && [ "$lines" = 1 ] && grep -q '^suslov: error: ' "$T/err" &&
       [ ! -e "$T/new.csv" ] && [ "$(cat "$T/keep.csv")" = "keep me" ] && [ ! -s "$T/out" ]; then
        ok "bad input ($d): exit 2, one line: $(cat "$T/err")"
    else
        ko "bad input ($d): rc=$rc1/$rc2, $lines stderr lines: $(head -2 "$T/err")"
    fi
}
bad "unknown option" --method rk4 --eps 0.1 --steps 3 --frobnicate 2
bad "unknown method" --method leapfrog --eps 0.1 --steps 3
bad "malformed number" --method rk4 --eps 0.1x --steps 3
bad "H <= 0" --method rk4 --eps -1 --steps 3
bad "H not finite" --method rk4 --eps inf --steps 3
bad "H NaN" --method rk4 --eps nan --steps 3
bad "N <= 0" --method rk4 --eps 0.1 --steps 0
bad "N not an integer" --method rk4 --eps 0.1 --steps 2.5
bad "--time rounds to 0 steps" --method rk4 --eps 1 --time 0.2
bad "both --steps and --time" --method rk4 --eps 0.1 --steps 3 --time 1
bad "missing --eps" --method rk4 --steps 3
bad "non-symmetric I_m" --method rk4 --eps 0.1 --steps 3 --inertia 1,0.1,0.2,0.3,1,0.2,0.2,0.1,1
bad "indefinite I_m" --method rk4 --eps 0.1 --steps 3 --inertia 1,2,0,2,1,0,0,0,1
bad "non-finite inertia" --method rk4 --eps 0.1 --steps 3 --inertia 1,0.1,0.2,0.1,1,0.2,nan,0.1,1
bad "short --omega0" --method rk4 --eps 0.1 --steps 3 --omega0 0.4
bad "unknown reconstruction" --method rk4 --eps 0.1 --steps 3 --reconstruct exp

# a solver failure: exit 3, message names step, t, residual; the file keeps the rows before it
"$S" --method variational --eps 1000 --steps 10 --omega0 4,5 --output "$T/fail.csv" 2>"$T/err"; rc=$?
check "solver failure: exit 3 and the message names step 1, t = 1000 and the residual ($(cat "$T/err"))" \
    sh -c "test $rc = 3 && grep -q 'variational step 1 (t = 1000) failed' '$T/err' && grep -q 'residual' '$T/err'"
check "solver failure: the output file holds the header and row 0, complete" \
    sh -c "test \$(wc -l <'$T/fail.csv') = 2 && tail -1 '$T/fail.csv' | grep -q '^0,0,4,5,0,.*,1\$' && ! ls '$T'/fail.csv.tmp.* >/dev/null 2>&1"

# a failure after many good steps (from the stability map, src/stability.h: the variational
# step at h = eps k = 158, where the explicit predictor lands ~1e5 away and Newton runs out of
# iterations): every row before it is in the file, complete
"$S" --method variational --eps 1087.1941548935877 --steps 1000 --omega0 -0.37395729723339016,-0.52077483600674224 \
    --output "$T/late.csv" 2>"$T/err"; rc=$?
rows=$(tail -n +2 "$T/late.csv" | wc -l)
last=$(tail -1 "$T/late.csv" | cut -d, -f1)
nf=$(awk -F, 'NR > 1 && NF != 16 { bad++ } END { print bad + 0 }' "$T/late.csv")
check "late solver failure: exit 3, 'variational step 175' in the message, rows k = 0..174 complete ($(cat "$T/err"))" \
    sh -c "test $rc = 3 && grep -q 'variational step 175 (t = ' '$T/err' && test $rows = 175 -a $last = 174 -a $nf = 0"

# --output to a device writes through and leaves the device alone
"$S" --method rk4 --eps 0.1 --steps 5 --output /dev/null; rc=$?
check "--output /dev/null works and /dev/null is still a character device" test "$rc" = 0 -a -c /dev/null

# the file written with --output equals stdout
"$S" --method midpoint --eps 0.2 --steps 50 --every 7 --output "$T/o.csv"
"$S" --method midpoint --eps 0.2 --steps 50 --every 7 >"$T/s.csv"
check "--output FILE writes exactly what stdout gets" cmp -s "$T/o.csv" "$T/s.csv"

# the animation draws exactly the R_k that suslov prints for the same settings (same driver)
printf 'width = 96\nheight = 54\nfps = 4\nseconds = 2\nt_end = 6\neps = 1\n' >"$T/anim.cfg"
mkdir -p "$T/fig" "$T/dat"
SUSLOV_NO_VIDEO=1 "$B/animation" "$T/anim.cfg" "$T/fig" "$T/dat" >/dev/null 2>&1; rc=$?
same=1
for m in midpoint variational; do
    "$S" --method $m --eps 1 --steps 6 | tail -n +2 | cut -d, -f1,8- >"$T/cli_$m"
    grep "^$m," "$T/dat/attitude.csv" | cut -d, -f2,4- >"$T/anim_$m"
    cmp -s "$T/cli_$m" "$T/anim_$m" || same=0
done
check "animation: exit 0, 8 frames and a filmstrip; its R_k equal suslov's, digit for digit, for both integrators" \
    test "$rc" = 0 -a "$same" = 1 -a -s "$T/fig/attitude_filmstrip.png" -a -s "$T/fig/attitude/frame_0007.png"

# streaming: 2e7 steps in bounded memory (skipped under AddressSanitizer, which reserves
# terabytes of virtual memory)
if [ -z "${SUSLOV_SAN:-}" ]; then
    (ulimit -v 65536 && "$S" --method euler --eps 1e-3 --steps 20000000 --every 1000000 >"$T/long.csv"); rc=$?
    check "2e7 steps with --every 1e6 run in under 64 MiB of address space (21 rows)" \
        test "$rc" = 0 -a "$(tail -n +2 "$T/long.csv" | wc -l)" = 21
fi

echo "test_cli: $pass passed, $fail failed"
[ "$fail" = 0 ]
