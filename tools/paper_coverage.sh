#!/bin/sh
# Every numbered statement of the paper (proposition, theorem, corollary, remark, algorithm,
# figure; paper/labels.tsv) must be tested by a ledger line (its label, or its published name,
# "Proposition 5.2", in the paper_ref column of claims.tsv) or listed, with the reason, in
# paper/not_tested.tsv; every claim of the Conclusions (paper/conclusions.tsv) and every finding
# (paper/findings.tsv) must name ledger lines that exist; and every ledger line whose verdict is
# "not reproduced" or "erratum" must belong to a finding; and every unit test that
# paper/unit_tested.tsv names (FILE:FUNCTION, a statement checked by the unit tests rather than
# by a ledger line) must exist. Prints each gap and, last,
# "paper_coverage: N passed, N failed" (one check per statement, claim, finding line and
# contradicted line); exit 1 on any gap. Run by make check (tests/run.sh) and make paper.
# Usage: paper_coverage.sh CLAIMS_TSV
set -eu
C=$1
awk -F'\t' '
FNR == 1 { file++; next }
file == 1 { ref[FNR] = $2; verdict[$1] = $7; nref = FNR; next }
file == 2 { untested[$1] = 1; next }
file == 3 { n = split($2, ids, " ");
            for (i = 1; i <= n; i++) { checks++; if (!(ids[i] in verdict)) { print "conclusions: no ledger line " ids[i]; bad++ } }
            next }
file == 4 { n = split($4, ids, " ");
            for (i = 1; i <= n; i++) { infinding[ids[i]] = 1; checks++
                if (!(ids[i] in verdict)) { print "findings " $1 ": no ledger line " ids[i]; bad++ } }
            next }
file == 5 && $2 ~ /^(proposition|theorem|corollary|remark|algorithm|figure)$/ {
    label[$1] = $2 " " $3
    # its published name, as the paper_ref column prints it: "Proposition 5.2" (a regex)
    pub[$1] = toupper(substr($2, 1, 1)) substr($2, 2) " " $3; gsub(/\./, "\\.", pub[$1]) }
END {
    for (l in label) {
        checks++
        found = (l in untested)
        for (r = 2; r <= nref && !found; r++) {
            s = ref[r]; gsub(/[(),;]/, " ", s)
            found = (" " s " ") ~ (" " l " ") || (" " s " ") ~ (" " pub[l] " ")
        }
        if (!found) { print "coverage: " label[l] " (" l ") is in neither the ledger nor paper/not_tested.tsv"; bad++ }
    }
    for (id in verdict)
        if (verdict[id] == "not reproduced" || verdict[id] == "erratum") {
            checks++
            if (!(id in infinding)) { print "findings: ledger line " id " (" verdict[id] ") belongs to no finding"; bad++ } }
    # the unit tests named for statements that no ledger line measures
    while ((getline row < "paper/unit_tested.tsv") > 0) {
        if (++urow == 1) continue
        split(row, u, "\t"); n = split(u[4], fl, ":"); checks++
        found = 0
        if (n == 2) while ((getline line < fl[1]) > 0) if (line ~ ("^static void " fl[2] "\\(")) found = 1
        close(fl[1])
        if (!found) { print "unit_tested: no function " fl[2] " in " fl[1]; bad++ }
    }
    printf "paper_coverage: %d passed, %d failed\n", checks - bad, bad
    exit bad > 0
}' "$C" paper/not_tested.tsv paper/conclusions.tsv paper/findings.tsv paper/labels.tsv
