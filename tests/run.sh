#!/bin/sh
# make check: run every unit test, the CLI tests and the claims ledger; print the ledger and,
# alone on the last line, "N passed, N failed" over all of them. Usage: run.sh BUILD_DIR
set -u
B=${1:-build}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
run() { # run NAME COMMAND...: show failures and the summary line, keep the counts
    name=$1; shift
    "$@" >"$log" 2>&1 || status=1
    grep -E '^(FAIL|SKIP)' "$log"
    if ! grep -qE "^$name: [0-9]+ passed, [0-9]+ failed" "$log"; then
        echo "$name: no summary line (crashed?); its output:"; cat "$log"; status=1
        echo "$name: 0 passed, 1 failed" >>"$log"
    fi
    grep -E "^$name: [0-9]+ passed, [0-9]+ failed" "$log" >>"$B/check-summary.txt"
}
: >"$B/check-summary.txt"
for t in "$B"/test_*; do
    case $t in *.o|*.d) continue ;; esac
    run "$(basename "$t")" "$t"
done
run test_cli sh tests/test_cli.sh "$B"
run test_cli_values sh tests/test_cli_values.sh "$B"
run test_animation_errors sh tests/test_animation_errors.sh "$B"
run make_deps sh tests/make_deps.sh "$B"
run eqmap sh tools/eqmap.sh check

# The claims ledger prints its own table.
"$B/claims" "$B/claims.tsv" >"$log" 2>&1 || status=1
if grep -q '^claims: [0-9]* passed' "$log"; then
    sed '/^claims: [0-9]* passed/d' "$log"
    grep '^claims: ' "$log" >>"$B/check-summary.txt"
else
    cat "$log"; echo "claims: 0 passed, 1 failed" >>"$B/check-summary.txt"; status=1
fi
# No field of the ledger may read nan: a measurement that did not happen is a failure that says so.
if grep -iqw nan "$B/claims.tsv" 2>/dev/null; then
    grep -iw nan "$B/claims.tsv" | cut -f1 | sed 's/^/FAIL claims.tsv has nan: /'
    echo "claims_no_nan: 0 passed, 1 failed" >>"$B/check-summary.txt"; status=1
else
    echo "claims_no_nan: 1 passed, 0 failed" >>"$B/check-summary.txt"
fi
cat "$B/check-summary.txt"
awk '{ p += $2; f += $4 } END { printf "%d passed, %d failed\n", p, f; exit f > 0 }' "$B/check-summary.txt" || status=1
exit $status
