#!/bin/sh
# The companion's three tables from the team's TSV files (fields are LaTeX text, math in $...$):
# paper/findings.tsv (one row per independent finding, with the ledger lines it rests on),
# paper/errata.tsv (for the authors) and paper/not_tested.tsv, plus the counts of findings by
# verdict as macros (\FindingsCount, \FindingsReproduced, \FindingsErratum, \FindingsNotReproduced,
# \FindingsExtension: a statement the paper promises but does not make, supplied by us;
# \FindingsByDefinition: a statement that holds by a definition, measured as an implementation check).
# It also writes conclusions.tex (each claim of the Conclusions, paper/conclusions.tsv, with the
# verdicts of its ledger lines) and summary_ordered.tex: the ledger's summary (Table 1) with its
# rows in the paper's order, the order of the first paper label each row cites in labels.tsv.
# Last, cited_lines.tex: the extension lines the text quotes (see its block below).
# Usage: paper_tables.sh OUT_DIR CLAIMS_TSV SUMMARY_TEX
set -eu
O=$1
C=$2
S=$3
head_row() { # file caption label colspec header
    printf '\\begin{longtable}{@{}%s@{}}\n\\caption{%s}\\label{%s}\\\\\n\\toprule %s\\\\\n\\midrule\\endfirsthead\n\\toprule %s\\\\\n\\midrule\\endhead\n\\bottomrule\\endlastfoot\n' \
        "$4" "$2" "$3" "$5" "$5" >"$1"
}
# Table 1 is one float page: a tabular, not a longtable, so that it is never cut across pages.
{ printf '%s\n' '\begin{table}[p]' '\centering\footnotesize\setlength{\tabcolsep}{3pt}' \
    '\caption{The findings, one row per independent finding, with the number of ledger lines it rests on and the tests that measure them (each line: Table~\ref{tab:summary}, Appendix~\ref{sec:appendix}; E1--E9: Table~\ref{tab:errata}; $O_0$: the last term of \eqref{LagMult}). Program: the claims ledger, \repolink{claims.c} (\cmd{make ledger}); data: \href{../build/claims.tsv}{\texttt{build/claims.tsv}}.}\label{tab:findings}' \
    '\begin{tabular}{@{}>{\raggedright}p{0.04\linewidth} >{\raggedright}p{0.21\linewidth} >{\raggedright}p{0.1\linewidth} >{\raggedright\arraybackslash}p{0.61\linewidth}@{}}' \
    '\toprule & finding & verdict & what we measure\\' '\midrule'; } >"$O/findings.tex"
# An erratum finding names the row of the errata table that corrects it (erratum (E1)).
# Each row links the test files its lines come from (the source column of the ledger, file:line).
awk -F'\t' 'FILENAME == ARGV[1] { if (FNR > 1 && $6 != "") eid[$6] = $1; next }
    FILENAME == ARGV[2] { f = $9; sub(/:[0-9]+$/, "", f); sub(/.*\//, "", f); src[$1] = f; next }
    FNR > 1 { v = ($3 == "not reproduced") ? "\\textbf{not reproduced}" : $3
    if ($3 == "erratum") v = v " (" eid[$1] ")"
    n = split($4, a, " ")
    t = ""; delete had
    for (i = 1; i <= n; i++) if (!(src[a[i]] in had)) { had[src[a[i]]] = 1; t = t (t == "" ? "" : ", ") "\\repolink{" src[a[i]] "}" }
    printf "%s & %s & %s & %s {\\scriptsize(%d line%s; %s)}\\\\\n", $1, $2, v, $5, n, (n > 1 ? "s" : ""), t }' \
    paper/errata.tsv "$C" paper/findings.tsv >>"$O/findings.tex"
printf '%s\n' '\bottomrule' '\end{tabular}' '\end{table}' >>"$O/findings.tex"
awk -F'\t' 'NR > 1 { n++; c[$3]++ } END {
    printf "\\newcommand{\\FindingsCount}{%d}\n\\newcommand{\\FindingsReproduced}{%d}\n", n, c["reproduced"]
    printf "\\newcommand{\\FindingsErratum}{%d}\n\\newcommand{\\FindingsNotReproduced}{%d}\n", c["erratum"], c["not reproduced"]
    printf "\\newcommand{\\FindingsExtension}{%d}\n", c["extension"]
    printf "\\newcommand{\\FindingsByDefinition}{%d}\n", c["by definition"] }' \
    paper/findings.tsv >"$O/findings_counts.tex"
# Every ledger line that tests the paper (verdict other than extension and by construction) rests
# under a finding,
# and every line a finding names exists: a line left out of Table 1 fails the build.
awk -F'\t' 'FILENAME == ARGV[1] { if (FNR > 1) { n = split($4, a, " "); for (i = 1; i <= n; i++) f[a[i]] = 1 }; next }
    FNR > 1 { seen[$1] = 1; if ($7 != "extension" && $7 != "by construction" && !($1 in f)) { print "paper_tables: ledger line " $1 " is in no finding of paper/findings.tsv" > "/dev/stderr"; bad = 1 } }
    END { for (i in f) if (!(i in seen)) { print "paper_tables: finding names " i ", not a ledger line" > "/dev/stderr"; bad = 1 }
          exit bad }' paper/findings.tsv "$C"
# One count of the errata: each erratum finding is corrected by exactly one row of the errata
# table (its finding column), each row that names a finding names an erratum finding, and the
# other rows are read off the source; a mismatch fails the build.
awk -F'\t' 'FILENAME == ARGV[1] { if (FNR > 1 && $3 == "erratum") need[$1] = 1; if (FNR > 1) known[$1] = $3; next }
    FNR == 1 { next }
    { n++ } $6 == "" { read++; next }
    { if (known[$6] != "erratum") { print "paper_tables: erratum " $1 " names " $6 ", not an erratum finding" > "/dev/stderr"; bad = 1 }
      if (seen[$6]++) { print "paper_tables: finding " $6 " has two errata rows" > "/dev/stderr"; bad = 1 }
      delete need[$6] }
    END { for (f in need) { print "paper_tables: erratum finding " f " has no row in paper/errata.tsv" > "/dev/stderr"; bad = 1 }
          if (bad) exit 1
          printf "\\newcommand{\\ErrataCount}{%d}\n\\newcommand{\\ErrataRead}{%d}\n", n, read }' \
    paper/findings.tsv paper/errata.tsv >>"$O/findings_counts.tex"

head_row "$O/errata.tex" 'Errata for the authors: typos and internal inconsistencies, with the evidence.' tab:errata \
    '>{\raggedright}p{0.04\linewidth} >{\raggedright}p{0.12\linewidth} >{\raggedright}p{0.2\linewidth} >{\raggedright}p{0.2\linewidth} >{\raggedright\arraybackslash}p{0.38\linewidth}' \
    '& where & printed & corrected & evidence'
# a ledger id in \texttt{..} may break after each hyphen
awk -F'\t' 'function brk(s,   out, i, c, tt) {
        out = ""; tt = 0
        for (i = 1; i <= length(s); i++) {
            c = substr(s, i, 1)
            if (substr(s, i, 8) == "\\texttt{") tt = 1
            else if (c == "}") tt = 0
            out = out c
            if (tt && c == "-") out = out "\\allowbreak{}"
        }
        return out }
    NR > 1 { w = $2; if ($6 != "") w = w "; finding " $6
             printf "%s & %s & %s & %s & %s\\\\[3pt]\n", $1, w, $3, $4, brk($5) }' paper/errata.tsv >>"$O/errata.tex"
printf '%s\n' '\end{longtable}' >>"$O/errata.tex"

head_row "$O/not_tested.tex" 'Statements of the paper we do not test, and why.' tab:nottested \
    '>{\raggedright}p{0.16\linewidth} >{\raggedright\arraybackslash}p{0.8\linewidth}' 'statement & why it is not tested'
awk -F'\t' 'NR > 1 { printf "%s & %s\\\\\n", $2, $3 }' paper/not_tested.tsv >>"$O/not_tested.tex"
printf '%s\n' '\end{longtable}' >>"$O/not_tested.tex"

head_row "$O/unit_tested.tex" 'Statements of the paper checked by the unit tests (\cmd{make test}), not by ledger lines: the test function and what it checks.' tab:unittested \
    '>{\raggedright}p{0.22\linewidth} >{\raggedright}p{0.26\linewidth} >{\raggedright\arraybackslash}p{0.48\linewidth}' \
    'statement & unit test & what it checks'
awk -F'\t' 'NR > 1 { split($4, t, ":"); f = t[1]; sub(/.*\//, "", f); fn = t[2]; gsub(/_/, "\\_", fn)
    printf "%s & \\repolink{%s}: \\texttt{%s} & %s\\\\\n", $3, f, fn, $5 }' paper/unit_tested.tsv >>"$O/unit_tested.tex"
printf '%s\n' '\end{longtable}' >>"$O/unit_tested.tex"

head_row "$O/conclusions.tex" 'The claims of the Conclusions and the ledger lines that test them.' tab:conclusions \
    '>{\raggedright}p{0.5\linewidth} >{\raggedright}p{0.13\linewidth} >{\raggedright\arraybackslash}p{0.33\linewidth}' \
    'claim & verdict & ledger lines'
# A reproduced line that rests under a "by definition" finding (Table 1) reads "by definition"
# here too: one verdict for one measurement.
awk -F'\t' 'FNR == 1 { file++; next }
file == 1 { if ($3 == "by definition") { n = split($4, a, " "); for (i = 1; i <= n; i++) bydef[a[i]] = 1 }; next }
file == 2 { verdict[$1] = ($7 == "reproduced" && ($1 in bydef)) ? "by definition" : $7; next }
{ n = split($2, ids, " "); v = ""
  for (i = 1; i <= n; i++) if (v == "" || verdict[ids[i]] == "erratum" || verdict[ids[i]] == "not reproduced") v = verdict[ids[i]]
  list = $2; gsub(/-/, "-\\allowbreak{}", list); gsub(/ /, ", ", list)
  printf "%s & %s & {\\scriptsize\\texttt{%s}}\\\\\n", $1, v, list }' paper/findings.tsv "$C" paper/conclusions.tsv >>"$O/conclusions.tex"
printf '%s\n' '\end{longtable}' >>"$O/conclusions.tex"

# The appendix's table of every line that tests the paper, in the paper's order: a stable sort of
# its rows (one per line, ending in \\) by the position in labels.tsv of the first label they
# cite (\PaperRef.. or \eqref), or of the figure they cite if any (a row about a figure sits
# with the figure, not with the section's text that introduces it); the header and footer stay
# in place. A (sub)section's own text (a row citing "Sec. 5.6 text") sorts after the section's
# numbered statements and before its figures, where the source discusses its experiments. Each
# row gets the finding of Table 1 it rests under (paper/findings.tsv).
awk -F'\t' 'FILENAME == ARGV[1] { if (FNR == 1) next
                      if ($2 ~ /section$/) sec = $1; else if ($2 != "figure" && sec != "") pos[sec] = FNR
                      if ($2 == "figure") isfig[$1] = 1
                      if (!($1 in pos)) pos[$1] = FNR; next }
FILENAME == ARGV[2] { if (FNR == 1) { for (i = 1; i <= NF; i++) if ($i == "source") sc = i; next }
                      if (sc) src[$1] = $sc; next }
FILENAME == ARGV[3] { if (FNR > 1) { n = split($4, a, " "); for (i = 1; i <= n; i++) finding[a[i]] = $1 }; next }
/\\endlastfoot/ { print "0\t" FNR "\t" $0; body = 1; next }
/\\end\{longtable\}/ { print "99999\t" FNR "\t" $0; next }
!body { print "0\t" FNR "\t" $0; next }
{ key = 9999; s = $0
  # the ledger line behind the row, linked to its test (when claims.tsv has a source column)
  if (match($0, /^\\texttt\{[^}]*(\{\}[^}]*)*\}/)) {
      id = substr($0, RSTART + 8, RLENGTH - 9); gsub(/\\allowbreak\{\}/, "", id); sub(/-\*$/, "-", id)
      # the link goes after the count of a grouped row (id-*~$\times n$), which stays beside the id
      len = RLENGTH; if (match(substr($0, len + 1), /^~\$\\times[0-9]+\$/)) len += RLENGTH
      link = ""; fd = ""
      # a grouped row (id-*) takes the finding most of its members rest under
      delete votes; best = 0
      for (k in src) if (k == id || (id ~ /-$/ && index(k, id) == 1)) {
          if (link == "") link = src[k]
          if (finding[k] != "" && ++votes[finding[k]] > best) { best = votes[finding[k]]; fd = finding[k]; link = src[k] } }
      if (link != "") { file = link; sub(/:[0-9]+$/, "", file); shown = link; sub(/.*\//, "", shown); gsub(/_/, "\\\\_", shown)
          $0 = substr($0, 1, len) " {\\scriptsize\\href{\\RepoBase " file "}{\\texttt{" shown "}}}" substr($0, len + 1) }
      if (fd != "" && substr($0, length($0) - 1) == "\\\\") $0 = substr($0, 1, length($0) - 2) " " fd "\\\\" }
  got = 0
  while (match(s, /\\(PaperRef(Or|Paren)|eqref)\{[^}]*\}/)) {
      l = substr(s, RSTART, RLENGTH); sub(/^[^{]*\{/, "", l); sub(/\}$/, "", l)
      if ((l in pos) && !got) { key = pos[l]; got = 1 }
      if ((l in pos) && (l in isfig)) { key = pos[l]; break }
      s = substr(s, RSTART + RLENGTH) }
  print key "\t" FNR "\t" $0 }' paper/labels.tsv "$C" paper/findings.tsv "$S" | sort -t '	' -k1,1n -k2,2n | cut -f3- >"$O/summary_ordered.tex"
# cited_lines.tex: the ledger lines the companion's text quotes (by \texttt{id}, id-* or one of the
# id's macros, \FigTwoAccuracy for fig2-accuracy) that Table 1 leaves out, being extensions, so
# that every line the text cites is in Appendix A. A \texttt{...-...} that names no ledger line
# (a stale citation) fails the build. Each cell is the ledger's own macro (numbers.tex), so that the
# table and the text print a measured value to one precision.
head_row "$O/cited_lines.tex" 'The lines of our own that the companion quotes: extensions, controls and readings, which test no statement of the paper and so are not in its table of the lines that do. $m$: measured.' \
    tab:cited '>{\raggedright}p{0.52\linewidth} >{\raggedright}p{0.14\linewidth} >{\raggedright}p{0.2\linewidth} >{\raggedright\arraybackslash}p{0.08\linewidth}' \
    'line (test file) & measured $m$ & test & verdict'
perl -e '
sub macro { my @w = qw(Zero One Two Three Four Five Six Seven Eight Nine); my ($o, $up) = ("", 1);
    for my $c (split //, shift) { if ($c =~ /\d/) { $o .= $w[$c]; $up = 1 }
        elsif ($c =~ /[A-Za-z]/) { $o .= $up ? uc $c : $c; $up = 0 } else { $up = 1 } } $o }
my ($claims, $summary, $tex) = @ARGV;
open my $f, "<", $claims or die; my @h = split /\t/, scalar <$f>; chomp @h;
my %col; @col{@h} = 0 .. $#h; my (@ids, %row);
while (<$f>) { chomp; my @c = split /\t/; push @ids, $c[0]; $row{$c[0]} = \@c }
local $/; open my $s, "<", $summary or die; (my $sum = <$s>) =~ s/\\allowbreak\{\}//g;
my @in_table = $sum =~ /\\texttt\{([^{}]*)\}/g;
open my $t, "<", $tex or die; (my $txt = <$t>) =~ s/\\allowbreak\{\}//g; $txt =~ s/(?<!\\)%[^\n]*//g;
my (%cited, $bad);
for my $id (@ids) { my $m = macro($id); $cited{$id} = 1 if $txt =~ /\\\Q$m\E(?:Verdict|Tol|Test|Expected)?(?![A-Za-z])/ }
for my $tok ($txt =~ /\\texttt\{([a-z0-9][a-z0-9*-]*-[a-z0-9*-]*)\}/g) {
    (my $p = $tok) =~ s/\*$//; my @m = grep { $tok =~ /\*$/ ? index($_, $p) == 0 : $_ eq $tok } @ids;
    if (!@m) { print STDERR "paper_tables: the text cites $tok, which is no ledger line\n"; $bad = 1 }
    $cited{$_} = 1 for @m }
for my $id (grep { $cited{$_} } @ids) {
    next if $row{$id}->[$col{verdict}] eq "by construction"; # the text names them, by pattern, as such
    next if grep { (my $p = $_) =~ s/\*$//; /\*$/ ? index($id, $p) == 0 : $_ eq $id } @in_table;
    my $c = $row{$id}; (my $shown = $id) =~ s/-/-\\allowbreak{}/g;
    my $src = $c->[$col{source}] // ""; (my $file = $src) =~ s/:\d+$//; (my $srct = $src) =~ s/_/\\_/g;
    my $m = macro($id);
    printf "\\texttt{%s} {\\scriptsize\\href{\\RepoBase %s}{\\texttt{%s}}} & \$\\%s\$ & \\%sTest & \\%sVerdict\\\\\n", $shown, $file,
        $srct, $m, $m, $m }
exit($bad ? 1 : 0)' "$C" "$S" paper/companion.tex >>"$O/cited_lines.tex"
printf '%s\n' '\end{longtable}' >>"$O/cited_lines.tex"
