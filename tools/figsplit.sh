#!/bin/sh
# Where to cut a tall figure in two for the companion, so that it can be printed at a scale
# that keeps its labels legible (see \FigScale in paper/preamble.tex): at the top of the
# panel row whose label "(x)" (in the left margin) lies nearest the middle of the page, so
# that neither half is taller than a page.
# Writes \NAMETopHalf and \NAMEBottomHalf (the two parts as \fig commands, trimmed in PDF
# points) to OUT; writes an empty OUT when pdftotext is missing or no row label is found, and
# the companion then prints the figure whole, scaled to the page.
# Usage: figsplit.sh FIGURE.pdf NAME OUT.tex
set -eu
pdf=$1 name=$2 out=$3
: >"$out.tmp"
if command -v pdftotext >/dev/null 2>&1 && command -v pdfinfo >/dev/null 2>&1; then
    h=$(pdfinfo "$pdf" | awk '/^Page size/ { print $5 }')
    pdftotext -bbox "$pdf" - | awk -F'"' -v h="$h" -v name="$name" -v pdf="$(basename "$pdf")" '
        /<word/ { w = $0; sub(/.*">/, "", w); sub(/<.*/, "", w)
                  d = $4 - h / 2; if (d < 0) d = -d
                  if (w ~ /^\([a-z]\)$/ && $2 + 0 < 40 && $4 > 40 && (cut == "" || d < best)) { cut = $4; best = d } }
        END { if (cut != "") { top = cut - 6
                  printf "\\newcommand{\\%sTopHalf}{\\fig[trim=0 %.1f 0 0,clip]{%s}}\n", name, h - top, pdf
                  printf "\\newcommand{\\%sBottomHalf}{\\fig[trim=0 0 0 %.1f,clip]{%s}}\n", name, top, pdf } }
    ' >"$out.tmp"
fi
mv "$out.tmp" "$out"
