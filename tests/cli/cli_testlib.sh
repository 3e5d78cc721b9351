# Sourced by the CLI test scripts (after B=${1:-build}): B made absolute, so that a script works
# the same from a relative or an absolute build directory (B_GIVEN keeps it as given); a scratch directory $T removed at exit
# and on an interrupt; and the PASS/FAIL counting behind their last line "NAME: N passed,
# N failed" (done NAME prints it and sets the status).
B_GIVEN=${B:-build} # as given, for make: its stamps hold the paths BUILD spells
B=$(cd "$B_GIVEN" 2>/dev/null && pwd -P || echo "$B_GIVEN")
# at_exit COMMAND: run COMMAND too when the script ends (normally or by a signal), before $T goes
cleanup_extra=""
at_exit() { cleanup_extra="$1; $cleanup_extra"; }
cleanup() { eval "$cleanup_extra"; rm -rf "${T:-}"; }
# Set before $T is made, and $T named before it is made, so that a signal at any moment (run.sh
# may end a script it has just started) leaves nothing behind; mkdir refuses a name that exists
# (then mktemp picks one).
. tools/on_exit.sh
on_exit cleanup
T="${TMPDIR:-/tmp}/cli.$$"
mkdir -m 700 "$T" 2>/dev/null || T=$(mktemp -d)
pass=0 fail=0
ok() { printf '%s\n' "PASS $*"; pass=$((pass + 1)); }
ko() { printf '%s\n' "FAIL $*"; fail=$((fail + 1)); }
skip() { printf '%s\n' "SKIP $*"; }
check() { # check DESCRIPTION COMMAND...
    d=$1; shift
    if "$@"; then ok "$d"; else ko "$d"; fi
}
# one_line FILE: is FILE one line ended by a newline? Its first line is left in $line1 either way,
# read by the shell itself: these scripts read hundreds of messages, and a process (cat, wc)
# costs milliseconds on a small VM.
one_line() {
    line1="" line2=""
    { IFS= read -r line1 || return 1; ! IFS= read -r line2 && [ -z "$line2" ]; } <"$1"
}
# has_tmp DIR...: does a name in a DIR hold ".tmp."? By the shell's globs, not ls and grep: the
# scripts ask it in polling loops.
has_tmp() {
    for d in "$@"; do
        for f in "$d"/*.tmp.* "$d"/.*.tmp.* "$d"/.tmp.*; do [ -e "$f" ] && return 0; done
    done
    return 1
}
# entries DIR: the names in DIR (those of ls -A, in the order of the shell's globs), each followed
# by a space, into $entries
entries() {
    entries=""
    for f in "$1"/* "$1"/.[!.]* "$1"/..?*; do
        [ -e "$f" ] || [ -L "$f" ] && entries="$entries${f##*/} "
    done
}
done_tests() {
    echo "$1: $pass passed, $fail failed"
    [ "$fail" = 0 ]
}
