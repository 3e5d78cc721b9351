#!/bin/sh
# What the documents state that another file decides, kept in step with it:
#   - docs/reference/make-targets.md quotes the Makefile's header verbatim (tools/readme_make.sh
#     --print gives the block; run tools/readme_make.sh to rewrite it);
#   - README.md's "Not reproduced" and "Errata" items name exactly the findings of
#     paper/findings.tsv with those verdicts (by their ids, F12, ...);
#   - README.md is a front door: at most 150 lines, and its first 40 say what was found, show
#     a figure and give the two commands.
# (suslov --help and its copy in docs/reference/cli.md: tests/cli/test_cli_methods.sh.)
# Usage: doc_facts.sh. Last line: "doc_facts: N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
pass=0 fail=0
check() { # check DESCRIPTION COMMAND...
    d=$1; shift
    if "$@"; then pass=$((pass + 1)); else echo "FAIL doc_facts: $d"; fail=$((fail + 1)); fi
}
tmp=""
. tools/on_exit.sh
on_exit 'rm -rf "$tmp"'
tmp=$(mktemp -d)

sh tools/readme_make.sh --print >"$tmp/want"
sed -n '/^<!-- make targets -->$/,/^<!-- end make targets -->$/p' docs/reference/make-targets.md |
    sed '1d;$d' >"$tmp/got"
check "docs/reference/make-targets.md quotes the Makefile's header (run tools/readme_make.sh)" \
    cmp -s "$tmp/want" "$tmp/got"

# The ids of a README item: the item starting "- **TITLE" up to the next item or blank line.
item_ids() {
    awk -v t="- **$1" 'index($0, t) == 1 { on = 1; print; next }
        on && (/^- / || /^$/) { exit } on' README.md |
        grep -o 'F[0-9][0-9]*' | sort -u | tr '\n' ' '
}
verdict_ids() {
    awk -F'\t' -v v="$1" 'NR > 1 && $3 == v { print $1 }' paper/findings.tsv | sort -u | tr '\n' ' '
}
for pair in "Not reproduced:not reproduced" "Errata:erratum"; do
    title=${pair%%:*} verdict=${pair#*:}
    got=$(item_ids "$title") want=$(verdict_ids "$verdict")
    d="README.md's \"$title\" item names the findings ${want:-(none)}with verdict $verdict in"
    check "$d paper/findings.tsv (it names ${got:-none})" test -n "$want" -a "$got" = "$want"
done

n=$(wc -l <README.md)
check "README.md is at most 150 lines ($n)" test "$n" -le 150
head -40 README.md >"$tmp/first"
check "README.md's first 40 lines say what was found, show a figure, give the two commands" \
    sh -c "grep -q '^## What we found' '$tmp/first' &&
           grep -Eq 'figures/[a-z0-9_]+\\.png' '$tmp/first' &&
           grep -q '^make figures' '$tmp/first' && grep -q '^make check' '$tmp/first'"
echo "doc_facts: $pass passed, $fail failed"
[ "$fail" = 0 ]
