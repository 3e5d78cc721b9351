"""The pages that carry the argument: the findings table of the home page, one page per statement
of the paper in the paper's order (the statement quoted from the paper's source, its verdict, its
evidence and its ledger lines), and the errata and not-tested tables. Everything comes from
statements.Statements (the companion's TSVs and the ledger) and the paper's source."""
import html

import frame


def esc(s):
    return html.escape(s, quote=True)


def stmt_page(lab):
    """nolabel:proposition-5.2 -> stmt-nolabel-proposition-5.2.html"""
    return "stmt-%s.html" % lab.replace(":", "-")


def verdict_span(v):
    return '<span class="v-%s">%s</span>' % (v.replace(" ", "-"), esc(v))


def table(heads, rows, cls="claims"):
    """An HTML table: a header row of `heads`, then `rows` (already HTML)."""
    head = "".join("<th>%s</th>" % h for h in heads)
    return "<table class='%s'><tr>%s</tr>%s</table>" % (cls, head, rows)


def ledger_links(ids):
    return ", ".join('<a href="ledger.html#claim-%s">%s</a>' % (esc(i), esc(i)) for i in ids)


class ArgumentPages:
    def __init__(self, site, st):
        self.site, self.st = site, st

    def stmt_link(self, lab):
        return '<a href="%s">%s</a>' % (stmt_page(lab), esc(self.st.name(lab)))

    def findings_table(self):
        """Every finding: its statements, its verdict, its summary and its ledger lines."""
        st, tex = self.st, self.site.tex.inline
        if not st.findings:
            return ("<p class='note'>paper/findings.tsv is missing: the findings are listed when "
                    "it exists.</p>")
        out = ["<table class='findings'><tr><th>finding</th><th>statements</th><th>verdict</th>"
               "<th>summary</th></tr>"]
        for fd in st.findings:
            ids = st.finding_claims(fd)
            stmts = ", ".join(self.stmt_link(lab) for lab in st.of_finding[fd["id"]])
            out.append("<tr id='finding-%s'><td><b>%s</b> %s</td><td>%s</td><td>%s</td><td>%s "
                       "<details><summary>%d ledger line%s</summary>%s</details></td></tr>"
                       % (esc(fd["id"]), esc(fd["id"]), tex(fd["title"]),
                          stmts or "&ndash;",
                          verdict_span(fd["verdict"]), tex(fd["summary"]), len(ids),
                          "s" if len(ids) != 1 else "", ledger_links(ids)))
        out.append("</table>")
        return "\n".join(out)

    def statements_index(self):
        rows = []
        for lab in self.st.order:
            v = self.st.verdict(lab)
            rows.append("<tr><td>%s</td><td>%s</td><td class='num'>%d</td></tr>"
                        % (self.stmt_link(lab), verdict_span(v), len(self.st.claims_of(lab))))
        body = ("<main class='text'><h1>The paper's statements</h1><p class='note'>In the paper's "
                "order: each definition, proposition, theorem, corollary, remark, algorithm and "
                "figure, quoted on its page, its verdict (the worst of its findings, else of its "
                "ledger lines) and how many ledger lines measure it.</p>%s</main>"
                % table(("statement", "verdict", "ledger lines"), "".join(rows)))
        self.site.write_page("statements.html", "Statements", "statements", body)

    def quote(self, lab):
        """The statement as the paper's source prints it, or a line saying why it is not here."""
        kind, number = self.st.labels[lab]
        got = self.site.quotes.statement(kind, number) if self.site.quotes else None
        if not got:
            why = ("this build did not have the paper's LaTeX source (make web PAPER_TEX=FILE)"
                   if not self.site.quotes else "the paper's source has no %s %s" % (kind, number))
            return "<p class='note noquote'>The statement is not quoted here: %s.</p>" % why
        body, line = got
        what = "caption" if kind == "figure" else "statement"
        return ("<blockquote class='quote %s' id='quote'><p class='qhead'><b>%s.</b></p>%s"
                "<p class='qsrc'>The %s as printed in the paper's LaTeX source, line %d.</p>"
                "</blockquote>" % ("caption" if kind == "figure" else "thm", esc(self.st.name(lab)),
                                   body, what, line))

    def evidence(self, lab):
        """The findings, errata and not-tested entries about a statement."""
        st, tex, out = self.st, self.site.tex.inline, []
        for fd in st.findings_of(lab):
            out.append("<div class='box'><h4><a href='index.html#finding-%s'>Finding %s</a>: %s "
                       "&mdash; %s</h4><p>%s</p></div>"
                       % (esc(fd["id"]), esc(fd["id"]), tex(fd["title"]),
                          verdict_span(fd["verdict"]), tex(fd["summary"])))
        for e in st.errata_of(lab):
            out.append("<div class='box'><h4>Erratum %s, %s</h4><p>Printed: %s<br>Corrected: %s</p>"
                       "<p>%s</p></div>"
                       % tuple(tex(e[k]) for k in ("id", "location", "printed", "corrected",
                                                   "evidence")))
        for r in st.not_tested_of(lab):
            out.append("<p><b>Not tested.</b> %s</p>" % tex(r["reason"]))
        return out

    def figures(self, lab, claims):
        kind, number = self.st.labels[lab]
        figs = sorted({f for f in (self.site.claim_figure(c["id"]) for c in claims) if f})
        if kind == "figure" and ("fig" + number) in self.site.figures:
            figs = ["fig" + number] + [f for f in figs if f != "fig" + number]
        return ['<figure>%s<figcaption>%s: <a href="figures/%s.png">full size</a>, <a '
                'href="figures.html#fig-%s">caption and data</a></figcaption></figure>'
                % (frame.figure_img(f), esc(f), esc(f), esc(f)) for f in figs]

    def statement_page(self, k, lab):
        st, order = self.st, self.st.order
        nav = "<p class='pn'><span>%s</span><span>%s</span></p>" % (
            ("&larr; " + self.stmt_link(order[k - 1])) if k > 0 else "",
            (self.stmt_link(order[k + 1]) + " &rarr;") if k + 1 < len(order) else "")
        claims = st.claims_of(lab)
        out = ["<main class='text'>", nav,
               "<h1>%s %s</h1>" % (esc(st.name(lab)), frame.secondary(lab)), self.quote(lab),
               "<p class='verdict'>Our verdict: %s</p>" % verdict_span(st.verdict(lab))]
        tex, _ = self.site.restated.get(lab, ("", ""))
        if tex:
            out.append('<div class="restated"><span class="k">As we restate it</span>'
                       '<div class="math">\\[%s\\]</div></div>' % esc(tex))
        out += self.evidence(lab) + self.figures(lab, claims)
        if lab in self.site.declared or lab in self.site.impl or lab in self.site.label_claims:
            out.append("<p>Its entry on the equations page: %s</p>"
                       % frame.label_link(lab, self.site.labels))
        out.append("<h2>The ledger lines behind it (%d)</h2>" % len(claims))
        if claims:
            out.append("<p><a href='ledger.html#g-%s'>In the ledger</a>, with what each line "
                       "measures.</p>" % esc(lab.replace(":", "-")))
        out.append(self.site.claims_table(claims, len(claims)) if claims else "<p>none</p>")
        out.append(nav + "</main>")
        self.site.write_page(stmt_page(lab), st.name(lab), st.name(lab), "\n".join(out))

    def errata_page(self):
        def row(e):
            tex = self.site.tex.inline
            where = tex(e["location"])
            if e.get("finding"):
                where += ("; finding <a href='index.html#finding-%s'>%s</a>"
                          % (esc(e["finding"]), esc(e["finding"])))
            where += "".join("<br>" + self.stmt_link(lab) for lab in self.st.of_erratum[e["id"]])
            return ("<tr id='erratum-%s'><td>%s</td><td>%s</td><td data-h='printed'>%s</td>"
                    "<td data-h='corrected'>%s</td><td data-h='evidence'>%s</td></tr>"
                    % (esc(e["id"]), esc(e["id"]), where, tex(e["printed"]), tex(e["corrected"]),
                       tex(e["evidence"])))
        rows = ("".join(map(row, self.st.errata))
                or "<tr><td colspan=5>paper/errata.tsv is missing</td></tr>")
        body = ("<main class='text'><h1>Errata</h1><p class='note'>paper/errata.tsv: a typo or an "
                "internal inconsistency of the paper, with the evidence.</p>"
                "<div class='wide'>%s</div></main>"
                % table(("id", "where", "printed", "corrected", "evidence"), rows, "claims errata"))
        self.site.write_page("errata.html", "Errata", "errata", body)

    def not_tested_page(self):
        def row(r):
            name = self.stmt_link(r["label"]) if r["label"] in self.st.order else esc(r["number"])
            return "<tr><td>%s</td><td>%s</td></tr>" % (name, self.site.tex.inline(r["reason"]))
        rows = ("".join(map(row, self.st.not_tested))
                or "<tr><td colspan=2>paper/not_tested.tsv is missing</td></tr>")
        body = ("<main class='text'><h1>Not tested</h1><p class='note'>paper/not_tested.tsv: the "
                "statements of the paper no ledger line measures, and why.</p>%s</main>"
                % table(("statement", "reason"), rows))
        self.site.write_page("not-tested.html", "Not tested", "not tested", body)

    def build(self):
        self.statements_index()
        for k, lab in enumerate(self.st.order):
            self.statement_page(k, lab)
        self.errata_page()
        self.not_tested_page()
