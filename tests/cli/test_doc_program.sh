#!/bin/sh
# The minimal program of docs/howto/use-the-library.md, as the document prints it (the lines
# between its <!-- program --> markers, without the code fence): it compiles as C17 and as C++17
# with every warning an error, against the public header as <suslov/suslov.h> and the library's
# two layers (what libsuslov.a holds), and prints the rows that suslov prints for the same run.
# Usage: test_doc_program.sh BUILD_DIR. Last line: "test_doc_program: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
DOC=docs/howto/use-the-library.md
sed -n '/^<!-- program -->$/,/^<!-- end program -->$/p' "$DOC" | sed '1,2d;$d' | sed '$d' \
    >"$T/prog.c"
check "$DOC holds a program between its markers ($(wc -l <"$T/prog.c") lines)" \
    grep -q 'int main(void)' "$T/prog.c"
cp "$T/prog.c" "$T/prog.cpp"
# <suslov/suslov.h> as make install lays it out: the headers of core and methods in one folder
mkdir -p "$T/include/suslov"
ln -s "$PWD"/src/core/*.h "$PWD"/src/methods/*.h "$T/include/suslov/"
san=""; [ -n "${SUSLOV_SAN:-}" ] && san="-fsanitize=address,undefined"
libs="$B/libsus_methods.a $B/libsus_core.a -lm"
want=$("$B/suslov" --no-header --method midpoint --eps 0.1 --steps 200 --every 50 \
    --inertia 2,0.3,1,0.3,1,0.5,1.5,-0.7,3 --omega0 1,-0.5 |
    awk -F, 'NR > 1 { printf "%.6g %s %s %s\n", $2, $3, $4, $6 }')
for lang in c cpp; do
    if [ $lang = c ]; then cc=${CC:-cc} std=-std=c17; else cc=${CXX:-c++} std=-std=c++17; fi
    if ! command -v "$cc" >/dev/null; then
        skip "the $lang program: no $cc"
        continue
    fi
    # shellcheck disable=SC2086 # flags and libraries are meant to split
    $cc $san $std -Wall -Wextra -pedantic -Werror -I"$T/include" "$T/prog.$lang" \
        -o "$T/prog_$lang" $libs 2>"$T/cc"; rc=$?
    check "the document's program compiles as $lang with $cc ($(head -c 300 "$T/cc"))" \
        test "$rc" = 0
    "$T/prog_$lang" >"$T/out_$lang"; rc=$?
    got=$(awk '{ printf "%.6g %s %s %s\n", $1, $2, $3, $4 }' "$T/out_$lang")
    check "the $lang program prints the rows suslov prints for the same run" \
        test "$rc" = 0 -a -n "$got" -a "$got" = "$want"
done
done_tests test_doc_program
