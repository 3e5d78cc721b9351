#!/bin/sh
# make bench: the benchmark program, then the wall-clock targets of `make check` and
# `make figures`, with the machine described. Prints PASS/MISS lines; never fails on a MISS.
set -eu
B=${1:-build}
CFLAGS_USED=${2:-}
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'),"
echo "         $(cc --version | head -1), CFLAGS: $CFLAGS_USED"
echo
# bench_boost is the same program with the Boost.Odeint peers (make bench builds it)
if [ -x "$B/bench_boost" ]; then "$B/bench_boost" figures data; else "$B/bench" figures data; fi
sh tools/readme_bench.sh # the README's tables from this run's data/what_to_use.tsv
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
t0=$(date +%s.%N)
# make check's work, timed whole: the tests, and the ledger run afresh (make reruns it only when
# its program changed), into a scratch directory: the ledger writes numbers.tex, ledger.tex,
# summary.tex and methods.tsv beside its TSV, and build/'s are the ones make made
tmp=$(mktemp -d)
{ sh tests/run.sh "$B" test "$B"/test_* && "$B/claims" "$tmp/claims.tsv"; } >/dev/null 2>&1 ||
    echo "  (make check reported failures)"
rm -rf "$tmp"
t1=$(date +%s.%N)
tmp=$(mktemp -d)
# only the figure programs themselves: build/ also holds figure_*.link.d, *.trace and the like
for f in "$B"/figure_*; do
    [ -f "$f" ] && [ -x "$f" ] || continue
    "$f" "$tmp" "$tmp" >/dev/null
done
"$B/animation" data/animation.cfg "$tmp" "$tmp" >/dev/null 2>&1
t2=$(date +%s.%N)
rm -rf "$tmp"
c=$(secs "$t0" "$t1") f=$(secs "$t1" "$t2")
awk -v c="$c" -v f="$f" 'BEGIN {
    printf "  %s make check (tests + claims ledger, built) in %s s (target < 60 s)\n", (c < 60 ? "PASS" : "MISS"), c
    printf "  %s make figures (every figure program and the animation, built) in %s s (target < 120 s)\n", (f < 120 ? "PASS" : "MISS"), f
}'
