#!/bin/sh
# The claims ledger run one section after the other in one process (make ledger-inproc: claims
# --in-process, into BUILD_DIR/ledger-inproc) writes the same files, byte for byte, as the run of a
# process per section that make check reads: a section leaning on another's state, or a result
# that loses a digit on its way from its process, fails it.
# Usage: ledger_inproc.sh BUILD_DIR FILE... (the ledger's files, named in BUILD_DIR: the Makefile
# passes its list). Last line: "ledger_inproc: N passed, N failed".
[ $# -gt 1 ] || { echo "usage: ledger_inproc.sh BUILD_DIR FILE..." >&2; exit 2; }
B=$1
shift
differ=""
for f in "$@"; do cmp -s "$B/ledger-inproc/$f" "$B/$f" || differ="$differ $f"; done
if [ -z "$differ" ]; then
    echo "PASS the ledger in one process ($B/ledger-inproc) is the run of a process per section"
    echo "ledger_inproc: 1 passed, 0 failed"
else
    echo "FAIL the ledger in one process ($B/ledger-inproc) differs from the run of a process per section in:$differ"
    echo "ledger_inproc: 0 passed, 1 failed"
    exit 1
fi
