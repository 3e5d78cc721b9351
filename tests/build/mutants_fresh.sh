#!/bin/sh
# The hand-listed mutants still match the code: the FROM text of every line of
# tests/build/mutants occurs exactly once in its file, so a rename or a reformatting cannot
# silently turn a mutant into one that make mutants reports as stale only in CI.
# Last line "mutants_fresh: N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
awk -F' [|] ' '
/^#/ || NF < 3 { next }
{
    file = $1; from = $2; n = 0
    text = ""; while ((getline line < file) > 0) text = text line "\n"; close(file)
    while ((i = index(text, from)) > 0) { n++; text = substr(text, i + length(from)) }
    if (n == 1) pass++
    else { printf "FAIL mutant of %s: its text occurs %d times (once expected): %s\n", file, n, from; fail++ }
}
END { printf "mutants_fresh: %d passed, %d failed\n", pass, fail; exit fail > 0 }' tests/build/mutants
