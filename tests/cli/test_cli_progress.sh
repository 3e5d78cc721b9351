#!/bin/sh
# The progress of a long step (src/prog/progress.c, through build/timed as make runs the figure
# programs and the ledger): on a terminal a line redrawn with the fraction done, the time taken and
# an estimate, erased at the end; off a terminal a plain line (the next ten seconds later); nothing
# under NO_PROGRESS; and timed's own promises: the time recorded (marked "failed" for a failed
# command), the command's exit status or signal passed on, its output sent to --output.
# SUSLOV_PROGRESS_AFTER=S (a test hook) shows the first line after S seconds.
# Usage: test_cli_progress.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
TIMED="$B/timed"

"$TIMED" "$T/t1" sleep 0.2; rc=$?
check "a run: status 0 and its seconds recorded ($(cat "$T/t1" 2>/dev/null))" \
    sh -c "test $rc = 0 && grep -qx '0\\.[2-9]' '$T/t1'"
"$TIMED" "$T/t2" sh -c 'exit 3'; rc=$?
check "a failed run: its status (3: $rc) and its time marked failed ($(cat "$T/t2" 2>/dev/null))" \
    sh -c "test $rc = 3 && grep -qx '[0-9.]* failed' '$T/t2'"
"$TIMED" "$T/t3" sh -c 'kill -TERM $$' 2>/dev/null; rc=$?
check "a command killed by SIGTERM: timed dies of it too (143: $rc)" test "$rc" = 143
"$TIMED" --output "$T/out" "$T/t4" sh -c 'echo to-stdout; echo to-stderr >&2' >"$T/so" 2>"$T/se"
check "--output: the command's stdout and stderr in the file, nothing on timed's own" \
    sh -c "grep -q to-stdout '$T/out' && grep -q to-stderr '$T/out' && test ! -s '$T/so' -a ! -s '$T/se'"
"$TIMED" "$T/t5" >/dev/null 2>&1; rc=$?
check "no command: usage, status 2 ($rc)" test "$rc" = 2

# off a terminal: the first line after SUSLOV_PROGRESS_AFTER, the next only 10 s later
echo 4.0 >"$T/last"
SUSLOV_PROGRESS_AFTER=0.3 "$TIMED" --progress sleeper "$T/last" sleep 1 2>"$T/log"
check "off a terminal: one plain line 'sleeper: N% done, N s elapsed, about N s left' ($(head -c 120 "$T/log"))" \
    sh -c "test \$(wc -l <'$T/log') = 1 && grep -q '^sleeper: [0-9]*% done, [0-9]* s elapsed, about [0-9]* s left\$' '$T/log' && ! grep -q \"\$(printf '[\\r\\033]')\" '$T/log'"
echo 4.0 >"$T/last"
NO_PROGRESS=1 SUSLOV_PROGRESS_AFTER=0 "$TIMED" --progress sleeper "$T/last" sleep 0.3 2>"$T/log"
check "NO_PROGRESS: no line" test ! -s "$T/log"

if command -v script >/dev/null; then
    echo 4.0 >"$T/last"
    SUSLOV_PROGRESS_AFTER=0.2 script -qec "'$TIMED' --progress sleeper '$T/last' sleep 1" /dev/null >"$T/tty" 2>&1
    check "on a terminal: 'sleeper: N% done, N s elapsed, about N s left' redrawn, then erased (ends with CR ESC[K)" \
        sh -c "test \$(grep -o 'sleeper: [0-9]*% done, [0-9]* s elapsed, about [0-9]* s left' '$T/tty' | wc -l) -ge 2 && test \"\$(tail -c 4 '$T/tty' | od -An -tx1 | tr -d ' \n')\" = 0d1b5b4b"
    echo 0.4 >"$T/last"
    SUSLOV_PROGRESS_AFTER=0.7 script -qec "'$TIMED' --progress sleeper '$T/last' sleep 1.2" /dev/null >"$T/tty" 2>&1
    check "a run longer than the last: 'longer than the last run (0 s)', no estimate" \
        sh -c "grep -q 'sleeper: longer than the last run (0 s), [0-9]* s elapsed' '$T/tty' && ! grep -q 'left' '$T/tty'"
    NO_PROGRESS=1 SUSLOV_PROGRESS_AFTER=0 script -qec "'$B/suslov' --no-header --method rk4 --eps 1e-3 --steps 200000 --every 100000 --output '$T/pr.csv'" /dev/null >"$T/tty" 2>&1
    check "NO_PROGRESS: suslov draws no progress on a terminal" test ! -s "$T/tty"
else
    skip "progress on a terminal: needs script(1)"
fi
done_tests test_cli_progress
