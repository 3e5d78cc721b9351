#!/bin/sh
# The claims ledger run one section after the other in one process (make ledger-inproc: claims
# --in-process, into BUILD_DIR/ledger-inproc) writes the same files, byte for byte, as the run of a
# process per section that make check reads: a section leaning on another's state, or a result
# that loses a digit on its way from its process, fails it.
# Usage: ledger_inproc.sh BUILD_DIR. Last line: "ledger_inproc: N passed, N failed".
B=${1:-build}
differ=""
for f in claims.out claims.tsv methods.tsv numbers.tex ledger.tex summary.tex sensitivity.tex \
    claims_tex.tsv; do
    cmp -s "$B/ledger-inproc/$f" "$B/$f" || differ="$differ $f"
done
if [ -z "$differ" ]; then
    echo "PASS the ledger in one process ($B/ledger-inproc) is the run of a process per section"
    echo "ledger_inproc: 1 passed, 0 failed"
else
    echo "FAIL the ledger in one process ($B/ledger-inproc) differs from the run of a process per section in:$differ"
    echo "ledger_inproc: 0 passed, 1 failed"
    exit 1
fi
