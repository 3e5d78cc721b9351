#!/bin/sh
# The promises of suslov and the build that a demanding user broke, one regression
# check each, numbered as there: output through descriptors (/dev/stdout), long names, permissions
# checked before the run, every signal in the named-temporary mode, figure programs and make
# interrupted, an empty BUILD, exact for any t and w0, messages without NaN, full devices and
# exhausted inodes. Usage: test_cli_promises.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
NOASANSIG=handle_segv=0:handle_sigbus=0:handle_sigfpe=0
LONG="--eps 1e-9 --steps 9000000000000 --every 1000000000000" # hours: only a pre-run check ends it fast

# 1. /dev/stdout is the shell's descriptor: written in place, at its offset, never renamed over
printf 'old\n' >"$T/log.csv"
"$S" --method euler --eps 0.1 --steps 2 --output /dev/stdout >>"$T/log.csv"; rc=$?
check "--output /dev/stdout >> log keeps the old line and appends header and 3 rows (rc $rc)" \
    sh -c "test $rc = 0 -a \"\$(head -1 '$T/log.csv')\" = old -a \$(grep -c '^[0-9]' '$T/log.csv') = 3"
{ echo '# before'; "$S" --no-header --method euler --eps 0.1 --steps 1 --output /dev/stdout; echo '# after'; } >"$T/f"
check "{ echo; suslov --output /dev/stdout; echo; } > f keeps all three parts in order" \
    sh -c "test \"\$(head -1 '$T/f')\" = '# before' -a \"\$(tail -1 '$T/f')\" = '# after' -a \$(wc -l <'$T/f') = 5"
ln -s /dev/stdout "$T/to_stdout"
printf 'old\n' >"$T/log2.csv"
"$S" --no-header --method euler --eps 0.1 --steps 1 --output "$T/to_stdout" >>"$T/log2.csv"
check "a link to /dev/stdout is written through the descriptor too" \
    sh -c "test \"\$(head -1 '$T/log2.csv')\" = old -a \$(wc -l <'$T/log2.csv') = 4 -a -L '$T/to_stdout'"
(cd "$T" && "$S" --no-header --method euler --eps 0.1 --steps 1 --output - >"$T/dash.out")
check "--output - is stdout: no file named '-'" sh -c "test ! -e '$T/-' -a \$(wc -l <'$T/dash.out') = 3"
"$S" --no-header --method euler --eps 0.1 --steps 1 --output /dev/stdout | cat >"$T/pipe.out"
check "--output /dev/stdout into a pipe" test "$(wc -l <"$T/pipe.out")" = 3

# 2. a valid name of 250 bytes is written (the temporary's name does not grow with it); one of
# 256 is refused before the run
n250=$(printf '%0250d' 0)
"$S" --method euler --eps 0.1 --steps 2 --output "$T/$n250" 2>"$T/err"; rc=$?
check "a 250-byte file name is written (rc $rc, $(cat "$T/err")), no temporary left" \
    sh -c "test $rc = 0 -a -s '$T/$n250' && ! ls -A '$T' | grep -q '^\\.tmp\\.'"
n256=$(printf '%0256d' 0)
timeout 20 "$S" --method rk4 $LONG --output "$T/$n256" 2>"$T/err"; rc=$?
check "a 256-byte file name is refused before the run: exit 2 ($(cat "$T/err"))" \
    sh -c "test $rc = 2 && grep -q 'too long\\|longer than the directory allows' '$T/err'"

# 3. permissions as an unprivileged user (nobody): a read-only file is refused, and so is a
# mode-666 file of another user in a sticky directory (the rename would fail after the run)
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null && id nobody >/dev/null 2>&1 &&
   setpriv --reuid=nobody --regid=nogroup --clear-groups test -x "$S"; then
    P=$(mktemp -d /tmp/suslov-perm.XXXXXX) # not in $T, which nobody cannot enter
    at_exit 'rm -rf "$P"'
    chmod 1777 "$P"
    echo keep >"$P/other.csv"; chmod 666 "$P/other.csv"            # root's file, sticky dir of root
    asnobody() { setpriv --reuid=nobody --regid=nogroup --clear-groups "$@"; }
    asnobody sh -c "echo ro >'$P/ro.csv'; chmod 444 '$P/ro.csv'"
    asnobody timeout 20 "$S" --method rk4 $LONG --output "$P/other.csv" 2>"$T/err"; rc1=$?
    asnobody timeout 20 "$S" --method rk4 $LONG --output "$P/ro.csv" 2>"$T/err2"; rc2=$?
    asnobody "$S" --method rk4 --eps 0.1 --steps 3 --output "$P/mine.csv" 2>"$T/err3"; rc3=$?
    check "as nobody: another user's 666 file in a sticky dir and a read-only file are refused before the run (exit $rc1, $rc2: $(cat "$T/err" "$T/err2" | tr '\n' ' ')); a new file is written ($rc3)" \
        sh -c "test $rc1 = 2 -a $rc2 = 2 -a $rc3 = 0 && grep -q sticky '$T/err' && grep -q read-only '$T/err2' && test \"\$(cat '$P/other.csv' '$P/ro.csv')\" = 'keep
ro' && ! ls -A '$P' | grep -q '^\\.tmp\\.'"
    # root's 644 file: its owner may write it, nobody may not: read-only to nobody by access()
    echo keep >"$P/root644.csv"; chmod 644 "$P/root644.csv"
    asnobody timeout 20 "$S" --method rk4 $LONG --output "$P/root644.csv" 2>"$T/err4"; rc4=$?
    check "as nobody: root's 644 file is read-only to nobody (exit $rc4: $(cat "$T/err4"))" \
        sh -c "test $rc4 = 2 && grep -q 'read-only (Permission denied)' '$T/err4'"
    rm -rf "$P"
else
    skip "permissions as nobody: needs root, setpriv and a user nobody who can run $S"
fi

# 4. the named-temporary fallback: every catchable signal whose default ends the process
# removes the temporary, and the process dies of that signal (status 128 + n)
if env --default-signal true 2>/dev/null; then
    mkdir -p "$T/sig"
    kres=""
    # Linux's numbers (O_TMPFILE is Linux's too); 34 and 64 are glibc's SIGRTMIN and SIGRTMAX
    for sn in HUP:1 INT:2 QUIT:3 ILL:4 TRAP:5 ABRT:6 BUS:7 FPE:8 USR1:10 SEGV:11 USR2:12 PIPE:13 ALRM:14 \
              TERM:15 STKFLT:16 XCPU:24 XFSZ:25 VTALRM:26 PROF:27 IO:29 PWR:30 SYS:31 RTMIN:34 RTMAX:64; do
        sig=${sn%:*} n=${sn#*:}
        echo previous >"$T/sig/s.csv"
        # under SAN=1 AddressSanitizer would take SEGV, BUS and FPE for itself: leave them to suslov
        (ulimit -c 0; SUSLOV_NO_O_TMPFILE=1 ASAN_OPTIONS="${ASAN_OPTIONS:-}:$NOASANSIG" \
            exec env --default-signal "$S" --method rk4 $LONG --output "$T/sig/s.csv") 2>/dev/null &
        pid=$!
        i=0
        while [ $i -lt 500 ] && ! has_tmp "$T/sig"; do sleep 0.02; i=$((i + 1)); done
        kill -$n $pid; { wait $pid; } 2>/dev/null; rc=$?
        want=$((128 + n))
        entries "$T/sig"
        left=$entries
        if [ "$rc" = "$want" ] && [ "$left" = "s.csv " ] && one_line "$T/sig/s.csv" &&
            [ "$line1" = previous ]; then
            kres="$kres $sig"
        else
            kres="$kres $sig:FAILED(rc=$rc,want=$want,left=$left)"
            rm -f "$T/sig/".tmp.*
        fi
    done
    check "named fallback: every catchable fatal signal leaves only the previous file, status 128+n:$kres" \
        sh -c "! echo '$kres' | grep -q FAILED"
else
    skip "signals: env --default-signal is missing"
fi

# 5. a figure program killed while writing leaves no temporary (it writes through the atomic
# file, whose named fallback removes it on a signal), and make never deletes a figure output
if [ -x "$B/figure_fig1" ] && env --default-signal true 2>/dev/null; then
    # The temporaries live only while a file is written: a run whose window the polling misses
    # says nothing, so try a few runs, and say SKIP if none was caught.
    caught=0 try=0
    while [ "$caught" = 0 ] && [ $try -lt 5 ]; do
        try=$((try + 1))
        rm -rf "$T/fig" "$T/dat"; mkdir -p "$T/fig" "$T/dat"
        (SUSLOV_NO_O_TMPFILE=1 exec env --default-signal "$B/figure_fig1" "$T/fig" "$T/dat") >/dev/null 2>&1 &
        pid=$!
        while kill -0 $pid 2>/dev/null && ! has_tmp "$T/fig" "$T/dat"; do :; done
        caught=$(ls -A "$T/fig" "$T/dat" | grep -c '\.tmp\.')
        kill -INT $pid 2>/dev/null; { wait $pid; } 2>/dev/null; rc=$?
    done
    left=$(ls -A "$T/fig" "$T/dat" | grep -c '\.tmp\.')
    if [ "$caught" -ge 1 ]; then
        check "figure_fig1 interrupted by SIGINT while a temporary existed ($caught, run $try): status 130, no temporary left ($left)" \
            test "$rc" = 130 -a "$left" = 0
    else
        skip "figure_fig1: no run of $try was caught while a temporary existed"
    fi
fi
prec=$(make -s -p -q -f Makefile BUILD="$B" nothing 2>/dev/null | sed -n 's/^\.PRECIOUS: //p')
check "make keeps an interrupted figure's outputs: .PRECIOUS holds figures/%.pdf, figures/%.png, data/%.csv ($prec)" \
    sh -c "echo '$prec' | grep -q 'figures/%.pdf' && echo '$prec' | grep -q 'figures/%.png' && echo '$prec' | grep -q 'data/%.csv'"
make -n BUILD= all >/dev/null 2>"$T/err"; rc=$?
check "make BUILD= is refused ($(cat "$T/err"))" sh -c "test $rc != 0 && grep -q 'BUILD is empty' '$T/err'"

# 7. exact for any t and w0: the scaling law w(t; w0) = c w(c t; w0 / c), R(t; w0) = R(c t; w0 / c)
# ((ContDyn)'s field is homogeneous quadratic), against the paper's w0 at t = 0.5 and 2.5
last() { "$S" --no-header --method exact --eps "$1" --steps 1 --omega0 "$2" | tail -1; }
same() { # same ROW_A ROW_B C TOL: w_a = C w_b and R_a = R_b to TOL (relative for w)
    awk -F, -v a="$1" -v b="$2" -v c="$3" -v tol="$4" 'BEGIN { split(a, x, ","); split(b, y, ",");
        bad = 0; for (i = 3; i <= 4; i++) { d = x[i] / c - y[i]; if (d < 0) d = -d; if (d > tol * (y[i] < 0 ? -y[i] : y[i]) + 1e-300) bad = 1 }
        for (i = 8; i <= 16; i++) { d = x[i] - y[i]; if (d < 0) d = -d; if (d > tol || x[i] == "") bad = 1 }
        exit bad }'
}
ref=$(last 2.5 0.4,0.5)
for c in 1e-300 1e150; do
    t=$(awk -v c=$c 'BEGIN { printf "%.17g", 2.5 / c }')
    w=$(awk -v c=$c 'BEGIN { printf "%.17g,%.17g", 0.4 * c, 0.5 * c }')
    got=$(timeout 20 "$S" --no-header --method exact --eps "$t" --steps 1 --omega0 "$w" | tail -1)
    check "exact at |w0| ~ $c, t = 2.5/$c: w/c and R equal the paper's at t = 2.5 to 1e-14 (scaling law)" \
        same "$got" "$ref" "$c" 1e-14
done
t300=$(timeout 20 "$S" --no-header --method exact --eps 1e300 --steps 1 --omega0 1e-300,0 | tail -1)
ref2=$(last 1 1,0)
check "exact at t = 1e300, w0 = (1e-300, 0): R equals that at t = 1, w0 = (1, 0) to 1e-14" same "$t300" "$ref2" 1e-300 1e-14
# the largest final time the reference serves on the paper's body: the angle |w_inf| T, |w_inf| =
# sqrt(0.05 * 0.45 / 0.046) (c(w) = 0 on the energy ellipse), just below 2^60
big=$(timeout 20 "$S" --no-header --method exact --eps 1.64e18 --steps 1 2>"$T/err" | tail -1); rc=$?
check "exact at t = 1.64e18, an angle just below 2^60: finite, R orthogonal to 1e-14 ($(cat "$T/err"))" \
    sh -c "echo '$big' | awk -F, '{ for (i = 0; i < 3; i++) for (j = 0; j < 3; j++) { s = 0; for (l = 0; l < 3; l++) s += \$(8 + 3 * i + l) * \$(8 + 3 * j + l); d = s - (i == j); if (d * d > 1e-28) bad = 1 } } END { exit bad || NR != 1 }'"
# ... and beyond it, the angle past the reference's 2^60 (1e155 once squared the rotation
# vector in sus_so3_exp) or past the tolerance-driven methods' 2^50: refused, saying how far
for run in "exact --eps 1e155 --steps 1:2^60" "exact --eps 1.66e18 --steps 1:2^60" \
    "exact-attitude --tol 1e-6 --time 1e27:2^50" "taylor-adaptive --tol 1e-6 --time 1.62e15:2^50"; do
    timeout 20 "$S" --method ${run%:*} >"$T/out" 2>"$T/err"; rc=$?
    check "--method ${run%:*}: refused, the angle over ${run#*:} (exit $rc: $(cat "$T/err"))" \
        sh -c "test $rc = 2 -a ! -s '$T/out' && grep -q 'radians, more than the .* (${run#*:}) to which its attitude keeps its accuracy: ask for a final time of at most' '$T/err'"
    # ... and the final time it suggests is taken
    longest=$(sed -n 's/.*of at most \([0-9.e+]*\) .*/\1/p' "$T/err")
    case $run in
    exact*--eps*) again="--method exact --eps $longest --steps 1" ;;
    *) again="--method ${run%% --time*} --time $longest" ;;
    esac
    timeout 20 "$S" $again >/dev/null 2>"$T/err"; rc=$?
    check "... the suggested $again runs (exit $rc $(cat "$T/err"))" test $rc = 0
done
# the --tol methods from about the smallest w0 they take, |w0| = 5e-151 (at least 2^-500, its
# energy 1e-301 a normal double): the scaling law holds to their promise (TOL for exact-attitude;
# 10 N TOL for taylor-adaptive, N its steps, here under 10). Below 2^-500, or with an energy
# below the normal doubles (a body I scaled by 1e-100: E ~ 1e-320 at |w0| ~ 1e-110), their series
# multiply w by w and lose bits, and they are refused; exact serves both
same_R() { # same_R ROW_A ROW_B TOL: R_a = R_b to TOL
    awk -F, -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { split(a, x, ","); split(b, y, ","); bad = 0
        for (i = 8; i <= 16; i++) { d = x[i] - y[i]; if (d < 0) d = -d; if (d > tol || x[i] == "") bad = 1 }
        exit bad }'
}
small_I=1e-100,1e-101,2e-101,1e-101,1e-100,2e-101,2e-101,1e-101,1e-100
for run in exact-attitude:1e-10 taylor-adaptive:1e-8; do
    m=${run%:*}
    got=$(timeout 20 "$S" --no-header --method $m --tol 1e-10 --time 2.5e150 --every-time 2.5e150 \
        --omega0 4e-151,5e-151 | tail -1)
    check "$m at |w0| = 5e-151, t = 2.5e150: R equals the paper's at t = 2.5 to ${run#*:} (scaling law)" \
        same_R "$got" "$ref" "${run#*:}"
    for start in "--omega0 4e-152,5e-152" "--omega0 4e-111,5e-111 --inertia $small_I"; do
        timeout 20 "$S" --method $m --tol 1e-10 --time 1 $start >"$T/out" 2>"$T/err"; rc=$?
        check "$m $start: too small, refused (exit $rc: $(cat "$T/err"))" \
            sh -c "test $rc = 2 -a ! -s '$T/out' && grep -q 'is too small for the --tol methods' '$T/err'"
    done
done
got=$(timeout 20 "$S" --no-header --method exact --eps 2.5e110 --steps 1 --omega0 4e-111,5e-111 --inertia $small_I | tail -1)
check "exact with I scaled by 1e-100 from |w0| ~ 1e-110: R equals the paper's at t = 2.5 to 1e-14" same_R "$got" "$ref" 1e-14
a=$("$S" --no-header --method exact --eps 1e19 --steps 1 --omega0 1e-20,0 | tail -1)
b=$("$S" --no-header --method exact --eps 0.1 --steps 1 --omega0 1,0 | tail -1)
check "exact --eps 1e19 --omega0 1e-20,0 equals its scaled twin --eps 0.1 --omega0 1,0 (R11 = $(echo "$a" | cut -d, -f8))" \
    same "$a" "$b" 1e-20 1e-14
timeout 10 "$S" --method exact --eps 1e6 --steps 1 --omega0 4e-4,0 >/dev/null; rc=$?
check "exact at w0 = (4e-4, 0), t = 1e6 costs no more than at |w0| ~ 1 (under 10 s; was minutes): rc $rc" test $rc = 0

# a body whose motion nears the steady rotation at a rate ~1e-200 would need ~1e203 reference
# steps: refused before the run (no float-to-integer overflow, no endless run); a short run works
timeout 20 "$S" --method exact --eps 1e10 --steps 1 --inertia 1,0.1,0.2,0.1,1,0.2,1e-200,1e-200,1 \
    >"$T/out" 2>"$T/err"; rc=$?
timeout 20 "$S" --method exact --eps 1 --steps 1 --inertia 1,0.1,0.2,0.1,1,0.2,1e-200,1e-200,1 >/dev/null; rc2=$?
check "exact with I31 = I32 = 1e-200 to t = 1e10 is refused (exit $rc: $(cat "$T/err")); to t = 1 it runs ($rc2)" \
    sh -c "test $rc = 2 -a $rc2 = 0 -a ! -s '$T/out' && grep -q 'reference attitude needs' '$T/err'"

# 9. failure messages describe a NaN, never print one
"$S" --method midpoint --eps 1e6 --steps 3 --omega0 1e100,1e100 >/dev/null 2>"$T/err"; rc=$?
check "a Newton iteration reaching NaN: exit 3, one line, no 'nan' in it ($(cat "$T/err"))" \
    sh -c "test $rc = 3 -a \$(wc -l <'$T/err') = 1 && ! grep -qiwE 'nan|inf(inity)?' '$T/err' && grep -q 'not a finite number' '$T/err'"
# ... and every solver failure names the residual (docs/reference/cli.md and
# docs/explanation/where-methods-fail.md: "the step, t and the residual"): when
# it is not a finite number, says so, with the last finite one before it if there was one
fails() { # fails METHOD ARGS...: one failing run, the line kept in $T/err
    m=$1; shift
    "$S" --method "$m" "$@" >/dev/null 2>"$T/err"; rc=$?
}
fails variational --eps 1e-150 --steps 5 --omega0 1e150,1e100
check "variational overflowing at its starting guess: exit 3, one line naming step 1, t and the residual ($(cat "$T/err"))" \
    sh -c "test $rc = 3 -a \$(wc -l <'$T/err') = 1 && grep -q 'variational step 1 (t = 1e-150) failed: .*the residual is not a finite number already at the starting guess' '$T/err' && ! grep -qiwE 'nan|inf(inity)?' '$T/err'"
fails midpoint --eps 1e30 --steps 3 --omega0 1e10,1e10
check "midpoint overflowing after an iteration: the last finite residual is named ($(cat "$T/err"))" \
    sh -c "test $rc = 3 && grep -q 'midpoint step 1 (t = 1e+30) failed: .*the residual is not a finite number; the last finite residual was [0-9]' '$T/err'"
for run in "midpoint --eps 1e6 --steps 3 --omega0 1e100,1e100" "gauss4 --eps 1 --steps 3 --omega0 1e100,1e99" \
           "comp4-s5 --eps 1e6 --steps 3 --omega0 1e100,1e100" \
           "gauss4 --eps 1000 --steps 10 --omega0 0.27619224,-0.63956748"; do
    fails $run
    check "$run: exit 3, one line naming the step, t and the residual ($(cat "$T/err"))" \
        sh -c "test $rc = 3 -a \$(wc -l <'$T/err') = 1 && grep -q 'step [0-9]* (t = [^)]*) failed: .*residual' '$T/err' && ! grep -qiwE 'nan|inf(inity)?' '$T/err'"
done

# 10. --help to a full device fails; running out of inodes is an output error (1), not bad input
"$S" --help >/dev/full 2>"$T/err"; rc=$?
check "--help > /dev/full: exit 1, one line ($(cat "$T/err"))" sh -c "test $rc = 1 -a \$(wc -l <'$T/err') = 1"
M=$(mktemp -d)
at_exit 'umount "$M" 2>/dev/null; rmdir "$M" 2>/dev/null'
if [ "$(id -u)" = 0 ] && mount -t tmpfs -o size=1m,nr_inodes=2 tmpfs "$M" 2>/dev/null; then
    : >"$M/a" 2>/dev/null
    "$S" --method euler --eps 0.1 --steps 2 --output "$M/x.csv" 2>"$T/err"; rc=$?
    umount "$M"
    check "no inode left: exit 1 (output error), one line ($(cat "$T/err"))" sh -c "test $rc = 1 -a \$(wc -l <'$T/err') = 1"
else
    skip "inodes: cannot mount a small tmpfs (needs root)"
fi
rmdir "$M"

# 11. a bind-mounted output file (mount --bind src.csv mnt.csv; here from the same filesystem,
# where the devices agree and only the mount-root attribute tells) cannot be renamed over (EBUSY):
# refused before the run, exit 2, the file and its source untouched, no temporary left
mkdir -p "$T/bm"
echo source >"$T/bm/src.csv"; echo mounted-on >"$T/bm/mnt.csv"
if [ "$(id -u)" = 0 ] && mount --bind "$T/bm/src.csv" "$T/bm/mnt.csv" 2>/dev/null; then
    at_exit 'umount "$T/bm/mnt.csv" 2>/dev/null'
    ln -s mnt.csv "$T/bm/to_mnt.csv"
    for o in mnt.csv to_mnt.csv; do
        timeout 20 "$S" --method rk4 $LONG --output "$T/bm/$o" >"$T/out" 2>"$T/err"; rc=$?
        check "--output $o, a bind-mounted file$([ $o = to_mnt.csv ] && echo ' through a link'): refused before the run, exit $rc (2), one line ($(cat "$T/err")), nothing changed" \
            sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' && grep -q 'mount point' '$T/err' &&
                   test \"\$(cat '$T/bm/mnt.csv' '$T/bm/src.csv' | tr '\n' ' ')\" = 'source source ' &&
                   ! ls -A '$T/bm' | grep -q '^\\.tmp\\.'"
    done
    umount "$T/bm/mnt.csv"
else
    skip "bind-mounted --output: mount --bind is not permitted here (needs root)"
fi

# 12. a chain of links is written through to its end, also when it dangles (l1 -> l2 -> e/l3 ->
# ../missing.csv creates missing.csv, as echo x > l1 does), the links staying links, in both
# temporary modes; a loop of links is refused before the run
for nt in "" 1; do
    rm -rf "$T/ch"; mkdir -p "$T/ch/e"
    ln -s l2 "$T/ch/l1"; ln -s e/l3 "$T/ch/l2"; ln -s ../missing.csv "$T/ch/e/l3"
    SUSLOV_NO_O_TMPFILE=$nt "$S" --no-header --method rk4 --eps 0.1 --steps 3 --output "$T/ch/l1" 2>"$T/err"; rc=$?
    check "--output l1 -> l2 -> e/l3 -> ../missing.csv${nt:+ (named temporary)}: exit $rc, missing.csv created with 5 lines, l1, l2, e/l3 still links ($(cat "$T/err"))" \
        sh -c "test $rc = 0 -a -L '$T/ch/l1' -a -L '$T/ch/l2' -a -L '$T/ch/e/l3' -a -f '$T/ch/missing.csv' &&
               test \$(wc -l <'$T/ch/missing.csv') = 5 -a \$(find '$T/ch' | wc -l) = 6"
done
ln -s loop_b "$T/ch/loop_a"; ln -s loop_a "$T/ch/loop_b"
timeout 20 "$S" --method rk4 $LONG --output "$T/ch/loop_a" >"$T/out" 2>"$T/err"; rc=$?
check "--output into a loop of links: refused before the run, exit $rc (2), one line ($(cat "$T/err"))" \
    sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 && grep -q 'symbolic links' '$T/err'"

# 13. a start within a rounding of the repelling steady rotation: I31 w1 + I32 w2 = 0.3 w1 + 0.7 w2
# is 7.4e-23 exactly at this w0 (the doubles' exact product), below the rounding of its terms
# (1e-16), and c' = g c with g > 0 there. The motion leaves it for the attracting rotation, -w0 up
# to c(w0), as exact and exact-attitude show with no warning; a method that
# steps w stays at w0 and says so in one warning line; the mirrored start (-w0, attracting side) and
# the paper's body warn of nothing.
UI=1.0,0.1,0.05,0.1,1.0,-0.03,0.3,0.7,1.0 UW=0.7000093300886674,-0.3000039986094289
last_w1() { awk -F, '/^[0-9]/ { w = $3 } END { print w }' "$1"; }
for m in "taylor-adaptive --tol 1e-10 --time 300" "rk4 --eps 1 --steps 300" \
         "exact-attitude --tol 1e-10 --time 300" "exact --eps 1 --steps 300"; do
    "$S" --method $m --inertia $UI --omega0 $UW >"$T/out" 2>"$T/err"; rc=$?
    w1=$(last_w1 "$T/out")
    case $m in
    exact*) check "--method $m from w0 within a rounding of the repelling rotation: exit $rc, no warning, w1(300) = $w1 (the motion left: -0.70001)" \
                sh -c "test $rc = 0 -a ! -s '$T/err' && awk 'BEGIN { exit !($w1 < -0.70000) }'" ;;
    *) check "--method $m from the same w0: exit $rc, one warning naming the repelling rotation, w1(300) = $w1 (here it stayed at 0.70001)" \
           sh -c "test $rc = 0 -a \$(wc -l <'$T/err') = 1 && grep -q 'warning: --omega0: .*repelling steady rotation' '$T/err' &&
                  awk 'BEGIN { exit !($w1 > 0.70000) }'" ;;
    esac
done
for w in =-0.7000093300886674,0.3000039986094289 " 0.4,0.5"; do
    "$S" --method rk4 --eps 1 --steps 3 --inertia $UI --omega0$w >/dev/null 2>"$T/err"; rc=$?
    check "--method rk4 --omega0$w (not near the repelling rotation): exit $rc, no warning" test $rc = 0 -a ! -s "$T/err"
done
# the edge, a few ulps away (c / (u (|I31 w1| + |I32 w2|)) in exact rational arithmetic, u = 2^-53):
# 0.357 of a rounding is warned of, 2.14 roundings are not
for wc in 0.7000093300886671,-0.3000039986094287:1 0.7000093300886677,-0.3000039986094289:0; do
    "$S" --method rk4 --eps 1 --steps 3 --inertia $UI --omega0 ${wc%:*} >/dev/null 2>"$T/err"; rc=$?
    check "--method rk4 --omega0 ${wc%:*}: exit $rc, $(test ${wc#*:} = 1 && echo 'a warning' || echo 'no warning') ($(cat "$T/err"))" \
        sh -c "test $rc = 0 -a \$(wc -l <'$T/err') = ${wc#*:}"
done

done_tests test_cli_promises
