"""The home page: what was found first (not reproduced, errata, reproduced, from paper/findings.tsv,
paper/errata.tsv and the ledger's counts), beside the figure of the first finding that was not
reproduced; then where to read on, every finding, and the annotated source."""
import os

import argument_pages
import frame
import ledger_page
from frame import esc
from source_pages import page_of
from statements import VERDICT_RANK

HEADS = {"not reproduced": "Not reproduced", "erratum": "Errata the measurements show",
         "reproduced": "Reproduced", "by definition": "True by definition",
         "extension": "Beyond the paper"}


def headline_figure(site):
    """The paper's figure that the first not-reproduced finding is about, else the first of the
    paper's figures: (name, the first line of its caption file)."""
    names = []
    for fd in site.st.findings:
        if fd["verdict"] == "not reproduced":
            names += ["fig" + site.st.labels[lab][1] for lab in site.st.of_finding[fd["id"]]
                      if site.st.labels[lab][0] == "figure"]
    names += sorted(n for n in site.figures if n.startswith("fig") and n[3:].isdigit())
    for name in names:
        if name in site.figures:
            cap = "figures/%s.txt" % name
            first = open(cap, encoding="utf-8").readline().strip() if os.path.exists(cap) else name
            return name, first
    return None, None


def finding_line(site, fd, full):
    stmts = site.st.of_finding[fd["id"]]
    links = ", ".join('<a href="%s">%s</a>' % (argument_pages.stmt_page(lab),
                                               esc(site.st.name(lab))) for lab in stmts)
    text = '<a href="#finding-%s"><b>%s</b></a> %s' % (esc(fd["id"]), esc(fd["id"]),
                                                       site.tex.inline(fd["title"]))
    if full:
        text += '<span class="hl-summary">%s</span>' % site.tex.inline(fd["summary"])
    return "<li>%s%s</li>" % (text, " &rarr; %s" % links if links and full else "")


def errata_block(site):
    st = site.st
    if not st.errata:
        return ""
    measured = sum(1 for e in st.errata if e.get("finding"))
    items = "".join('<li><a href="errata.html#erratum-%s"><b>%s</b></a> %s</li>'
                    % (esc(e["id"]), esc(e["id"]), site.tex.inline(e["location"]))
                    for e in st.errata)
    return ("<div class='hl hl-erratum'><h3>%d errata in the paper</h3><p>%d shown by measurement "
            "(the erratum findings above), %d read off the source; each with the printed and the "
            "corrected form in <a href='errata.html'>the errata table</a>.</p>"
            "<ul class='compact'>%s</ul></div>"
            % (len(st.errata), measured, len(st.errata) - measured, items))


def headline(site):
    st = site.st
    by = {}
    for fd in st.findings:
        by.setdefault(fd["verdict"], []).append(fd)
    blocks = []
    for v in sorted(by, key=lambda v: VERDICT_RANK.index(v) if v in VERDICT_RANK else 9):
        full = v in ("not reproduced", "erratum")
        lines = "".join(finding_line(site, fd, full) for fd in by[v])
        blocks.append("<div class='hl hl-%s'><h3>%s <span class='n'>(%d finding%s)</span></h3>"
                      "<ul class='compact'>%s</ul></div>"
                      % (v.replace(" ", "-"), esc(HEADS.get(v, v.capitalize())), len(by[v]),
                         "s" if len(by[v]) != 1 else "", lines))
        if v == "erratum":
            blocks.append(errata_block(site))
    if not st.findings:
        blocks.append("<p class='note'>paper/findings.tsv is missing: the findings are listed "
                      "when it exists.</p>")
    blocks.append("<p>The claims ledger behind them: %s (<a href='ledger.html'>every line</a>). %d "
                  "statements are <a href='not-tested.html'>not tested</a>, with the reason.</p>"
                  % (ledger_page.tally(st.counts()), len(st.not_tested)))
    name, first = headline_figure(site)
    fig = ("<figure class='hl-fig'>%s<figcaption>%s <a href='figures/%s.png'>Full size</a>; "
           "<a href='figures.html#fig-%s'>its caption and data</a>.</figcaption></figure>"
           % (frame.figure_img(name), esc(first), esc(name), esc(name)) if name else "")
    # the figure comes second: beside the list on a wide screen, after the first block on a phone
    return ("<section class='headline' id='summary'><h2>What we found</h2><div class='hl-grid'>"
            "<div class='hl-first'>%s</div>%s<div class='hl-rest'>%s</div></div></section>"
            % (blocks[0], fig, "".join(blocks[1:])))


READ_ON = (("statements.html", "Statements",
            "each statement of the paper, quoted, with its verdict and the evidence"),
           ("ledger.html", "Claims ledger",
            "every measured line, grouped by statement, searchable"),
           ("figures.html", "Figures",
            "each figure, its caption, the command that draws it, its data"),
           ("live-fig2.html", "Live", "the integrators run again in this browser: Figure 2 at your "
            "own step, orders, work and precision, the attitude"),
           ("equations.html", "Equations", "each equation we implement, as printed and as coded"),
           ("errata.html", "Errata", "the paper's errata, printed and corrected"),
           ("#source", "Annotated source",
            "the C code beside its comments, linked to the equations"))


def source_list(site):
    def first_sentence(f):
        secs = site.sections[f]
        if secs and secs[0].comment:
            t = " ".join(secs[0].comment[0].split())
            return t if len(t) <= 160 else t[:160].rsplit(" ", 1)[0] + " \u2026"
        return ""
    out = ["<h2 id='source'>The annotated source</h2><p>On each source page the comments are on "
           "the left and the code on the right, section by section; a label of the paper links to "
           "the equation it cites, a function name to its definition.</p>"]
    for title, prefix in (("The library and the programs (src/)", "src/"),
                          ("Tests and the claims ledger (tests/)", "tests/")):
        out.append("<h3>%s</h3><ul class='files'>" % title)
        for f in (f for f in site.files if f.startswith(prefix)):
            out.append('<li><a href="%s">%s</a><div class="desc">%s</div></li>'
                       % (page_of(f), esc(f), esc(first_sentence(f))))
        out.append("</ul>")
    return "".join(out)


def build(site):
    out = ["<main class='text'><h1>On some aspects of the discretization of the Suslov problem, "
           "reproduced</h1>",
           "<p class='lead'>A reproducible companion to F. Jim&eacute;nez and J. Scheurle, <i>On "
           "some aspects of the discretization of the Suslov problem</i>, J. Geom. Mech. 10(1), "
           "2018 (doi:10.3934/jgm.2018002): every statement of the paper we could test is measured "
           "by a line of the claims ledger, under the paper's own numbering.</p>",
           headline(site),
           "<h2>Read on</h2><ul class='read-on'>%s</ul>" % "".join(
               '<li><a href="%s">%s</a>: %s</li>' % (h, t, d) for h, t, d in READ_ON),
           "<h2 id='findings'>Every finding</h2>", site.argument.findings_table(),
           source_list(site), "</main>"]
    site.write_page("index.html", "Suslov companion", "index", "\n".join(out))
