#!/bin/sh
# The test runner. Usage: run.sh BUILD_DIR MODE [TEST_PROGRAM...]
#   test    run exactly the given unit test programs, then the CLI and build tests below
#   ledger  the claims ledger's table (whole) and checks, on what make kept in BUILD_DIR/claims.out
#   check   both
# One line per stage (unit tests, CLI tests, build checks, the ledger, the paper's checks): PASS or
# FAIL, what ran and its counts. A failure is shown in full under its stage: the FAIL lines of each
# program that failed, or all its output when it printed no summary (a crash). Every program's
# output is kept in BUILD_DIR/tests/NAME.log, its counts in BUILD_DIR/MODE-summary.txt, the skipped
# checks in BUILD_DIR/tests/skipped.txt. The last line is "N passed, N failed" over all that ran.
set -u
B=${1:-build}
mode=${2:-check}
shift 2 2>/dev/null || shift $#
L="$B/tests"
mkdir -p "$L"
sum="$B/$mode-summary.txt"
: >"$sum"
: >"$L/skipped.txt"
status=0
# the current stage: its title, programs' names, counts and failures so far
st_names="" st_pass=0 st_fail=0 st_skip=0 st_out=""
st_begin() { # st_begin TITLE N: N programs to run
    st_title=$1 st_n=$2 st_k=0 st_t0=$(date +%s)
    st_names="" st_pass=0 st_fail=0 st_skip=0 st_out=$(mktemp)
}
# On a terminal (not under NO_PROGRESS), the stage's line says what runs until its result replaces
# it: "      CLI tests      3 of 10, 12 s: test_cli_promises"; a terminal without escape
# sequences (TERM=dumb, NO_COLOR) gets spaces over it.
live=0
[ -t 1 ] && [ -z "${NO_PROGRESS:-}" ] && live=1
clear_line() {
    [ "$live" = 1 ] || return 0
    if [ "${TERM:-}" = dumb ] || [ -n "${NO_COLOR:-}" ]; then printf '\r%79s\r' ''; else printf '\r\033[K'; fi
}
# count NAME LOG [STATUS]: the program's summary line into the stage and the summary file; a log
# with none is a failure shown whole, and so is a failing exit STATUS beside no failed check
count() {
    line=$(grep -E "^$1: [0-9]+ passed, [0-9]+ failed" "$2" | tail -1)
    if [ -z "$line" ]; then
        { echo "$1: no summary line (crashed?); its output:"; sed 's/^/    /' "$2"; } >>"$st_out"
        line="$1: 0 passed, 1 failed"
    elif [ "${3:-0}" != 0 ] && [ "$(echo "$line" | awk '{ print $4 }')" = 0 ]; then
        { echo "$1: exit status $3 after no failed check; its output:"
          sed 's/^/    /' "$2"; } >>"$st_out"
        line=$(echo "$line" | awk '{ $4 = 1; print }')
    fi
    echo "$line" >>"$sum"
    set -- $line
    st_pass=$((st_pass + $2)) st_fail=$((st_fail + $4))
}
# run NAME COMMAND...: the program's output into its log; its FAIL lines into the stage's failures
run() {
    name=$1; shift
    st_names="$st_names $name" st_k=$((st_k + 1))
    if [ "$live" = 1 ]; then
        clear_line
        printf '      %-14s %d of %d, %d s: %s' "$st_title" "$st_k" "$st_n" $(($(date +%s) - st_t0)) \
            "$name" | cut -c1-79 | tr -d '\n'
    fi
    rc=0
    "$@" </dev/null >"$L/$name.log" 2>&1 || rc=$? # a test never reads the terminal
    grep -E '^FAIL' "$L/$name.log" >>"$st_out"
    n=$(grep -cE '^SKIP' "$L/$name.log")
    grep -E '^SKIP' "$L/$name.log" >>"$L/skipped.txt"
    st_skip=$((st_skip + n))
    count "$name" "$L/$name.log" "$rc"
}
# st_end TITLE WHAT: the stage's line, then its failures
st_end() {
    clear_line
    skipped=""
    [ "$st_skip" = 0 ] || skipped=", $st_skip skipped (see $L/skipped.txt)"
    [ "$st_fail" = 0 ] && verdict=PASS || { verdict=FAIL; status=1; }
    printf '%s  %-14s %s: %d passed, %d failed%s\n' "$verdict" "$1" "$2" "$st_pass" "$st_fail" \
        "$skipped"
    sed 's/^/      /' "$st_out"
    rm -f "$st_out"
}
# dash runs no EXIT trap when a signal ends it: remove the stage's file, then die of the same
# signal, so that make (or the terminal) sees the interrupt
trap 'rm -f "$st_out"' EXIT
for sig in INT TERM HUP; do
    # shellcheck disable=SC2064 # $sig now, the rest at the signal
    trap "trap - EXIT $sig; rm -f \"\$st_out\"; kill -$sig \$\$" $sig
done
if [ "$mode" != ledger ]; then
    st_begin "unit tests" $#
    for t in "$@"; do run "$(basename "$t")" "$t"; done
    st_end "unit tests" "$# programs"
    # every CLI test script, found by name (tools/mutants.sh finds them the same way)
    st_begin "CLI tests" "$(ls tests/cli/test_*.sh | wc -l)"
    for c in tests/cli/test_*.sh; do run "$(basename "$c" .sh)" sh "$c" "$B"; done
    st_end "CLI tests" "$(echo $st_names | wc -w) scripts"
    st_begin "build checks" 9
    run make_deps sh tests/build/make_deps.sh "$B"
    run layers sh tests/build/layers.sh
    run style sh tests/build/style.sh
    run format sh tests/build/format.sh
    run mutants_fresh sh tests/build/mutants_fresh.sh
    run history sh tests/build/history.sh
    run eqmap sh tools/eqmap.sh check
    run doc_links sh tests/build/doc_links.sh
    run doc_facts sh tests/build/doc_facts.sh
    # the steps of docs/howto/add-a-method.md, taken in a scratch copy of the tree and build
    run scaffold_method sh tests/build/scaffold_method.sh "$B"
    st_end "build checks" "$(echo $st_names | tr ' ' ',' | sed 's/,/, /g')"
fi
if [ "$mode" != test ]; then
    st_begin "claims ledger" 0
    # claims.out (make ran the ledger only if the claims program changed) holds the table, then
    # under "checks that failed:" each failing line again, then the findings. The table is printed
    # whole by make ledger and with V=1; a failing line always, in full, under the stage's line.
    cp "$B/claims.out" "$L/claims.log"
    st_names=claims
    if [ "$mode" = ledger ] || [ "${V:-0}" = 1 ]; then
        awk '/^checks that failed:$/ || /^findings of / { exit } { print }' "$B/claims.out"
    fi
    awk '/^checks that failed:$/ { on = 1; next } /^findings of / { exit } on && NF' \
        "$B/claims.out" >>"$st_out"
    grep -q '^claims: [0-9]* passed, 0 failed' "$B/claims.out" || status=1
    count claims "$B/claims.out"
    # claims.tsv is the TSV (its header first), not the printed table
    want='^id	paper_ref	quantity	measured	expected	tolerance	verdict'
    if head -1 "$B/claims.tsv" | grep -q "$want"; then
        echo "claims_tsv: 1 passed, 0 failed" >>"$sum"; st_pass=$((st_pass + 1))
    else
        echo "FAIL claims.tsv does not start with its header" >>"$st_out"
        echo "claims_tsv: 0 passed, 1 failed" >>"$sum"; st_fail=$((st_fail + 1))
    fi
    # every id once: the companion makes a macro of each
    dup=$(cut -f1 "$B/claims.tsv" | sort | uniq -d | head -3 | tr '\n' ' ')
    if [ -z "$dup" ]; then
        echo "claims_ids: 1 passed, 0 failed" >>"$sum"; st_pass=$((st_pass + 1))
    else
        echo "FAIL claims.tsv repeats ids: $dup" >>"$st_out"
        echo "claims_ids: 0 passed, 1 failed" >>"$sum"; st_fail=$((st_fail + 1))
    fi
    # No field of the ledger may read nan: a measurement that did not happen is a failure that
    # says so.
    if grep -iqw nan "$B/claims.tsv" 2>/dev/null; then
        grep -iw nan "$B/claims.tsv" | cut -f1 | sed 's/^/FAIL claims.tsv has nan: /' >>"$st_out"
        echo "claims_no_nan: 0 passed, 1 failed" >>"$sum"; st_fail=$((st_fail + 1))
    else
        echo "claims_no_nan: 1 passed, 0 failed" >>"$sum"; st_pass=$((st_pass + 1))
    fi
    # The same files, byte for byte, from one section after the other in one process (claims -j1,
    # which make ran into $B/ledger-j1): the parallel sections lean on no other's state.
    differ=""
    for f in claims.out claims.tsv methods.tsv numbers.tex ledger.tex summary.tex sensitivity.tex \
        claims_tex.tsv; do cmp -s "$B/ledger-j1/$f" "$B/$f" || differ="$differ $f"; done
    if [ -z "$differ" ]; then
        echo "ledger_j1: 1 passed, 0 failed" >>"$sum"; st_pass=$((st_pass + 1))
    else
        echo "FAIL the ledger on one core ($B/ledger-j1) differs from the parallel run in:$differ" \
            >>"$st_out"
        echo "ledger_j1: 0 passed, 1 failed" >>"$sum"; st_fail=$((st_fail + 1))
    fi
    lines=$(awk 'END { print NR - 1 }' "$B/claims.tsv")
    st_end "claims ledger" "$lines lines, table in $B/claims.out"
    st_begin "paper checks" 3
    # Every numbered statement of the paper is in the ledger or in paper/not_tested.tsv.
    run paper_coverage sh tools/paper_coverage.sh "$B/claims.tsv"
    # Every tolerance of the ledger has a rule with its reason in paper/tolerances.tsv.
    run paper_tolerances sh tools/paper_tolerances.sh "$B/claims.tsv" paper/tolerances.tsv \
        "$B/tolerances.tex"
    # The committed PDFs print the numbers this ledger gives (make paper writes them).
    run paper_fresh sh tools/paper_fresh.sh "$B"
    st_end "paper checks" "$(echo $st_names | tr ' ' ',' | sed 's/,/, /g')"
    # The findings, last: the tally by verdict and each line that contradicts the paper, by its
    # published number; then where the whole ledger is.
    awk '/^findings of / { on = 1 } /^claims: [0-9]+ passed/ { exit } on' "$B/claims.out"
    echo "the whole ledger: $B/claims.out (each line's check and finding) and $B/claims.tsv;" \
        "make ledger, or make check V=1, prints it"
fi
awk '{ p += $2; f += $4 } END { printf "%d passed, %d failed\n", p, f; exit f > 0 }' "$sum" || status=1
exit $status
