#!/bin/sh
# The C sources of src/ (any depth) that the WebAssembly build can compile: those that include,
# directly or through the project's own headers, no GSL, Cairo, libpng, OpenGL or signal header,
# and define no main. Prints them one a line, sorted.
set -eu
libs='^#include <(gsl/|cairo|GL/|png\.h|signal\.h)'
# project headers that reach such a header, found by repeating the rule until nothing changes
bad=$(grep -rlE "$libs" --include='*.h' src | xargs -r -n1 basename | sort -u)
while :; do
    pat=$(printf '%s\n' $bad | sed 's/\./\\./; s/^/^#include "/; s/$/"/' | paste -sd'|' -)
    more=$( { printf '%s\n' $bad
              [ -z "$pat" ] ||
                  grep -rlE "$pat" --include='*.h' src | xargs -r -n1 basename; } | sort -u)
    [ "$more" = "$(printf '%s\n' $bad | sort -u)" ] && break
    bad=$more
done
pat=$(printf '%s\n' $bad | sed 's/\./\\./; s/^/^#include "/; s/$/"/' | paste -sd'|' -)
for f in $(find src -name '*.c' | sort); do
    grep -qE "$libs|^int main" "$f" && continue
    [ -n "$pat" ] && grep -qE "$pat" "$f" && continue
    echo "$f"
done
