#!/bin/sh
# Replaces the lines of README.md between "<!-- NAME -->" and "<!-- end NAME -->" with the lines of
# FILE (tools/readme_help.sh, tools/readme_bench.sh). Fails, leaving README.md as it was, when the
# block's opening marker is missing.
# Usage: tools/readme_block.sh NAME FILE
set -eu
name=$1 file=$2
grep -qxF "<!-- $name -->" README.md || { echo "readme_block: README.md has no <!-- $name --> block" >&2; exit 1; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
awk -v first="<!-- $name -->" -v last="<!-- end $name -->" -v file="$file" '
    $0 == last { skip = 0 }
    !skip { print }
    $0 == first { while ((getline l < file) > 0) print l; skip = 1 }
' README.md >"$out"
cat "$out" >README.md
