#!/bin/sh
# Proportion: no function body in src/ or tests/ longer than 60 lines (from its opening brace in
# column 0 to its closing one), no file longer than 600 lines, and no line of C longer than 100
# columns (the formatter's limit, .clang-format). Last line "style: N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
files=$(ls src/*/*.c src/*/*.h src/*/*.cpp tests/*/*.c tests/*/*.h 2>/dev/null)
# shellcheck disable=SC2086
awk -v maxf=60 -v maxl=100 -v maxn=600 '
FNR == 1 { if (prev && prevn > maxn) { printf "FAIL style: %s is %d lines (at most %d)\n", prev, prevn, maxn; bad++ }; start = 0 }
{ prev = FILENAME; prevn = FNR }
{ line = $0; gsub(/[\200-\277]/, "", line) } # columns, not bytes: UTF-8 continuation bytes dropped
length(line) > maxl { printf "FAIL style: %s:%d is %d columns (at most %d)\n", FILENAME, FNR, length(line), maxl; bad++ }
/^\{$/ { start = FNR }
/^\}$/ && start {
    n = FNR - start + 1; nf++
    if (n > maxf) { printf "FAIL style: %s:%d: a function of %d lines (at most %d)\n", FILENAME, start, n, maxf; bad++ }
    start = 0
}
END {
    if (prevn > maxn) { printf "FAIL style: %s is %d lines (at most %d)\n", prev, prevn, maxn; bad++ }
    printf "%s style: %d functions and every line checked, %d too long\n", bad ? "FAIL" : "PASS", nf, bad
    printf "style: %d passed, %d failed\n", bad ? 0 : 1, bad ? 1 : 0
    exit bad > 0
}' $files
