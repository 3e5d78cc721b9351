#!/bin/sh
# One formatter: every tracked C and C++ source is as clang-format (the committed .clang-format)
# leaves it. Formatting rules change between clang-format's major versions, so the check runs
# with Debian 12's, version 14 (make deps installs it), and is skipped with a line saying why
# under any other or none. To format a file: clang-format -i FILE.
# Last line "format: N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
want=14
cf=""
for c in clang-format-$want clang-format; do
    command -v "$c" >/dev/null 2>&1 && { cf=$c; break; }
done
major=$([ -n "$cf" ] && "$cf" --version | sed -n 's/.*version \([0-9]*\).*/\1/p')
if [ "$major" != "$want" ]; then
    echo "SKIP format: clang-format $want is not installed${major:+ (found version $major)}: make deps installs it"
    echo "format: 0 passed, 0 failed"
    exit 0
fi
# All files in a few clang-format runs on every core (one run per file costs its start-up each
# time); a file it would change is named in its warnings.
files=$(git ls-files '*.c' '*.h' '*.cpp' 2>/dev/null)
total=$(printf '%s\n' "$files" | grep -c .)
out=$(printf '%s\n' "$files" | xargs -P "$(nproc 2>/dev/null || echo 1)" -n 40 "$cf" --dry-run 2>&1)
bad=$(printf '%s\n' "$out" | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: \(warning\|error\): .*/\1/p' | sort -u)
fail=0
for f in $bad; do
    echo "FAIL format: $f is not as clang-format leaves it (clang-format -i $f)"
    fail=$((fail + 1))
done
# a run that failed without naming a file (clang-format could not start): the check fails
if [ "$fail" = 0 ] && printf '%s\n' "$out" | grep -q .; then
    echo "FAIL format: clang-format printed what no file explains:"
    printf '%s\n' "$out" | head -5 | sed 's/^/    /'
    fail=1
fi
echo "format: $((total - fail)) passed, $fail failed"
[ "$fail" = 0 ]
