#!/bin/sh
# make paper: pull the code listings and the equation map from the source, gather the generated
# numbers, the paper's numbering (paper/labels.tsv) and the reproducibility block, check that no
# number is typed by hand (tools/paper_numbers.sh), and run pdflatex three times (longtable
# column widths settle over passes). Prints every overfull box.
# Usage: paper.sh BUILD_DIR
set -eu
B=$1
P="$B/paper"
mkdir -p "$P"
snip() { sh tools/snippet.sh "$1" "$2" >"$P/snip_$2.c"; }
snip src/methods/step_midpoint.c mid_residual
snip src/methods/step_variational.c taudyn_residual
snip src/methods/step_variational.c taualg
snip src/core/reconstruct.c suslov_reconstruct
snip src/core/exact.c suslov_exact_omega
awk 'NR == 1, /\*\// { print }' src/core/exact.h >"$P/snip_exact_derivation.c"
# A gap in the equation map fails make check (tests/run.sh); here it is reported, not fatal.
sh tools/eqmap.sh tex "$P/eqmap.tex" >/dev/null ||
    echo "paper: the equation map has gaps; run: sh tools/eqmap.sh check" >&2
[ -s "$P/eqmap.tex" ]
sh tools/paper_numbers.sh paper/companion.tex
sh tools/paper_refs.sh paper/labels.tsv "$P/labels.tex"
sh tools/repro.sh "$B" "$P/repro.tex"
sh tools/figsplit.sh figures/stability.pdf Stability "$P/figsplit.tex"
cp "$B/numbers.tex" "$B/ledger.tex" "$B/summary.tex" data/bench.tex "$P/"
# A fixed timestamp in the PDF's metadata (the text's date is the commit's, from repro.tex).
export TEXINPUTS="$P:" SOURCE_DATE_EPOCH=946684800
for pass in 1 2 3; do
    if ! pdflatex -interaction=nonstopmode -halt-on-error -output-directory="$P" paper/companion.tex >"$P/pdflatex.out" 2>&1; then
        grep -A5 '^!' "$P/companion.log" | head -20 >&2
        echo "paper: pdflatex failed (pass $pass); the log is $P/companion.log" >&2
        exit 1
    fi
done
grep -A1 'Overfull' "$P/companion.log" || true
cp "$P/companion.pdf" paper/companion.pdf.tmp && mv paper/companion.pdf.tmp paper/companion.pdf
echo "paper: wrote paper/companion.pdf ($(grep -c . "$P/companion.log" >/dev/null; pdfinfo paper/companion.pdf 2>/dev/null | awk '/^Pages/ { print $2 " pages" }'))"
