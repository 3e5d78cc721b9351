"""The equations page: each label we implement, by the number the paper prints, with the display
as printed (quoted from the paper's source when it is at hand), our restatement, the functions that
implement it, the tests that name it and the ledger lines that measure it; then every other label
a page links to."""
import os

import argument_pages
import frame
from frame import esc, link_labels, published, secondary
from source_pages import page_of


def section_link(f, k):
    return '<a href="%s#s%d">%s &sect;%d</a>' % (page_of(f), k + 1, esc(f), k + 1)


def entry_links(site, lab, desc):
    """The entry's list: implemented by, tests, other citations, ledger lines."""
    dl = []
    impl = site.impl.get(lab, [])
    if desc is not None or impl:
        dl.append(("Implemented by", ", ".join(
            '<a class="impl" href="%s#fn-%s">%s</a> (%s)' % (page_of(f), esc(fn), esc(fn), esc(f))
            for f, fn, _ in impl) or "<b>no function is marked</b>"))
    cites = site.cited.get(lab, [])
    tests = [(f, k) for f, k in cites if f.startswith("tests/")]
    implemented = {(a, c) for a, _, c in impl}
    srcs = [(f, k) for f, k in cites if f.startswith("src/") and (f, k) not in implemented]
    if desc is not None or tests:
        dl.append(("Tests that name it", ", ".join(
            '<a class="test" href="%s#s%d">%s &sect;%d</a>' % (page_of(f), k + 1, esc(f), k + 1)
            for f, k in tests) or "<b>none</b>"))
    if srcs:
        dl.append(("Also cited in", ", ".join(section_link(f, k) for f, k in srcs)))
    claims = site.label_claims.get(lab, [])
    dl.append(("Ledger lines", site.claims_table(claims, 6) if claims else "none"))
    return "<dl>%s</dl>" % "".join("<dt>%s</dt><dd>%s</dd>" % r for r in dl)


def entry(site, lab, desc):
    kind, number = site.labels.get(lab, ("?", "?"))
    tex, note = site.restated.get(lab, ("", ""))
    out = ['<div class="eq" id="eq-%s"><h2>%s %s</h2>'
           % (esc(lab), esc(published(kind, number)).capitalize(), secondary(lab))]
    if desc:
        out.append("<p>%s</p>" % esc(desc))
    if kind in frame.STATEMENT_KINDS and lab in site.st.order:
        out.append("<p>Its page: <a href='%s'>%s</a>, quoted, with its verdict.</p>"
                   % (argument_pages.stmt_page(lab), esc(site.st.name(lab))))
    printed = site.quotes.display(lab) if site.quotes else None
    if printed:
        out.append('<div class="printed"><span class="k">As printed</span>%s</div>' % printed)
    if tex:
        out.append('<div class="restated"><span class="k">%s</span>'
                   '<div class="math">\\[%s\\]</div></div>'
                   % ("Restated" if printed else "As we restate it", esc(tex)))
    if note:
        out.append('<p class="note">%s</p>' % link_labels(esc(note), site.labels))
    out.append(entry_links(site, lab, desc))
    return "".join(out) + "</div>"


def build(site):
    out = ["<main class='text'><h1>The equations we implement</h1>",
           "<p class='note'>Each entry: the number the paper prints (its LaTeX label follows in "
           "small type), the display as the paper's source prints it, the equation as we restate "
           "it, the functions marked <code>/* (label) */</code> that implement it, the tests that "
           "name it and the claims-ledger lines that measure it. %s The restatements are ours.</p>"
           % site.numbering.provenance_html(esc)]
    for lab, desc in site.declared.items():
        out.append(entry(site, lab, desc))
    cited = list(site.cited) + list(site.label_claims) + list(frame.REFERENCED)
    others = sorted({lab for lab in cited if lab not in site.declared})
    out.append("<h2>Other statements of the paper cited in the code or the ledger</h2>")
    for lab in others:
        out.append(entry(site, lab, None))
    out.append("</main>")
    frame.write(os.path.join(site.out, "equations.html"),
                frame.page("Equations", "equations", "\n".join(out)))
