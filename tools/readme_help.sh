#!/bin/sh
# Rewrites the block of README.md between "<!-- suslov --help -->" and "<!-- end suslov --help -->"
# with the output of SUSLOV --help (tests/cli/test_cli_conventions.sh fails until they agree).
# Usage: tools/readme_help.sh [SUSLOV] (default build/suslov).
set -eu
S=${1:-build/suslov}
help=$(mktemp)
trap 'rm -f "$help"' EXIT
{ echo '```'; "$S" --help; echo '```'; } >"$help"
sh "$(dirname "$0")/readme_block.sh" "suslov --help" "$help"
