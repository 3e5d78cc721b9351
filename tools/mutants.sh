#!/bin/sh
# make mutants: the mutation check. Each line of the mutants file is one semantic, one-line
# change to the source,
#     FILE | FROM-TEXT | TO-TEXT | REASON
# (fields separated by " | "; lines starting with # and blank lines are skipped). The tree is
# copied once to a scratch directory and built there; then, for each mutant, FILE is patched
# (FROM-TEXT must occur exactly once, else the mutant is stale and counts as failed), the copy
# is rebuilt incrementally, and the tests run, quick unit tests first and the claims ledger
# last, stopping at the first that fails: the mutant is killed. If every test passes it
# survived. A mutant that does not build is not semantic and counts as failed. The file is then
# restored. Last line: "mutants: N passed, N failed" (passed = killed); exit status 1 on any
# failure. The unmutated tree must pass every test; where it does not (work in progress), its
# failures are recorded, a mutant is killed only by a failure beyond them, and the run fails.
# Usage: mutants.sh [MUTANTS_FILE [STRIDE]]: with STRIDE k, only mutants 1, 1+k, 1+2k, ...
# (counted over the non-comment lines), a fixed subset spread over the file (CI).
set -u
LIST=$(cd "$(dirname "${1:-tests/mutants}")" && pwd)/$(basename "${1:-tests/mutants}")
STRIDE=${2:-1}
ROOT=$(pwd)
S=$(mktemp -d)
chmod 755 "$S" # the permission tests run the scratch build as the user nobody
trap 'rm -rf "$S"' EXIT
unset MAKEFLAGS MFLAGS MAKELEVEL SAN BUILD  # a fresh make of its own, whatever called it
cp -R src tests tools paper Makefile README.md "$S"/
mkdir -p "$S/data" "$S/figures"
cp data/animation.cfg "$S/data/" 2>/dev/null || true
cp -R data/bench-recorded "$S/data/" 2>/dev/null || true # the recorded bench run (test_bench_record)
cd "$S" || exit 2
B=build/mut
# Every mutant relinks each program: gold does that faster than ld.bfd, where cc has it.
FAST_LD=""
cc -fuse-ld=gold -Wl,--version -o /dev/null >/dev/null 2>&1 && FAST_LD=-fuse-ld=gold
build() { make -s BUILD=$B -j2 LDFLAGS="${LDFLAGS:-} $FAST_LD" all >"$S/build.log" 2>&1; }
# What a failing test reports, without the numbers: its FAIL lines with digits removed.
signature() { sed -n 's/^FAIL *//p' "$1" | sed 's/[0-9]//g' | sort -u; }
# run_one NAME TIMEOUT COMMAND...: 0 when NAME passes, or fails exactly as on the unmutated tree
# (only there can a baseline exist: see below); else 1.
run_one() {
    name=$1 secs=$2; shift 2
    timeout "$secs" "$@" >"$S/test.log" 2>&1 && return 0
    status=$?
    signature "$S/test.log" >"$S/sig"
    [ -f "$S/base.$name" ] && comm -23 "$S/sig" "$S/base.$name" >"$S/new" || cp "$S/sig" "$S/new"
    [ -f "$S/base.$name" ] && [ ! -s "$S/new" ] && grep -q '^FAIL' "$S/test.log" && return 0
    why=$(head -1 "$S/new" | awk '{ print $1 }')
    [ -n "$why" ] || why="exit status $status, no FAIL line"
    return 1
}
# The CLI test scripts, every one make check runs but the install test (it installs the scratch
# tree), found by name so that a new script is never left out.
cli_scripts() {
    for c in tests/cli/test_cli*.sh; do case $c in *install*) ;; *) echo "$c" ;; esac; done
}
# the tests, quick ones first; prints the first failing one and returns 1
tests() {
    for t in $B/test_*; do
        case $t in *.d | *.o) continue ;; esac
        run_one "$(basename "$t")" 300 "$t" || { echo "$(basename "$t") ($why)"; return 1; }
    done
    for c in $(cli_scripts); do
        run_one "$(basename "$c" .sh)" 300 sh "$c" $B || { echo "$(basename "$c" .sh) ($why)"; return 1; }
    done
    run_one claims 900 $B/claims $B/claims.tsv || { echo "claims ($why)"; return 1; }
    return 0
}
echo "mutants: building the scratch copy in $S"
if ! build; then cat "$S/build.log"; echo "mutants: the unmutated tree does not build"; echo "mutants: 0 passed, 1 failed"; exit 1; fi
# The unmutated tree should pass every test. Where it does not (work in progress), its failures
# are recorded and a mutant is killed only by a failure beyond them; the run then fails anyway.
base_bad=0
for t in $B/test_* $(cli_scripts) claims; do
    case $t in *.d | *.o) continue ;; esac
    name=$(basename "$t" .sh)
    case $t in
        *.sh) set -- sh "$t" $B ;;
        claims) set -- $B/claims $B/claims.tsv ;;
        *) set -- "$t" ;;
    esac
    if ! timeout 900 "$@" >"$S/test.log" 2>&1; then
        signature "$S/test.log" >"$S/base.$name"
        echo "FAIL the unmutated tree fails $name: $(grep -c '^FAIL' "$S/test.log") FAIL lines, e.g. $(grep -m1 '^FAIL' "$S/test.log" | cut -c1-80)"
        base_bad=1
    fi
done
killed=0 bad=0 n=0
# one mutant per line, read through a file descriptor the tests cannot consume
grep -v '^[[:space:]]*#' "$LIST" | grep -v '^[[:space:]]*$' >"$S/list"
while IFS= read -r line <&3; do
    n=$((n + 1))
    [ $(((n - 1) % STRIDE)) = 0 ] || continue
    file=$(printf '%s\n' "$line" | awk -F ' [|] ' '{ print $1 }')
    from=$(printf '%s\n' "$line" | awk -F ' [|] ' '{ print $2 }')
    to=$(printf '%s\n' "$line" | awk -F ' [|] ' '{ print $3 }')
    why=$(printf '%s\n' "$line" | awk -F ' [|] ' '{ print $4 }')
    label="#$n $file: '$from' -> '$to'"
    if [ ! -f "$file" ] || [ -z "$from" ] || [ -z "$why" ]; then
        echo "FAIL $label: malformed or missing file (FILE | FROM | TO | REASON)"; bad=$((bad + 1)); continue
    fi
    # count the exact occurrences of FROM (literal, may span nothing but one line)
    hits=$(FROM=$from awk 'BEGIN { f = ENVIRON["FROM"] } { s = $0; while ((i = index(s, f)) > 0) { c++; s = substr(s, i + length(f)) } } END { print c + 0 }' "$file")
    if [ "$hits" != 1 ]; then
        echo "FAIL $label: stale, FROM found $hits times (must be exactly once)"; bad=$((bad + 1)); continue
    fi
    cp "$file" "$S/orig"
    FROM=$from TO=$to awk 'BEGIN { f = ENVIRON["FROM"]; t = ENVIRON["TO"] }
        { i = index($0, f); if (i > 0) $0 = substr($0, 1, i - 1) t substr($0, i + length(f)); print }' "$S/orig" >"$file"
    if ! build; then
        echo "FAIL $label: does not build (not a semantic mutant)"; bad=$((bad + 1))
    elif failed=$(tests); then
        echo "FAIL $label: SURVIVED ($why)"; bad=$((bad + 1))
    else
        echo "PASS $label: killed by $failed"; killed=$((killed + 1))
    fi
    cp "$S/orig" "$file" # a new mtime: the next build recompiles what the mutant changed
done 3<"$S/list"
cd "$ROOT" || exit 2
[ "$base_bad" = 1 ] && echo "mutants: the unmutated tree fails tests (above): that counts as one failure"
bad=$((bad + base_bad))
echo "mutants: $killed passed, $bad failed"
[ "$bad" = 0 ]
