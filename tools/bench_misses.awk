# The targets a bench run misses, for the software note (tools/bench_summary.sh DIR misses; make
# paper reads the recorded run's). Input: the run's bench.txt, whose "  PASS ...", "  MISS ..."
# and "  UNDECIDED ..." lines are its targets (src/render/bench_report.c prints most,
# tools/bench.sh the wall-clock ones). Output: LaTeX macros \BenchTargetCount, \BenchMissCount
# and \BenchMisses, the misses separated by semicolons, and likewise \BenchUndecidedCount and
# \BenchUndecided; each said short with its measured value and its target, the numbers as the
# line prints them. A line of a shape this file does not know is listed as printed, so that no
# miss is ever left out. Text is escaped by latex_esc (tools/latex_esc.awk, given first with -f).

# A number for math mode: 3.51 as it is, 1.7e-13 as 1.7\times10^{-13}, 1e-04 and 1e4 as powers
# of ten.
function num(s,    m, e, sg) {
    if (s !~ /^[0-9.]+e[-+]?[0-9]+$/) return s
    m = s; sub(/e.*$/, "", m)
    e = s; sub(/^[^e]*e/, "", e)
    sg = ""
    if (e ~ /^[-+]/) { sg = substr(e, 1, 1); e = substr(e, 2) }
    sub(/^0+/, "", e)
    if (e == "") return m
    return (m == "1" ? "" : m "\\times") "10^{" (sg == "-" ? "-" : "") e "}"
}

# The text of s between the first a and the next b after it ("" when a is not in s; the rest of
# s when b is "" or not found).
function between(s, a, b,    i) {
    i = index(s, a)
    if (i == 0) return ""
    s = substr(s, i + length(a))
    i = b == "" ? 0 : index(s, b)
    return i ? substr(s, 1, i - 1) : s
}

# The text after the last ": " of s, without a trailing unit "x" or " %".
function last_value(s) {
    sub(/^.*: /, "", s)
    sub(/( %|x)$/, "", s)
    return s
}

function target_le(t) { return " (target~$\\le " num(t) "$)" }
function target_ge(t) { return " (target~$\\ge " num(t) "$)" }

# "... in S s (target <= X s)": the wall-clock targets.
function wall(what, t,    secs, tg) {
    secs = between(t, " in ", " s (target")
    tg = "(target~$\\le " between(t, "(target <= ", " s)") "$\\,s)"
    if (secs == "" || secs == "nan")
        return what " did not finish " tg
    return what ", $" secs "$\\,s " tg
}

# T = 1e4, NAME: |R^T R - I| = a, |E - E0| = b, |w3| = c (targets ta, tb, tc)[; |E - E0| by T/2:
# h]: each quantity over its target, and the energy error by half the run where the line gives it.
function longrun(t,    name, v, tg, sym, i, o, half) {
    name = between(t, "T = 1e4, ", ": |R^T R - I|")
    v[1] = between(t, "|R^T R - I| = ", ",")
    v[2] = between(t, "|E - E0| = ", ",")
    v[3] = between(t, "|w3| = ", " (")
    split(between(t, "(targets ", ")"), tg, ", ")
    sym[1] = "|R^{\\mathsf T}R-I|"; sym[2] = "|E-E_0|"; sym[3] = "|\\w_3|"
    o = ""
    for (i = 1; i <= 3; i++)
        if (v[i] + 0 > tg[i] + 0)
            o = o (o == "" ? "" : " and ") "$" sym[i] "=" num(v[i]) "$ (target~$\\le " \
                num(tg[i]) "$)"
    half = between(t, "|E - E0| by T/2: ", "")
    if (half != "")
        o = o ", $" num(half) "$ already by $T/2$"
    return "\\cmd{" latex_esc(name) "} at $T=10^{4}$, " o
}

function short(t,    what, lvl, v) {
    if (t ~ /^an implicit [^ ]+ step costs <= /)
        return "the \\cmd{" latex_esc(between(t, "an implicit ", " step costs")) "} step, $" \
            last_value(between(t, "our rk4 step: ", " (")) "$ RK4 steps" \
            target_le(between(t, "costs <= ", "x our"))
    if (t ~ /^our rk4 step is >= /)
        return "our RK4 step, $" last_value(t) "$ times as fast as GSL's \\cmd{rk4}" \
            target_ge(between(t, "is >= ", "x faster"))
    if (t ~ /^the driver adds <= /)
        return "the driver on a \\cmd{" latex_esc(between(t, "to a ", " step (")) "} step, $" \
            last_value(t) "\\,\\%$ (target~$\\le " between(t, "adds <= ", " %") "\\,\\%$)"
    if (t ~ /^the driver \(sus_run_tol/)
        return "the driver on tolerance-driven runs, $" last_value(t) "\\,\\%$ (target~$\\le " \
            between(t, "adds <= ", " %") "\\,\\%$)"
    if (t ~ /^attitude accuracy [^ ]+: no floor/)
        return "the attitude to $" num(between(t, "accuracy ", ":")) \
            "$: none of our explicit methods reaches it"
    if (t ~ /^attitude accuracy [^ ]+: our best /)
        return "our best time to the attitude to $" num(between(t, "accuracy ", ":")) "$, $" \
            last_value(t) "$ times the floor" target_le(between(t, "within ", "x of"))
    if (t ~ /accuracy [^ ]+ at t = 50: /) {
        what = t; sub(/ accuracy .*$/, "", what)
        lvl = num(between(t, "accuracy ", " at t"))
        what = what == "attitude (reduced problem)" ? "the attitude to $" lvl \
            "$ on the reduced problem" : what == "attitude" ? "the attitude to $" lvl "$" : \
            latex_esc(what) " to $" lvl "$"
        if (index(t, ": none of our"))
            return what ": none of our structure-preserving methods reaches it"
        if (index(t, "(target ")) {
            v = t; sub(/ \(target [^(]*$/, "", v)
            return what ", $" last_value(v) "$ times as fast as the best peer" \
                (index(t, "fastest rounds ") ? ", $" between(t, "fastest rounds ", "x)") \
                    "$ by the fastest rounds" : "") target_ge(between(t, "(target ", "x"))
        }
    }
    if (t ~ /^T = 1e4, .*: \|R\^T R - I\| = /)
        return longrun(t)
    if (t ~ /^T = 1e4 at equal error: none/)
        return "at $T=10^{4}$, none of our explicit own-attitude methods reaches the attitude " \
            "error $" num(between(t, "reaches attitude ", " there")) "$"
    if (t ~ /^T = 1e4 at equal error .* faster than /)
        return "at $T=10^{4}$ and equal attitude error, \\cmd{" \
            latex_esc(between(t, "ours ", " is ")) "} $" between(t, " is ", "x faster") \
            "$ times as fast as \\cmd{rk8pd}" target_ge(between(t, "(target ", "x)"))
    if (t ~ /^cost at T = 1e6 <= /)
        return "the cost to $T=10^{6}$, $" last_value(t) "$ times that to $T=10^{4}$" \
            target_le(between(t, "<= ", "x the cost"))
    if (t ~ /^figure_stability on /)
        return wall("\\cmd{figure\\_stability} on $" between(t, " on ", " cores") "$ cores", t)
    if (t ~ /^make -j2 figures /)
        return wall("\\cmd{make -j2 figures}", t)
    if (t ~ /^make check .*: a test failed/)
        return "\\cmd{make check}: a test failed, so no time to judge"
    if (t ~ /^make check /)
        return wall("\\cmd{make check}", t)
    return latex_esc(t)
}

/^  (PASS|MISS|UNDECIDED) / { n++ }
/^  MISS / {
    t = $0; sub(/^  MISS /, "", t)
    list = list (m++ ? "; " : "") short(t)
}
/^  UNDECIDED / {
    t = $0; sub(/^  UNDECIDED /, "", t)
    und = und (u++ ? "; " : "") short(t)
}
END {
    print "% Generated by tools/bench_misses.awk from bench.txt: do not edit."
    printf "\\newcommand{\\BenchTargetCount}{%d}\n\\newcommand{\\BenchMissCount}{%d}\n", n, m
    print "\\newcommand{\\BenchMisses}{" list "}"
    printf "\\newcommand{\\BenchUndecidedCount}{%d}\n", u
    print "\\newcommand{\\BenchUndecided}{" und "}"
}
