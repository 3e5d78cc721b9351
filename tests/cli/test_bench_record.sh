#!/bin/sh
# The recorded bench run (data/bench-recorded/, written only by make bench-record) that the
# companion and the docs quote: every file there, every \Bench macro the companion uses defined by
# it, and its figures drawn again from its data alone by `bench --plot` (what make figures does),
# the same bytes twice. And bench's refusals: a usage error is one line and exit 2; a directory
# without a bench.csv is one line, a failure, and no figure.
# Usage: test_bench_record.sh BUILD_DIR. Last line: "test_bench_record: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
R=data/bench-recorded
for f in bench.csv bench.tex what_to_use.tsv longruns.tsv bench.txt machine.txt machine.tex summary.md; do
    check "the recorded run has $f" test -s "$R/$f"
done
check "machine.txt says when, from which commit, and how loaded the machine was" \
    sh -c "grep -q '^date: ' $R/machine.txt && grep -q '^commit: [0-9a-f]\{40\}' $R/machine.txt &&
           grep -q '^load average .* at the start: ' $R/machine.txt"
check "summary.md lists the targets' verdicts" grep -q '^- \*\*\(PASS\|MISS\)\*\*' "$R/summary.md"
# every \Bench... macro the companion's sources use is defined by the recorded run (its misses by
# tools/bench_summary.sh from its bench.txt, as make paper has them)
sh tools/bench_summary.sh "$R" misses >"$T/misses.tex"
missing=$(awk 'FNR == 1 { used = FILENAME ~ /^paper\// }
    !used { s = $0; while (match(s, /\\newcommand\{\\Bench[A-Za-z]*\}/)) {
                def[substr(s, RSTART + 12, RLENGTH - 13)] = 1; s = substr(s, RSTART + RLENGTH) } }
    used { s = $0; while (match(s, /\\Bench[A-Za-z]*/)) {
               m = substr(s, RSTART, RLENGTH); if (!(m in def) && !seen[m]++) printf " %s", m
               s = substr(s, RSTART + RLENGTH) } }' "$R/bench.tex" "$R/machine.tex" "$T/misses.tex" paper/*.tex)
check "every \\Bench macro of paper/*.tex is defined by the recorded run (missing:${missing:- none})" \
    test -z "$missing"
mkdir -p "$T/a" "$T/b"
check "bench --plot draws the figures from the recorded data" "$B/bench" --plot "$T/a" "$R"
for f in work_precision.pdf work_precision.png work_precision_best.pdf work_precision_best.png \
    step_cost.pdf step_cost.png; do
    check "bench --plot wrote $f" test -s "$T/a/$f"
done
"$B/bench" --plot "$T/b" "$R" >/dev/null 2>&1
check "the same data, the same bytes" sh -c "cmp -s '$T/a/work_precision.png' '$T/b/work_precision.png' &&
    cmp -s '$T/a/step_cost.pdf' '$T/b/step_cost.pdf'"
"$B/bench" --plot >"$T/out" 2>"$T/err"
rc=$?
check "bench with missing arguments: exit 2 (got $rc), usage on stderr, nothing on stdout" \
    sh -c "[ $rc = 2 ] && grep -q '^usage: bench' '$T/err' && [ ! -s '$T/out' ]"
mkdir -p "$T/empty" "$T/c"
"$B/bench" --plot "$T/c" "$T/empty" 2>"$T/err"
rc=$?
check "bench --plot without a bench.csv: fails (exit $rc) with one line, and draws nothing" \
    sh -c "[ $rc != 0 ] && [ \$(wc -l <'$T/err') = 1 ] && [ -z \"\$(ls '$T/c')\" ]"
done_tests test_bench_record
