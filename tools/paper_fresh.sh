#!/bin/sh
# The committed PDFs (paper/companion.pdf, paper/methods.pdf) against the ledger of this build:
# make paper records in paper/ledger.sha256 the SHA-256 of the ledger's outputs the PDFs print
# (numbers.tex, ledger.tex, summary.tex, sensitivity.tex); when the ledger now writes other ones,
# the PDFs quote numbers it no longer gives, and this fails, naming the files that differ. Needs
# no TeX. Run by make check (tests/run.sh).
# Usage: paper_fresh.sh BUILD_DIR. Last line: "paper_fresh: N passed, N failed".
set -u
B=${1:-build}
pass=0 fail=0
for pdf in paper/companion.pdf paper/methods.pdf; do
    if [ "$(head -c 5 "$pdf" 2>/dev/null)" = "%PDF-" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL paper_fresh: $pdf is missing or not a PDF (make paper writes it; it is committed)"
    fi
done
if [ ! -s paper/ledger.sha256 ]; then
    fail=$((fail + 1))
    echo "FAIL paper_fresh: paper/ledger.sha256 is missing (make paper writes it beside the PDFs)"
else
    while read -r sum name; do
        now=$(sha256sum "$B/$name" 2>/dev/null | cut -d' ' -f1)
        if [ "$now" = "$sum" ]; then
            pass=$((pass + 1))
        else
            fail=$((fail + 1))
            echo "FAIL paper_fresh: the committed PDFs print another $name than this build's ledger" \
                "writes ($B/$name): run make paper and commit paper/*.pdf and paper/ledger.sha256"
        fi
    done <paper/ledger.sha256
fi
echo "paper_fresh: $pass passed, $fail failed"
[ "$fail" = 0 ]
