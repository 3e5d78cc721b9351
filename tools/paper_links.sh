#!/bin/sh
# Where each source file is, for the links in the companion's captions (\repolink{NAME} in
# paper/preamble.tex): writes one \RepoPath{NAME}{PATH} per file of src/, tests/ and tools/,
# found in the tree (git ls-files in a clone, find otherwise), so that the captions keep working
# when files move between folders. Links are relative to paper/, where the PDFs are.
# Usage: paper_links.sh OUT.tex
set -eu
out=$1
{ git ls-files src tests tools 2>/dev/null || find src tests tools -type f; } |
    awk -F/ '{ printf "\\RepoPath{%s}{%s}\n", $NF, $0 }' >"$out.tmp"
mv "$out.tmp" "$out"
