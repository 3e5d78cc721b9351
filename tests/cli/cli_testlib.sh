# Sourced by the CLI test scripts: a scratch directory $T removed at exit, and the PASS/FAIL
# counting behind their last line "NAME: N passed, N failed" (done NAME prints it and sets the
# status).
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
ok() { printf '%s\n' "PASS $*"; pass=$((pass + 1)); }
ko() { printf '%s\n' "FAIL $*"; fail=$((fail + 1)); }
skip() { printf '%s\n' "SKIP $*"; }
check() { # check DESCRIPTION COMMAND...
    d=$1; shift
    if "$@"; then ok "$d"; else ko "$d"; fi
}
done_tests() {
    echo "$1: $pass passed, $fail failed"
    [ "$fail" = 0 ]
}
