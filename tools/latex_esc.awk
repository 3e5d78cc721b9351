# LaTeX's special characters in text escaped: the one escaper of the tools that write LaTeX.
# tools/bench_misses.awk calls latex_esc() (run as awk -f tools/latex_esc.awk -f
# tools/bench_misses.awk); the shell scripts use it through tools/latex.sh, which runs this file
# alone with -v filter=1 to escape each line of its input.
# A loop over the characters, not gsub: gsub's treatment of "\\" in its replacement differs
# between awks; and a character is replaced once, so the braces of \textbackslash{} stay braces.
function latex_esc(s,    i, c, o) {
    o = ""
    for (i = 1; i <= length(s); i++) {
        c = substr(s, i, 1)
        if (c == "\\") c = "\\textbackslash{}"
        else if (c == "~") c = "\\textasciitilde{}"
        else if (c == "^") c = "\\textasciicircum{}"
        else if (index("_%&#${}", c)) c = "\\" c
        o = o c
    }
    return o
}

filter { print latex_esc($0) }
