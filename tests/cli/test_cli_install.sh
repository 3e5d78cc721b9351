#!/bin/sh
# make install PREFIX=DIR: the command, its manual page, libsuslov.a, its headers and
# suslov.pc; a ten-line C program builds against the installed files through pkg-config alone
# and computes what the installed suslov prints. Usage: test_cli_install.sh BUILD_DIR
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"

P="$T/prefix"
# BUILD as make check spells it: an archive's member-list stamp holds that spelling, so another
# would make the next `make` relink every program
if [ -n "${SUSLOV_SAN:-}" ]; then set -- SAN=1; else set -- BUILD="$B_GIVEN"; fi
make -s install PREFIX="$P" "$@" >"$T/log" 2>&1; rc=$?
check "make install PREFIX='$P': exit 0 ($(tail -1 "$T/log"))" test "$rc" = 0
check "installed: bin/suslov, lib/libsuslov.a, include/suslov/driver.h, lib/pkgconfig/suslov.pc, share/man/man1/suslov.1" \
    test -x "$P/bin/suslov" -a -s "$P/lib/libsuslov.a" -a -s "$P/include/suslov/driver.h" \
         -a -s "$P/lib/pkgconfig/suslov.pc" -a -s "$P/share/man/man1/suslov.1"

cat >"$T/prog.c" <<'C'
#include <driver.h>
#include <dsp.h>
#include <stdio.h>
int main(void)
{
    sus_model m; char err[256]; sus_row last; sus_run_report rep;
    if (sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err) != 0) return 1;
    const sus_run_config cfg = {&m, sus_step_midpoint, SUS_RECON_CAYLEY, 0.1, 10, 10};
    if (sus_run(&cfg, SUS_PAPER_OMEGA0, sus_keep_last, &last, &rep) != SUS_RUN_OK) return 1;
    printf("%ld,%.17g,%.17g,%.17g\n", last.k, last.t, last.w[0], last.w[1]);
    return 0;
}
C
san=""; [ -n "${SUSLOV_SAN:-}" ] && san="-fsanitize=address,undefined"
flags=$(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags --libs suslov 2>"$T/err")
check "pkg-config --cflags --libs suslov names the installed include and lib directories ($flags)" \
    sh -c "echo '$flags' | grep -q -- '-I$P/include/suslov' && echo '$flags' | grep -q -- '-L$P/lib -lsuslov'"
# shellcheck disable=SC2086 # pkg-config's words are meant to split
${CC:-cc} $san -std=c17 "$T/prog.c" -o "$T/prog" $flags 2>"$T/cc"; rc=$?
check "a ten-line program compiles and links with pkg-config's flags alone ($(head -c 300 "$T/cc"))" test "$rc" = 0
got=$("$T/prog")
want=$("$P/bin/suslov" --no-header --method midpoint --eps 0.1 --steps 10 --every 10 | tail -1 | cut -d, -f1-4)
check "the program computes what the installed suslov prints ($got = $want)" test -n "$got" -a "$got" = "$want"

done_tests test_cli_install
