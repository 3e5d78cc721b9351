#!/bin/sh
# The layout checks a journal makes, on one pdflatex log and its PDF: no undefined reference or
# citation, no float too large for its page, no overfull box wider than 10 pt (smaller ones are
# invisible at print size), and only Type 1 (or TrueType/CID) fonts: a Type 3 font is a bitmap,
# breaks text search and ligatures. Prints each problem; exit 1 on any.
# Usage: paper_layout.sh LOG PDF
set -eu
log=$1
pdf=$2
bad=0
if grep -E "There were undefined references|Reference .* undefined|Citation .* undefined" "$log"; then bad=1; fi
if grep "Float too large" "$log"; then bad=1; fi
if awk '/^Overfull \\[hv]box \(/ { w = $3; sub(/^\(/, "", w); sub(/pt$/, "", w); if (w + 0 > 10) { print; bad = 1 } }
        END { exit !bad }' "$log"; then bad=1; fi
if pdffonts "$pdf" | awk 'NR > 2 && $0 ~ / Type 3 / { print "Type 3 font: " $0; found = 1 } END { exit !found }'; then
    bad=1
fi
[ "$bad" -eq 0 ] || echo "paper: layout problems in $pdf (log $log)" >&2
exit "$bad"
