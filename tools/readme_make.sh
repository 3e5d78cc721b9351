#!/bin/sh
# The make targets as the Makefile's header comment states them, for docs/reference/make-targets.md:
# its lines that start with "#   " (a target, a variable, or their continuation), without the "# ".
# With --print, writes them to stdout in the code fence the document holds (tests/build/doc_facts.sh
# compares); without, rewrites the document's block between "<!-- make targets -->" and
# "<!-- end make targets -->".
# Usage: tools/readme_make.sh [--print]
set -eu
cd "$(dirname "$0")/.."
block() {
    echo '```'
    awk '!/^#/ { exit } /^#   / { sub(/^# /, ""); print }' Makefile
    echo '```'
}
if [ "${1:-}" = --print ]; then
    block
    exit 0
fi
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
block >"$tmp"
sh tools/readme_block.sh docs/reference/make-targets.md "make targets" "$tmp"
