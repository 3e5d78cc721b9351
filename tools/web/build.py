#!/usr/bin/python3
"""make web: the annotated web edition, a static site that opens from disk.

    build.py --out DIR --claims CLAIMS.TSV [--labels LABELS.TSV] [--paper PAPER.TEX]

Writes into DIR the home page (what was found, with a figure), one page per statement of the
paper (quoted from the paper's LaTeX source when it is given and exists), the claims ledger, the
equations, the figures, the errata, the live pages, and one page per source file (src/, tests/)
in the side-by-side layout, and copies KaTeX (tools/web/node_modules) and the figures' PNG and CSV
files into DIR. Math is rendered by KaTeX in the browser from the copy inside DIR, so nothing is
fetched when a page is opened. Prints one line: what it wrote, and what it fell back to.
The pages are built by the modules beside this file, one for each kind of page.
"""
import argparse
import base64
import fnmatch
import glob
import json
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import argument_pages  # noqa: E402
import equations_page  # noqa: E402
import figures_page  # noqa: E402
import frame  # noqa: E402
import home_page  # noqa: E402
import inputs  # noqa: E402
import latex_html  # noqa: E402
import ledger_page  # noqa: E402
import live_pages  # noqa: E402
import paper_quotes  # noqa: E402
import source_pages  # noqa: E402
import statements  # noqa: E402
from frame import LABEL_RE, esc  # noqa: E402
from source_pages import WORD_RE, page_of  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
KATEX = os.path.join(HERE, "node_modules", "katex", "dist")
TEX_REF_RE = re.compile(r"\\(?:eqref|PaperRefOr)\{([^}]*)\}")
THEOREM_KINDS = {"proposition", "theorem", "definition", "algorithm", "corollary", "remark",
                 "lemma"}


class Site:
    def __init__(self, args):
        self.out = args.out
        self.fallbacks = []     # what this build had to do without, in words
        self.numbering = inputs.Numbering(args.labels, args.paper)
        self.labels = self.numbering.labels
        self.declared = inputs.read_declared(args.equations)
        self.restated = inputs.read_restatements(os.path.join(HERE, "equations.tex"))
        self.claims = inputs.read_claims(args.claims)
        self.claims_tex = inputs.read_claims_tex(
            os.path.join(os.path.dirname(args.claims), "claims_tex.tsv"))
        self.figrules = inputs.read_figure_rules(os.path.join(HERE, "ledger_figures.tsv"))
        # any depth: the library may live in layer folders (src/core, src/methods, ...)
        def under(d, *exts):
            return sorted(f for e in exts for f in glob.glob("%s/**/*.%s" % (d, e), recursive=True))
        self.files = under("src", "c", "h") + under("tests", "c", "sh")
        self.wasm = args.wasm
        self.methods = inputs.read_methods(args.methods, args.wasm)
        self.paper_dir = args.paper_dir
        self.st = statements.Statements(self.labels, self.claims, args.paper_dir,
                                        os.path.join(HERE, "statement_aliases.tsv"))
        self.tex = latex_html.Converter(self.ref_html, self.equation_number)
        self.quotes = (paper_quotes.Quotes(self.numbering.text, self.tex)
                       if self.numbering.text is not None else None)
        self.defs = source_pages.function_definitions(self.files)
        self.sections = {f: source_pages.split_sections(f) for f in self.files}
        self.figures = sorted(os.path.basename(p)[:-4] for p in glob.glob("figures/*.png"))
        self.index_sections()
        self.index_claims()
        self.note_fallbacks(args)

    def note_fallbacks(self, args):
        if self.quotes is None:
            self.fallbacks.append("no paper source at %s, so no quotes and the numbers of %s "
                                  "(PAPER_TEX=FILE)" % (args.paper or "(none given)", args.labels))
        if self.claims_tex is None:
            self.fallbacks.append("no claims_tex.tsv beside %s, so the ledger's quantities are "
                                  "plain text" % args.claims)
        if not os.path.exists(args.methods):
            self.fallbacks.append("no %s, so the method names of the WebAssembly module"
                                  % args.methods)
        for lab, ours, theirs in self.numbering.disagree:
            print("web: warning: %s is %s in %s but %s counted from %s"
                  % (lab, ours, args.labels, theirs, args.paper), file=sys.stderr)

    # --- the paper's labels in text: the published number, linked --------------------------
    def equation_number(self, lab):
        kind, number = self.labels.get(lab, (None, None))
        return number if kind == "equation" else None

    def ref_html(self, how, lab):
        """A reference in LaTeX text (\\eqref, \\ref, the ledger's \\PaperRefParen/\\PaperRefOr)
        as the paper prints it, linked to its page or entry."""
        if lab not in self.labels:
            if how == "ref" and re.match(r"(tab|sec|fig|app):", lab):
                return '<span class="xref">in the companion PDF</span>'
            return esc(lab)
        kind, number = self.labels[lab]
        if kind in frame.STATEMENT_KINDS and lab in self.st.labels:
            text = number if how == "ref" else self.st.name(lab)
            return '<a href="%s" title="%s">%s</a>' % (argument_pages.stmt_page(lab), esc(lab),
                                                      esc(text))
        if kind == "equation":
            frame.REFERENCED.add(lab)
            text = number if how in ("ref", "or") else "(%s)" % number
            return ('<a class="label" href="equations.html#eq-%s" title="%s">%s</a>'
                    % (esc(lab), esc(lab), esc(text)))
        return esc(number if how == "ref" else frame.published(kind, number))

    # --- where each label is implemented, cited, tested; which ledger lines measure it -----
    def index_sections(self):
        self.impl = {}       # label -> [(file, function, section index)]
        self.cited = {}      # label -> [(file, section index)]
        self.sec_impl = {}   # (file, section index) -> [labels implemented there]
        for f, secs in self.sections.items():
            defs_here = {}
            for name, places in self.defs.items():
                for pf, line in places:
                    if pf == f:
                        defs_here.setdefault(line, []).append(name)
            for k, s in enumerate(secs):
                self.index_section(f, k, s, defs_here)

    def index_section(self, f, k, s, defs_here):
        text = "\n".join(s.comment)
        for lab in dict.fromkeys(LABEL_RE.findall(text + "\n" + "\n".join(t for _, t in s.code))):
            if lab in self.labels:
                self.cited.setdefault(lab, []).append((f, k))
        # the equation map's rule (tools/eqmap.sh): a comment that starts with "(label)" right
        # before a function definition marks the function as its implementation
        m = re.match(r"\(([A-Za-z][A-Za-z0-9-]*)\)", text)
        first = s.code_start()
        names = defs_here.get(first, []) if first is not None else []
        if m and m.group(1) in self.labels and names and f.startswith("src/"):
            self.impl.setdefault(m.group(1), []).append((f, names[0], k))
            self.sec_impl.setdefault((f, k), []).append(m.group(1))

    def claim_method(self, cid):
        """The registered method a ledger line measures: the longest method name that is a
        hyphen-separated part of its id (reduced-order-comp6-kl -> comp6-kl), or None."""
        best = None
        for name in self.methods:
            if "-%s-" % name in "-%s-" % cid:
                if best is None or len(name) > len(best):
                    best = name
        return best

    def labels_of_claim(self, c, file_labels):
        labs = []
        # (label) in the reference, \eqref{label} in the quantity's LaTeX (its plain text shows
        # the number alone); statements (TeoL, PropoFinal) by name
        tex = (self.claims_tex or {}).get(c["id"], {}).get("quantity", "")
        for lab in LABEL_RE.findall(c["paper_ref"]) + TEX_REF_RE.findall(tex):
            if lab in self.labels:
                labs.append(lab)
        for w in WORD_RE.findall(c["paper_ref"]):
            if w in self.labels and self.labels[w][0] in THEOREM_KINDS:
                labs.append(w)
        # the method the line measures: the equations its source file (build/methods.tsv) implements
        src = self.methods.get(self.claim_method(c["id"]) or "", {}).get("source", "")
        labs.extend(sorted(file_labels.get(src, [])))
        return list(dict.fromkeys(labs))

    def index_claims(self):
        file_labels = {}
        for lab, places in self.impl.items():
            for f, _, _ in places:
                file_labels.setdefault(f, []).append(lab)
        self.claim_labels, self.label_claims = {}, {}
        for c in self.claims:
            labs = self.labels_of_claim(c, file_labels)
            self.claim_labels[c["id"]] = labs
            for lab in labs:
                self.label_claims.setdefault(lab, []).append(c)
        # the orders first (reduced, global, multiplier, then the others), then the rest in the
        # ledger's order
        rank = ("reduced-order", "global-order", "lambda-order")
        index = {c["id"]: i for i, c in enumerate(self.claims)}
        for lab, claims in self.label_claims.items():
            self.label_claims[lab] = sorted(claims, key=lambda c: (
                [not c["id"].startswith(r) for r in rank], "order" not in c["id"], index[c["id"]]))

    def claim_figure(self, cid):
        for pat, fig in self.figrules:
            if fnmatch.fnmatchcase(cid, pat):
                return fig if fig in self.figures else None
        return None

    def resolver(self, f):
        """A function name -> the link to its definition: in this file if defined here, else the
        one definition elsewhere (a name defined in several files, like main, is not linked)."""
        def resolve(name):
            places = self.defs.get(name)
            if not places:
                return None
            if any(p[0] == f for p in places):
                return "#fn-" + name
            if len({p[0] for p in places}) == 1:
                return "%s#fn-%s" % (page_of(places[0][0]), name)
            return None
        return resolve

    # --- shared pieces of pages ---------------------------------------------------------------
    @staticmethod
    def claim_row_short(c):
        v = c["verdict"]
        return ('<tr><td><a href="ledger.html#claim-%s">%s</a></td><td class="num">%s</td>'
                '<td class="num">%s</td><td class="v-%s">%s</td></tr>'
                % (esc(c["id"]), esc(c["id"]), esc(c["measured"]), esc(c["expected"]),
                   v.replace(" ", "-"), esc(v)))

    def claims_table(self, claims, shown):
        """The first `shown` ledger lines as a table, the rest folded under it."""
        head = ('<table class="claims"><tr><th>claim</th><th>measured</th><th>expected</th>'
                '<th>verdict</th></tr>%s</table>')
        out = head % "".join(map(self.claim_row_short, claims[:shown]))
        if claims[shown:]:
            rest = head % "".join(map(self.claim_row_short, claims[shown:]))
            out += ('<details><summary>%d more ledger lines</summary>%s</details>'
                    % (len(claims) - shown, rest))
        return out

    def write_page(self, name, title, here, body, scripts=()):
        frame.write(os.path.join(self.out, name), frame.page(title, here, body, scripts))

    def search_index(self):
        """search_index.js: every page, statement, ledger line, equation and function, for the
        site-wide search box (site.js); a script, not JSON, so that it loads from disk."""
        st = self.st
        items = [[st.name(lab) + " " + lab, argument_pages.stmt_page(lab)] for lab in st.order]
        items += [["%s %s %s" % (c["id"], c["paper_ref"],
                                 " ".join(map(st.name, st.of_claim[c["id"]]))),
                   "ledger.html#claim-" + c["id"]] for c in self.claims]
        items += [["%s %s" % (frame.published(*self.labels[lab]).capitalize(), lab),
                   "equations.html#eq-" + lab] for lab in self.declared if lab in self.labels]
        items += [[f, page_of(f)] for f in self.files]
        items += [["%s() %s" % (name, f), "%s#fn-%s" % (page_of(f), name)]
                  for name, places in sorted(self.defs.items()) for f, _ in places[:1]]
        items += [[t, h] for h, t in frame.NAV]
        items += [["Errata", "errata.html"], ["Not tested", "not-tested.html"]]
        frame.write(os.path.join(self.out, "search_index.js"),
                    "window.SEARCH_INDEX = %s;\n" % json.dumps(items, separators=(",", ":")))

    def copy_assets(self):
        """KaTeX, the style, the site's own scripts, the paper's macros and, as a script (a page
        opened from disk may not fetch), the WebAssembly module of the integrators."""
        kdst = os.path.join(self.out, "katex")
        if os.path.exists(kdst):
            shutil.rmtree(kdst)
        os.makedirs(os.path.join(kdst, "contrib"))
        for f in ("katex.min.css", "katex.min.js", os.path.join("contrib", "auto-render.min.js")):
            shutil.copyfile(os.path.join(KATEX, f), os.path.join(kdst, f))
        shutil.copytree(os.path.join(KATEX, "fonts"), os.path.join(kdst, "fonts"))
        with open(os.path.join(HERE, "style.css"), encoding="utf-8") as f:
            frame.write(os.path.join(self.out, "style.css"), f.read() + frame.PYG_CSS)
        for f in glob.glob(os.path.join(HERE, "js", "*.js")):
            shutil.copyfile(f, os.path.join(self.out, os.path.basename(f)))
        frame.write(os.path.join(self.out, "paper_macros.js"),
                    self.quotes.macros_js() if self.quotes else "window.PAPER_MACROS = {};\n")
        if self.wasm:
            with open(self.wasm, "rb") as f:
                data = base64.b64encode(f.read()).decode("ascii")
            frame.write(os.path.join(self.out, "suslov_wasm.js"),
                        "window.SUSLOV_WASM = '%s';\n" % data)

    def build(self):
        os.makedirs(self.out, exist_ok=True)
        for old in glob.glob(os.path.join(self.out, "*.html")):
            os.remove(old)      # a page of a file that no longer exists must not survive
        self.copy_assets()
        for f in self.files:
            source_pages.source_page(self, f)
        self.argument = argument_pages.ArgumentPages(self, self.st)
        self.argument.build()
        live_pages.build(self)
        ledger_page.build(self)
        figures_page.build(self)
        equations_page.build(self)  # after the pages that link to it: an entry per label they cite
        self.search_index()
        home_page.build(self)       # last: make takes index.html as the whole site's time stamp
        if self.tex.unknown:
            print("web: warning: LaTeX commands passed over: %s"
                  % " ".join(sorted(self.tex.unknown)), file=sys.stderr)
        return len(glob.glob(os.path.join(self.out, "*.html")))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--claims", required=True)
    ap.add_argument("--labels", default="paper/labels.tsv")
    ap.add_argument("--paper", default=None)
    ap.add_argument("--equations", default="paper/equations.txt")
    ap.add_argument("--paper-dir", default="paper", help="findings.tsv, errata.tsv, not_tested.tsv")
    ap.add_argument("--methods", default=None, help="build/methods.tsv (default: beside --claims)")
    ap.add_argument("--wasm", default=None,
                    help="the integrators compiled to WebAssembly (make wasm)")
    args = ap.parse_args()
    if args.methods is None:
        args.methods = os.path.join(os.path.dirname(args.claims), "methods.tsv")
    if not os.path.isdir(KATEX):
        sys.exit("web: %s is missing: run make web-deps" % KATEX)
    site = Site(args)
    pages = site.build()
    said = ["statements quoted from %s" % args.paper] if site.quotes else []
    said += ["fell back: " + "; ".join(site.fallbacks)] if site.fallbacks else []
    print("web: wrote %s (%d pages); %s" % (args.out, pages, "; ".join(said)))


if __name__ == "__main__":
    main()
