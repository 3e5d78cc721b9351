#!/bin/sh
# What suslov says of its methods, the part of its conventions that adding a method changes (and
# that tests/build/scaffold_method.sh runs again with the guide's new method): --method list, each
# method's header line (its order, its attitude: a reconstruction or its own), --help's lines for
# it, and --help, the manual page and docs/reference/cli.md telling the same.
# Usage: test_cli_methods.sh BUILD_DIR. Last line: "test_cli_methods: N passed, N failed".
set -u
B=${1:-build}
. "$(dirname "$0")/cli_testlib.sh"
S="$B/suslov"

# --method list: TSV when piped, name family order reconstruct about; every method once
"$S" --method list >"$T/list"; rc=$?
nm=$(tail -n +2 "$T/list" | cut -f1 | tr '\n' ' ')
check "--method list: TSV header, 5 fields per line, exact and the registry ($nm)" \
    sh -c "test $rc = 0 -a \"\$(head -1 '$T/list')\" = \"\$(printf 'name\tfamily\torder\treconstruct\tabout')\" &&
           awk -F '\t' 'NF != 5 { exit 1 }' '$T/list' && echo '$nm' | grep -q '^exact euler midpoint rk4 variational '"
if command -v script >/dev/null; then
    script -qec "'$S' --method list" /dev/null >"$T/tty" 2>&1
    check "--method list on a terminal: an aligned table, no tabs" sh -c "grep -q '^exact  *closed form' '$T/tty' && ! grep -q \"\$(printf '\t')\" '$T/tty'"
fi

# a --tol method's order is the one it chose for that TOL, and the header says so
"$S" --method exact-attitude --tol 1e-6 --time 1 >"$T/h.csv"
check "header: a --tol method's order is the one for its TOL" \
    grep -q '^# method: exact-attitude (closed form, order [0-9]* at this TOL), attitude: own' "$T/h.csv"
# a method that carries its own attitude (--method list: reconstruct "own") says so in its header,
# with the attitude form it declares (--help's --reconstruct block: "NAMES: none, their own FORM
# attitude", from the method's self-description), never a reconstruction it does not use;
# --help says "(ignores --reconstruct)" on its line and lists it under no reconstruction (gauss4's
# attitude is its collocation's, as the Taylor series')
"$S" --method list >"$T/list"
"$S" --help >"$T/help"
wrong=""
while IFS="$(printf '\t')" read -r m family order recon about; do
    [ "$m" = name ] || [ "$m" = exact ] && continue
    args="--eps 0.25 --steps 1"; [ "$order" = tol ] && args="--tol 1e-8 --time 0.25"
    line=$("$S" --method "$m" $args | grep '^# method: ')
    hl=$(grep "^ *$m " "$T/help" | head -1)
    if [ "$recon" = own ]; then
        form=$(grep -E ': none, their own [a-z]+ attitude$' "$T/help" | grep -w -- "$m" |
            sed -E 's/.*: none, their own ([a-z]+) attitude$/\1/' | head -1)
        want="attitude: own (${form:-?}; --reconstruct does not apply)"
        [ -n "$form" ] || wrong="$wrong [$m: --help declares no attitude form for it]"
        echo "$line" | grep -qF ", $want" && [ "${line%"$want"}" != "$line" ] ||
            wrong="$wrong [$m: expected '... $want', got '$line']"
        echo "$hl" | grep -q '(ignores --reconstruct)$' ||
            wrong="$wrong [$m: expected '(ignores --reconstruct)' ending its --help line, got '$hl']"
        grep -E '^ +[a-z0-9, -]+: (cayley|cayley-mid|exp-mid)$' "$T/help" | grep -qw -- "$m" &&
            wrong="$wrong [$m: listed under a default reconstruction in --help]"
    else
        echo "$line" | grep -q ", reconstruction $recon\$" ||
            wrong="$wrong [$m: expected '..., reconstruction $recon', got '$line']"
    fi
done <"$T/list"
own_ok() {
    test -z "$wrong" && grep -q '^ *gauss4 .*(ignores --reconstruct)$' "$T/help" &&
        grep -q '^gauss4.*own' "$T/list"
}
check "header and --help: own-attitude methods say 'attitude: own' with their declared form, the others their reconstruction${wrong:+; wrong:$wrong}" \
    own_ok
# --help, the manual page and docs/reference/cli.md tell the same: the manual page is written from
# the option table --help prints, and docs/reference/cli.md quotes --help verbatim between its
# markers (tools/readme_help.sh rewrites its copy)
"$S" --help >"$T/help"
"$S" --man >"$T/man"
missing=""
for o in $(grep -o '^  --[a-z0-9-]*' "$T/help"); do
    grep -q "^\\.BI\\{0,1\\} \\{0,1\\}\"\\{0,1\\}$(echo "$o" | sed 's/-/\\\\-/g')\\( \\|\$\\)" "$T/man" || missing="$missing $o"
done
check "every option of --help has its entry in the manual page${missing:+ (missing:$missing)}" test -z "$missing"
# ... and reads as one: no groff warning; EXAMPLES one command a line, the CSV header a line of
# its own, each exit status, column and variable a tag starting its line (not run together into
# filled paragraphs)
if command -v groff >/dev/null; then
    groff -man -Tutf8 -ww -z "$T/man" 2>"$T/gw"
    groff -man -Tutf8 -P-cbu -rLL=120n "$T/man" 2>/dev/null >"$T/man.txt"
    starts() { grep -c "^ \{7,11\}$1" "$T/man.txt"; }
    n_ex=$(sed -n '/^EXAMPLES/,$p' "$T/man.txt" | grep -c '^ \{7,11\}suslov --method [^ ]*\( --[a-z-]* [^ ]*\)*$')
    n_tags=$(for t in '0 ' '1 ' '2 ' '3 ' '128+n ' 'k ' 't ' 'lambda ' 'energy ' NO_COLOR SUSLOV_NO_O_TMPFILE \
                      SUSLOV_PROGRESS_AFTER 'omega1,omega2,omega3$' 'R11,...,R33$' \
                      'k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33$'; do
                 [ "$(starts "$t")" -ge 1 ] && echo "$t"; done | wc -l)
    check "the manual page in groff: no warning ($(head -c 200 "$T/gw")), 4 examples on lines of their own ($n_ex), 15 tags and the CSV header each starting a line ($n_tags)" \
        test ! -s "$T/gw" -a "$n_ex" = 4 -a "$n_tags" = 15
else
    skip "the manual page's layout: no groff"
fi
check "the built manual page $B/man/suslov.1 is the one suslov --man writes" cmp -s "$T/man" "$B/man/suslov.1"
sed -n '/^<!-- suslov --help -->$/,/^<!-- end suslov --help -->$/p' docs/reference/cli.md |
    sed '1,2d;$d' | sed '$d' >"$T/doc"
check "docs/reference/cli.md quotes suslov --help verbatim (run tools/readme_help.sh after a change)" \
    cmp -s "$T/help" "$T/doc"

done_tests test_cli_methods
