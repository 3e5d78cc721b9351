#!/bin/sh
# The equation map, generated from the source: a comment that starts with "/* (label)" right
# before a function definition (in a .c file, or static inline in a header) marks that function
# as the implementation of the paper's \label{label}. Lists, for every label declared in paper/equations.txt, the files and functions
# that implement it and the tests that name it.
#   eqmap.sh tex OUT    write the LaTeX table
#   eqmap.sh check      fail (and say why) when a declared label has no implementation or no
#                       test, or an implemented label is not declared
set -eu
mode=${1:-check}
impl=$(awk '
    FNR == 1 { pending = "" }
    /^\/\* \([A-Za-z][A-Za-z0-9]*\)/ { match($0, /\([A-Za-z][A-Za-z0-9]*\)/); pending = substr($0, RSTART + 1, RLENGTH - 2); next }
    pending != "" && /^[A-Za-z].*[a-z_0-9]+\(/ && (FILENAME ~ /\.c$/ || /^static inline/) {
        line = $0; gsub(/__attribute__\(\([^)]*\)\) */, "", line)
        sub(/\(.*/, "", line); n = split(line, w, /[ *]+/)
        printf "%s\t%s\t%s\n", pending, FILENAME, w[n]; pending = ""; next }
    pending != "" && !/^ \*/ && !/^\/\*/ { pending = "" }
' src/*/*.c src/*/*.h | sort -u)
declared=$(grep -v '^#' paper/equations.txt | awk 'NF { print $1 }')
# Every "(label)" a test file names, as "label<TAB>file": read once, then looked up without a
# process per label (the check runs inside make check, where each process costs milliseconds).
named=$(awk '{ s = $0
        while (match(s, /\([A-Za-z][A-Za-z0-9]*\)/)) {
            f = FILENAME; sub(/.*\//, "", f); print substr(s, RSTART + 1, RLENGTH - 2) "\t" f
            s = substr(s, RSTART + RLENGTH) } }' tests/*/*.c tests/*/*.sh | awk '!seen[$0]++')
tests_of() { printf '%s\n' "$named" | awk -F'\t' -v l="$1" '$1 == l { printf "%s ", $2 }'; }
impl_labels=" $(printf '%s\n' "$impl" | cut -f1 | tr '\n' ' ') "
named_labels=" $(printf '%s\n' "$named" | cut -f1 | tr '\n' ' ') "
has() { case $1 in *" $2 "*) return 0 ;; esac; return 1; } # has " A B " B
fail=0 pass=0
for l in $declared; do
    if ! has "$impl_labels" "$l"; then
        echo "FAIL eqmap: ($l) is declared in paper/equations.txt but no function is marked /* ($l) */"; fail=$((fail + 1))
    elif ! has "$named_labels" "$l"; then
        echo "FAIL eqmap: ($l) has no test that names it"; fail=$((fail + 1))
    else
        pass=$((pass + 1))
    fi
done
declared_labels=" $(printf '%s ' $declared)"
for l in $(printf '%s\n' "$impl" | cut -f1 | sort -u); do
    if ! has "$declared_labels" "$l"; then
        echo "FAIL eqmap: ($l) is implemented but not declared in paper/equations.txt"; fail=$((fail + 1))
    fi
done
# the name read off each marked definition is the function's, not a word of its declaration
# (an attribute, a qualifier) that the reading above failed to skip
bad_names=$(printf '%s\n' "$impl" | awk -F'\t' '$3 !~ /^[a-z][a-z0-9_]*$/ ||
    $3 ~ /^(static|inline|const|void|int|double|long|unsigned|char|struct|extern)$/ {
        printf " %s:%s", $2, $3 }')
if [ -n "$bad_names" ]; then
    echo "FAIL eqmap: a marked definition read as no function name:$bad_names"; fail=$((fail + 1))
else
    pass=$((pass + 1))
fi
if [ "$mode" = tex ]; then
    out=$2
    {
        printf '%s\n' '\begin{longtable}{@{}l l >{\raggedright}p{0.2\textwidth} >{\raggedright}p{0.25\textwidth} >{\raggedright\arraybackslash}p{0.18\textwidth}@{}}'
        printf '%s\n' '\toprule paper & label & file & function & tests that name it\\ \midrule \endhead'
        for l in $declared; do
            printf '%s\n' "$impl" | awk -F'\t' -v l="$l" '$1 == l { printf "%s\t%s\n", $2, $3 }' | while IFS="$(printf '\t')" read -r f fn; do
                printf '\\PaperRefOr{%s} & (\\textsf{%s}) & \\texttt{%s} & \\texttt{%s} & \\texttt{%s}\\\\\n' "$l" "$l" "$(echo "$f" | sed 's/_/\\_/g; s#/#/\\allowbreak{}#g')" "$(echo "$fn" | sed 's/_/\\_\\allowbreak{}/g')" \
                    "$(tests_of "$l" | sed 's/_/\\_\\allowbreak{}/g')"
            done
        done
        printf '%s\n' '\bottomrule\end{longtable}'
    } >"$out.tmp" && mv "$out.tmp" "$out"
fi
echo "eqmap: $pass passed, $fail failed"
[ "$fail" = 0 ]
