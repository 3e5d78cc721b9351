#!/bin/sh
# Runs a command and records its wall-clock time, for the companion's reproducibility block.
# Usage: timed.sh OUT COMMAND...   OUT gets one line, the seconds; the exit status is the
# command's. A failed run is recorded as "SECONDS failed", so that the companion does not quote
# it as a normal one. The file is written whole (through a temporary) or not at all.
set -u
out=$1; shift
t0=$(date +%s.%N)
"$@"
rc=$?
t1=$(date +%s.%N)
mkdir -p "$(dirname "$out")"
awk -v a="$t0" -v b="$t1" -v rc="$rc" 'BEGIN { printf "%.1f%s\n", b - a, rc == 0 ? "" : " failed" }' \
    >"$out.tmp" && mv "$out.tmp" "$out"
exit $rc
