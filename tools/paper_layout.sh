#!/bin/sh
# The layout checks a journal makes, on one pdflatex log and its PDF: no undefined reference or
# citation, no float too large for its page, no overfull box wider than 10 pt (smaller ones are
# invisible at print size), and only Type 1 (or TrueType/CID) fonts: a Type 3 font is a bitmap,
# breaks text search and ligatures; and no text of a figure (the figures' font, DejaVu, which the
# LaTeX text never uses) printed below 7 pt, measured on the PDF as printed through Ghostscript's
# text extraction, so that it holds whatever the scale a figure is included at. Prints each
# problem; exit 1 on any.
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
if command -v gs >/dev/null 2>&1; then
    if gs -q -dNOPAUSE -dBATCH -dSAFER -sDEVICE=txtwrite -dTextFormat=0 -sOutputFile=- "$pdf" | awk '
        /<page/ { page++ }
        /<span / && /font="[A-Z]*\+?DejaVu/ { s = $0; sub(/.*size="/, "", s); sub(/".*/, "", s)
            if (s + 0 < 6.995) { n[page]++; if (!(page in lo) || s + 0 < lo[page]) lo[page] = s + 0 } }
        END { for (p in n) { printf "page %d: %d pieces of figure text below 7 pt (smallest %.2f pt)\n", p, n[p], lo[p]; bad = 1 }
              exit !bad }'; then bad=1; fi
else
    echo "paper: gs missing (make deps-paper installs ghostscript): figure text size unchecked" >&2
    bad=1
fi
[ "$bad" -eq 0 ] || echo "paper: layout problems in $pdf (log $log)" >&2
exit "$bad"
