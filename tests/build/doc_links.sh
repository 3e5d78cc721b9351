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
on_exit 'rm -f "$tmp" "$tmp.anchors" "$tmp.out"'
tmp=$(mktemp)
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
: >"$tmp.anchors"
while read -r doc line target; do
    case $target in http://* | https://* | mailto:*) continue ;; esac
    path=${target%%#*}
    anchor=""
    case $target in *'#'*) anchor=${target#*#} ;; esac
    case $doc in */*) file=${doc%/*}/$path ;; *) file=$path ;; esac
    [ -n "$path" ] || file=$doc
    if [ ! -e "$file" ]; then
        echo "FAIL doc_links: $doc:$line: $target: no file $file"
        fail=$((fail + 1))
    elif [ -n "$anchor" ]; then
        printf '%s %s %s %s\n' "$file" "$anchor" "$doc:$line" "$target" >>"$tmp.anchors"
    else
        pass=$((pass + 1))
    fi
done <"$tmp"
# Each #anchor against the headings of its file, outside fenced code, as GitHub derives anchors
# from them: lowercased, punctuation dropped but - and _, spaces as -. Each file read once.
awk -v punct='!"#$%&'"'"'()*+,./:;<=>?@[\]^`{|}~' '
    function read_anchors(f,   l, code, a, i, c) {
        while ((getline l <f) > 0) {
            if (l ~ /^```/) { code = !code; continue }
            if (code || l !~ /^#+ /) continue
            sub(/^#+ +/, "", l); l = tolower(l); a = ""
            for (i = 1; i <= length(l); i++) {
                c = substr(l, i, 1)
                if (!index(punct, c)) a = a (c == " " ? "-" : c)
            }
            has[f, a] = 1
        }
        close(f); seen[f] = 1
    }
    !($1 in seen) { read_anchors($1) }
    ($1, $2) in has { ok++; next }
    { printf "FAIL doc_links: %s: %s: no heading of %s has the anchor #%s\n", $3, $4, $1, $2; bad++ }
    END { print "counts", ok + 0, bad + 0 }' "$tmp.anchors" >"$tmp.out"
while IFS= read -r l; do
    case $l in
        'counts '*) set -- $l; pass=$((pass + $2)) fail=$((fail + $3)) ;;
        *) printf '%s\n' "$l" ;;
    esac
done <"$tmp.out"
echo "doc_links: $pass passed, $fail failed"
[ "$fail" = 0 ]
