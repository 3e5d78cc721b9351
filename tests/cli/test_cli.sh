#!/bin/sh
# The suslov command's interface: CSV format, rows, exit statuses, all-or-nothing output,
# solver failures, constant memory. Usage: test_cli.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
HEADER='k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33'

# --help documents every option and exits 0
"$S" --help >"$T/help" 2>&1; rc=$?
missing=$(awk 'BEGIN { n = split("--method --eps --steps --time --omega0 --inertia --reconstruct " \
                                 "--every --output --help exact euler midpoint rk4 variational " \
                                 "cayley cayley-mid", o, " ") }
               { for (k = 1; k <= n; k++) if (index($0, o[k])) f[k] = 1 }
               END { for (k = 1; k <= n; k++) if (!f[k]) printf " %s", o[k] }' "$T/help")
check "--help exits 0 and documents every option and value${missing:+ (missing:$missing)}" \
    test "$rc" = 0 -a -z "$missing"

# rows_are FILE "K ...": the first line of FILE is the CSV header, and the rest are rows of 16
# fields whose first column reads K ... (each followed by a space)
rows_are() {
    awk -F, -v h="$HEADER" -v want="$2" 'NR == 1 { ok = $0 == h; next }
        { got = got $1 " "; if (NF != 16) ok = 0 } END { exit !(ok && got == want) }' "$1"
}
# exact header, row count with --every and the last row, %.17g numbers, 16 fields
for m in exact euler midpoint rk4 variational; do
    "$S" --no-header --method $m --eps 0.1 --steps 25 --every 10 >"$T/$m.csv" 2>"$T/err"; rc=$?
    check "$m: exit 0, exact header, rows k = 0 10 20 25, 16 fields" \
        eval '[ "$rc" = 0 ] && rows_are "$T/$m.csv" "0 10 20 25 "'
done
check "numbers are printed with %.17g (t = 2.5 at k = 25, w1(0) = 0.40000000000000002)" \
    grep -q '^25,2.5,' "$T/rk4.csv"
check "row 0 of a DSP has w1 = 0.40000000000000002, R = I" \
    grep -q '^0,0,0.40000000000000002,0.5,0,.*,1,0,0,0,1,0,0,0,1$' "$T/midpoint.csv"

# --time T takes N = T/H steps when that is a whole number to 4 rounding units of T, else it is
# refused naming the nearest valid final times (never a silent rounding)
"$S" --no-header --method euler --eps 0.3 --time 1.2 | tail -1 | cut -d, -f1,2 >"$T/n"
check "--time 1.2 --eps 0.3 gives N = 4 steps, last t = 4 * 0.3 ($(cat "$T/n"))" test "$(cat "$T/n")" = 4,1.2
# Every row's t is k H as computed (awk's double product, printed as suslov prints it), the time
# the steps reach: the last is N H, which IEEE double arithmetic makes differ from T in its last
# digits for these four (3 x 0.1 = 0.30000000000000004, 7 x 0.1 = 0.70000000000000007, 3 x 0.2 =
# 0.60000000000000009, 3 x 0.3 = 0.89999999999999991), and the header's final time says the same.
for case in "euler 0.1 0.3 3 0.30000000000000004" "exact 0.1 0.7 7 0.70000000000000007" \
    "midpoint 0.2 0.6 3 0.60000000000000009" "exact 0.3 0.9 3 0.89999999999999991" \
    "rk4 0.1 1 10 1"; do
    set -- $case
    "$S" --method "$1" --eps "$2" --time "$3" >"$T/tk.csv"
    # the last row's k,t; the header's final time; the rows whose t is not k H
    r=$(awk -F, -v h="$2" 'sub(/^# eps: .*, final time: /, "") { fin = $0; next } /^#/ { next }
                           ++n > 1 && $2 != sprintf("%.17g", $1 * h) { off++ }
                           { last = $1 "," $2 } END { print last, fin, off + 0 }' "$T/tk.csv")
    last=${r%% *} r=${r#* }
    fin=${r%% *} off=${r#* }
    check "--method $1 --eps $2 --time $3: every t = k H, the last row $4,$5 and final time $5 ($last; $fin; $off rows off)" \
        test "$last" = "$4,$5" -a "$fin" = "$5" -a "$off" = 0
done
"$S" --method euler --eps 3 --time 10 >"$T/out" 2>"$T/err"; rc=$?
check "--time 10 --eps 3 is refused (exit 2), naming --time 9 and --time 12 ($(cat "$T/err"))" \
    sh -c "test $rc = 2 -a ! -s '$T/out' && grep -q -- '--time 9 or --time 12' '$T/err'"

# deterministic: the same command gives the same bytes
"$S" --no-header --method variational --eps 0.5 --steps 200 --reconstruct cayley-mid >"$T/a.csv"
"$S" --no-header --method variational --eps 0.5 --steps 200 --reconstruct cayley-mid >"$T/b.csv"
check "the same command gives identical output" cmp -s "$T/a.csv" "$T/b.csv"

# bad input: one line "suslov: error: ...", exit 2, no output file created or truncated
echo "keep me" >"$T/keep.csv"
bad() { # bad DESCRIPTION ARGS... (some sixty times: no process beyond suslov's two runs)
    d=$1; shift
    [ ! -e "$T/new.csv" ] || rm -f "$T/new.csv"
    "$S" "$@" --output "$T/new.csv" >"$T/out" 2>"$T/err"; rc1=$?
    "$S" "$@" --output "$T/keep.csv" >/dev/null 2>&1; rc2=$?
    one=0 kept=""
    one_line "$T/err" && one=1
    IFS= read -r kept <"$T/keep.csv"
    case $line1 in "suslov: error: "*) ;; *) one=0 ;; esac
    if [ "$rc1" = 2 ] && [ "$rc2" = 2 ] && [ "$one" = 1 ] && [ ! -e "$T/new.csv" ] &&
       [ "$kept" = "keep me" ] && [ ! -s "$T/out" ]; then
        ok "bad input ($d): exit 2, one line: $line1"
    else
        ko "bad input ($d): rc=$rc1/$rc2, not one 'suslov: error:' line: $line1${line2:+ / $line2}"
    fi
}
bad "unknown option" --method rk4 --eps 0.1 --steps 3 --frobnicate 2
bad_says() { # bad_says DESCRIPTION PATTERN ARGS...: bad input, and its one line matches PATTERN
    d=$1 pat=$2; shift 2
    bad "$d" "$@"
    check "$d: the line says '$pat' ($line1)" grep -q -- "$pat" "$T/err"
}
bad "unknown method" --method leapfrog --eps 0.1 --steps 3
# an unknown method is named first, not a missing option its kind of run would want
bad_says "an unknown method and nothing else" "^suslov: error: unknown method 'LIST' (exact, " \
    --method LIST
bad_says "--time -0 gives 0 steps (not -0)" "with --eps 0.10000000000000001 gives 0 steps; need" \
    --method rk4 --eps 0.1 --time -0
# --method exact: a reference attitude estimated over ten minutes (src/prog/suslov_cli_checks.c:
# about 1e-5 s a step) is refused before it starts, saying what to do (the timeout: one let
# through would run for an hour)
timeout 20 "$S" --method exact --eps 1e6 --steps 1000 --inertia 1,0,0,0,1,0,1e-12,0,1 \
    >"$T/out" 2>"$T/err"; rc=$?
check "--method exact, a body that nears its steady rotation slowly: exit $rc (2), refused ($(cat "$T/err"))" \
    sh -c "test $rc = 2 -a ! -s '$T/out' && grep -q 'attitude needs [0-9.e+]* Taylor steps (.*), roughly .* hours (at most 6e+07, ten minutes): ask for a shorter final time' '$T/err'"
# ... and so is one whose rows cost it: each row before the steady tail is one more reference
# step, so 2^63 - 1 rows 1e-300 apart (all before the tail) would run for ever
timeout 20 "$S" --method exact --eps 1e-300 --steps 9223372036854775807 >"$T/out" 2>"$T/err"; rc=$?
check "--method exact, 2^63 - 1 rows before the tail: exit $rc (2), refused ($(cat "$T/err"))" \
    sh -c "test $rc = 2 -a ! -s '$T/out' && grep -q 'attitude needs 9.22e+18 Taylor steps' '$T/err'"
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
# a tolerance-driven method: --tol in [2^-52, 1) with --time, never with a fixed step
A="--method taylor-adaptive"
bad "--tol 0" $A --tol 0 --time 1
bad "--tol 1" $A --tol 1 --time 1
bad "--tol NaN" $A --tol nan --time 1
bad "--tol below 2^-52" $A --tol 1e-17 --time 1
bad "--tol with --eps" $A --tol 1e-8 --eps 0.1 --time 1
bad "--tol with --steps" $A --tol 1e-8 --steps 3
bad "--tol without --time" $A --tol 1e-8
bad "--tol with --every" $A --tol 1e-8 --time 1 --every 2
bad "--every-time <= 0" $A --tol 1e-8 --time 1 --every-time 0
# T/DT rows below 2^62, as the library counts them (driver.h): bad input, exit 2, not a failed run
bad_says "--every-time 1e-300 to --time 10" "asks for 1e+301 rows, 2^62 or more" \
    $A --tol 1e-8 --time 10 --every-time 1e-300
bad "--every-time 1e-19 to --time 1 (1e19 > 2^62 rows)" $A --tol 1e-8 --time 1 --every-time 1e-19
bad "--every-time 1.5e-19 to --time 1 (6.7e18 rows: 2^62 to 2^63)" $A --tol 1e-8 --time 1 \
    --every-time 1.5e-19
bad "taylor-adaptive without --tol" $A --time 1
bad "--tol to a fixed-step method" --method rk4 --eps 0.1 --steps 3 --tol 1e-8
bad "--every-time without --tol" --method rk4 --eps 0.1 --steps 3 --every-time 0.5
"$S" $A --tol 1e-10 --time 10 --every-time 2.5 --no-header >"$T/tol.csv"; rc=$?
check "--tol 1e-10 --every-time 2.5 to 10: exit $rc, rows at t = $(cut -d, -f2 "$T/tol.csv" | tail -n +2 | tr '\n' ' ')" \
    test "$rc" = 0 -a "$(cut -d, -f2 "$T/tol.csv" | tail -n +2 | tr '\n' ' ')" = "0 2.5 5 7.5 10 "
# 3 x 0.7 rounds to 2.0999999999999996, within 4u T of T = 2.1: that is T, one final row
"$S" $A --tol 1e-8 --time 2.1 --every-time 0.7 --no-header >"$T/tol.csv"; rc=$?
ts=$(cut -d, -f2 "$T/tol.csv" | tail -n +2 | tr '\n' ' ')
check "--time 2.1 --every-time 0.7: exit $rc, rows at t = 0, 0.7, 1.4 and T = 2.1 only ($ts)" \
    test "$rc" = 0 -a "$ts" = "0 0.69999999999999996 1.3999999999999999 2.1000000000000001 "
bad "unknown reconstruction" --method rk4 --eps 0.1 --steps 3 --reconstruct exp
bad "empty list field" --method rk4 --eps 0.1 --steps 3 --omega0 1,,2
bad "leading and trailing comma" --method rk4 --eps 0.1 --steps 3 --omega0 ,1,2,
bad "trailing comma" --method rk4 --eps 0.1 --steps 3 --omega0 1,2,
bad "empty inertia field" --method rk4 --eps 0.1 --steps 3 --inertia 1,0.1,0.2,0.1,1,0.2,0.2,,1
bad "non-symmetric I_m at 1e308 (the old scale overflowed)" --method rk4 --eps 0.1 --steps 3 --inertia 1e308,1e308,0,-1e308,1e308,0,0,0,1
bad "I_m at 1e308: its determinant overflows" --method rk4 --eps 0.1 --steps 3 --inertia 1e308,1,0,5,1e308,0,0,0,1
bad "I_m = 1e308 I: its determinant overflows" --method rk4 --eps 0.1 --steps 3 --inertia 1e308,0,0,0,1e308,0,0,0,1
bad "subnormal --eps" --method rk4 --eps 1e-320 --steps 3
bad "N H overflows" --method rk4 --eps 1e308 --steps 2
bad "--steps beyond 2^63-1" --method exact --eps 1 --steps 9223372036854775808
bad "--time gives more than 2^63-1 steps" --method exact --eps 1e-300 --time 1e300
bad_says "the energy at w0 overflows: the line names --omega0 only" \
    '^suslov: error: --omega0: the energy at w0 = (9.9999999999999997e+199, 9.9999999999999997e+199) overflows' \
    --method rk4 --eps 0.1 --steps 3 --omega0 1e200,1e200
bad_says "the multiplier at the default w0 overflows with this inertia: the line names --inertia, not --omega0" \
    '^suslov: error: --inertia: the multiplier lambda at w0 = (0.40000000000000002, 0.5) overflows with this inertia' \
    --method midpoint --eps 0.1 --steps 5 --inertia 1,0,0,0,1,0,1e300,1e300,1
# finite at w0, but not along the motion from it (test_exact_run derives where): refused by
# every method alike, not a blow-up whose step depends on the method and TOL
for m in "exact --eps 0.1 --steps 3" "exact-attitude --tol 1e-13 --time 10" "rk4 --eps 0.1 --steps 3"; do
    bad_says "lambda overflows along the motion from the default w0 ($m)" \
        '^suslov: error: --inertia: the multiplier lambda along the motion from w0 = (0.40000000000000002, 0.5) overflows with this inertia' \
        --method $m --inertia 1,0,0,0,1e-300,0,1,1,1
done
# what double precision cannot hold is refused for that reason, not called indefinite or put on w0
bad_says "I_m positive definite but lost to cancellation" "too ill-conditioned for double precision" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1,0.99999999999999989,0,0.99999999999999989,1,0,0,0,1
bad_says "I22/|I_m| = 1e10/1e-305 overflows" "too extreme for double precision: a coefficient I_ij/|I_m| of eq. (27)" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1e-300,9.9999999999999956e-146,0,9.9999999999999956e-146,1e10,0,0,0,1
bad_says "|(I31, I32)| overflows" "too extreme for double precision: the size of the field of eq. (27)" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1,0,0,0,1,0,1.7e308,1.7e308,1
bad_says "I11/|I_m| = 1e10/1e-305 overflows" "too extreme for double precision: a coefficient I_ij/|I_m| of eq. (27)" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1e10,9.9999999999999956e-146,0,9.9999999999999956e-146,1e-300,0,0,0,1
bad_says "I31 I22 = 1e310 overflows" "too extreme for double precision: a coefficient I32 Ij1 - I31 Ij2 of eq. (28)" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1,0,0,0,1e10,0,1e300,1,1 --omega0 1e-200,1e-200
bad_says "I32 I11 = 1e310 overflows (the other coefficient of O_0)" \
    "too extreme for double precision: a coefficient I32 Ij1 - I31 Ij2 of eq. (28)" \
    --method rk4 --eps 0.1 --steps 3 --inertia 1e10,0,0,0,1,0,1,1e300,1 --omega0 1e-200,1e-200
# I_m = diag(1e-200, 1e200) is positive definite with |I_m| = 1 and every coefficient in range: a
# body; with I31 = I32 = 0, c(w) = 0 and (ContDyn) keeps w = w0 on every row
for m in exact midpoint taylor8; do
    "$S" --no-header --method $m --eps 0.1 --steps 3 --inertia 1e-200,0,0,0,1e200,0,0,0,1 >"$T/wide.csv" 2>"$T/err"
    rc=$? w=$(tail -n +2 "$T/wide.csv" | cut -d, -f3-5 | sort -u | tr '\n' ' ')
    check "$m: I_m = diag(1e-200, 1e200) is accepted (exit $rc, $(cat "$T/err")), w = w0 on rows 0-3 ($w)" \
        test "$rc" = 0 -a "$w" = "0.40000000000000002,0.5,0 " -a "$(wc -l <"$T/wide.csv")" = 5
done
bad "a newline in an argument" --method "$(printf 'rk\n4')" --eps 0.1 --steps 3
bad "control characters in an option name" --method rk4 --eps 0.1 --steps 3 "$(printf -- '--a\tb\rc\033d\ne')" 1
bad "a newline in a list" --method rk4 --eps 0.1 --steps 3 --omega0 "$(printf '1\n,2')"
"$S" --no-header --method rk4 --eps 1e-320 --steps 3 2>"$T/err" >/dev/null
check "a subnormal --eps is called too small, not 'not finite' ($(cat "$T/err"))" \
    sh -c "grep -q 'too small' '$T/err' && ! grep -q 'not a finite' '$T/err'"
"$S" --no-header --method rk4 --eps 0.1 --steps 3 --omega0 "$(printf '1\n,2')" 2>"$T/err" >/dev/null
check "control characters in quoted text are escaped: $(cat "$T/err")" grep -qF "'1\n'" "$T/err"
# a long argument is echoed as its first 40 characters, "..." and its length, so that the reason
# after it always fits the line (a 2103-character --eps cut it after the quoted digits)
"$S" --method rk4 --eps "0.$(printf '%02100d' 0)1" --steps 1 2>"$T/err" >/dev/null; rc=$?
check "a 2103-character --eps: exit $rc, echoed cut to 40 characters, then the reason: $(cat "$T/err")" \
    sh -c "test $rc = 2 && grep -q \"^suslov: error: --eps: '0\\.0\\{38\\}\\.\\.\\.' (2103 characters) is too small: .* (see suslov --help)\$\" '$T/err'"
e50=$(awk 'BEGIN { for (i = 0; i < 50; i++) printf "\303\251" }') # 50 times U+00E9, 2 bytes each
e40=$(printf '%s' "$e50" | cut -c1-80)
"$S" --method "$e50" --eps 0.1 --steps 1 2>"$T/err" >/dev/null
check "a 50-character method name is cut after 40 characters (UTF-8 counted as characters, none split)" \
    grep -qF "unknown method '$e40...' (50 characters) (exact, " "$T/err"
deep="$T/missing"
for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15; do deep="$deep/$(printf '%0200d' "$i")"; done
"$S" --method rk4 --eps 0.1 --steps 1 --output "$deep/x.csv" 2>"$T/err" >/dev/null; rc=$?
check "a 3000-character --output path in no directory: exit $rc, one line that still ends with its reason" \
    sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 && grep -q 'characters) does not exist (see suslov --help)\$' '$T/err'"

# the output path is checked before computing (a run of 10^13 steps would take hours):
# empty, a directory, a missing directory, a read-only directory -> exit 2, nothing created.
# Read-only is the owner's write bit too, so root is refused alike.
mkdir -p "$T/ro"; chmod 555 "$T/ro"
for o in "" "$T" "$T/missing/x.csv" "$T/ro/x.csv"; do
    timeout 20 "$S" --no-header --method rk4 --eps 1e-9 --steps 10000000000000 --every 10000000000000 --output "$o" >"$T/out" 2>"$T/err"; rc=$?
    check "--output '$o' is refused before computing: exit 2, one line ($(cat "$T/err")), nothing created" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' -a ! -e '$T/missing' -a -z \"\$(ls -A '$T/ro')\""
done
chmod 755 "$T/ro"
# a directory root's access() calls writable but where no file can be created (/sys/kernel:
# EACCES at creation) is bad input too: exit 2 and one line before computing, as above (it was
# exit 1, an output error, without the pointer to --help)
if [ "$(id -u)" = 0 ] && [ -d /sys/kernel ] && ! (: >/sys/kernel/suslov-probe) 2>/dev/null; then
    timeout 20 "$S" --no-header --method rk4 --eps 1e-9 --steps 10000000000000 --every 10000000000000 \
        --output /sys/kernel/x.csv >"$T/out" 2>"$T/err"; rc=$?
    check "--output /sys/kernel/x.csv as root: exit $rc (2), one line, before computing ($(cat "$T/err"))" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' && grep -q 'Permission denied (see suslov --help)\$' '$T/err'"
    # ... and found by the check itself, so that --help refuses it as a run does
    "$S" --method rk4 --eps 0.1 --steps 1 --output /sys/kernel/x.csv --help >"$T/out" 2>"$T/err"; rc=$?
    check "--output /sys/kernel/x.csv --help as root: exit $rc (2), the same line ($(cat "$T/err"))" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' && grep -q 'Permission denied (see suslov --help)\$' '$T/err'"
else
    skip "--output where root cannot create a file: needs root and a /sys/kernel that refuses files"
fi
# /proc takes no new file (an existing one cannot be replaced either): exit 2 before computing,
# not exit 1 at the open
if [ -f /proc/version ]; then
    timeout 20 "$S" --no-header --method rk4 --eps 1e-9 --steps 10000000000000 --every 10000000000000 \
        --output /proc/version >"$T/out" 2>"$T/err"; rc=$?
    check "--output /proc/version: exit $rc (2), one line, before computing ($(cat "$T/err"))" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' && grep -q '^suslov: error: --output: ' '$T/err'"
else
    skip "--output /proc/version: no /proc"
fi
# a mode-444 FILE is read-only to root as well (its owner may not write it): refused, kept; the
# same FILE made writable by its owner (644) is replaced, the control
echo "keep" >"$T/r444.csv"; chmod 444 "$T/r444.csv"
timeout 20 "$S" --no-header --method rk4 --eps 1e-9 --steps 10000000000000 --every 10000000000000 \
    --output "$T/r444.csv" >"$T/out" 2>"$T/err"; rc=$?
check "--output FILE of mode 444: exit $rc (2), one line saying read-only, FILE kept ($(cat "$T/err"))" \
    sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a \"\$(cat '$T/r444.csv')\" = keep && grep -q 'read-only' '$T/err'"
chmod 644 "$T/r444.csv"
"$S" --no-header --method rk4 --eps 0.1 --steps 1 --output "$T/r444.csv" 2>"$T/err"; rc=$?
check "control: the same FILE at mode 644 is replaced (exit $rc, $(wc -l <"$T/r444.csv") lines)" \
    test "$rc" = 0 -a "$(wc -l <"$T/r444.csv")" = 3
# a --method exact run estimated over 5 s is announced on one note line before it starts (its
# rows may come minutes apart; the progress line shows on a terminal only); not under --quiet
SLOW="--method exact --eps 1e6 --steps 3 --inertia 1,0,0,0,1,0,1e-12,0,1 --no-header"
NO_PROGRESS= timeout 0.5 "$S" $SLOW >/dev/null 2>"$T/err"
check "a --method exact run estimated over 5 s: a note first ($(head -1 "$T/err"))" \
    sh -c "head -1 '$T/err' | grep -q '^suslov: note: --method exact: the reference attitude needs [0-9.e+]* Taylor steps, roughly [0-9]* s\$'"
NO_PROGRESS= timeout 0.5 "$S" $SLOW --quiet >/dev/null 2>"$T/err"
check "... and none under --quiet ($(cat "$T/err"))" test ! -s "$T/err"
NO_PROGRESS= "$S" --method exact --eps 0.1 --steps 25 >/dev/null 2>"$T/err"; rc=$?
check "no note for a short --method exact run (exit $rc: $(cat "$T/err"))" test "$rc" = 0 -a ! -s "$T/err"

# a solver failure: exit 3, message names step, t, residual; stdout keeps the rows before it,
# and --output FILE is all or nothing: a new FILE is not created, an existing one is left as it
# was (even with --no-header, where nothing could mark it incomplete), in both temporary modes.
# The 2-stage Gauss step from W0 meets a fold of its branch (no root beyond it) at h = eps k ~ 3.6
# (the stability map, src/lab/stability.h): eps = 1000 is far beyond.
W0=0.27619224,-0.63956748
"$S" --no-header --method gauss4 --eps 1000 --steps 10 --omega0 $W0 >"$T/fail.csv" 2>"$T/err"; rc=$?
check "solver failure: exit 3 and the message names step 1, t = 1000 and the residual ($(cat "$T/err"))" \
    sh -c "test $rc = 3 && grep -q 'gauss4 step 1 (t = 1000) failed: .*fold' '$T/err' && grep -q 'residual' '$T/err'"
check "solver failure: stdout holds the header and row 0, complete" \
    sh -c "test \$(wc -l <'$T/fail.csv') = 2 && tail -1 '$T/fail.csv' | grep -q '^0,0,0.2761922399[0-9]*,-0.6395674799[0-9]*,0,.*,1\$'"
for nt in "" 1; do
    rm -rf "$T/ff"; mkdir "$T/ff"; echo good >"$T/ff/old.csv"
    for f in old new; do
        for h in --header --no-header; do
            # a relative --output, so that the line names it whole whatever TMPDIR is (a long
            # path is shortened there)
            (cd "$T/ff" && SUSLOV_NO_O_TMPFILE=$nt "$S" $h --method gauss4 --eps 1000 --steps 10 \
                --omega0 $W0 --output "$f.csv" >"$T/out" 2>"$T/err_$f"); rc=$?
            [ "$rc" = 3 ] || echo "rc $rc" >>"$T/err_$f"
        done
    done
    check "solver failure${nt:+ (named temporary)}: an existing --output file is left as it was, a new one not created, no temporary, and the line says so ($(cat "$T/err_old"); $(cat "$T/err_new"))" \
        sh -c "test \"\$(ls -A '$T/ff')\" = old.csv -a \"\$(cat '$T/ff/old.csv')\" = good -a ! -s '$T/out' &&
               grep -q \"failed: .*residual.*; --output 'old.csv' is left as it was\$\" '$T/err_old' &&
               grep -q \"; --output 'new.csv' was not created\$\" '$T/err_new'"
done

# a late solver failure, as a property (no step number pinned), on stdout: from the stability
# map's start at 290.6 degrees the 2-stage Gauss step's branch meets a fold, the later the larger
# eps (the map, src/lab/stability.h), so runs at eps = 700..1700 fail at some step S. Each failure
# must exit 3 with one line naming "gauss4 step S (t = S eps)", and the file must hold every row
# before S, complete: k = 0..S-1 with --every 1; with --every 7 the rows 0, 7, 14, ... below S
# and the last good step S-1.
nfail=0 nlate=0 bad_runs=""
for e in 700 1000 1300 1700; do
    for w in 0.29884646991209679,-0.63120309801933794; do
        for K in 1 7; do
            "$S" --no-header --method gauss4 --eps $e --steps 3000 --every $K --omega0=$w >"$T/pf.csv" 2>"$T/err"; rc=$?
            [ "$rc" = 0 ] && continue
            # the one line: "suslov: error: gauss4 step S (t = TT) failed: ...residual..."
            step="" tt=""
            if one_line "$T/err"; then
                case $line1 in
                    "suslov: error: gauss4 step "*" (t = "*") failed: "*residual*)
                        step=${line1#suslov: error: gauss4 step } tt=${line1#*(t = }
                        step=${step%% *} tt=${tt%%)*} ;;
                esac
            fi
            case $step in '' | *[!0-9]*) step="" ;; esac
            # rows k < S, every K-th and the last good step S-1, of 16 fields; t = S eps
            if [ "$rc" = 3 ] && [ -n "$step" ] &&
               awk -F, -v S="$step" -v K=$K -v e=$e -v t="$tt" 'NR > 1 { got = got $1 " "; if (NF != 16) bad = 1 }
                   END { for (k = 0; k < S; k++) if (k % K == 0 || k == S - 1) want = want k " "
                         exit !(!bad && got == want && t == S * e) }' "$T/pf.csv"; then
                nfail=$((nfail + 1))
                [ "$step" -gt 7 ] && nlate=$((nlate + 1))
            else
                bad_runs="$bad_runs [eps $e w $w K $K: rc $rc, $(head -c 150 "$T/err")]"
            fi
        done
    done
done
check "solver failures: $nfail runs exit 3 with one line naming step S and t = S eps, rows k < S complete per --every plus the last good step S-1 ($nlate fail after step 7; need >= 3)${bad_runs:+; broken:$bad_runs}" \
    test -z "$bad_runs" -a "$nlate" -ge 3

# blow-up: a non-finite state stops the run with exit 3, one line naming the step, t and
# "blow-up"; the last good step is written (explicit Euler diverges for h = eps k > 2)
for m in euler rk4; do
    "$S" --no-header --method $m --eps 1e308 --steps 1 >"$T/bu.csv" 2>"$T/err"; rc=$?
    check "$m at --eps 1e308: exit 3, one line '$m blow-up at step 1 (t = 1e+308)', file has row 0 ($(cat "$T/err"))" \
        sh -c "test $rc = 3 -a \$(wc -l <'$T/err') = 1 && grep -q '^suslov: error: $m blow-up at step 1 (t = 1e+308)' '$T/err' && test \"\$(tail -n +2 '$T/bu.csv' | cut -d, -f1)\" = 0"
done
"$S" --no-header --method euler --eps 30 --steps 100000 --every 100 --omega0 4,5 >"$T/bu.csv" 2>"$T/err"; rc=$?
bstep=$(sed -n 's/^suslov: error: euler blow-up at step \([0-9]*\) (t = .*/\1/p' "$T/err")
rows=$(tail -n +2 "$T/bu.csv" | cut -d, -f1 | tr '\n' ' ')
check "euler at h = 4.3 > 2 blows up: exit 3, one line, --every 100 still writes rows 0 and the last good step S-1 ($rows; $(cat "$T/err"))" \
    test "$rc" = 3 -a -n "$bstep" -a "$rows" = "0 $((${bstep:-1} - 1)) " -a "$(wc -l <"$T/err")" = 1
for m in euler rk4; do
    "$S" --no-header --method $m --eps 1 --steps 50 --omega0 1e150,1e150 >"$T/bu.csv" 2>"$T/err"; rc=$?
    nonfinite=$(grep -ciE 'nan|inf' "$T/bu.csv")
    check "$m from w0 = (1e150, 1e150): exit 3 with 'blow-up', no nan/inf in the output ($(cat "$T/err"))" \
        sh -c "test $rc = 3 -a $nonfinite = 0 && grep -q 'blow-up at step' '$T/err'"
done
# a Taylor step far beyond its series' radius (|w0| = 1e10, so the radius is ~1e-9 time
# units, at eps = 1000): the series diverges (taylor8's terms stay finite, taylor16's overflow),
# and the step fails there, instead of its sum being scaled onto the energy ellipse
for m in taylor8 taylor16; do
    "$S" --no-header --method $m --eps 1000 --steps 3 --omega0 1e10,1e10 >"$T/bu.csv" 2>"$T/err"; rc=$?
    check "$m beyond its radius: exit 3, one line 'step 1 ... diverges', only row 0 written ($(cat "$T/err"))" \
        sh -c "test $rc = 3 -a \$(wc -l <'$T/err') = 1 && grep -q '$m step 1 (t = 1000) failed: the Taylor series diverges' '$T/err' && test \"\$(tail -n +2 '$T/bu.csv' | cut -d, -f1)\" = 0"
done

# no overflow in step arithmetic: N = K = 2^63 - 1 gives rows 0 and N and stops (steps short
# enough that the final angle, some 0.7 N eps, stays below the reference's 2^60)
timeout 60 "$S" --no-header --method exact --eps 1e-3 --steps 9223372036854775807 --every 9223372036854775807 >"$T/big.csv" 2>"$T/err"; rc=$?
check "--method exact, N = K = 2^63-1: exit 0, rows k = 0 and 9223372036854775807 only ($(cat "$T/err"))" \
    test "$rc" = 0 -a "$(tail -n +2 "$T/big.csv" | cut -d, -f1 | tr '\n' ' ')" = "0 9223372036854775807 "
timeout 60 "$S" --no-header --method exact --eps 0.1 --steps 9223372036854775807 --every 3074457345618258602 >"$T/big.csv" 2>"$T/err"; rc=$?
check "--method exact, N = 2^63-1, K = N/3: rows 0, K, 2K, 3K, N (no wrap to negative k)" \
    test "$rc" = 0 -a "$(tail -n +2 "$T/big.csv" | cut -d, -f1 | tr '\n' ' ')" = "0 3074457345618258602 6148914691236517204 9223372036854775806 9223372036854775807 "
# --method exact at large T is O(1) in T beyond the steady rotation (exact_run.c)
timeout 60 "$S" --no-header --method exact --eps 1e7 --steps 1 >"$T/big.csv" 2>"$T/err"; rc=$?
check "--method exact --eps 1e7 --steps 1 finishes (exit $rc within 60 s), R(1e7) orthogonal to 1e-10" \
    sh -c "test $rc = 0 && tail -1 '$T/big.csv' | awk -F, '{ for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) { s = 0; for (l = 0; l < 3; l++) s += \$(8 + 3 * i + l) * \$(8 + 3 * j + l); d = s - (i == j); if (d * d > 1e-20) bad = 1 } } END { exit bad }'"

# killed runs leave nothing but the untouched previous file: O_TMPFILE for every signal
# including SIGKILL, and the named-temporary fallback (SUSLOV_NO_O_TMPFILE=1) for the four
# catchable signals, which must end the process with status 128 + signo
if env --default-signal true 2>/dev/null; then
    mkdir -p "$T/kill"
    kres=""
    for mode in tmpfile named; do
        for sig in INT TERM HUP PIPE KILL; do
            [ $mode = named ] && [ $sig = KILL ] && continue
            echo "previous" >"$T/kill/sig.csv"
            nt=""; [ $mode = named ] && nt=1
            SUSLOV_NO_O_TMPFILE=$nt env --default-signal "$S" --no-header --method rk4 --eps 1e-9 --steps 9000000000000 \
                --every 1000000000000 --output "$T/kill/sig.csv" 2>/dev/null &
            pid=$!
            # wait (up to 10 s) until the run has its temporary: named, or an fd in $T/kill (a look a
            # hundredth of a second: the run computes at full speed until its signal)
            i=0
            while [ $i -lt 1000 ] && ! ls -l /proc/$pid/fd 2>/dev/null | grep -q "$T/kill/"; do sleep 0.01; i=$((i + 1)); done
            kill -s $sig $pid; wait $pid; rc=$?
            case $sig in HUP) n=1 ;; INT) n=2 ;; KILL) n=9 ;; PIPE) n=13 ;; TERM) n=15 ;; esac
            want=$((128 + n))
            entries "$T/kill"
            left=$entries
            if [ "$rc" = "$want" ] && [ "$left" = "sig.csv " ] && one_line "$T/kill/sig.csv" &&
                [ "$line1" = previous ]; then
                kres="$kres $mode/$sig:ok"
            else
                kres="$kres $mode/$sig:FAILED(rc=$rc,left=$left)"
                rm -f "$T/kill/sig.csv.tmp."*
            fi
        done
    done
    check "killed --output runs leave only the untouched previous file, status 128+signo:$kres" \
        sh -c "! echo '$kres' | grep -q FAILED"
else
    echo "SKIP kill tests: env --default-signal is missing (a background job ignores SIGINT)"
fi

# file semantics: a new file gets 0666 & ~umask, an existing file keeps its mode, a symbolic
# link is written through to its target (also when dangling), for both ways of writing
for nt in "" 1; do
    rm -rf "$T/fs"; mkdir -p "$T/fs/d"
    (umask 027 && SUSLOV_NO_O_TMPFILE=$nt "$S" --no-header --method rk4 --eps 0.1 --steps 3 --output "$T/fs/new.csv")
    echo x >"$T/fs/old.csv"; chmod 600 "$T/fs/old.csv"
    SUSLOV_NO_O_TMPFILE=$nt "$S" --no-header --method rk4 --eps 0.1 --steps 3 --output "$T/fs/old.csv"
    echo x >"$T/fs/d/target.csv"; ln -s d/target.csv "$T/fs/link.csv"; ln -s gone.csv "$T/fs/dangling.csv"
    SUSLOV_NO_O_TMPFILE=$nt "$S" --no-header --method rk4 --eps 0.1 --steps 3 --output "$T/fs/link.csv"
    SUSLOV_NO_O_TMPFILE=$nt "$S" --no-header --method rk4 --eps 0.1 --steps 3 --output "$T/fs/dangling.csv"
    modes="$(stat -c %a "$T/fs/new.csv" "$T/fs/old.csv" | tr '\n' ' ')"
    check "file semantics${nt:+ (named-temporary fallback)}: new file 640 under umask 027, existing 600 kept ($modes), links still links, targets written, no temporary left" \
        sh -c "test '$modes' = '640 600 ' -a -L '$T/fs/link.csv' -a -L '$T/fs/dangling.csv' && test \$(wc -l <'$T/fs/d/target.csv') = 5 -a \$(wc -l <'$T/fs/gone.csv') = 5 && test -z \"\$(find '$T/fs' -name '*.tmp.*')\""
done

# progress: on a terminal stderr (script(1) gives one) a progress line is drawn and erased at
# the end; --quiet and a non-terminal stderr get nothing. SUSLOV_PROGRESS_AFTER=0 (a test hook)
# shows it from the first step, so that a short run exercises it on any machine.
if command -v script >/dev/null; then
    SUSLOV_PROGRESS_AFTER=0 script -qec "'$S' --no-header --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output '$T/pr.csv'" /dev/null >"$T/tty" 2>&1; rc=$?
    SUSLOV_PROGRESS_AFTER=0 script -qec "'$S' --no-header --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output '$T/pr.csv' --quiet" /dev/null >"$T/ttyq" 2>&1
    SUSLOV_PROGRESS_AFTER=0 "$S" --no-header --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output "$T/pr.csv" 2>"$T/notty"
    check "progress on a terminal: 'step .. of 200000 (..%), t = .., .. s elapsed' then erased (ends with CR ESC[K); nothing with --quiet or without a terminal" \
        sh -c "test $rc = 0 && grep -q 'suslov: step [0-9]* of 200000 (.*), t = .*, [0-9]* s elapsed' '$T/tty' && test \"\$(tail -c 4 '$T/tty' | od -An -tx1 | tr -d ' \n')\" = 0d1b5b4b && test ! -s '$T/ttyq' -a ! -s '$T/notty'"
    # a --tol run's steps are uneven: its progress is the share of [0, T] done
    SUSLOV_PROGRESS_AFTER=0 script -qec "'$S' --no-header --method exact-attitude --tol 1e-8 --time 100 --every-time 0.01 --output '$T/pr.csv'" /dev/null >"$T/tty" 2>&1; rc=$?
    check "progress of a --tol run on a terminal: 'N% done, t = .., .. s elapsed', then erased" \
        sh -c "test $rc = 0 && grep -q 'suslov: [0-9]*% done, t = [0-9.e+]*, [0-9]* s elapsed' '$T/tty' && test \"\$(tail -c 4 '$T/tty' | od -An -tx1 | tr -d ' \n')\" = 0d1b5b4b"
fi

# a write error (emit asks the run to stop: SUS_RUN_STOPPED) is status 1 with one line,
# distinct from a solver failure (3)
if [ -c /dev/full ]; then
    "$S" --no-header --method rk4 --eps 0.1 --steps 100000 >/dev/full 2>"$T/err"; rc1=$?
    "$S" --no-header --method exact --eps 0.1 --steps 100000 --output /dev/full 2>"$T/err2"; rc2=$?
    check "a full device: exit 1 and one line 'writing ... failed' ($(cat "$T/err"); $(cat "$T/err2"))" \
        sh -c "test $rc1 = 1 -a $rc2 = 1 -a \$(cat '$T/err' '$T/err2' | wc -l) = 2 && grep -q '^suslov: error: writing stdout failed' '$T/err' && grep -q '^suslov: error: writing /dev/full failed' '$T/err2'"
fi

# --output to a device writes through and leaves the device alone
"$S" --no-header --method rk4 --eps 0.1 --steps 5 --output /dev/null; rc=$?
check "--output /dev/null works and /dev/null is still a character device" test "$rc" = 0 -a -c /dev/null

# the file written with --output equals stdout
"$S" --no-header --method midpoint --eps 0.2 --steps 50 --every 7 --output "$T/o.csv"
"$S" --no-header --method midpoint --eps 0.2 --steps 50 --every 7 >"$T/s.csv"
check "--output FILE writes exactly what stdout gets" cmp -s "$T/o.csv" "$T/s.csv"

# the animation draws exactly the R_k that suslov prints for the same settings (same driver)
printf 'width = 96\nheight = 54\nfps = 4\nseconds = 2\nt_end = 6\neps = 1\n' >"$T/anim.cfg"
mkdir -p "$T/fig" "$T/dat"
SUSLOV_NO_VIDEO=1 "$B/animation" "$T/anim.cfg" "$T/fig" "$T/dat" >/dev/null 2>&1; rc=$?
same=1
for m in midpoint variational; do
    "$S" --no-header --method $m --eps 1 --steps 6 | tail -n +2 | cut -d, -f1,8- >"$T/cli_$m"
    grep "^$m," "$T/dat/attitude.csv" | cut -d, -f2,4- >"$T/anim_$m"
    cmp -s "$T/cli_$m" "$T/anim_$m" || same=0
done
check "animation: exit 0, 8 frames and a filmstrip; its R_k equal suslov's, digit for digit, for both integrators" \
    test "$rc" = 0 -a "$same" = 1 -a -s "$T/fig/attitude_filmstrip.png" -a -s "$T/fig/attitude/frame_0007.png"

# streaming: 4e6 steps in bounded memory (skipped under AddressSanitizer, which reserves
# terabytes of virtual memory). The least block malloc gives is 32 bytes: one kept per step is
# 128 MiB, twice the limit.
if [ -z "${SUSLOV_SAN:-}" ]; then
    (ulimit -v 65536 && "$S" --no-header --method euler --eps 1e-3 --steps 4000000 --every 200000 >"$T/long.csv"); rc=$?
    check "4e6 steps with --every 2e5 run in under 64 MiB of address space (21 rows)" \
        test "$rc" = 0 -a "$(tail -n +2 "$T/long.csv" | wc -l)" = 21
fi

done_tests test_cli
