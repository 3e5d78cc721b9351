#!/bin/sh
# make bench and make bench-record: one run of the benchmark program, then the wall-clock targets
# of `make check`, `make figures` and figure_stability, the machine described, and a Markdown
# summary. Prints PASS/MISS lines; never fails on a MISS.
# Usage: bench.sh BUILD CFLAGS OUTDIR FIGDIR [NOTE]
#   OUTDIR gets the run whole or not at all (it is replaced only when the run succeeded): bench.csv,
#   bench.tex, what_to_use.tsv and longruns.tsv (the program's), bench.txt (what it printed, and
#   the wall-clock lines), machine.txt and machine.tex (where, when, from which commit, the load
#   on the machine, NOTE), summary.md (tools/bench_summary.sh). FIGDIR gets the run's figures.
set -eu
B=$1 CFLAGS_USED=$2 OUT=$3 FIG=$4 NOTE=${5:-}
mkdir -p "$(dirname "$OUT")" "$FIG"
tmp="$OUT.tmp.$$"
rm -rf "$tmp"
mkdir "$tmp"
. tools/on_exit.sh
on_exit 'rm -rf "$tmp"'
load() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown; }
load0=$(load)
start=$(date -u '+%Y-%m-%d %H:%M UTC')
t0=$(date +%s.%N)
# bench_boost is the same program with the Boost.Odeint peers (make bench builds it)
prog="$B/bench"
[ -x "$B/bench_boost" ] && prog="$B/bench_boost"
if ! "$prog" "$FIG" "$tmp" >"$tmp/bench.txt"; then
    cat "$tmp/bench.txt"
    echo "bench: the run failed; $OUT is left as it was" >&2
    exit 1
fi
cat "$tmp/bench.txt"
t1=$(date +%s.%N)
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
# make check's work, timed whole, three times (the median judges; this VM's speed varies between
# runs by more than a target's margin): the tests, and the ledger run afresh (make reruns it only
# when its program changed) as make runs it, a process per section on every core, into a scratch
# directory: the ledger writes numbers.tex, ledger.tex, summary.tex and methods.tsv beside its TSV,
# and build/'s are the ones make made. A failing run ends the timing: its time says nothing.
checked=1 ctimes=""
for run in 1 2 3; do
    scratch=$(mktemp -d)
    c0=$(date +%s.%N)
    { sh tests/run.sh "$B" test "$B"/test_* && "$B/claims" "$scratch/claims.tsv"; } >/dev/null 2>&1 ||
        checked=0
    ctimes="$ctimes $(secs "$c0" "$(date +%s.%N)")"
    rm -rf "$scratch"
    [ "$checked" = 1 ] || break
done
scratch=$(mktemp -d)
# figure_stability alone, on every core (its own target); then make -j2 figures' work: every figure
# program and the animation two at a time, the two long ones first, as the Makefile lists them
# (only the programs themselves: build/ also holds figure_*.link.d, *.trace and the like)
stab=""
s0=$(date +%s.%N)
"$B/figure_stability" "$scratch" "$scratch" >/dev/null 2>&1 && stab=$(secs "$s0" "$(date +%s.%N)")
# one program, run by xargs: sh -c's $0 is the scratch directory, $1 the program
# shellcheck disable=SC2016
run_one='case $1 in */animation) exec "$1" data/animation.cfg "$0" "$0" ;; *) exec "$1" "$0" "$0" ;; esac'
f0=$(date +%s.%N)
for f in "$B/figure_stability" "$B/animation" "$B"/figure_*; do
    [ -f "$f" ] && [ -x "$f" ] && echo "$f"
done | awk '!seen[$0]++' | xargs -d '\n' -P 2 -n 1 sh -c "$run_one" "$scratch" >/dev/null 2>&1
f1=$(date +%s.%N)
rm -rf "$scratch"
awk -v ct="$ctimes" -v f="$(secs "$f0" "$f1")" -v s="${stab:-nan}" -v n="$(nproc)" \
    -v ok="$checked" -v logs="$B/tests" 'BEGIN {
    k = split(ct, t, " ") # the make check times (at most three), the last, then sorted
    last = t[k]
    for (i = 2; i <= k; i++)
        for (j = i; j > 1 && t[j - 1] + 0 > t[j] + 0; j--) { x = t[j]; t[j] = t[j - 1]; t[j - 1] = x }
    c = t[int((k + 1) / 2)]
    printf "Wall-clock targets (this machine, as loaded as it was):\n"
    printf "  %s figure_stability on %d cores in %s s (target <= 10 s)\n", (s != "nan" && s <= 10 ? "PASS" : "MISS"), n, s
    printf "  %s make -j2 figures (every figure program and the animation, built, two at a time) in %s s (target <= 25 s)\n", (f <= 25 ? "PASS" : "MISS"), f
    if (ok)
        printf "  %s make check (the tests and the claims ledger run afresh, built; the median of %d runs, %s to %s s) in %s s (target <= 40 s)\n", (c <= 40 ? "PASS" : "MISS"), k, t[1], t[k], c
    else # a failing test ends the run early: its time says nothing of make check
        printf "  MISS make check (the tests and the claims ledger run afresh, built): a test failed after %s s, so there is no time to judge (the logs: %s/)\n", last, logs
}' | tee -a "$tmp/bench.txt"
load1=$(load)
commit=$(git rev-parse HEAD 2>/dev/null || echo "not a git checkout")
dirty=""
[ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ] && dirty=" (with uncommitted changes)"
{
    echo "date: $start"
    echo "commit: $commit$dirty"
    echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
    echo "cores: $(nproc)"
    echo "os: $( (. /etc/os-release && echo "$PRETTY_NAME") 2>/dev/null || uname -s), kernel $(uname -r)"
    echo "compiler: $(${CC:-cc} --version | head -1), CFLAGS $CFLAGS_USED"
    echo "gsl: $(pkg-config --modversion gsl 2>/dev/null || echo unknown)"
    echo "boost: $(sed -n 's/^#define BOOST_LIB_VERSION "\(.*\)"/\1/p' /usr/include/boost/version.hpp 2>/dev/null | tr _ .)"
    echo "load average (1, 5, 15 min) at the start: $load0"
    echo "load average (1, 5, 15 min) at the end: $load1"
    echo "bench seconds (wall clock): $(secs "$t0" "$t1")"
    [ -z "$NOTE" ] || echo "note: $NOTE"
} >"$tmp/machine.txt"
sh tools/bench_summary.sh "$tmp" tex >"$tmp/machine.tex"
sh tools/bench_summary.sh "$tmp" md "$OUT" >"$tmp/summary.md"
rm -rf "$OUT"
mv "$tmp" "$OUT"
trap - EXIT
echo "bench: wrote $OUT/ (summary.md, the data and machine.txt) and $FIG/ (the figures)"
