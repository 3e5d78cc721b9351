#!/bin/sh
# paper/labels.tsv (label, kind, number, section; written once by tools/paper_labels.py from the
# paper's source) as LaTeX: \PaperLabel{label}{how the text cites it}{in parentheses}{number}
# {short form for tables}. Equations are cited "(27)", statements "Proposition 5.3" ("Prop. 5.3"
# in tables), sections "Section 5.6" ("Sec. 5.6").
# Usage: paper_refs.sh paper/labels.tsv OUT.tex
set -eu
awk -F'\t' 'NR > 1 {
    k = $2; n = $3
    if (k == "equation" || k == "subequation") { r = "(" n ")"; p = r; s = r }
    else {
        name = toupper(substr(k, 1, 1)) substr(k, 2)
        if (k == "subsection") name = "Section"
        r = name "~" n
        s = (name == "Figure" ? "Fig." : substr(name, 1, 3) ".") "~" n
        if (name == "Proposition") s = "Prop.~" n
        if (name == "Theorem") s = "Thm.~" n
        p = "(" s ")"
    }
    printf "\\PaperLabel{%s}{%s}{%s}{%s}{%s}\n", $1, r, p, n, s
}' "$1" >"$2.tmp"
mv "$2.tmp" "$2"
