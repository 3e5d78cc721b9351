#!/bin/sh
# "Adding a method" as a tested promise: in a scratch copy of the tree (with a copy of the built
# BUILD_DIR, so that the build is incremental), take exactly the numbered steps of
# docs/howto/add-a-method.md, each by its block's first line (new FILE, list FILE NAME, append
# FILE, run), then check that the method they add is picked up: suslov --method NAME writes its
# rows, --help and the registry's table list it, the registry and attitude-order tests pass with
# it (and each mutant the guide adds fails the latter), the copy of --help in the docs agrees,
# the mutants file stays fresh, and the ledger's per-method lines for it (claims --method NAME)
# run and pass. The guide is the script: a step this test cannot take fails it.
# Usage: scaffold_method.sh [BUILD_DIR]. Last line: "scaffold_method: N passed, N failed".
set -u
B=${1:-build}
cd "$(dirname "$0")/../.." || exit 2
ROOT=$(pwd)
GUIDE=docs/howto/add-a-method.md
pass=0 fail=0
# The guide's commands build in build/, the default; another build (SAN=1: build/san) is not
# copied into the scratch tree, which would build everything again.
if [ "$B" != build ]; then
    echo "SKIP scaffold_method: the guide builds in build/, this run in $B"
    echo "scaffold_method: 0 passed, 0 failed"
    exit 0
fi
check() { # check DESCRIPTION COMMAND...
    d=$1; shift
    if "$@"; then pass=$((pass + 1)); else echo "FAIL scaffold_method: $d"; fail=$((fail + 1)); fi
}
finish() {
    echo "scaffold_method: $pass passed, $fail failed"
    [ "$fail" = 0 ]
    exit
}
S=""
. tools/on_exit.sh
on_exit 'rm -rf "$S"'
S=$(mktemp -d)

# The guide's steps: step K's block into $S/steps/K (its first line, the block's info string
# without the language, into $S/steps/K.how). A step with no block or two, or a block outside a
# numbered step, is a guide this test cannot follow.
mkdir -p "$S/steps"
awk -v dir="$S/steps" '
    function bad(why) { print "FAIL scaffold_method: " FILENAME ":" FNR ": " why; err = 1 }
    !code && /^[0-9]+\. / { step = $1 + 0; if (step != last + 1) bad("step " step " after " last)
                            last = step; next }
    !code && /^ *```[a-z]+ / { if (!step) bad("a block outside a numbered step")
                               else if (seen[step]++) bad("step " step " has two blocks")
                               code = 1; match($0, /^ */); ind = RLENGTH
                               how = $0; sub(/^ *```[a-z]+ /, "", how)
                               print how >(dir "/" step ".how"); printf "" >(dir "/" step); next }
    code && /^ *```$/ { code = 0; close(dir "/" step); close(dir "/" step ".how"); next }
    code { print substr($0, ind + 1) >>(dir "/" step) }
    END { for (k = 1; k <= last; k++) if (!seen[k]) bad("step " k " has no block")
          print last >(dir "/count"); exit err }' "$GUIDE" || { fail=$((fail + 1)); finish; }
n=$(cat "$S/steps/count")
check "$GUIDE lists numbered steps ($n)" test "$n" -ge 1

# The scratch tree: the sources and the built BUILD_DIR with their times, so that only what the
# steps change is built again (as `make` sees it in this tree). Not BUILD_DIR/tests, where the
# test runner writes while this runs beside the other tests.
cp -Rp src tests tools paper docs Makefile README.md "$S/" || finish
[ -f .clang-format ] && cp -p .clang-format "$S/"
mkdir -p "$S/build" &&
    find "$B" -mindepth 1 -maxdepth 1 ! -name tests -exec sh -c 'cp -Rp "$@" "$0"' "$S/build" {} + ||
    finish
cd "$S" || finish
# make reads the command line's variables (WERROR=1, SAN=1: the flags the copy was built with)
# from MAKEFLAGS after " -- "; the job server of the make that runs this test is not ours.
case " ${MAKEFLAGS:-}" in
    *" -- "*) MAKEFLAGS="-j2 -- ${MAKEFLAGS#* -- }" ;;
    *) MAKEFLAGS=-j2 ;;
esac
export MAKEFLAGS
unset MFLAGS MAKELEVEL BUILD

# list FILE NAME < LINES: LINES at the end of the list NAME in FILE: a macro "#define NAME(...)"
# continued by "\" (the last entry gets one), or an array "NAME[] = {" closed by "};".
list_add() {
    awk -v name="$2" -v add="$S/add" '
        function emit() { while ((getline l <add) > 0) print l; close(add); done = 1 }
        !done && !in_list && index($0, "#define " name "(") == 1 && /\\$/ { in_list = 1; macro = 1 }
        !done && !in_list && index($0, " " name "[] = {") { in_list = 1; macro = 0 }
        in_list && macro && !/\\$/ { print $0 " \\"; emit(); in_list = 0; next }
        in_list && !macro && /^};/ { emit(); in_list = 0 }
        { print }
        END { exit !done }' "$1" >"$S/list.tmp" && mv "$S/list.tmp" "$1"
}
# The guide formats with clang-format 14 (tests/build/format.sh's version); without it, a stand-in
# that changes nothing takes its place and the formatting is not checked.
cf=""
for c in clang-format-14 clang-format; do
    command -v "$c" >/dev/null 2>&1 && "$c" --version | grep -q 'version 14\.' && { cf=$c; break; }
done
if [ "$cf" != clang-format ]; then
    mkdir -p "$S/bin"
    if [ -n "$cf" ]; then
        printf '#!/bin/sh\nexec %s "$@"\n' "$cf" >"$S/bin/clang-format"
    else
        echo "SKIP scaffold_method: clang-format 14 is not installed: the steps' files not formatted"
        printf '#!/bin/sh\nexit 0\n' >"$S/bin/clang-format"
    fi
    chmod +x "$S/bin/clang-format"
    PATH="$S/bin:$PATH"
fi
# run FILE: the commands of FILE, quiet unless they fail
run_block() { sh -e "$1" >run.log 2>&1 || { sed 's/^/    /' run.log; return 1; }; }
# what to do when a new file is there already: the tree holds the guide's own example
HELD=" (it exists: this tree already holds the guide's example; undo it, or follow"
HELD="$HELD $GUIDE under another name, as it says)"
k=1
while [ "$k" -le "$n" ]; do
    set -- $(cat "steps/$k.how")
    how=${1:-} file=${2:-} list=${3:-}
    case $how in
        new) check "step $k: $file is new$HELD" test ! -e "$file" && mkdir -p "$(dirname "$file")" &&
            cp "steps/$k" "$file" ;;
        list) cp "steps/$k" "$S/add"
            check "step $k: the list $list in $file takes the lines" list_add "$file" "$list" ;;
        append) check "step $k: $file is there to append to" test -f "$file" &&
            cat "steps/$k" >>"$file" ;;
        run) check "step $k: its commands run ($(tr '\n' ';' <"steps/$k"))" run_block "steps/$k" ;;
        *) check "step $k: '$how' is new FILE, list FILE NAME, append FILE or run" false ;;
    esac
    k=$((k + 1))
done
[ "$fail" = 0 ] || finish

# The C files the steps wrote are as the formatter leaves them.
if [ -n "$cf" ]; then
    for f in $(awk '($1 == "new" || $1 == "list") && $2 ~ /\.[ch]$/ { print $2 }' steps/*.how); do
        check "$f is as clang-format leaves it" "$cf" --dry-run -Werror "$f"
    done 2>/dev/null
fi

# The method the steps add: the name in the new stepper type.
name=$(sed -n 's/^ *\.name = "\([^"]*\)".*/\1/p' $(awk '$1 == "new" { print $2 }' steps/*.how) |
    head -1)
check "the steps add a stepper type with a name ($name)" test -n "$name"
make -s build/suslov build/man/suslov.1 build/test_registry build/test_attitude_order build/claims \
    >build.log 2>&1
rc=$?
check "the tree with the method builds ($(tail -3 build.log | tr '\n' ' '))" test $rc = 0 || finish

build/suslov --no-header --method "$name" --eps 0.1 --steps 10 >rows 2>run.err
rc=$?
check "suslov --method $name writes its 11 rows ($(cat run.err))" \
    test $rc = 0 -a "$(grep -c '^[0-9]' rows)" = 11
check "suslov --help lists $name" sh -c "build/suslov --help | grep -q -- '$name'"
check "the registry's test passes with $name" sh -c 'build/test_registry >reg.log 2>&1'
grep '^FAIL' reg.log
build/test_attitude_order >att.log 2>&1
rc=$?
check "test_attitude_order passes with $name ($(grep -c "^PASS $name," att.log) of its lines)" \
    sh -c "test $rc = 0 && grep -q '^PASS $name, w:' att.log"
grep '^FAIL' att.log
check "the --help copy in docs/reference/cli.md and what suslov says of its methods hold" \
    sh -c 'sh tests/cli/test_cli_methods.sh build >conv.log 2>&1'
grep '^FAIL' conv.log
check "tests/build/mutants stays fresh" sh -c 'sh tests/build/mutants_fresh.sh >fresh.log 2>&1'
grep '^FAIL' fresh.log

# Each mutant the steps add to tests/build/mutants dies in the attitude-order test: applied (its
# text occurs once: mutants_fresh), built, run, and the file put back as it was.
# Its fields are separated by " | " (tools/mutants.sh): here by tabs.
: >mutants.add
for f in $(awk '$1 == "append" && $2 == "tests/build/mutants" { print FILENAME }' steps/*.how); do
    awk -F' [|] ' '!/^#/ && NF >= 4 { print $1 "\t" $2 "\t" $3 "\t" $4 }' "${f%.how}" >>mutants.add
done
tab=$(printf '\t')
while IFS=$tab read -r file from to why <&3; do
    cp -p "$file" mutant.orig
    awk -v a="$from" -v b="$to" '{ i = index($0, a) }
        i { $0 = substr($0, 1, i - 1) b substr($0, i + length(a)) } { print }' mutant.orig >"$file"
    rc=1
    make -s build/test_attitude_order >/dev/null 2>&1 && ! build/test_attitude_order >/dev/null &&
        rc=0
    check "the mutant '$to' of $file ($why) dies in test_attitude_order" test $rc = 0
    cp mutant.orig "$file" # a new time: make builds the file again
done 3<mutants.add

# The ledger's lines of this method alone, and the registry's table it writes beside them.
mkdir -p ledger
build/claims --method "$name" ledger/claims.tsv >ledger/claims.out 2>&1
rc=$?
check "claims --method $name passes ($(grep '^claims:' ledger/claims.out))" \
    sh -c "test $rc = 0 && grep -q '^claims: [1-9][0-9]* passed, 0 failed' ledger/claims.out"
awk '/^checks that failed:$/ { on = 1; next } /^findings of / { exit } on && NF' ledger/claims.out
check "the ledger's lines name $name ($(grep -c -- "$name" ledger/claims.tsv))" \
    grep -q -- "$name" ledger/claims.tsv
check "the registry's table (methods.tsv) lists $name" \
    sh -c "cut -f1 ledger/methods.tsv | grep -qx -- '$name'"
cd "$ROOT" || exit 2
finish
