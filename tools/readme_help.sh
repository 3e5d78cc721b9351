#!/bin/sh
# Rewrites the block of docs/reference/cli.md between "<!-- suslov --help -->" and
# "<!-- end suslov --help -->" with the output of SUSLOV --help, in a code fence
# (tests/cli/test_cli_methods.sh fails until they agree). Run it after a change to the
# options or to the registry of methods, which --help lists.
# Usage: tools/readme_help.sh [SUSLOV] (default build/suslov).
set -eu
S=${1:-build/suslov}
help=$(mktemp)
trap 'rm -f "$help"' EXIT
{ echo '```'; "$S" --help; echo '```'; } >"$help"
sh "$(dirname "$0")/readme_block.sh" docs/reference/cli.md "suslov --help" "$help"
