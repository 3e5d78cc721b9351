#!/bin/sh
# Every relative link of README.md and docs/ resolves: each markdown link `[text](target)` and
# each <img src=...> or <a href=...> outside code leads to a file or folder of the tree, and each
# #anchor to a heading of its markdown file, by the anchors GitHub derives from headings
# (lowercased, punctuation dropped but - and _, spaces as -). Links to other sites are not
# followed. Each broken link is printed as FILE:LINE: TARGET.
# Usage: doc_links.sh. Last line: "doc_links: N passed, N failed".
set -u
cd "$(dirname "$0")/../.." || exit 2
pass=0 fail=0
tmp=""
. tools/on_exit.sh
on_exit 'rm -f "$tmp"'
tmp=$(mktemp)
# The anchors of a markdown file, one a line.
anchors() {
    awk '/^```/ { code = !code; next } !code && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
        tr 'A-Z' 'a-z' | tr -d '!"#$%&'"'"'()*+,./:;<=>?@[\\]^`{|}~' | tr ' ' '-'
}
# FILE LINE TARGET for every link of a file, outside fenced code and inline code spans.
links() {
    awk -v f="$1" '
        /^```/ { code = !code; next }
        code { next }
        {
            s = $0
            gsub(/`[^`]*`/, "", s)
            while (match(s, /\]\([^) ]+/)) {
                print f, FNR, substr(s, RSTART + 2, RLENGTH - 2); s = substr(s, RSTART + RLENGTH)
            }
            while (match(s, /(src|href)="[^"]+"/)) {
                t = substr(s, RSTART, RLENGTH); sub(/^[a-z]+="/, "", t); sub(/"$/, "", t)
                print f, FNR, t; s = substr(s, RSTART + RLENGTH)
            }
        }' "$1"
}
for doc in README.md $(find docs -name '*.md' | sort); do links "$doc"; done >"$tmp"
while read -r doc line target; do
    case $target in http://* | https://* | mailto:*) continue ;; esac
    path=${target%%#*}
    anchor=""
    case $target in *'#'*) anchor=${target#*#} ;; esac
    if [ -z "$path" ]; then file=$doc; else file=$(dirname "$doc")/$path; fi
    if [ ! -e "$file" ]; then
        echo "FAIL doc_links: $doc:$line: $target: no file $file"
        fail=$((fail + 1))
    elif [ -n "$anchor" ] && ! anchors "$file" | grep -qxF "$anchor"; then
        echo "FAIL doc_links: $doc:$line: $target: no heading of $file has the anchor #$anchor"
        fail=$((fail + 1))
    else
        pass=$((pass + 1))
    fi
done <"$tmp"
echo "doc_links: $pass passed, $fail failed"
[ "$fail" = 0 ]
