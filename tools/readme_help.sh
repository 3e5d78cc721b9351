#!/bin/sh
# Rewrites the block of README.md between "<!-- suslov --help -->" and "<!-- end suslov --help -->"
# with the output of SUSLOV --help (tests/cli/test_cli_conventions.sh fails until they agree).
# Usage: tools/readme_help.sh [SUSLOV] (default build/suslov).
set -eu
S=${1:-build/suslov}
help=$(mktemp)
out=$(mktemp)
trap 'rm -f "$help" "$out"' EXIT
"$S" --help >"$help"
awk -v help="$help" '
    /^<!-- end suslov --help -->$/ { skip = 0 }
    !skip { print }
    /^<!-- suslov --help -->$/ { print "```"; while ((getline l < help) > 0) print l; print "```"; skip = 1 }
' README.md >"$out"
cat "$out" >README.md
