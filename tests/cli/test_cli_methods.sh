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
nm=$(awk -F '\t' 'NR == 1 { ok = $0 == "name\tfamily\torder\treconstruct\tabout" }
                  NF != 5 { ok = 0 } NR > 1 { printf "%s ", $1 } END { if (!ok) printf "BAD" }' "$T/list")
check "--method list: TSV header, 5 fields per line, exact and the registry ($nm)" \
    eval 'test $rc = 0 && case $nm in *BAD) false ;; "exact euler midpoint rk4 variational "*) ;; *) false ;; esac'
if command -v script >/dev/null; then
    script -qec "'$S' --method list" /dev/null >"$T/tty" 2>&1
    check "--method list on a terminal: an aligned table, no tabs" \
        awk '/^exact  *closed form/ { e = 1 } /\t/ { t = 1 } END { exit !(e && !t) }' "$T/tty"
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
"$S" --help >"$T/help"
: >"$T/lines"
while IFS="$(printf '\t')" read -r m family order recon about; do
    [ "$m" = name ] || [ "$m" = exact ] && continue
    args="--eps 0.25 --steps 1"; [ "$order" = tol ] && args="--tol 1e-8 --time 0.25"
    "$S" --method "$m" $args >"$T/m.csv"
    line=""
    while IFS= read -r l; do case $l in '# method: '*) line=$l; break ;; esac; done <"$T/m.csv"
    printf '%s\t%s\t%s\n' "$m" "$recon" "$line" >>"$T/lines"
done <"$T/list"
# each method's header line against --help: NAME's line there (the first one starting with it),
# the attitude form of the "NAMES: none, their own FORM attitude" line naming it, and whether a
# default reconstruction's line names it (a name as a whole word, as grep -w reads one)
wrong=$(awk -F '\t' '
    function named(s, m,   i, j, b, a) {
        for (j = 0; (i = index(substr(s, j + 1), m)) > 0; j += i) {
            b = substr(s, j + i - 1, 1); a = substr(s, j + i + length(m), 1)
            if (b !~ /[A-Za-z0-9_]/ && a !~ /[A-Za-z0-9_]/) return 1
        }
        return 0
    }
    function ends(s, t) { return length(s) >= length(t) && substr(s, length(s) - length(t) + 1) == t }
    FNR == NR { help[++nh] = $0; next }
    {
        m = $1; recon = $2; line = $3; hl = ""; form = ""; under = 0
        for (k = 1; k <= nh; k++) {
            h = help[k]
            if (hl == "" && match(h, /^ *[^ ]+ /) && substr(h, RSTART, RLENGTH) ~ ("^ *" m " $")) hl = h
            if (form == "" && h ~ /: none, their own [a-z]+ attitude$/ && named(h, m)) {
                form = h; sub(/.*: none, their own /, "", form); sub(/ attitude$/, "", form)
            }
            if (h ~ /^ +[a-z0-9, -]+: (cayley|cayley-mid|exp-mid)$/ && named(h, m)) under = 1
        }
        if (recon == "own") {
            want = "attitude: own (" (form == "" ? "?" : form) "; --reconstruct does not apply)"
            if (form == "") printf " [%s: --help declares no attitude form for it]", m
            if (!(index(line, ", " want) && ends(line, want)))
                printf " [%s: expected '"'"'... %s'"'"', got '"'"'%s'"'"']", m, want, line
            if (!ends(hl, "(ignores --reconstruct)"))
                printf " [%s: expected '"'"'(ignores --reconstruct)'"'"' ending its --help line, got '"'"'%s'"'"']", m, hl
            if (under) printf " [%s: listed under a default reconstruction in --help]", m
        } else if (!ends(line, ", reconstruction " recon))
            printf " [%s: expected '"'"'..., reconstruction %s'"'"', got '"'"'%s'"'"']", m, recon, line
    }' "$T/help" "$T/lines")
own_ok() {
    test -z "$wrong" && grep -q '^ *gauss4 .*(ignores --reconstruct)$' "$T/help" &&
        grep -q '^gauss4.*own' "$T/list"
}
check "header and --help: own-attitude methods say 'attitude: own' with their declared form, the others their reconstruction${wrong:+; wrong:$wrong}" \
    own_ok
# --help, the manual page and docs/reference/cli.md tell the same: the manual page is written from
# the option table --help prints, and docs/reference/cli.md quotes --help verbatim between its
# markers (tools/readme_help.sh rewrites its copy)
"$S" --man >"$T/man"
# an option's entry: a line ".B", ".BI", a space and a quote optional, then the option with its
# hyphens escaped (\-), then a space or the line's end
missing=$(awk 'FNR == NR { if (match($0, /^  --[a-z0-9-]*/)) opt[++n] = substr($0, 3, RLENGTH - 2)
                          next }
               /^\.B/ { e = $0; sub(/^\.BI? ?"?/, "", e); sub(/ .*/, "", e); entry[e] = 1 }
               END { for (k = 1; k <= n; k++) { o = opt[k]; gsub(/-/, "\\-", o)
                                                if (!(o in entry)) printf " %s", opt[k] } }' \
    "$T/help" "$T/man")
check "every option of --help has its entry in the manual page${missing:+ (missing:$missing)}" test -z "$missing"
# ... and reads as one: no groff warning; EXAMPLES one command a line, the CSV header a line of
# its own, each exit status, column and variable a tag starting its line (not run together into
# filled paragraphs)
if command -v groff >/dev/null; then
    groff -man -Tutf8 -ww -z "$T/man" 2>"$T/gw"
    groff -man -Tutf8 -P-cbu -rLL=120n "$T/man" 2>/dev/null >"$T/man.txt"
    # the examples (after EXAMPLES, a command a line) and the tags, each starting a line indented
    # by 7 to 11 spaces
    set -- $(awk 'BEGIN { n = split("0 |1 |2 |3 |128\\+n |k |t |lambda |energy |NO_COLOR|" \
                  "SUSLOV_NO_O_TMPFILE|SUSLOV_PROGRESS_AFTER|omega1,omega2,omega3$|R11,...,R33$|" \
                  "k,t,omega1,omega2,omega3,lambda,energy,R11,R12,R13,R21,R22,R23,R31,R32,R33$", tag, "|") }
                  /^EXAMPLES/ { ex = 1 }
                  { match($0, /^ */); if (RLENGTH < 7 || RLENGTH > 11) next; r = substr($0, RLENGTH + 1)
                    if (ex && r ~ /^suslov --method [^ ]*( --[a-z-]* [^ ]*)*$/) n_ex++
                    for (k = 1; k <= n; k++) if (r ~ ("^" tag[k])) seen[k] = 1 }
                  END { for (k in seen) n_tags++; print n_ex + 0, n_tags + 0 }' "$T/man.txt")
    n_ex=$1 n_tags=$2
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
