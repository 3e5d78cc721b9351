"""The claims ledger as a page a reader can use: every line of build/claims.tsv as a card (the id,
what is measured, typeset from the ledger's own LaTeX in claims_tex.tsv, the measured value, the
test and the verdict, then where it comes from), grouped by the statement of the paper it tests,
in the paper's order, each group folded; a search box and filters (js/ledger.js) open the groups
that hold a match. A card is a row of a grid on a wide screen and stacks on a phone."""
import os
import re

import argument_pages
import frame
from frame import esc, secondary
from source_pages import page_of
from statements import VERDICT_RANK, read_tsv

BEYOND = ("beyond", "Beyond the paper: extensions and controls")
# the column heads of a group's cards, seen on a wide screen only
HEAD = ('<div class="claim head" aria-hidden="true"><span>ledger line</span>'
        '<span>what is measured</span><span>measured <i>m</i></span><span>test</span>'
        '<span>verdict</span></div>')


# In claims.tsv's paper_ref the paper is cited by its published numbers, each label that has one
# following as a secondary id: "Proposition 5.1 (TeoL)", "eq. (27) (ContDyn)", "Remark 5.2".
CITED_RE = re.compile(r"(eq\. \([0-9a-z]+\)|[A-Z][a-z]+ [0-9]+(?:\.[0-9]+)?)"
                      r"(?: \(([A-Za-z][A-Za-z0-9-]*)\))?")


def published_ref(site, text):
    """The ledger's paper_ref with each citation linked: a statement to its page, an equation to its
    entry, the label after it in small type (Proposition 5.1 (TeoL) -> Proposition 5.1, linked,
    then TeoL)."""
    def sub(m):
        name, lab = m.group(1), m.group(2)
        if not lab:     # an unlabelled statement, cited by number alone: "Remark 5.2"
            kind, _, number = name.partition(" ")
            lab = site.st.by_name.get((kind.lower(), number))
            if not lab:
                return esc(m.group(0))
            return '<a href="%s">%s</a>' % (argument_pages.stmt_page(lab), esc(name))
        if lab not in site.labels:
            return esc(m.group(0))
        kind = site.labels[lab][0]
        if kind in frame.STATEMENT_KINDS and lab in site.st.labels:
            link = '<a href="%s" title="%s">%s</a>' % (argument_pages.stmt_page(lab), esc(lab),
                                                      esc(name))
        elif kind == "equation":    # "eq. " before the link, which shows the number: (27)
            frame.REFERENCED.add(lab)
            link = ('%s<a class="label" href="equations.html#eq-%s" title="%s">%s</a>'
                    % (esc(name[:name.index("(")]), esc(lab), esc(lab),
                       esc(name[name.index("("):])))
        else:
            link = esc(name)
        return "%s %s" % (link, secondary(lab))
    out, last = [], 0
    for m in CITED_RE.finditer(text):
        out += [esc(text[last:m.start()]), sub(m)]
        last = m.end()
    return "".join(out) + esc(text[last:])


def source_link(site, c):
    """tests/FILE.c:LINE (claims.tsv's source column) -> that line on the file's page."""
    m = re.match(r"(.+):(\d+)$", c.get("source") or "")
    if not m or m.group(1) not in site.files:
        return None
    return '<a class="src" href="%s#L%s">%s</a>' % (page_of(m.group(1)), m.group(2),
                                                     esc(c["source"]))


def direction(c):
    """The test column's direction as a filter value: at most, at least, within."""
    t = (c.get("test") or "").strip()
    if not t:
        return ""
    return "at most" if t.startswith("<") else "at least" if t.startswith(">") else "within"


def measured_html(text):
    """claims.tsv's measured value (%.6g) with its exponent typeset: 3.05e-16 -> 3.05 x 10^-16."""
    m = re.match(r"^(-?[\d.]+)e([+-]\d+)$", text)
    if m:
        return "\\(%s\\times10^{%d}\\)" % (m.group(1), int(m.group(2)))
    return esc(text)


class Groups:
    """Which group a line belongs to: the first statement it tests, in the paper's order; else the
    first equation or section its reference names; else the lines beyond the paper."""

    def __init__(self, site):
        self.site = site
        rows = read_tsv(os.path.join(site.paper_dir, "labels.tsv"))
        self.order = {r["label"].strip(): i for i, r in enumerate(rows)}
        self.sections = {r["label"]: r["number"] for r in rows
                         if r["kind"] in ("section", "subsection")}

    def of(self, c):
        st = self.site.st
        labs = st.of_claim[c["id"]]
        if labs:
            lab = min(labs, key=lambda x: self.order.get(x, len(self.order)))
            return lab, st.name(lab)
        for w in re.findall(r"[A-Za-z][A-Za-z0-9-]*", c["paper_ref"]):
            kind, number = self.site.labels.get(w, (None, None))
            if kind in ("equation", "section", "subsection"):
                return w, ("Equation (%s)" if kind == "equation" else "Section %s") % number
        for phrase, lab in st.aliases:
            if phrase in c["paper_ref"] and lab in self.sections:
                return lab, "Section %s" % self.sections[lab]
        return BEYOND

    def rank(self, key):
        return self.order.get(key, len(self.order))


def card(site, c, tex):
    """One ledger line: its cells in grid areas (id, quantity, measured, test, verdict, where)."""
    stmts = site.st.of_claim[c["id"]]
    search = " ".join([c["id"], c["paper_ref"], c["quantity"]]
                      + [site.st.name(lab) for lab in stmts])
    data = {"verdict": c["verdict"], "statement": " ".join(stmts),
            "method": site.claim_method(c["id"]) or "", "test": direction(c),
            "search": search.lower()}
    t = tex.get(c["id"]) if tex else None
    quantity = site.tex.inline(t["quantity"]) if t else esc(c["quantity"])
    test = site.tex.inline(t["test"]) if t else esc(c.get("test") or "")
    where = ["<span>in the paper: %s</span>" % (published_ref(site, c["paper_ref"]) or "&ndash;")]
    src = source_link(site, c)
    if src:
        where.append("<span>code: %s</span>" % src)
    labs = site.claim_labels.get(c["id"], [])
    if labs:
        where.append("<span>equations: %s</span>"
                     % " ".join(frame.label_link(lb, site.labels) for lb in labs))
    fig = site.claim_figure(c["id"])
    if fig:
        where.append('<span>figure: <a href="figures.html#fig-%s">%s</a></span>'
                     % (esc(fig), esc(fig)))
    v = c["verdict"]
    return ('<article class="claim" id="claim-%s" %s><code class="c-id">%s</code>'
            '<div class="c-q">%s</div><div class="c-m"><span class="k">measured</span> %s</div>'
            '<div class="c-t"><span class="k">test</span> %s</div>'
            '<div class="c-v"><span class="v-%s">%s</span></div><div class="c-w">%s</div></article>'
            % (esc(c["id"]), " ".join('data-%s="%s"' % (k, esc(x)) for k, x in data.items()),
               esc(c["id"]), quantity, measured_html(c.get("measured") or ""), test,
               v.replace(" ", "-"), esc(v), " ".join(where)))


def tally(counts, link=True):
    """Counts by verdict, each a link to the ledger filtered to that verdict."""
    def one(v, n):
        text = '%d <span class="v-%s">%s</span>' % (n, v.replace(" ", "-"), esc(v))
        return ('<a href="ledger.html?verdict=%s">%s</a>' % (v.replace(" ", "+"), text) if link
                else text)
    return " &middot; ".join(one(v, n) for v, n in counts)


def verdict_counts(claims):
    counts = {}
    for c in claims:
        counts[c["verdict"]] = counts.get(c["verdict"], 0) + 1
    return sorted(counts.items(),
                  key=lambda kv: VERDICT_RANK.index(kv[0]) if kv[0] in VERDICT_RANK else 9)


def by_stem(site, claims, tex):
    """The lines beyond the paper, folded again by the first word of their ids (method-...,
    highorder-...), in the order the ledger first meets each."""
    stems = {}
    for c in claims:
        stems.setdefault(c["id"].split("-")[0], []).append(c)
    return "".join('<details class="sub"><summary><span class="g-name">%s-&hellip;</span> '
                   '<span class="g-count">%d line%s</span> <span class="g-tally">%s</span>'
                   '</summary>%s%s</details>'
                   % (esc(stem), len(cs), "s" if len(cs) != 1 else "",
                      tally(verdict_counts(cs), link=False), HEAD,
                      "".join(card(site, c, tex) for c in cs))
                   for stem, cs in stems.items())


def group_html(site, key, name, claims, tex, also=()):
    """A group of lines; `also`: the other statements whose lines all sit in this group (a line
    citing two is under the first in the paper's order), each an anchor that opens it."""
    link = ""
    if key in site.st.order:
        link = ("<p class='g-link'><a href='%s'>%s: the statement as printed, its verdict and its "
                "evidence</a></p>" % (argument_pages.stmt_page(key), esc(name)))
    anchors = "".join('<span id="g-%s"></span>' % esc(lab.replace(":", "-")) for lab in also)
    return ('<details class="group" id="g-%s"><summary><span class="g-name">%s</span>%s '
            '<span class="g-count">%d line%s</span> <span class="g-tally">%s</span></summary>%s%s'
            '%s</details>'
            % (esc(key.replace(":", "-")), esc(name), secondary(key) if key != BEYOND[0] else "",
               len(claims), "s" if len(claims) != 1 else "", tally(verdict_counts(claims), False),
               anchors, link, by_stem(site, claims, tex) if key == BEYOND[0] else
               HEAD + "".join(card(site, c, tex) for c in claims)))


def other_statements(site, order, groups):
    """For each group, the statements its lines cite that have no group of their own."""
    keys, placed, out = {k for k, _ in order}, set(), {}
    for k in order:
        labs = [lab for c in groups[k] for lab in site.st.of_claim[c["id"]]]
        out[k] = [lab for lab in dict.fromkeys(labs) if lab not in keys and lab not in placed]
        placed.update(out[k])
    return out


def filters(site):
    """The search box and the filters: verdict, statement, method, test direction."""
    methods = sorted({m for m in (site.claim_method(c["id"]) for c in site.claims) if m})
    stmts = [lab for lab in site.st.order if site.st.claims_of(lab)]

    def options(name, values):
        opts = "".join('<option value="%s">%s</option>' % (esc(v), esc(t)) for v, t in values)
        return ('<label>%s <select data-filter="%s"><option value="">all</option>%s</select>'
                '</label>' % (name, name, opts))
    return "".join([
        '<label class="q">search <input type="search" id="ledger-q" '
        'placeholder="id, Proposition 5.1, words"></label>',
        options("verdict", [(v, v) for v, _ in site.st.counts()]),
        options("statement", [(lab, site.st.name(lab)) for lab in stmts]),
        options("method", [(m, m) for m in methods]) if methods else "",
        options("test", [(d, d) for d in ("within", "at most", "at least")]),
        '<button type="button" id="ledger-open">open all</button>'
        '<button type="button" id="ledger-close">close all</button>'])


def build(site):
    groups, g = {}, Groups(site)
    for c in site.claims:
        key, name = g.of(c)
        groups.setdefault((key, name), []).append(c)
    order = sorted(groups, key=lambda k: (k[0] == BEYOND[0], g.rank(k[0])))
    tex = site.claims_tex
    note = ("" if tex is not None else " (No claims_tex.tsv beside claims.tsv: the quantities "
            "are shown as the ledger prints them on a terminal.)")
    out = ["<main class='text wide-page'><h1>The claims ledger</h1>",
           "<p class='lead'>%d lines: %s.</p>" % (len(site.claims), tally(site.st.counts())),
           "<p class='note'>Every line of <code>build/claims.tsv</code>, grouped by the "
           "statement of the paper it tests, in the paper's order (open a group to read its "
           "lines). Each line gives what is measured, the measured value <i>m</i>, the test it "
           "must pass and the verdict; then where it comes from: the paper's reference, the line "
           "of test code that records it, the equations and the figure. Search or filter to open "
           "the groups that hold a match.%s</p>" % note,
           "<form class='filters' onsubmit='return false'>%s <span id='ledger-count'></span></form>"
           % filters(site),
           "<div id='ledger'>"]
    also = other_statements(site, order, groups)
    out += [group_html(site, key, name, groups[(key, name)], tex, also[(key, name)])
            for key, name in order]
    out.append("</div></main>")
    site.write_page("ledger.html", "Claims ledger", "ledger", "\n".join(out), ["ledger.js"])
