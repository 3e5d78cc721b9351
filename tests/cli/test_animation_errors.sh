#!/bin/sh
# The animation's exit paths: on an error or a signal it stops its ffmpeg child and leaves no
# temporary file; a bad config is one line and exit 2; a failing ffmpeg costs only the video.
# ffmpeg is replaced by a stand-in on PATH that records its pid and copies its input to the
# output file, so the test needs no ffmpeg and can see whether the child outlived the program.
# Usage: test_animation_errors.sh BUILD_DIR. Last line: "test_animation_errors: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
A="$B/animation"
tmp=$T
result() { # result OK MESSAGE
    if [ "$1" = 1 ]; then pass=$((pass + 1)); echo "PASS $2"; else fail=$((fail + 1)); echo "FAIL $2"; fi
}
yes_if() { if "$@"; then echo 1; else echo 0; fi; }
mkdir -p "$tmp/bin"
# the stand-in ffmpeg: MODE=copy reads everything into the output, MODE=fail exits 1 at once
cat >"$tmp/bin/ffmpeg" <<'EOF'
#!/bin/sh
echo $$ >>"$FAKE_FFMPEG_PIDS"
for a; do out=$a; done
[ "${FAKE_FFMPEG_MODE:-copy}" = fail ] && exit 1
exec cat >"$out"
EOF
chmod +x "$tmp/bin/ffmpeg"
cfg="$tmp/small.cfg"
printf 'width = 96\nheight = 54\nfps = 5\nseconds = 2\nt_end = 10\neps = 1\n' >"$cfg"
export FAKE_FFMPEG_PIDS="$tmp/pids"
run_anim() { # run_anim DIR [ENV...]: the animation into DIR with the stand-in ffmpeg
    d=$1; shift
    mkdir -p "$d"
    : >"$FAKE_FFMPEG_PIDS"
    env PATH="$tmp/bin:$PATH" "$@" "$A" "$cfg" "$d" "$d" >"$d.out" 2>"$d.err"
}
no_child() { # no stand-in ffmpeg recorded in the pid file is still running
    for p in $(cat "$FAKE_FFMPEG_PIDS"); do kill -0 "$p" 2>/dev/null && return 1; done
    return 0
}
no_temp() { [ -z "$(find "$1" -name '*.tmp.*')" ]; }

# 0. the stand-in works: a normal run makes a video, exit 0
run_anim "$tmp/ok"
st=$?
result "$(yes_if [ $st = 0 ] && [ -s "$tmp/ok/attitude.mp4" ] && [ -s "$FAKE_FFMPEG_PIDS" ])" \
    "normal run: exit $st, video written through the (stand-in) ffmpeg"

# 1. an error mid-run: frame 5's name is taken by a directory, so writing it fails
mkdir -p "$tmp/err/attitude/frame_0005.png"
run_anim "$tmp/err"
st=$?
result "$(yes_if [ $st = 1 ])" "a frame that cannot be written: exit $st (1)"
result "$(yes_if [ "$(grep -c . "$tmp/err.err")" = 1 ])" "one line on stderr: $(head -c 120 "$tmp/err.err")"
sleep 0.2
result "$(yes_if no_child)" "the ffmpeg child does not outlive the failed run"
result "$(yes_if no_temp "$tmp/err")" "no temporary file left: $(find "$tmp/err" -name '*.tmp.*' | head -3)"
result "$(yes_if [ ! -e "$tmp/err/attitude.mp4" ])" "no video from the failed run"

# 2. ffmpeg fails at once: the frames and the rest are written, no video, no temporary file
run_anim "$tmp/ff" FAKE_FFMPEG_MODE=fail
st=$?
result "$(yes_if [ $st = 0 ] && [ -s "$tmp/ff/attitude_filmstrip.png" ] && [ ! -e "$tmp/ff/attitude.mp4" ])" \
    "failing ffmpeg: exit $st, filmstrip written, no video"
result "$(yes_if grep -q 'no video' "$tmp/ff.err")" "failing ffmpeg is reported: $(head -c 120 "$tmp/ff.err")"
result "$(yes_if no_temp "$tmp/ff")" "failing ffmpeg: no temporary file left"

# 3. SIGTERM during the run (a long one: 600 frames): killed by the signal, child and files gone
printf 'width = 96\nheight = 54\nfps = 60\nseconds = 10\nt_end = 10\neps = 1\n' >"$cfg"
mkdir -p "$tmp/sig"
: >"$FAKE_FFMPEG_PIDS"
env PATH="$tmp/bin:$PATH" "$A" "$cfg" "$tmp/sig" "$tmp/sig" >/dev/null 2>"$tmp/sig.err" &
apid=$!
i=0
while [ ! -e "$tmp/sig/attitude/frame_0010.png" ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
kill -TERM $apid
wait $apid 2>/dev/null
st=$?
sleep 0.2
result "$(yes_if [ $st = 143 ])" "SIGTERM mid-run: the program dies of the signal (status $st, 143)"
result "$(yes_if no_child)" "SIGTERM: the ffmpeg child is stopped"
result "$(yes_if no_temp "$tmp/sig")" "SIGTERM: no temporary file left: $(find "$tmp/sig" -name '*.tmp.*' | head -3)"

# 4. a bad config: one line, exit 2, nothing written
printf 'width = 95\n' >"$cfg"
mkdir -p "$tmp/bad"
"$A" "$cfg" "$tmp/bad" "$tmp/bad" >/dev/null 2>"$tmp/bad.err"
st=$?
result "$(yes_if [ $st = 2 ] && [ "$(grep -c . "$tmp/bad.err")" = 1 ] && [ -z "$(ls -A "$tmp/bad")" ])" \
    "bad config: exit $st (2), one line ($(cat "$tmp/bad.err")), nothing written"

echo "test_animation_errors: $pass passed, $fail failed"
[ "$fail" = 0 ]
