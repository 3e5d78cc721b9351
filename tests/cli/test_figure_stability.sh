#!/bin/sh
# figure_stability's number of processes (--jobs N, SUSLOV_JOBS): a value that is not a whole
# number from 1 to 256 is refused before any run, with one line and exit 2, and nothing written;
# its usage line names both options.
# (That the map is the same bytes for any number of processes is test_workpool's.)
# Usage: test_figure_stability.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
P="$B/figure_stability"
refused() { # refused DESCRIPTION [VAR=VALUE] ARG...: exit 2, one line on stderr, nothing written
    d=$1
    shift
    mkdir -p "$T/out"
    env "$@" "$T/out" "$T/out" >/dev/null 2>"$T/err"
    rc=$?
    n=$(wc -l <"$T/err")
    check "$d is refused: exit $rc (2), $n line(s) (1): $(head -1 "$T/err"); nothing written" \
        sh -c "test $rc = 2 -a $n = 1 -a -z \"\$(ls -A '$T/out')\""
}
if [ -x "$P" ]; then
    refused "--jobs 0" "$P" --quiet --jobs 0
    refused "--jobs 257" "$P" --quiet --jobs 257
    refused "--jobs 2x" "$P" --quiet --jobs 2x
    refused "SUSLOV_JOBS=0" SUSLOV_JOBS=0 "$P" --quiet
    refused "SUSLOV_JOBS= (empty)" SUSLOV_JOBS= "$P" --quiet
    "$P" --quiet >/dev/null 2>"$T/err"; rc=$?
    check "a missing directory: exit $rc (2), a usage line that names both options ($(cat "$T/err"))" \
        sh -c "test $rc = 2 -a \$(wc -l <'$T/err') = 1 && grep -q -- '--quiet.*--jobs N' '$T/err'"
else
    skip "figure_stability is not built"
fi
done_tests test_figure_stability
