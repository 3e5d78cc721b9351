#!/bin/sh
# The test scripts' own promises: an interrupted test (INT, TERM or HUP, as make test gets from a
# terminal or a job control) leaves no scratch file behind and dies of the signal, under dash
# too, which runs no EXIT trap on a signal; the runner reports what its programs did; and every
# CLI script works the same from a relative or an absolute build directory.
# Usage: test_scripts.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
LIB="$PWD/tests/cli/cli_testlib.sh"

# interrupted SIG DESCRIPTION READY COMMAND...: runs COMMAND with TMPDIR in a fresh directory, in
# a process group of its own (so that, as from a terminal, the signal reaches the script and its
# child at once), with SIG at its default action (a background job would ignore SIGINT); once the
# file READY exists and $after seconds more have passed (default 0), signals the group. The script
# must die of SIG (128 + n) and leave TMPDIR empty.
interrupted() {
    sig=$1 d=$2 ready=$3; shift 3
    X=$(mktemp -d "$T/tmp.XXXXXX")
    rm -f "$ready"
    TMPDIR=$X setsid env --default-signal=INT,TERM,HUP "$@" >/dev/null 2>&1 &
    pid=$!
    i=0
    while [ ! -e "$ready" ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
    sleep "${after:-0}"
    kill -s "$sig" -- "-$pid"
    { wait "$pid"; } 2>/dev/null; rc=$?
    case $sig in HUP) want=129 ;; INT) want=130 ;; TERM) want=143 ;; esac
    entries "$X"
    left=$entries
    check "$d, interrupted by SIG$sig: status $rc ($want), nothing left in TMPDIR (${left:-empty})" \
        test -e "$ready" -a "$rc" = "$want" -a -z "$left"
}

if command -v setsid >/dev/null && env --default-signal=INT true 2>/dev/null; then
    # a script of the library: its scratch directory and an at_exit file outside it
    cat >"$T/victim.sh" <<EOF
B="$B"
. "$LIB"
extra=\$(mktemp)
at_exit 'rm -f "\$extra"'
: >"$T/ready"
sleep 30
EOF
    for sig in INT TERM HUP; do
        interrupted $sig "a script using cli_testlib.sh" "$T/ready" sh "$T/victim.sh"
    done
    # the runner itself, interrupted while it runs a (stand-in) unit test beside the CLI scripts
    # its pool has started (each at whatever point of its start the signal finds it)
    printf '#!/bin/sh\n: >"%s"\nexec sleep 30\n' "$T/ready" >"$T/sleeper"
    chmod +x "$T/sleeper"
    mkdir -p "$T/b"
    for after in 0 0.3 0.6; do # the pool's scripts caught at three points of their start
        interrupted INT "tests/run.sh, $after s after its stand-in started" "$T/ready" \
            sh tests/run.sh "$T/b" test "$T/sleeper"
    done
else
    skip "interrupts: needs setsid and env --default-signal"
fi

# The runner's report (its header): a failure is shown under its stage, in the order of the
# programs: the FAIL lines of a program that failed; all the output of one that printed no summary
# line (a crash), or that exited with a failing status beside no failed check, each then counted
# as one failed check. SKIP lines are counted and kept in skipped.txt, the counts in the summary
# file; the last line is the total, and the status fails.
mkdir -p "$T/u"
stand_in() { printf '#!/bin/sh\n%s\n' "$2" >"$T/u/$1" && chmod +x "$T/u/$1"; } # stand_in NAME BODY
stand_in ok 'echo "PASS a"; echo "SKIP b: no tool"; echo "ok: 3 passed, 0 failed"'
stand_in bad 'echo "FAIL x"; echo "  why"; echo "bad: 4 passed, 1 failed"; exit 1'
stand_in crash 'echo "PASS y"; echo two'
stand_in quiet 'echo "quiet: 2 passed, 0 failed"; exit 3'
sh tests/run.sh "$T/u" unit "$T/u/ok" "$T/u/bad" "$T/u/crash" "$T/u/quiet" >"$T/u/out" 2>&1; rc=$?
printf '%s\n' \
    "FAIL  unit tests     4 programs: 9 passed, 3 failed, 1 skipped (see $T/u/tests/skipped.txt)" \
    "      FAIL x" "      crash: no summary line (crashed?); its output:" "          PASS y" \
    "          two" "      quiet: exit status 3 after no failed check; its output:" \
    "          quiet: 2 passed, 0 failed" "9 passed, 3 failed" >"$T/u/want"
printf '%s\n' "ok: 3 passed, 0 failed" "bad: 4 passed, 1 failed" "crash: 0 passed, 1 failed" \
    "quiet: 2 passed, 1 failed" >"$T/u/want-summary"
check "tests/run.sh reports a failed check, a crash, a failing status, a skip: status 1 ($rc)" \
    sh -c "test $rc = 1 && cmp -s '$T/u/out' '$T/u/want' &&
        cmp -s '$T/u/unit-summary.txt' '$T/u/want-summary' &&
        test \"\$(cat '$T/u/tests/skipped.txt')\" = 'SKIP b: no tool'"

# Every test script that makes a scratch file cleans it up on a signal: through cli_testlib.sh,
# through tools/on_exit.sh, or with its own INT TERM HUP trap.
missing=$(awk 'function judge() { if (mk && !clean) printf " %s", f }
    FNR == 1 { if (NR > 1) judge(); f = FILENAME; mk = clean = 0 }
    /mktemp/ { mk = 1 }
    /^\. .*cli_testlib\.sh"$/ || /^on_exit '"'"'/ || /for sig in INT TERM HUP/ { clean = 1 }
    END { if (NR) judge() }' tests/run.sh tests/cli/test_*.sh tests/build/*.sh)
check "every test script with a scratch file cleans it up on INT, TERM and HUP${missing:+ (not:$missing)}" \
    test -z "$missing"

# The build directory: cli_testlib.sh makes it absolute before a script uses it, so that the two
# forms behave the same. Every script sources it before its first use of $B ...
early=$(awk 'FNR == 1 { sourced = 0 } sourced { next } /^\. .*cli_testlib\.sh"$/ { sourced = 1; next }
             /\$B|\$\{B/ && !/^B=\$\{1:-build\}$/ { printf " %s", FILENAME; sourced = 1 }' tests/cli/test_*.sh)
check "every CLI script sources cli_testlib.sh before it uses \$B${early:+ (not:$early)}" test -z "$early"
# ... and a script given either form runs the same checks with the same results
rel=$(realpath --relative-to="$PWD" "$B")
sh tests/cli/test_figure_stability.sh "$rel" >"$T/rel" 2>&1; rc1=$?
sh tests/cli/test_figure_stability.sh "$B" >"$T/abs" 2>&1; rc2=$?
check "test_figure_stability.sh with the build directory as $rel and as $B: both pass, the same lines" \
    sh -c "test $rc1 = 0 -a $rc2 = 0 && cmp -s '$T/rel' '$T/abs'"

done_tests test_scripts
