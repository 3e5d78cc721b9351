#!/bin/sh
# The test runner. Usage: run.sh BUILD_DIR MODE [TEST_PROGRAM...]
#   test    run exactly the given unit test programs, then the CLI and build tests below
#   ledger  print the claims ledger's table, kept by make in BUILD_DIR/claims.out
#   check   both
# Failing lines are shown; the last line is "N passed, N failed" over all that ran.
set -u
B=${1:-build}
mode=${2:-check}
shift 2 2>/dev/null || shift $#
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# dash runs no EXIT trap when a signal ends it: remove the log, then die of the same signal, so
# that make (or the terminal) sees the interrupt
for sig in INT TERM HUP; do
    # shellcheck disable=SC2064 # $sig now, the rest at the signal
    trap "trap - EXIT $sig; rm -f \"\$log\"; kill -$sig \$\$" $sig
done
status=0
sum="$B/$mode-summary.txt"
: >"$sum"
count() { # count NAME LOGFILE: append its summary line, or a failure when it has none
    if ! grep -qE "^$1: [0-9]+ passed, [0-9]+ failed" "$2"; then
        echo "$1: no summary line (crashed?); its output:"; cat "$2"; status=1
        echo "$1: 0 passed, 1 failed" >>"$2"
    fi
    grep -E "^$1: [0-9]+ passed, [0-9]+ failed" "$2" >>"$sum"
}
run() { # run NAME COMMAND...: show failures and skips, keep the counts
    name=$1; shift
    "$@" >"$log" 2>&1 || status=1
    grep -E '^(FAIL|SKIP)' "$log"
    count "$name" "$log"
}
if [ "$mode" != ledger ]; then
    for t in "$@"; do run "$(basename "$t")" "$t"; done
    # every CLI test script, found by name (tools/mutants.sh finds them the same way)
    for c in tests/cli/test_*.sh; do run "$(basename "$c" .sh)" sh "$c" "$B"; done
    run make_deps sh tests/build/make_deps.sh "$B"
    run layers sh tests/build/layers.sh
    run style sh tests/build/style.sh
    run mutants_fresh sh tests/build/mutants_fresh.sh
    run history sh tests/build/history.sh
    run eqmap sh tools/eqmap.sh check
fi
if [ "$mode" != test ]; then
    # The ledger prints its own table; make ran it only if the claims program changed.
    sed '/^claims: [0-9]* passed/d' "$B/claims.out"
    grep -q '^claims: [0-9]* passed, 0 failed' "$B/claims.out" || status=1
    count claims "$B/claims.out"
    # Every numbered statement of the paper is in the ledger or in paper/not_tested.tsv.
    run paper_coverage sh tools/paper_coverage.sh "$B/claims.tsv"
    # Every tolerance of the ledger has a rule with its reason in paper/tolerances.tsv.
    run paper_tolerances sh tools/paper_tolerances.sh "$B/claims.tsv" paper/tolerances.tsv "$B/tolerances.tex"
    # claims.tsv is the TSV (its header first), not the printed table
    if head -1 "$B/claims.tsv" | grep -q '^id	paper_ref	quantity	measured	expected	tolerance	verdict'; then
        echo "claims_tsv: 1 passed, 0 failed" >>"$sum"
    else
        echo "FAIL claims.tsv does not start with its header"; echo "claims_tsv: 0 passed, 1 failed" >>"$sum"
        status=1
    fi
    # every id once: the companion makes a macro of each
    dup=$(cut -f1 "$B/claims.tsv" | sort | uniq -d | head -3 | tr '\n' ' ')
    if [ -z "$dup" ]; then echo "claims_ids: 1 passed, 0 failed" >>"$sum"; else
        echo "FAIL claims.tsv repeats ids: $dup"; echo "claims_ids: 0 passed, 1 failed" >>"$sum"; status=1; fi
    # No field of the ledger may read nan: a measurement that did not happen is a failure that
    # says so.
    if grep -iqw nan "$B/claims.tsv" 2>/dev/null; then
        grep -iw nan "$B/claims.tsv" | cut -f1 | sed 's/^/FAIL claims.tsv has nan: /'
        echo "claims_no_nan: 0 passed, 1 failed" >>"$sum"; status=1
    else
        echo "claims_no_nan: 1 passed, 0 failed" >>"$sum"
    fi
fi
cat "$sum"
awk '{ p += $2; f += $4 } END { printf "%d passed, %d failed\n", p, f; exit f > 0 }' "$sum" || status=1
exit $status
