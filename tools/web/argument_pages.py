"""The pages that carry the argument: the summary on the home page (counts by verdict, findings,
errata), one page per statement of the paper in the paper's order, and the errata and not-tested
tables. Everything comes from statements.Statements (the companion's TSVs and the ledger)."""
import html
import os
import re


def esc(s):
    return html.escape(s, quote=True)


def tex_text(s):
    """A field of the companion's TSVs (LaTeX text) as HTML: $...$ becomes \\(...\\) for KaTeX's
    auto-render, \\texttt{x} code, \\emph{x} emphasis, -- and ~ their characters."""
    out = []
    for k, part in enumerate(re.split(r"(\$[^$]*\$)", s)):
        if part.startswith("$") and part.endswith("$") and len(part) > 1:
            out.append("\\(" + esc(part[1:-1]) + "\\)")
            continue
        part = esc(part)
        part = re.sub(r"\\texttt\{([^{}]*)\}", r"<code>\1</code>", part)
        part = re.sub(r"\\emph\{([^{}]*)\}", r"<em>\1</em>", part)
        part = re.sub(r"~?\\cite\{[^{}]*\}", "", part)  # the text names the authors; no bibliography here
        part = re.sub(r"\\(?:ref|eqref)\{([^{}]*)\}", r"[\1]", part)
        out.append(part.replace("---", "&mdash;").replace("--", "&ndash;").replace("~", "&nbsp;")
                   .replace("``", "&ldquo;").replace("&#x27;&#x27;", "&rdquo;")
                   .replace("\\%", "%").replace("\\&amp;", "&amp;").replace("\\_", "_"))
    return "".join(out)


def stmt_page(lab):
    """nolabel:proposition-5.2 -> stmt-nolabel-proposition-5.2.html"""
    return "stmt-%s.html" % lab.replace(":", "-")


def verdict_span(v):
    return '<span class="v-%s">%s</span>' % (v.replace(" ", "-"), esc(v))


def table(heads, rows, cls="claims"):
    """An HTML table: a header row of `heads`, then `rows` (already HTML)."""
    return "<table class='%s'><tr>%s</tr>%s</table>" % (cls, "".join("<th>%s</th>" % h for h in heads), rows)


def ledger_links(ids):
    return ", ".join('<a href="ledger.html#claim-%s">%s</a>' % (esc(i), esc(i)) for i in ids)


class ArgumentPages:
    def __init__(self, site, st):
        self.site, self.st = site, st

    def stmt_link(self, lab):
        return '<a href="%s">%s</a>' % (stmt_page(lab), esc(self.st.name(lab)))

    def summary_html(self):
        """The home page's summary: counts by verdict, the findings, the errata."""
        st = self.st
        counts = ", ".join("%d %s" % (n, verdict_span(v)) for v, n in st.counts())
        out = ["<h2 id='summary'>What we found</h2>",
               "<p>The claims ledger (<a href='ledger.html'>build/claims.tsv</a>) holds %d lines: %s. "
               "Each statement of the paper has <a href='statements.html'>its own page</a> with its "
               "verdict, its evidence and the ledger lines behind it; every ledger line links to the test "
               "code that computes it.</p>" % (len(st.claims), counts)]
        if not st.findings:
            out.append("<p class='note'>paper/findings.tsv is missing: the findings are listed when it "
                       "exists.</p>")
            return "\n".join(out)
        out.append("<table class='findings'><tr><th>finding</th><th>statements</th><th>verdict</th>"
                   "<th>summary</th></tr>")
        for fd in st.findings:
            out.append("<tr id='finding-%s'><td><b>%s</b> %s</td><td>%s</td><td>%s</td><td>%s "
                       "<details><summary>%d ledger line%s</summary>%s</details></td></tr>"
                       % (esc(fd["id"]), esc(fd["id"]), tex_text(fd["title"]),
                          ", ".join(self.stmt_link(lab) for lab in st.of_finding[fd["id"]]) or "&ndash;",
                          verdict_span(fd["verdict"]), tex_text(fd["summary"]), len(st.finding_claims(fd)),
                          "s" if len(st.finding_claims(fd)) != 1 else "",
                          ledger_links(st.finding_claims(fd))))
        out.append("</table>")
        if st.errata:
            measured = sum(1 for e in st.errata if e.get("finding"))
            out.append("<p>%d errata in the paper (<a href='errata.html'>the errata table</a>): %d are the "
                       "erratum findings above, the other %d are read off the source. %d statements are "
                       "<a href='not-tested.html'>not tested</a>, with the reason.</p>"
                       % (len(st.errata), measured, len(st.errata) - measured, len(st.not_tested)))
        return "\n".join(out)

    def statements_index(self):
        rows = []
        for lab in self.st.order:
            v = self.st.verdict(lab)
            rows.append("<tr><td>%s</td><td>%s</td><td class='num'>%d</td></tr>"
                        % (self.stmt_link(lab), verdict_span(v), len(self.st.claims_of(lab))))
        body = ("<main class='text'><h1>The paper's statements</h1><p class='note'>In the paper's order: "
                "each definition, proposition, theorem, corollary, remark, algorithm and figure, its verdict "
                "(the worst of its findings, else of its ledger lines) and how many ledger lines measure it."
                "</p>%s</main>" % table(("statement", "verdict", "ledger lines"), "".join(rows)))
        self.site.write_page("statements.html", "Statements", "statements", body)

    def statement_page(self, k, lab):
        st = self.st
        order = st.order
        nav = "<p class='pn'><span>%s</span><span>%s</span></p>" % (
            ("&larr; " + self.stmt_link(order[k - 1])) if k > 0 else "",
            (self.stmt_link(order[k + 1]) + " &rarr;") if k + 1 < len(order) else "")
        kind, number = st.labels[lab]
        out = ["<main class='text'>", nav,
               "<h1>%s <span class='note'>(%s)</span></h1>" % (esc(st.name(lab)), esc(lab)),
               "<p>Verdict: %s</p>" % verdict_span(st.verdict(lab))]
        tex, _ = self.site.restated.get(lab, ("", ""))
        if tex:
            out.append('<div class="math">\\[%s\\]</div>' % esc(tex))
        for fd in st.findings_of(lab):
            out.append("<div class='box'><h4><a href='index.html#finding-%s'>Finding %s</a>: %s &mdash; "
                       "%s</h4><p>%s</p></div>" % (esc(fd["id"]), esc(fd["id"]), tex_text(fd["title"]),
                                                   verdict_span(fd["verdict"]), tex_text(fd["summary"])))
        for e in st.errata_of(lab):
            out.append("<div class='box'><h4>Erratum %s, %s</h4><p>Printed: %s<br>Corrected: %s</p>"
                       "<p>%s</p></div>"
                       % tuple(tex_text(e[k]) for k in ("id", "location", "printed", "corrected", "evidence")))
        for r in st.not_tested_of(lab):
            out.append("<p><b>Not tested.</b> %s</p>" % tex_text(r["reason"]))
        claims = st.claims_of(lab)
        figs = sorted({f for f in (self.site.claim_figure(c["id"]) for c in claims) if f})
        if kind == "figure" and ("fig" + number) in self.site.figures:
            figs = ["fig" + number] + [f for f in figs if f != "fig" + number]
        for f in figs:
            out.append('<figure><a href="figures.html#fig-%s"><img class="stmt" src="figures/%s.png" '
                       'alt="figure %s"></a><figcaption>%s (<a href="figures.html#fig-%s">caption and '
                       'data</a>)</figcaption></figure>' % ((esc(f),) * 5))
        if lab in self.site.declared or lab in self.site.impl or lab in self.site.label_claims:
            out.append("<p>Equations page entry: <a class='label' href='equations.html#eq-%s'>(%s)</a></p>"
                       % (esc(lab), esc(lab)))
        out.append("<h2>The ledger lines behind it (%d)</h2>" % len(claims))
        out.append(self.site.claims_table(claims, len(claims)) if claims else "<p>none</p>")
        out.append(nav + "</main>")
        self.site.write_page(stmt_page(lab), st.name(lab), st.name(lab), "\n".join(out))

    def errata_page(self):
        def row(e):
            where = tex_text(e["location"]) + (
                "; finding <a href='index.html#finding-%s'>%s</a>" % (esc(e["finding"]), esc(e["finding"]))
                if e.get("finding") else "") + "".join("<br>" + self.stmt_link(lab)
                                                 for lab in self.st.of_erratum[e["id"]])
            return ("<tr id='erratum-%s'><td>%s</td><td>%s</td><td data-h='printed'>%s</td>"
                    "<td data-h='corrected'>%s</td><td data-h='evidence'>%s</td></tr>"
                    % (esc(e["id"]), esc(e["id"]), where, tex_text(e["printed"]), tex_text(e["corrected"]),
                       tex_text(e["evidence"])))
        rows = "".join(map(row, self.st.errata)) or "<tr><td colspan=5>paper/errata.tsv is missing</td></tr>"
        body = ("<main class='text'><h1>Errata</h1><p class='note'>paper/errata.tsv: a typo or an internal "
                "inconsistency of the paper, with the evidence.</p><div class='wide'>%s</div></main>"
                % table(("id", "where", "printed", "corrected", "evidence"), rows, "claims errata"))
        self.site.write_page("errata.html", "Errata", "errata", body)

    def not_tested_page(self):
        def row(r):
            name = self.stmt_link(r["label"]) if r["label"] in self.st.order else esc(r["number"])
            return "<tr><td>%s</td><td>%s</td></tr>" % (name, tex_text(r["reason"]))
        rows = ("".join(map(row, self.st.not_tested))
                or "<tr><td colspan=2>paper/not_tested.tsv is missing</td></tr>")
        body = ("<main class='text'><h1>Not tested</h1><p class='note'>paper/not_tested.tsv: the statements "
                "of the paper no ledger line measures, and why.</p>%s</main>"
                % table(("statement", "reason"), rows))
        self.site.write_page("not-tested.html", "Not tested", "not tested", body)

    def build(self):
        self.statements_index()
        for k, lab in enumerate(self.st.order):
            self.statement_page(k, lab)
        self.errata_page()
        self.not_tested_page()
