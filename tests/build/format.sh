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
pass=0 fail=0
for f in $(git ls-files '*.c' '*.h' '*.cpp' 2>/dev/null); do
    if "$cf" --dry-run -Werror "$f" >/dev/null 2>&1; then
        pass=$((pass + 1))
    else
        echo "FAIL format: $f is not as clang-format leaves it (clang-format -i $f)"
        fail=$((fail + 1))
    fi
done
echo "format: $pass passed, $fail failed"
[ "$fail" = 0 ]
