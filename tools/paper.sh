#!/bin/sh
# make paper: pull the code listings and the equation map from the source, gather the generated
# numbers, and run pdflatex twice (longtable needs two passes). Prints every overfull box.
# Usage: paper.sh BUILD_DIR
set -eu
B=$1
P="$B/paper"
mkdir -p "$P"
snip() { sh tools/snippet.sh "$1" "$2" >"$P/snip_$2.c"; }
snip src/step_midpoint.c mid_residual
snip src/step_variational.c taudyn_residual
snip src/step_variational.c taualg
snip src/reconstruct.c suslov_reconstruct
snip src/exact.c suslov_exact_omega
awk 'NR == 1, /\*\// { print }' src/exact.h >"$P/snip_exact_derivation.c"
sh tools/eqmap.sh tex "$P/eqmap.tex" >/dev/null
cp "$B/numbers.tex" "$B/ledger.tex" data/bench.tex "$P/"
export TEXINPUTS="$P:" SOURCE_DATE_EPOCH=946684800 FORCE_SOURCE_DATE=1
for pass in 1 2; do
    if ! pdflatex -interaction=nonstopmode -halt-on-error -output-directory="$P" paper/companion.tex >"$P/pdflatex.out" 2>&1; then
        grep -A5 '^!' "$P/companion.log" | head -20 >&2
        echo "paper: pdflatex failed (pass $pass); the log is $P/companion.log" >&2
        exit 1
    fi
done
grep -A1 'Overfull' "$P/companion.log" || true
cp "$P/companion.pdf" paper/companion.pdf.tmp && mv paper/companion.pdf.tmp paper/companion.pdf
echo "paper: wrote paper/companion.pdf ($(grep -c . "$P/companion.log" >/dev/null; pdfinfo paper/companion.pdf 2>/dev/null | awk '/^Pages/ { print $2 " pages" }'))"
