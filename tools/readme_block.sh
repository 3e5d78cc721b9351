#!/bin/sh
# Replaces the lines of DOC between "<!-- NAME -->" and "<!-- end NAME -->" with the lines of FILE
# (tools/readme_help.sh, tools/readme_make.sh). Fails, leaving DOC as it was, when the block's
# markers are missing. Run by hand: no make target rewrites a tracked file.
# Usage: tools/readme_block.sh DOC NAME FILE
set -eu
doc=$1 name=$2 file=$3
grep -qxF "<!-- $name -->" "$doc" && grep -qxF "<!-- end $name -->" "$doc" ||
    { echo "readme_block: $doc has no <!-- $name --> ... <!-- end $name --> block" >&2; exit 1; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
awk -v first="<!-- $name -->" -v last="<!-- end $name -->" -v file="$file" '
    $0 == last { skip = 0 }
    !skip { print }
    $0 == first { while ((getline l < file) > 0) print l; skip = 1 }
' "$doc" >"$out"
cat "$out" >"$doc"
