#!/bin/sh
# make paper: pull the code listings and the equation map from the source, gather the generated
# numbers, the paper's numbering (paper/labels.tsv), the team's tables (findings, errata, not
# tested, Conclusions) and the reproducibility block, check that no number is typed by hand
# (tools/paper_numbers.sh) and that every numbered statement of the paper is accounted for
# (tools/paper_coverage.sh), and run pdflatex three times (longtable column widths settle over
# passes) on the companion and on the software note. Fails on an undefined reference, a float
# too large for its page, an overfull box wider than 10 pt, or a Type 3 (bitmap) font.
# Usage: paper.sh BUILD_DIR
set -eu
B=$1
P="$B/paper"
mkdir -p "$P"
# a source file by its name, wherever the tree keeps it (src/ or a layer folder under it)
where() { f=$(find src -name "$1" -type f | head -1); [ -n "$f" ] || { echo "paper: no $1 under src/" >&2; exit 1; }; echo "$f"; }
snip() { sh tools/snippet.sh "$(where "$1")" "$2" >"$P/snip_$2.c"; }
snip step_midpoint.c mid_residual
snip step_variational.c taudyn_residual
snip step_variational.c taualg
snip reconstruct.c sus_reconstruct
snip exact.c sus_exact_omega
awk 'NR == 1, /\*\// { print }' "$(where exact.h)" >"$P/snip_exact_derivation.c"
# A gap in the equation map fails make check (tests/run.sh); here it is reported, not fatal.
sh tools/eqmap.sh tex "$P/eqmap.tex" >/dev/null ||
    echo "paper: the equation map has gaps; run: sh tools/eqmap.sh check" >&2
[ -s "$P/eqmap.tex" ]
for doc in companion methods; do sh tools/paper_numbers.sh "paper/$doc.tex"; done
sh tools/paper_coverage.sh "$B/claims.tsv"
sh tools/paper_tables.sh "$P" "$B/claims.tsv" "$B/summary.tex"
sh tools/paper_tolerances.sh "$B/claims.tsv" paper/tolerances.tsv "$P/tolerances.tex"
sh tools/paper_refs.sh paper/labels.tsv "$P/labels.tex"
sh tools/paper_links.sh "$P/links.tex"
sh tools/repro.sh "$B" "$P/repro.tex"
sh tools/figsplit.sh figures/stability.pdf Stability "$P/figsplit.tex"
cp "$B/numbers.tex" "$B/ledger.tex" "$B/summary.tex" data/bench.tex "$P/"
# A fixed timestamp in the PDF's metadata (the text's date is the commit's, from repro.tex).
export TEXINPUTS="$P:" SOURCE_DATE_EPOCH=946684800
for doc in companion methods; do
    for pass in 1 2 3; do
        if ! pdflatex -interaction=nonstopmode -halt-on-error -output-directory="$P" "paper/$doc.tex" \
            >"$P/pdflatex.out" 2>&1; then
            grep -A5 '^!' "$P/$doc.log" | head -20 >&2
            echo "paper: pdflatex failed on $doc (pass $pass); the log is $P/$doc.log" >&2
            exit 1
        fi
    done
    sh tools/paper_layout.sh "$P/$doc.log" "$P/$doc.pdf"
done
for doc in companion methods; do
    cp "$P/$doc.pdf" "paper/$doc.pdf.tmp" && mv "paper/$doc.pdf.tmp" "paper/$doc.pdf"
    echo "paper: wrote paper/$doc.pdf ($(pdfinfo "paper/$doc.pdf" 2>/dev/null | awk '/^Pages/ { print $2 " pages" }'))"
done
