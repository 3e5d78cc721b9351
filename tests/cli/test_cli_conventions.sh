#!/bin/sh
# The conventions a scripting user expects of suslov: --version, --, --method list, one number
# grammar, repeated and inapplicable options, --header and its fields, the trailer of an
# incomplete file, long options with =, TERM=dumb and NO_COLOR, and --help, the manual page and
# README.md telling the same. Usage: test_cli_conventions.sh BUILD_DIR
set -u
B=${1:-build}
S="$B/suslov"
. "$(dirname "$0")/cli_testlib.sh"
bad() { # bad DESCRIPTION PATTERN ARGS...: exit 2, one line matching PATTERN, nothing on stdout
    d=$1 pat=$2; shift 2
    "$S" "$@" >"$T/out" 2>"$T/err"; rc=$?
    check "$d: exit 2, one line ($(cat "$T/err"))" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 -a ! -s '$T/out' && grep -q -- '$pat' '$T/err'"
}

# --version: "suslov COMMIT", the commit this checkout is at when built from git, else unknown
v=$("$S" --version); rc=$?
head=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
check "--version prints 'suslov <commit>' ($v; HEAD $head)" \
    sh -c "test $rc = 0 && case '$v' in 'suslov unknown') test '$head' = unknown ;; 'suslov '*) echo '$v' | grep -q '$head' ;; *) false ;; esac"

# -- ends the options; nothing may follow (suslov takes no operands)
"$S" --no-header --method euler --eps 0.1 --steps 1 -- >"$T/o"; rc=$?
check "-- at the end is accepted" test "$rc" = 0 -a "$(wc -l <"$T/o")" = 3
bad "an argument after --" "unexpected argument .--eps" --method euler --eps 0.1 --steps 1 -- --eps

# --method list: TSV when piped, name family order reconstruct about; every method once
"$S" --method list >"$T/list"; rc=$?
nm=$(tail -n +2 "$T/list" | cut -f1 | tr '\n' ' ')
check "--method list: TSV header, 5 fields per line, exact and the registry ($nm)" \
    sh -c "test $rc = 0 -a \"\$(head -1 '$T/list')\" = \"\$(printf 'name\tfamily\torder\treconstruct\tabout')\" &&
           awk -F '\t' 'NF != 5 { exit 1 }' '$T/list' && echo '$nm' | grep -q '^exact euler midpoint rk4 variational '"
if command -v script >/dev/null; then
    script -qec "'$S' --method list" /dev/null >"$T/tty" 2>&1
    check "--method list on a terminal: an aligned table, no tabs" sh -c "grep -q '^exact  *closed form' '$T/tty' && ! grep -q \"\$(printf '\t')\" '$T/tty'"
fi

# --method list takes no other option, valid or not: exit 2, one line, nothing written
for extra in "--eps -1" "--eps 0.1" "--output $T/lst.csv" "--help" "--no-header"; do
    bad "--method list $extra" "^suslov: error: --method list takes no other options" --method list $extra
done
bad "--eps -1 --method=list (either order, either spelling)" "takes no other options" --eps -1 --method=list
check "--method list --output FILE creates no FILE" test ! -e "$T/lst.csv"

# one number grammar: counts accept 1e6 and 0x10 when whole numbers
a=$("$S" --no-header --method exact --eps 1e-6 --steps 1e6 --every 1e6 | tail -1 | cut -d, -f1)
b=$("$S" --no-header --method exact --eps 1e-6 --steps 0x10 --every 2e0 | tail -1 | cut -d, -f1)
check "--steps 1e6 is 1000000 and --steps 0x10 is 16 ($a, $b)" test "$a" = 1000000 -a "$b" = 16
bad "--steps 2.5" "not a whole number" --method euler --eps 0.1 --steps 2.5
bad "--every 1e19 (beyond 2^63 - 1)" "out of range" --method euler --eps 0.1 --steps 1 --every 1e19
bad "a number with a leading blank" "not a number" --method euler --eps ' 0.1' --steps 1

# a repeated option is an error; so are both --header and --no-header
bad "--eps twice" "given twice" --method euler --eps 0.1 --eps 0.2 --steps 1
bad "--header with --no-header" "both given" --method euler --eps 0.1 --steps 1 --header --no-header

# options that do not apply: an error with exact, a one-line warning with a Taylor method
bad "--reconstruct with exact" "does not apply" --method exact --eps 0.1 --steps 1 --reconstruct cayley
"$S" --method taylor8 --eps 0.1 --steps 1 --reconstruct cayley >/dev/null 2>"$T/err"; rc=$?
check "--reconstruct with taylor8: exit 0 and one warning line ($(cat "$T/err"))" \
    sh -c "test $rc = 0 -a \$(wc -l <'$T/err') = 1 && grep -q '^suslov: warning: --reconstruct cayley is ignored' '$T/err'"
bad "--reconstruct with taylor8 and a bad --output (the warning waits for the checks)" "does not exist" \
    --method taylor8 --eps 0.1 --steps 1 --reconstruct cayley --output "$T/missing/x.csv"
"$S" --method midpoint --eps 0.1 --steps 1 --reconstruct exp-mid >/dev/null 2>"$T/err"
check "--reconstruct with midpoint: no warning" test ! -s "$T/err"

# a long option with = never swallows the next argument
long="--$(printf '%070d' 0)=1"
bad "a 72-character option with =" "unknown option .--0000" --method euler --eps 0.1 --steps 1 "$long" --quiet

# --header (default): # lines with version, command, method, eps, inertia, omega0, units, then
# the CSV header; --no-header: the CSV header first
"$S" --method comp4-s5 --eps 0.25 --steps 2 --omega0 0.3,-0.2 >"$T/h.csv"
check "header: version, command line, method, eps, inertia, omega0, units before the CSV header" \
    sh -c "grep -q '^# suslov ' '$T/h.csv' && grep -q '^# command: suslov --method comp4-s5 --eps 0.25 --steps 2 --omega0 0.3,-0.2$' '$T/h.csv' &&
           grep -q '^# method: comp4-s5 (composition, order 4), reconstruction exp-mid$' '$T/h.csv' &&
           grep -q '^# eps: 0.25, steps: 2, every: 1, final time: 0.5$' '$T/h.csv' && grep -q '^# inertia' '$T/h.csv' &&
           grep -q '^# omega0: 0.29999999999999999,-0.20000000000000001,0$' '$T/h.csv' && grep -q '^# units' '$T/h.csv' &&
           test \"\$(grep -v '^#' '$T/h.csv' | head -1 | cut -d, -f1-3)\" = k,t,omega1"
# a method that carries its own attitude (--method list: reconstruct "own") says so in its header,
# never a reconstruction it does not use; --help says "(ignores --reconstruct)" on its line and
# lists it under no reconstruction (gauss4's attitude is its collocation's, as the Taylor series')
"$S" --method list >"$T/list"
"$S" --help >"$T/help"
wrong=""
while IFS="$(printf '\t')" read -r m family order recon about; do
    [ "$m" = name ] || [ "$m" = exact ] && continue
    args="--eps 0.25 --steps 1"; [ "$order" = tol ] && args="--tol 1e-8 --time 0.25"
    line=$("$S" --method "$m" $args | grep '^# method: ')
    hl=$(grep "^ *$m " "$T/help" | head -1)
    if [ "$recon" = own ]; then
        echo "$line" | grep -q ', attitude: own (quaternion; --reconstruct does not apply)$' || wrong="$wrong [$line]"
        echo "$hl" | grep -q '(ignores --reconstruct)$' || wrong="$wrong [help: $hl]"
        grep -E '^ +[a-z0-9, -]+: (cayley|cayley-mid|exp-mid)$' "$T/help" | grep -qw -- "$m" && wrong="$wrong [$m under a default]"
    else
        echo "$line" | grep -q ", reconstruction $recon\$" || wrong="$wrong [$line]"
    fi
done <"$T/list"
check "header and --help: own-attitude methods say 'attitude: own', the others their reconstruction${wrong:+; wrong:$wrong}" \
    sh -c "test -z '$wrong' && grep -q '^ *gauss4 .*(ignores --reconstruct)\$' '$T/help' && grep -q '^gauss4.*own' '$T/list'"
"$S" --no-header --method euler --eps 0.1 --steps 1 | head -1 | cut -d, -f1-2 >"$T/nh"
check "--no-header: the CSV header is the first line" test "$(cat "$T/nh")" = k,t
"$S" --method euler --eps 0.1 --steps 1 "$(printf 'x\ny')" >/dev/null 2>&1
"$S" --method euler --eps 0.1 --steps 1 --output "$T/q'u o.csv" 2>/dev/null
check "the command line is quoted for the shell, on one line" grep -q "^# command: .* --output '.*q'\\\\''u o.csv'$" "$T/q'u o.csv"

# a file left after exit 3 says so in a last comment line (not with --no-header: bare CSV); the
# 2-stage Gauss step from this w0 meets a fold of its branch at h ~ 3.6 (src/exp/stability.h)
"$S" --method gauss4 --eps 1000 --steps 10 --omega0 0.27619224,-0.63956748 --output "$T/fail.csv" 2>/dev/null; rc=$?
check "after exit 3 the last line is '# incomplete: ...' naming the failure" \
    sh -c "test $rc = 3 && tail -1 '$T/fail.csv' | grep -q '^# incomplete: .*gauss4 step 1 (t = 1000) failed'"

# progress without escape sequences under TERM=dumb and NO_COLOR
if command -v script >/dev/null; then
    for env in TERM=dumb NO_COLOR=1; do
        env $env SUSLOV_PROGRESS_AFTER=0 script -qec "'$S' --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output '$T/pr.csv'" /dev/null >"$T/tty" 2>&1
        check "$env: a progress line, and no escape character" \
            sh -c "grep -q 'suslov: step' '$T/tty' && ! grep -q \"\$(printf '\033')\" '$T/tty'"
    done
fi

# --help, the manual page and README.md tell the same: the manual page is written from the
# option table --help prints, and README.md quotes --help verbatim between its markers
"$S" --help >"$T/help"
"$S" --man >"$T/man"
missing=""
for o in $(grep -o '^  --[a-z0-9-]*' "$T/help"); do
    grep -q "^\\.B $(echo "$o" | sed 's/-/\\\\-/g')" "$T/man" || missing="$missing $o"
done
check "every option of --help has its entry in the manual page${missing:+ (missing:$missing)}" test -z "$missing"
cmp -s "$T/man" "$B/man/suslov.1"
check "the built manual page $B/man/suslov.1 is the one suslov --man writes" cmp -s "$T/man" "$B/man/suslov.1"
sed -n '/^<!-- suslov --help -->$/,/^<!-- end suslov --help -->$/p' README.md | sed '1,2d;$d' | sed '$d' >"$T/readme"
check "README.md quotes suslov --help verbatim (its promises are --help's)" cmp -s "$T/help" "$T/readme"

done_tests test_cli_conventions
