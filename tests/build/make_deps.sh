#!/bin/sh
# The Makefile's promises, checked without building anything (make -n) or in a scratch directory:
#  1. a figure is redrawn exactly when an input it depends on changes (make -n -W FILE figures,
#     against hand-written expectations below), and `make -q figures` answers 0 when none is
#     (needs the figures up to date in BUILD_DIR, else this part is skipped with a SKIP line: CI
#     runs it after `make figures`);
#  2. SAN=1 keeps -fsanitize when CFLAGS is given on the command line;
#  3. `make check` waits only on the check profile of tools/deps.sh (no TeX, no ffmpeg);
#  4. `make distclean` removes generated files and keeps the committed ones;
#  5. an archive follows its layer's source list (a deleted source leaves no stale member), a
#     change of CFLAGS recompiles, `make -q all` is truthful, and the test runner is given
#     exactly the unit tests in tests/unit (not whatever BUILD_DIR holds); plain `make` is `make all`.
# Usage: make_deps.sh BUILD_DIR. Last line: "make_deps: N passed, N failed".
set -u
B=${1:-build}
unset MAKEFLAGS MFLAGS MAKELEVEL  # called from make check: a fresh make, not a sub-make
# Part 1 asks about the build in BUILD_DIR, so with the variables it was made with (make check's
# command line: WERROR=1 in CI; the flags stamp holds them, and without them every figure would
# look stale and the part be skipped); the other parts ask a fresh make.
b_werror=${WERROR-} b_san=${SAN-} b_cflags=${CFLAGS-} b_ldflags=${LDFLAGS-}
b_cflags_set=${CFLAGS+1} b_ldflags_set=${LDFLAGS+1}
make_b() {
    make BUILD="$B" ${b_werror:+"WERROR=$b_werror"} ${b_san:+"SAN=$b_san"} \
        ${b_cflags_set:+"CFLAGS=$b_cflags"} ${b_ldflags_set:+"LDFLAGS=$b_ldflags"} "$@"
}
unset SAN BUILD CFLAGS LDFLAGS WERROR  # make exports its command-line variables to recipes
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL make_deps: $*"; }

# The programs a plan of make (its -n output, on stdin) runs to draw (the recipe may wrap them,
# e.g. in a timer), as a sorted space-separated list; would_draw: those of `make figures`.
drawn() {
    sed -n "s#^.*$B/\(figure_[a-z0-9_]*\|animation\) \(figures\|data/\).*#\1#p" | sort -u | tr '\n' ' '
}
would_draw() { make_b -n "$@" figures 2>/dev/null | drawn; }

plan=$(make_b -n figures 2>/dev/null)
stale=$(printf '%s\n' "$plan" | drawn)
# the bench's two figures, redrawn from its recorded run (data/bench-recorded/) by build/bench
printf '%s\n' "$plan" | grep -q -- "$B/bench --plot" && stale="${stale}bench --plot "
if [ -n "$stale" ]; then
    echo "SKIP make_deps: figures in $B are not up to date ($stale); run make BUILD=$B figures first" \
        "(with the variables of this make check)"
else
    # every program that draws: the figure programs and the animation
    all="$(ls src/prog/figure_*.c | sed 's#src/prog/\(.*\)\.c#\1#' | tr '\n' ' ')animation"
    # FILE | the programs that must run again (ALL: every one), and why: what each links or includes
    while IFS='|' read -r file want; do
        [ "$want" = ALL ] && want=$all
        got=$(would_draw -W "$file")
        want=$(echo "$want" | tr ' ' '\n' | sed '/^$/d' | sort -u | tr '\n' ' ')
        if [ "$got" = "$want" ]; then ok; else bad "touch $file redraws '$got', expected '$want'"; fi
    done <<'EOF'
src/core/model.h|ALL
src/lab/midpoint_sweeps.c|figure_fig2_energy
src/render/scene.c|animation
data/animation.cfg|animation
tests/ledger/claims.c|
EOF
    # model.h: every program includes it. midpoint_sweeps: only the readings of Figure 2(d).
    # scene and the config: only the animation draws the body. The ledger: no figure.
    # and make -q says so (an always-run prerequisite, such as a phony deps target, made it 1)
    make_b -q figures 2>/dev/null && ok || bad "make -q figures answers 1 with every figure up to date"
fi

# 2. SAN=1 with a command-line CFLAGS still compiles and links with the sanitizers.
tmp=""
. tools/on_exit.sh
on_exit 'rm -rf "$tmp"'
tmp=$(mktemp -d)
line=$(make -n -B SAN=1 CFLAGS=-O1 BUILD="$tmp/san" "$tmp/san/obj/core/model.o" 2>/dev/null | grep -- '-c src/core/model.c')
case $line in *-O1*-fsanitize=address,undefined*) ok ;; *) bad "SAN=1 CFLAGS=-O1 compiles model.c as: $line" ;; esac
line=$(make -n -B SAN=1 LDFLAGS=-g BUILD="$tmp/san" "$tmp/san/figure_fig1" 2>/dev/null | grep -- '-o .*figure_fig1')
case $line in *-fsanitize=address,undefined*) ok ;; *) bad "SAN=1 LDFLAGS=-g links figure_fig1 as: $line" ;; esac

# 3. make check needs the check profile only; make paper asks for TeX. (What make check would do
#    in a fresh build directory is read once, here and in 5.)
make -n BUILD="$tmp/b" check >"$tmp/check.n" 2>/dev/null
if grep -q 'deps.sh \(figures\|paper\)' "$tmp/check.n"; then
    bad "make check waits on a deps profile beyond 'check'"
else ok; fi
if make -n BUILD="$tmp/b" paper 2>/dev/null | grep -q 'deps.sh paper'; then ok; else bad "make paper does not ask for the paper profile"; fi

# 4. distclean in a scratch tree: generated files go, committed ones stay.
mkdir -p "$tmp/t/figures/attitude" "$tmp/t/data" "$tmp/t/paper" "$tmp/t/build/x"
cp Makefile "$tmp/t/"
keep="data/animation.cfg data/.gitkeep figures/.gitkeep figures/fig1.png paper/companion.tex paper/equations.txt
      paper/companion.pdf paper/methods.pdf paper/ledger.sha256"
gone="figures/fig1.pdf figures/fig1.txt data/fig1.csv figures/attitude/frame_0000.png figures/attitude.mp4
      figures/attitude.txt data/attitude.csv data/bench.tex paper/x.tmp build/x/suslov"
for f in $keep $gone; do : >"$tmp/t/$f"; done
(cd "$tmp/t" && make -s distclean >/dev/null 2>&1)
for f in $keep; do [ -e "$tmp/t/$f" ] && ok || bad "distclean removed the committed $f"; done
for f in $gone; do [ -e "$tmp/t/$f" ] && bad "distclean left $f" || ok; done
[ -d "$tmp/t/figures/attitude" ] && bad "distclean left figures/attitude/" || ok

# 5. In a scratch tree holding only the lowest layer: an archive loses a deleted source's member,
#    a flags change makes -q answer "not up to date", and nothing is rebuilt twice.
mkdir -p "$tmp/l/src/util" "$tmp/l/tools"
cp Makefile "$tmp/l/"; cp tools/deps.sh tools/apt_install.sh "$tmp/l/tools/" 2>/dev/null
# (one source of the layer is enough to ask these, and each more is a compilation)
cp src/util/*.h src/util/atomic_file.c "$tmp/l/src/util/"
util_objs="atomic_file.o "
printf 'int layer_probe(void);\nint layer_probe(void) { return 1; }\n' >"$tmp/l/src/util/probe.c"
lib=build/libsus_util.a
(cd "$tmp/l" && make -s $lib >/dev/null 2>&1)
members() { (cd "$tmp/l" && ar t $lib 2>/dev/null | sort | tr '\n' ' '); }
[ "$(members)" = "$(echo $util_objs probe.o | tr ' ' '\n' | sort | tr '\n' ' ')" ] && ok ||
    bad "libsus_util.a holds '$(members)'"
rm "$tmp/l/src/util/probe.c"
(cd "$tmp/l" && make -s $lib >/dev/null 2>&1)
[ "$(members)" = "$util_objs" ] && ok || bad "a deleted source stays in the archive: '$(members)'"
(cd "$tmp/l" && make -q $lib) && ok || bad "make -q $lib: not up to date right after building it"
(cd "$tmp/l" && make -q CFLAGS=-O1 $lib) && bad "make -q CFLAGS=-O1 $lib says up to date" || ok
(cd "$tmp/l" && make -n CFLAGS=-O1 $lib | grep -q -- '-O1 .*-c src/util/atomic_file.c') && ok ||
    bad "CFLAGS=-O1 does not recompile atomic_file.c"
# the unit tests make check passes to the runner: exactly tests/unit/test_*.c
want=$(ls tests/unit/test_*.c | sed 's#tests/unit/##; s#\.c$##' | sort | tr '\n' ' ')
got=$(sed -n 's#.*tests/run.sh [^ ]* check ##p' "$tmp/check.n" | tr ' ' '\n' |
    sed 's#.*/##' | sed '/^$/d' | sort | tr '\n' ' ')
[ "$got" = "$want" ] && ok || bad "make check runs '$got', expected '$want'"

# plain `make` builds what `make all` builds (not only the first stamp the Makefile defines)
make -n BUILD="$tmp/b" 2>/dev/null | grep -q -- "-o $tmp/b/suslov\$" && ok || bad "plain make does not build suslov"

echo "make_deps: $pass passed, $fail failed"
[ "$fail" = 0 ]
