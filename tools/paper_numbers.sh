#!/bin/sh
# The companion types no number by hand: every measured value, tolerance and count is a macro
# written by the programs. This check (run by make paper) fails on any digit left in the body
# of paper/companion.tex once the following are set aside, each for the reason given:
#   comments                              not printed
#   \label \ref \eqref \PaperRef.. \cite \input \includegraphics \lstinputlisting \bibitem
#   \cmd \texttt \url \href \fig \listing names of labels, files, commands, addresses
#   \repolink \datalink \figlinks       names of files
#   \rotatebox                            an angle of the layout
#   \paperquote{..}                       the paper's own data and settings, quoted as printed
#   \setting{..}                          a parameter of a run or a target, fixed in the source
#                                         before measuring and named in that ledger line's text
#                                         or in the PASS/MISS line make bench prints
#   thebibliography                       citations (years, volumes, pages)
#   lengths, [..] options, column specs   layout, not numbers
#   _x _{..} ^x ^{..} after a letter      indices and exponents of symbols (w_1, I_{31}, w^{k+1});
#                                         a number's exponent (10^{-7}) leaves its 10 behind
#   SO(3), so(3), TSO(3)                  names of groups
#   \tfrac12, 2\times2, 3\times3           parts of formulas (a half; matrix sizes)
#   names with digits: RK4, rk8pd, fig1   names of methods and files
#   a lone digit inside math ($..$, \[..\])  constants of formulas (w_3 = 0, x/2, the (3,3)
#                                         entry, n = 1); a number with two digits or a
#                                         decimal point (10^{-7}, 0.1, 200) still fails
# Usage: paper_numbers.sh [FILE]
set -eu
f=${1:-paper/companion.tex}
perl -0777 -ne '
    my $b = $_;
    $b =~ s/(?<!\\)%[^\n]*//g;                                  # comments
    $b =~ s/^.*?\\begin\{document\}//s;                         # the preamble
    $b =~ s/\\begin\{thebibliography\}.*?\\end\{thebibliography\}//sg;
    my $g = qr/(\{(?:[^{}]++|(?-1))*\})/;                       # a balanced {...}
    $b =~ s/\\(?:label|ref|eqref|PaperRef\w*|PaperNum|cite|input|includegraphics|lstinputlisting|bibitem|cmd|texttt|url|href|paperquote|setting|fig|rotatebox|listing|repolink|datalink)\*?(?:\[[^\]]*\])?$g//g;
    $b =~ s/\\figlinks$g$g$g//g;                              # file names of a caption
    $b =~ s/\\begin\{(?:longtable|tabular)\}$g//g;               # column specs
    $b =~ s/\[[^\]]*\]//g;                                      # optional arguments
    $b =~ s/-?[0-9.]+\s*(?:pt|cm|mm|em|ex|bp|\\(?:text|line)width)//g;
    $b =~ s/(?<=[A-Za-z}\)])[_^](?:$g|\\?[A-Za-z0-9])//g for 1 .. 3;
    $b =~ s/\b[TSs][Oo]\(3\)//g;
    $b =~ s/\\tfrac12|[23]\\times[23]//g;
    $b =~ s/\b[A-Za-z]+[0-9]+[A-Za-z0-9]*\b//g;
    my $lone = sub { my $m = shift; $m =~ s/(?<![0-9.])[0-9](?![0-9.])//g; $m };
    $b =~ s/(\$[^\$]*\$|\\\[.*?\\\])/$lone->($1)/gse;
    my $n = 0;
    for my $line (split /\n/, $b) {
        next unless $line =~ /[0-9]/;
        print "typed number in paper/companion.tex: $line\n"; $n++;
    }
    if ($n) { print "paper_numbers: $n line(s) with a digit typed by hand: use a macro from build/numbers.tex or data/bench.tex, or \\paperquote/\\setting (see tools/paper_numbers.sh)\n"; exit 1 }
    print "paper_numbers: no typed numbers\n";
' "$f"
