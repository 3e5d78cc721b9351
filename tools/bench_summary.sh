#!/bin/sh
# The README's two "what to use when" tables, from the bench run that wrote data/what_to_use.tsv
# (the level, ours, the best peer, ratio, target and verdict) and data/bench.csv (each point's
# fastest and slowest round). The README quotes the run of the last make bench committed; the
# software note (paper/methods.pdf), built by make paper, quotes its own run (make paper does not
# rewrite the README).
# Usage: tools/readme_bench.sh (make bench runs it after the bench): rewrites the block between
# "<!-- bench tables -->" and "<!-- end bench tables -->" of README.md.
set -eu
tsv=data/what_to_use.tsv csv=data/bench.csv
tables=$(mktemp)
trap 'rm -f "$tables"' EXIT
# bench.csv fields may be quoted and hold commas ("GSL rkck (w,q) ..."): split by hand.
awk -F'\t' -v csv="$csv" '
function split_csv(line, f,    n, i, c, q, cur) {
    n = 0; cur = ""; q = 0
    for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (c == "\"") q = !q
        else if (c == "," && !q) { f[++n] = cur; cur = "" }
        else cur = cur c
    }
    f[++n] = cur
    return n
}
function range(name, sec,    k) { k = name SUBSEP sprintf("%.4g", sec)
    return (k in lo) ? sprintf("%.3g (%.3g–%.3g)", sec * 1e6, lo[k] * 1e6, hi[k] * 1e6) : sprintf("%.3g", sec * 1e6) }
function args(a,    n, w, s, i) { # the suslov arguments, numbers to 4 digits, without the run length every row shares
    sub(/^--method /, "", a); sub(/ --time [^ ]* --every-time [^ ]*$/, "", a)
    n = split(a, w, " "); s = ""
    for (i = 1; i <= n; i++) s = s (i > 1 ? " " : "") (w[i] ~ /^[0-9.e+-]+$/ && w[i] ~ /\./ ? sprintf("%.4g", w[i]) : w[i])
    return s }
BEGIN { while ((getline l < csv) > 0) { if (split_csv(l, f) < 11 || f[1] != "work") continue
        k = f[2] SUBSEP sprintf("%.4g", f[9]); lo[k] = f[10]; hi[k] = f[11] } }
NR == 1 { next }
$1 != last { printf "%s| %s | ours (`suslov` args) | µs median (min–max) | best peer | µs median (min–max) | ratio | target |\n|---|---|---|---|---|---|---|\n",
             (NR > 2 ? "\n" : ""), ($1 == "omega" ? "ω" : $1); last = $1 }
{ printf "| %s | `%s` | %s | %s, tol %s | %s | %.2f× | %g× %s |\n", $2, args($11), range($3, $4), $5, $6,
         range($5, $7), $8, $9, $10 }
' "$tsv" >"$tables"
sh "$(dirname "$0")/readme_block.sh" "bench tables" "$tables"
