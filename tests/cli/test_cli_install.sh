#!/bin/sh
# make install PREFIX=DIR, into a scratch PREFIX with a space in it: the command, its manual page,
# libsuslov.a, the public headers under include/suslov/ and suslov.pc. A C program and a C++
# program build against the installed files through pkg-config alone, run, and compute what the
# installed suslov prints; make uninstall then leaves no file behind. A relative PREFIX is refused
# in one line; the version stamp comes from git only when the checkout is its own work tree's top.
# Usage: test_cli_install.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
# Called from make check: a make of its own, not a sub-make of it (whose jobserver it would warn
# about). CC, CXX and the like reach it through the environment, where make put them.
unset MAKEFLAGS MFLAGS MAKELEVEL

P="$T/pre fix"
# BUILD as make check spells it: an archive's member-list stamp holds that spelling, so another
# would make the next `make` relink every program
if [ -n "${SUSLOV_SAN:-}" ]; then mk=SAN=1 bd=build/san; else mk=BUILD=$B_GIVEN bd=$B_GIVEN; fi
# What the build made is installed as it is (-o: never remade): a source edited while make check
# runs must not relink the suslov that the other tests are running.
make -s install PREFIX="$P" "$mk" -o "$bd/suslov" -o "$bd/man/suslov.1" >"$T/log" 2>&1; rc=$?
check "make install PREFIX='$P': exit 0 ($(tail -1 "$T/log"))" test "$rc" = 0
check "installed: bin/suslov, lib/libsuslov.a, include/suslov/suslov.h, lib/pkgconfig/suslov.pc, share/man/man1/suslov.1" \
    test -x "$P/bin/suslov" -a -s "$P/lib/libsuslov.a" -a -s "$P/include/suslov/suslov.h" \
         -a -s "$P/lib/pkgconfig/suslov.pc" -a -s "$P/share/man/man1/suslov.1"

# Only the public headers: suslov.h and what it includes; none of the internal ones, whose
# generic names would clash on a user's include path.
inst=$(cd "$P/include/suslov" && ls | tr '\n' ' ')
check "include/suslov holds the public headers only ($inst)" \
    test "$inst" = "driver.h exact.h exact_run.h model.h reconstruct.h registry.h stepper.h suslov.h "
# (suslov.h only includes the others)
nolink=$(grep -L 'extern "C"' "$P"/include/suslov/*.h src/util/*.h src/core/*.h src/methods/*.h \
    src/lab/*.h | grep -v '/suslov\.h$' | tr '\n' ' ')
check "every installed header and every header of src/{util,core,methods,exp} declares C linkage for C++:${nolink:- yes}" \
    test -z "$nolink"

# The installed command links neither Cairo nor OSMesa (nor, through them, LLVM).
libs=$(ldd "$P/bin/suslov" 2>&1 | grep -iE 'cairo|osmesa|llvm|libgl' | tr '\n' ' ')
check "bin/suslov needs no Cairo, OSMesa or LLVM at run time (${libs:-none mapped})" test -z "$libs"

cat >"$T/prog.c" <<'C'
#include <suslov/suslov.h>
#include <stdio.h>
int main(void)
{
    sus_model m; char err[256]; sus_row last; sus_run_report rep;
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0) return 1;
    const sus_step_method *me = sus_step_method_by_name("midpoint");
    const sus_run_config cfg = {&m, me->type, SUS_RECON_CAYLEY, 0.1, 10, 10};
    if (sus_run(&cfg, SUS_PAPER_OMEGA0, sus_keep_last, &last, &rep) != SUS_RUN_OK) return 1;
    const sus_run_config bad = {&m, me->type, SUS_RECON_CAYLEY, 0.1, 10, 0};
    if (sus_run(&bad, SUS_PAPER_OMEGA0, sus_keep_last, &last, &rep) != SUS_RUN_BAD_ARGUMENT) return 2;
    printf("%ld,%.17g,%.17g,%.17g\n", last.k, last.t, last.w[0], last.w[1]);
    return 0;
}
C
cp "$T/prog.c" "$T/prog.cpp"
san=""; [ -n "${SUSLOV_SAN:-}" ] && san="-fsanitize=address,undefined"
flags=$(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags --libs suslov 2>"$T/err")
# pkg-config escapes the space with a backslash: its output is shell words, read with eval.
eval "set -- $flags"
check "pkg-config --cflags --libs suslov gives the installed include and lib directories ($flags)" \
    test "$#" = 4 -a "$1" = "-I$P/include" -a "$2" = "-L$P/lib" -a "$3" = -lsuslov -a "$4" = -lm
want=$("$P/bin/suslov" --no-header --method midpoint --eps 0.1 --steps 10 --every 10 | tail -1 | cut -d, -f1-4)
for lang in c cpp; do
    if [ $lang = c ]; then cc=${CC:-cc} std=-std=c17; else cc=${CXX:-c++} std=-std=c++17; fi
    # shellcheck disable=SC2086 # the compiler's own flags are meant to split
    eval "\$cc $san $std -Wall -Wextra -pedantic -Werror \"\$T/prog.$lang\" -o \"\$T/prog_$lang\" $flags" \
        2>"$T/cc"; rc=$?
    check "a $lang program compiles and links with $cc and pkg-config's flags alone ($(head -c 300 "$T/cc"))" \
        test "$rc" = 0
    got=$("$T/prog_$lang"); rc=$?
    check "the $lang program computes what the installed suslov prints ($got = $want), a bad run refused" \
        test "$rc" = 0 -a -n "$got" -a "$got" = "$want"
done

make -s uninstall PREFIX="$P" "$mk" >"$T/log" 2>&1; rc=$?
left=$(find "$P" ! -type d | head -3 | tr '\n' ' ')
check "make uninstall: exit 0, no file left under PREFIX (${left:-none})" test "$rc" = 0 -a -z "$left"

# A relative PREFIX: one line, a failure, nothing installed.
make -s install PREFIX=relative/prefix "$mk" >"$T/log" 2>&1; rc=$?
check "make install PREFIX=relative/prefix is refused in one line ($(head -1 "$T/log"))" \
    test "$rc" != 0 -a "$(wc -l <"$T/log")" = 1 -a ! -e relative/prefix

# The version stamp of a source export unpacked inside another repository's work tree: not that
# repository's commit. Control: the same export as the top of its own repository.
mkdir -p "$T/outer/export"
git init -q "$T/outer" && cp -R Makefile src tools "$T/outer/export/" &&
    git -C "$T/outer" add -A && git -C "$T/outer" -c user.name=t -c user.email=t@t commit -qm outer
stamp() { make -s -C "$T/outer/export" BUILD=b b/version.stamp >/dev/null 2>&1
          cat "$T/outer/export/b/version.stamp" 2>/dev/null; rm -rf "$T/outer/export/b"; }
v=$(stamp)
check "a source export inside another work tree is version 'unknown' ($v)" test "$v" = unknown
git init -q "$T/outer/export" && git -C "$T/outer/export" add -A &&
    git -C "$T/outer/export" -c user.name=t -c user.email=t@t commit -qm own
v=$(stamp); own=$(git -C "$T/outer/export" describe --always --dirty)
check "control: the same export at the top of its own repository is its commit ($v = $own)" test "$v" = "$own"

done_tests test_cli_install
