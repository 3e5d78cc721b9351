#!/bin/sh
# The conventions a scripting user expects of suslov: --version, --, --method list's refusals, one
# number grammar, repeated and inapplicable options, --header and its fields, the trailer of an
# incomplete file, long options with =, TERM=dumb and NO_COLOR (what it says of its methods, and
# --help against the manual page and docs/reference/cli.md: test_cli_methods.sh).
# Usage: test_cli_conventions.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"
bad() { # bad DESCRIPTION GLOB ARGS...: exit 2, one line that GLOB matches, nothing on stdout
    d=$1 pat=$2; shift 2
    "$S" "$@" >"$T/out" 2>"$T/err"; rc=$?
    one=0
    one_line "$T/err" && case $line1 in $pat) one=1 ;; esac
    check "$d: exit 2, one line ($line1${line2:+ / $line2})" \
        eval 'test $rc = 2 -a $one = 1 -a ! -s "$T/out"'
}

# --version: "suslov COMMIT", the commit this checkout is at when built from git, else unknown
v=$("$S" --version); rc=$?
head=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
check "--version prints 'suslov <commit>' ($v; HEAD $head)" \
    sh -c "test $rc = 0 && case '$v' in 'suslov unknown') test '$head' = unknown ;; 'suslov '*) echo '$v' | grep -q '$head' ;; *) false ;; esac"

# --help, --man and --version act once the whole command line is read: whatever stands before or
# after them, bad input is exit 2 and one line, with nothing printed on stdout
for first in --help --man --version; do
    bad "$first --bogus" "suslov: error: unknown option ?--bogus?*" $first --bogus
    bad "$first --eps abc" "suslov: error: --eps: ?abc? is not a number*" $first --eps abc
    bad "$first --eps (no value)" "suslov: error: --eps needs a value*" $first --eps
    bad "$first, then an operand" "suslov: error: unexpected argument ?x?*" $first x
    bad "--bogus $first" "suslov: error: unknown option ?--bogus?*" --bogus $first
    bad "$first twice" "suslov: error: $first is given twice*" $first $first
done
bad "--help --version" "suslov: error: --help and --version are both given*" --help --version
bad "--version --man" "suslov: error: --version and --man are both given*" --version --man
# Every option given is checked before --help, --man or --version acts, as a run checks it: a
# command line refused without them is refused with them, before or after them, by the very line
# it gets without them (the expected line comes from that run, which must itself be refused).
for cmd in "--method euler --eps -1 --steps 1" "--method taylor-adaptive --tol 5 --time 1" \
    "--method euler --eps 0.1 --steps 1 --every-time 1" "--method euler --eps 0.1 --time 0.25" \
    "--method euler --eps 0.1 --steps 3 --time 1" "--method rk4 --eps 0.1 --time 1 --sweeps 2" \
    "--method midpoint --eps 0.1 --steps 1 --inertia 1,0,0,0,-1,0,0,0,1" \
    "--method exact --eps 0.1 --steps 1 --reconstruct cayley" "--method bogus --eps 0.1 --steps 1" \
    "--method euler --eps 0.1 --steps 1 --output $T/none/x.csv"; do
    "$S" $cmd >"$T/out" 2>"$T/want"; rc=$?
    wrong=""
    [ "$rc" = 2 ] && one_line "$T/want" || wrong=" [without them: exit $rc]"
    want=$line1
    for show in --help --man --version; do
        for at in before after; do
            if [ $at = before ]; then set -- $show $cmd; else set -- $cmd $show; fi
            "$S" "$@" >"$T/out" 2>"$T/err"; rc=$?
            [ "$rc" = 2 ] && [ ! -s "$T/out" ] && one_line "$T/err" && [ "$line1" = "$want" ] ||
                wrong="$wrong [$show $at: exit $rc, $(head -c 80 "$T/err")]"
        done
    done
    d="$cmd, with --help, --man or --version before or after it: exit 2 and its line"
    check "$d ($want)${wrong:+; wrong:$wrong}" test -z "$wrong"
done
# without --method, the options given are checked for the kind of run they describe
bad "--eps -1 --help" "suslov: error: --eps must be positive*" --eps -1 --help
bad "--help --tol 0" "suslov: error: --tol must be in*" --help --tol 0
bad "--eps 0.1 --tol 1e-6 --man" "*not --eps or --steps*" --eps 0.1 --tol 1e-6 --man
bad "--version --sweeps 9" "suslov: error: --sweeps must be at most 8*" --version --sweeps 9
bad "--reconstruct cay --help" "suslov: error: unknown reconstruction ?cay?*" \
    --reconstruct cay --help
# but none is required, and no warning is given for a run that is not made: the help, exit 0
"$S" --help >"$T/help0"
for cmd in "--method euler" "--method taylor-adaptive" "--eps 0.1 --steps 3" \
    "--tol 1e-6 --time 1 --every-time 0.5" "--method midpoint --sweeps 2 --eps 0.1" \
    "--method taylor8 --eps 0.1 --steps 1 --reconstruct cayley" \
    "--method euler --eps 0.1 --steps 1 --output $T/new.csv"; do
    "$S" $cmd --help >"$T/help1" 2>"$T/err"; rc=$?
    check "$cmd --help: exit 0, the help, nothing on stderr ($(head -c 80 "$T/err"))" \
        sh -c "test $rc = 0 -a ! -s '$T/err' && cmp -s '$T/help0' '$T/help1'"
done
check "--output FILE --help creates no FILE" test ! -e "$T/new.csv"

# -- ends the options; nothing may follow (suslov takes no operands)
"$S" --no-header --method euler --eps 0.1 --steps 1 -- >"$T/o"; rc=$?
check "-- at the end is accepted" test "$rc" = 0 -a "$(wc -l <"$T/o")" = 3
bad "an argument after --" "*unexpected argument ?--eps*" --method euler --eps 0.1 --steps 1 -- --eps

# --method list takes no other option, valid or not: exit 2, one line, nothing written
for extra in "--eps -1" "--eps 0.1" "--output $T/lst.csv" "--help" "--no-header"; do
    bad "--method list $extra" "suslov: error: --method list takes no other options*" --method list $extra
done
bad "--eps -1 --method=list (either order, either spelling)" "*takes no other options*" --eps -1 --method=list
check "--method list --output FILE creates no FILE" test ! -e "$T/lst.csv"

# one number grammar: counts accept 1e6 and 0x10 when whole numbers
a=$("$S" --no-header --method exact --eps 1e-6 --steps 1e6 --every 1e6 | tail -1 | cut -d, -f1)
b=$("$S" --no-header --method exact --eps 1e-6 --steps 0x10 --every 2e0 | tail -1 | cut -d, -f1)
check "--steps 1e6 is 1000000 and --steps 0x10 is 16 ($a, $b)" test "$a" = 1000000 -a "$b" = 16
bad "--steps 2.5" "*not a whole number*" --method euler --eps 0.1 --steps 2.5
bad "--every 1e19 (beyond 2^63 - 1)" "*out of range*" --method euler --eps 0.1 --steps 1 --every 1e19
bad "a number with a leading blank" "*not a number*" --method euler --eps ' 0.1' --steps 1

# a repeated option is an error; so are both --header and --no-header
bad "--eps twice" "*given twice*" --method euler --eps 0.1 --eps 0.2 --steps 1
bad "--header with --no-header" "*both given*" --method euler --eps 0.1 --steps 1 --header --no-header

# options that do not apply: an error with exact, a one-line warning with a Taylor method
bad "--reconstruct with exact" "*does not apply*" --method exact --eps 0.1 --steps 1 --reconstruct cayley
"$S" --method taylor8 --eps 0.1 --steps 1 --reconstruct cayley >/dev/null 2>"$T/err"; rc=$?
check "--reconstruct with taylor8: exit 0 and one warning line ($(cat "$T/err"))" \
    sh -c "test $rc = 0 -a \$(wc -l <'$T/err') = 1 && grep -q '^suslov: warning: --reconstruct cayley is ignored' '$T/err'"
bad "--reconstruct with taylor8 and a bad --output (the warning waits for the checks)" "*does not exist*" \
    --method taylor8 --eps 0.1 --steps 1 --reconstruct cayley --output "$T/missing/x.csv"
"$S" --method midpoint --eps 0.1 --steps 1 --reconstruct exp-mid >/dev/null 2>"$T/err"
check "--reconstruct with midpoint: no warning" test ! -s "$T/err"

# a long option with = never swallows the next argument
long="--$(printf '%070d' 0)=1"
bad "a 72-character option with =" "*unknown option ?--0000*" --method euler --eps 0.1 --steps 1 "$long" --quiet

# --header (default): # lines with version, command, method, eps, inertia, omega0, units, then
# the CSV header; --no-header: the CSV header first
"$S" --method comp4-s5 --eps 0.25 --steps 2 --omega0 0.3,-0.2 >"$T/h.csv"
check "header: version, command line, method, eps, inertia, omega0, units before the CSV header" \
    sh -c "grep -q '^# suslov ' '$T/h.csv' && grep -q '^# command: suslov --method comp4-s5 --eps 0.25 --steps 2 --omega0 0.3,-0.2$' '$T/h.csv' &&
           grep -q '^# method: comp4-s5 (composition, order 4), reconstruction exp-mid$' '$T/h.csv' &&
           grep -q '^# eps: 0.25, steps: 2, every: 1, final time: 0.5$' '$T/h.csv' && grep -q '^# inertia' '$T/h.csv' &&
           grep -q '^# omega0: 0.29999999999999999,-0.20000000000000001,0$' '$T/h.csv' && grep -q '^# units' '$T/h.csv' &&
           test \"\$(grep -v '^#' '$T/h.csv' | head -1 | cut -d, -f1-3)\" = k,t,omega1"
"$S" --no-header --method euler --eps 0.1 --steps 1 | head -1 | cut -d, -f1-2 >"$T/nh"
check "--no-header: the CSV header is the first line" test "$(cat "$T/nh")" = k,t
"$S" --method euler --eps 0.1 --steps 1 "$(printf 'x\ny')" >/dev/null 2>&1
"$S" --method euler --eps 0.1 --steps 1 --output "$T/q'u o.csv" 2>/dev/null
check "the command line is quoted for the shell, on one line" grep -q "^# command: .* --output '.*q'\\\\''u o.csv'$" "$T/q'u o.csv"

# the command line can be parsed as UTF-8 text and pasted into a shell: an --output name with a
# newline, a control character, a byte that is not UTF-8 (0xff), a quote, a backslash and a valid
# UTF-8 character; run again from the header's line by bash (and by sh when it knows $'...'), it
# writes the same bytes to the same name
name=$(printf 'a\nb\001\377 it'"'"'s \303\251\\.csv')
mkdir -p "$T/q1" "$T/q2"
(cd "$T/q1" && "$S" --method euler --eps 0.1 --steps 2 --output "$name") 2>"$T/err"; rc=$?
cp "$T/q1/$name" "$T/q1.csv" # a name the checks below can quote
line=$(grep -a '^# command: ' "$T/q1.csv")
check "a hostile --output name: exit $rc, the header is valid UTF-8, one command line ($line)" \
    sh -c "test $rc = 0 && iconv -f UTF-8 -t UTF-8 '$T/q1.csv' >/dev/null && test \$(grep -c '^# command: ' '$T/q1.csv') = 1"
cmd=${line#\# command: suslov}
for sh in bash sh; do
    if command -v $sh >/dev/null && [ "$($sh -c "printf %s \$'\\x41'" 2>/dev/null)" = A ]; then
        rm -f "$T/q2/"*
        (cd "$T/q2" && $sh -c "\"\$0\" $cmd" "$S") 2>"$T/err"; rc=$?
        check "the header's command line run again by $sh: exit $rc, the same file under the same name" \
            cmp -s "$T/q1/$name" "$T/q2/$name"
    else
        skip "the header's command line in $sh: no $sh, or it has no \$'...' quoting"
    fi
done
"$S" --method euler --eps 0.1 --steps 1 --output "$T/$(printf 'x\377y')" 2>/dev/null
"$S" --method "$(printf 'x\377y')" --eps 0.1 --steps 1 2>"$T/err"
check "a byte that is not UTF-8: escaped as \\xff in the header and the error line ($(cat "$T/err"))" \
    sh -c "grep -q \"^# command: .*--output \\\$'.*x\\\\\\\\xffy'\\\$\" '$T/$(printf 'x\377y')' && grep -qF 'x\\xffy' '$T/err' && iconv -f UTF-8 -t UTF-8 '$T/err' >/dev/null"

# rows left on stdout after exit 3 say so in a last comment line (not with --no-header: bare CSV)
# (the 2-stage Gauss step from this w0 meets a fold of its branch at h ~ 3.6: src/lab/stability.h)
"$S" --method gauss4 --eps 1000 --steps 10 --omega0 0.27619224,-0.63956748 >"$T/fail.csv" 2>/dev/null; rc=$?
check "after exit 3 the last line of stdout is '# incomplete: ...' naming the failure" \
    sh -c "test $rc = 3 && tail -1 '$T/fail.csv' | grep -q '^# incomplete: .*gauss4 step 1 (t = 1000) failed'"

# a count is read exactly as written: a double would round 2.0000000000000001 to 2 and
# 9007199254740993 (2^53 + 1) to 2^53; whole numbers in any notation are taken exactly
for opt in --steps --every --sweeps; do
    for v in 2.0000000000000001 9007199254740993.5 1.00000000000000000000001e1 0x1.00000000000001p0; do
        case $opt in --sweeps) args="--method midpoint --eps 0.1 --steps 2 --sweeps $v" ;;
                     --every) args="--method exact --eps 0.1 --steps 3 --every $v" ;;
                     *) args="--method exact --eps 0.1 --steps $v --every 1e18" ;; esac
        bad "$opt $v" "*not a whole number*" $args
    done
done
for v in 9007199254740993e0 9007199254740993 0x20000000000001 900719925474099.3e1 90071992547409930e-1; do
    last=$("$S" --no-header --method exact --eps 1e-9 --steps "$v" --every "$v" | tail -1 | cut -d, -f1)
    check "--steps $v --every $v: the last row is k = 9007199254740993 = 2^53 + 1 ($last)" test "$last" = 9007199254740993
done
k=$("$S" --no-header --method exact --eps 0.1 --steps 1.5e1 --every 0x5 | tail -n +2 | cut -d, -f1 | tr '\n' ' ')
check "--steps 1.5e1 --every 0x5: rows 0 5 10 15 ($k)" test "$k" = "0 5 10 15 "
k=$("$S" --no-header --method exact --eps 0.1 --steps 0x1.8p1 --every 0x.8p1 | tail -n +2 | cut -d, -f1 | tr '\n' ' ')
check "--steps 0x1.8p1 --every 0x.8p1 (3 and 1): rows 0 1 2 3 ($k)" test "$k" = "0 1 2 3 "
bad "--steps 922337203685477580.8e1 (2^63)" "*out of range*" --method exact --eps 1 --steps 922337203685477580.8e1
bad "--steps 1e400" "*out of range*" --method exact --eps 1 --steps 1e400
bad "--every -0x10" "*must be positive*" --method exact --eps 1 --steps 1 --every -0x10

# --every-time: k is the row's index, strictly increasing, t = k DT (the driver's k, the accepted
# step, repeats there: several rows fall in one step)
"$S" --no-header --method taylor-adaptive --tol 1e-6 --time 2 --every-time 0.25 >"$T/et.csv"; rc=$?
kt=$(tail -n +2 "$T/et.csv" | awk -F, '{ printf "%s:%s ", $1, ($2 == $1 * 0.25) }')
check "--every-time 0.25 to 2: k = 0..8 with t = k DT on each row ($kt)" \
    test "$rc" = 0 -a "$kt" = "0:1 1:1 2:1 3:1 4:1 5:1 6:1 7:1 8:1 "
"$S" --method taylor-adaptive --tol 1e-6 --time 2 --every-time 0.25 | grep '^# tol:' >"$T/tl"
check "--every-time: the header says what k is ($(cat "$T/tl"))" grep -q "k is the row's index: t = k DT" "$T/tl"

# --time that is no whole number of steps is refused naming times that are accepted
suggested="" broken=""
for et in "7 3" "7 5" "3 10" "0.1 0.35" "0.3 1" "1e-3 0.0105" "2.5 1e-3" "0.7 123456789.1"; do
    set -- $et
    "$S" --method euler --eps "$1" --time "$2" >/dev/null 2>"$T/err"; rc=$?
    times=$(grep -o -- '--time [0-9.e+-]*' "$T/err" | sed '1d; s/--time //')
    [ "$rc" = 2 ] && [ -n "$times" ] || broken="$broken [--eps $1 --time $2: rc $rc, $(cat "$T/err")]"
    for t in $times; do
        "$S" --method exact --eps "$1" --time "$t" --every 1e18 >/dev/null 2>&1 || broken="$broken [--eps $1 --time $t]"
        suggested="$suggested $1:$t"
    done
done
check "a refused --time names valid times (--eps:--time$suggested)${broken:+; broken:$broken}" test -z "$broken"

# progress without escape sequences under TERM=dumb and NO_COLOR
if command -v script >/dev/null; then
    for env in TERM=dumb NO_COLOR=1; do
        env $env SUSLOV_PROGRESS_AFTER=0 script -qec "'$S' --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output '$T/pr.csv'" /dev/null >"$T/tty" 2>&1
        check "$env: a progress line, and no escape character" \
            sh -c "grep -q 'suslov: step' '$T/tty' && ! grep -q \"\$(printf '\033')\" '$T/tty'"
    done
fi

done_tests test_cli_conventions
