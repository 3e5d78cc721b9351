#!/bin/sh
# The layers of src/, lowest first. A file may include headers of its own layer or of a layer
# below it, never above; and no chain of headers may lead back to where it started. The
# Makefile compiles each layer with only its own and lower folders on the include path, so an
# upward include also fails to build; this check says which line is wrong, and finds cycles,
# which the compiler's include guards hide. Last line "layers: N passed, N failed".
set -u
LAYERS="util core methods lab render prog"
cd "$(dirname "$0")/../.." || exit 2
awk -v layers="$LAYERS" '
BEGIN {
    n = split(layers, L, " ")
    for (i = 1; i <= n; i++) rank[L[i]] = i
    while (("ls src/*/*.c src/*/*.h src/*/*.cpp 2>/dev/null" | getline f) > 0) {
        split(f, p, "/"); home[p[3]] = p[2]; files[++nf] = f
    }
    for (k = 1; k <= nf; k++) {
        f = files[k]; split(f, p, "/"); lay = p[2]
        if (!(lay in rank)) { printf "FAIL %s: folder %s is not a layer (%s)\n", f, lay, layers; bad++; continue }
        ln = 0
        while ((getline line < f) > 0) {
            ln++
            if (line !~ /^[ \t]*#[ \t]*include[ \t]*"/) continue
            h = line; sub(/^[^"]*"/, "", h); sub(/".*/, "", h)
            if (!(h in home)) { printf "FAIL %s:%d includes \"%s\", which is in no layer\n", f, ln, h; bad++; continue }
            if (rank[home[h]] > rank[lay]) {
                printf "FAIL %s:%d (%s) includes %s/%s, a higher layer\n", f, ln, lay, home[h], h; bad++
            }
            if (f ~ /\.h$/) { split(f, q, "/"); edge[q[3]] = edge[q[3]] " " h }
            checked++
        }
        close(f)
    }
    # Cycles among headers: depth-first search with colours.
    for (h in edge) if (!(h in colour)) visit(h, h)
    printf "%s layers: %d includes checked, %d upward or unknown, %d header cycles\n", \
        (bad + cyc) ? "FAIL" : "PASS", checked, bad, cyc
    printf "layers: %d passed, %d failed\n", (bad + cyc) ? 0 : 1, (bad + cyc) ? 1 : 0
    exit (bad + cyc) > 0
}
function visit(h, path,   m, t, i) {
    colour[h] = 1
    m = split(edge[h], t, " ")
    for (i = 1; i <= m; i++) {
        if ((t[i] in colour) && colour[t[i]] == 1) { printf "FAIL include cycle: %s -> %s\n", path, t[i]; cyc++ }
        else if (!(t[i] in colour)) visit(t[i], path " -> " t[i])
    }
    colour[h] = 2
}'
