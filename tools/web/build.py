#!/usr/bin/python3
"""make web: the annotated web edition, a static site that opens from disk.

    build.py --out DIR --claims CLAIMS.TSV [--labels LABELS.TSV | --paper PAPER.TEX]

Writes DIR/index.html, one page per source file (src/*.c, src/*.h, tests/*.c, tests/*.sh: whatever
exists) in the side-by-side layout (comments as prose on the left, code on the right),
DIR/equations.html, DIR/ledger.html, DIR/figures.html, and copies KaTeX (tools/web/node_modules)
and the figures' PNG and CSV files into DIR. Prose goes through python3-markdown, code through
pygments; function definitions are found with universal-ctags. Math is rendered by KaTeX in the
browser from the copy inside DIR, so nothing is fetched when a page is opened.
"""
import argparse
import base64
import csv
import fnmatch
import glob
import html
import json
import os
import re
import shutil
import subprocess
import sys
import textwrap

import markdown

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import argument_pages  # noqa: E402
import live_pages  # noqa: E402
import statements  # noqa: E402
from pygments import highlight
from pygments.formatters import HtmlFormatter
from pygments.lexers import BashLexer, CLexer

HERE = os.path.dirname(os.path.abspath(__file__))
KATEX = os.path.join(HERE, "node_modules", "katex", "dist")
LABEL_RE = re.compile(r"\(([A-Za-z][A-Za-z0-9-]*)\)")
WORD_RE = re.compile(r"\b([A-Za-z_][A-Za-z0-9_]*)\b")
REFERENCED = set()   # every label some page links to: each needs an entry on the equations page
THEOREM_KINDS = {"proposition", "theorem", "definition", "algorithm", "corollary", "remark", "lemma"}


def esc(s):
    return html.escape(s, quote=True)


def page_of(path):
    """src/core/so3.c -> src-core-so3.c.html: one flat directory, so every link is a plain file name."""
    return path.replace("/", "-") + ".html"


# ---------------------------------------------------------------------------------------------
# The paper's labels, the declared (implemented) ones, our restatements, the ledger

def read_labels(labels_tsv, paper_tex):
    """label -> (kind, number): paper/labels.tsv when it exists, else counted from the LaTeX."""
    rows = []
    if labels_tsv and os.path.exists(labels_tsv):
        with open(labels_tsv, encoding="utf-8") as f:
            for r in csv.DictReader(f, delimiter="\t"):
                rows.append((r["label"], r["kind"], r["number"]))
    elif paper_tex and os.path.exists(paper_tex):
        sys.path.insert(0, HERE)
        import eqnumbers
        with open(paper_tex, encoding="utf-8", errors="replace") as f:
            rows = eqnumbers.Numberer(f.read()).run()
    else:
        sys.exit("web: need paper/labels.tsv or the paper's LaTeX source (--paper) for equation numbers")
    if rows and paper_tex and os.path.exists(paper_tex):
        # two independent counts of the same source must agree (the table another tool made, ours)
        sys.path.insert(0, HERE)
        import eqnumbers
        with open(paper_tex, encoding="utf-8", errors="replace") as f:
            ours = {lab.strip(): num for lab, _, num in eqnumbers.Numberer(f.read()).run()}
        for label, _, number in rows:
            if label.strip() in ours and ours[label.strip()] != number:
                print("web: warning: %s is %s in %s but %s counted from %s"
                      % (label, number, labels_tsv, ours[label.strip()], paper_tex), file=sys.stderr)
    out = {}
    for label, kind, number in rows:
        label = label.strip()
        if label.startswith("nolabel:") or not label:
            continue
        kind = kind.lower()
        if kind == "subequation":
            kind = "equation"
        out.setdefault(label, (kind, number))
    return out


def published(kind, number):
    """How the paper prints the reference: (37), Proposition 5.3, Algorithm 5.1."""
    if kind == "equation":
        return "equation (%s)" % number
    return "%s %s" % (kind.capitalize(), number)


def read_declared(path):
    """paper/equations.txt: label -> our one-line description."""
    out = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            parts = line.split(None, 1)
            out[parts[0]] = parts[1].strip() if len(parts) > 1 else ""
    return out


def read_restatements(path):
    """tools/web/equations.tex: '@label' starts an entry; its LaTeX lines follow; lines that start
    with '> ' are a note in prose under the equation; '%' lines are comments."""
    out, cur = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("%"):
                continue
            if line.startswith("@"):
                cur = line[1:].strip()
                out[cur] = {"tex": [], "note": []}
            elif cur is not None and line.startswith("> "):
                out[cur]["note"].append(line[2:])
            elif cur is not None and line.strip():
                out[cur]["tex"].append(line)
    return {k: ("\n".join(v["tex"]), " ".join(v["note"])) for k, v in out.items()}


def read_claims(path):
    if not os.path.exists(path):
        sys.exit("web: %s is missing (make builds it from the claims program)" % path)
    with open(path, encoding="utf-8") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def read_figure_rules(path):
    """tools/web/ledger_figures.tsv: claim-id glob -> figure name, the first match wins."""
    rules = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            pat, fig = line.split()
            rules.append((pat, fig))
    return rules


# ---------------------------------------------------------------------------------------------
# Source files: sections of (comment, code), function definitions

class Section:
    def __init__(self, start):
        self.start = start      # first line number (1-based) of the section
        self.comment = []       # comment text lines, markers stripped
        self.code = []          # (line number, text)

    def code_start(self):
        for n, t in self.code:
            if t.strip():
                return n
        return None


def comment_text(lines, shell):
    """The text of a comment block without its markers, dedented."""
    out = []
    for i, line in enumerate(lines):
        s = line.strip()
        if shell:
            s = re.sub(r"^#+ ?", "", s)
        else:
            if i == 0:
                s = re.sub(r"^(/\*+|//+)", "", s).lstrip()
            if s.endswith("*/"):
                s = s[:-2]
            s = re.sub(r"^(\*(?!/) ?|//+ ?)", "", s) if i > 0 else s
        out.append(s.rstrip())
    return textwrap.dedent("\n".join(out)).strip("\n")


def split_sections(path):
    """docco's rule: a line that holds only a comment starts (or continues) the prose of a new
    section; everything else is code of the current section."""
    shell = path.endswith(".sh")
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    sections = [Section(1)]
    i = 0
    while i < len(lines):
        s = lines[i].strip()
        block = None
        if shell and lines[i].startswith("#") and not s.startswith("#!"):
            j = i
            while j < len(lines) and lines[j].startswith("#") and not lines[j].startswith("#!"):
                j += 1
            block = (i, j)
        elif not shell and lines[i].startswith("//"):
            j = i
            while j < len(lines) and lines[j].strip().startswith("//"):
                j += 1
            block = (i, j)
        elif not shell and lines[i].startswith("/*"):
            # only a comment at the left margin opens a section: one inside a function stays
            # with its code, so that a function is never cut in two
            j = i
            while j < len(lines) and "*/" not in lines[j]:
                j += 1
            if j < len(lines) and lines[j].split("*/", 1)[1].strip() == "":
                block = (i, j + 1)
        if block:
            a, b = block
            cur = sections[-1]
            if any(t.strip() for _, t in cur.code):
                cur = Section(a + 1)
                sections.append(cur)
            elif not cur.comment:
                cur.start = a + 1
            if cur.comment:
                cur.comment.append("")
            cur.comment.append(comment_text(lines[a:b], shell))
            i = b
            continue
        sections[-1].code.append((i + 1, lines[i]))
        i += 1
    for sec in sections:
        while sec.code and not sec.code[-1][1].strip():
            sec.code.pop()
    return [s for s in sections if s.comment or any(t.strip() for _, t in s.code)]


def inner_comments(code, shell):
    """Comments that sit on lines of their own inside a function: taken out of the code, to be
    read in the prose column beside it. Returns (the code without them, [(line of the code they
    precede, comment text)])."""
    kept, notes, i = [], [], 0
    while i < len(code):
        n, t = code[i]
        s = t.strip()
        j = None
        if shell and s.startswith("#") and not s.startswith("#!") and t[:1].isspace():
            j = i
            while j + 1 < len(code) and code[j + 1][1].strip().startswith("#"):
                j += 1
        elif not shell and t[:1].isspace() and (s.startswith("//") or s.startswith("/*")):
            j = i
            if s.startswith("/*"):
                while j < len(code) and "*/" not in code[j][1]:
                    j += 1
                if j == len(code) or code[j][1].split("*/", 1)[1].strip():
                    j = None      # code after the comment on its last line: it stays in the code
            else:
                while j + 1 < len(code) and code[j + 1][1].strip().startswith("//"):
                    j += 1
        if j is None:
            kept.append((n, t))
            i += 1
            continue
        notes.append((code[j][0], comment_text([x for _, x in code[i:j + 1]], shell)))
        i = j + 1
    # each note points at the code line it precedes (or, at the end of a section, the last one)
    shown = [n for n, t in kept if t.strip()]
    notes = [(next((n for n in shown if n > end), shown[-1] if shown else None), text) for end, text in notes]
    return kept, notes


# A formula written in ASCII inside a comment (w^{k+1}, lambda_{k+1}, R_k, I_m): a short name
# with sub- or superscripts, typeset by KaTeX. A C identifier (sus_run) is not one: after a
# one-letter subscript no letter, digit or underscore may follow.
FORMULA_RE = re.compile(r"(?<![\\\w])([A-Za-z]{1,6}\d?)"
                        r"((?:[_^](?:\{[^{}\s]{1,24}\}|-?[A-Za-z0-9](?![A-Za-z0-9_])))+)(?![\w(])")
GREEK = {"lambda", "omega", "mu", "xi", "tau", "psi", "sigma", "rho", "gamma", "phi", "alpha", "beta",
         "delta", "eta"}


def mathify(text):
    """Wraps the ASCII formulas of a comment in \\( \\) for KaTeX (greek names as letters)."""
    def sub(m):
        base = "\\" + m.group(1) if m.group(1) in GREEK else m.group(1)
        if len(m.group(1).rstrip("0123456789")) > 1 and m.group(1) not in GREEK:
            return m.group(0)
        return "\\(%s%s\\)" % (base, m.group(2))
    parts = re.split(r"(\\\(.+?\\\)|\\\[.+?\\\]|`[^`]*`)", text, flags=re.S)
    return "".join(p if i % 2 else FORMULA_RE.sub(sub, p) for i, p in enumerate(parts))


def function_definitions(files):
    """name -> [(file, line)] for every C function definition, from universal-ctags."""
    cfiles = [f for f in files if f.endswith((".c", ".h"))]
    out = subprocess.run(["ctags", "-x", "--sort=no", "--kinds-C=f", "--language-force=C"] + cfiles,
                         check=True, capture_output=True, text=True).stdout
    defs = {}
    for line in out.splitlines():
        parts = line.split(None, 4)
        if len(parts) >= 4 and parts[1] == "function":
            defs.setdefault(parts[0], []).append((parts[3], int(parts[2])))
    return defs


# ---------------------------------------------------------------------------------------------
# Rendering

MATH_RE = re.compile(r"\\\(.+?\\\)|\\\[.+?\\\]", re.S)


def link_labels(text_html, labels, prefix=""):
    """(label) -> a link to the label's entry, for the labels of the paper; outside tags only."""
    def sub(m):
        lab = m.group(1)
        if lab in labels:
            REFERENCED.add(lab)
            return '<a class="label" href="%sequations.html#eq-%s">(%s)</a>' % (prefix, esc(lab), esc(lab))
        return m.group(0)
    parts = re.split(r"(<[^>]*>)", text_html)
    inside_a = False
    for i, p in enumerate(parts):
        if p.startswith("<"):
            if re.match(r"<a[\s>]", p):
                inside_a = True
            elif p.startswith("</a"):
                inside_a = False
            continue
        if not inside_a:
            parts[i] = LABEL_RE.sub(sub, p)
    return "".join(parts)


def link_functions_in_text(text_html, resolve):
    """Function names in prose -> links to their definitions; outside tags and links only. Only
    words that read as C names (with an underscore, like sus_c) are taken: an English word
    that happens to name a static helper (draw, field) is left alone."""
    parts = re.split(r"(<[^>]*>)", text_html)
    inside = 0
    for i, p in enumerate(parts):
        if p.startswith("<"):
            if re.match(r"<(a|code|pre)[\s>]", p):
                inside += 1
            elif re.match(r"</(a|code|pre)>", p):
                inside = max(0, inside - 1)
            continue
        if inside:
            continue
        def sub(m):
            href = resolve(m.group(1)) if "_" in m.group(1) else None
            return '<a class="fn" href="%s">%s</a>' % (href, m.group(1)) if href else m.group(0)
        parts[i] = WORD_RE.sub(sub, p)
    return "".join(parts)


def prose_html(text, labels, resolve):
    """A comment as prose: markdown, with \\( \\) and \\[ \\] math kept for KaTeX, '<' kept as text
    and '*' never taken for emphasis (in these comments it multiplies)."""
    maths = []
    text = mathify(text)

    def keep(m):
        maths.append(m.group(0))
        return "\x00%d\x00" % (len(maths) - 1)
    t = MATH_RE.sub(keep, text)
    t = t.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("*", "\\*")
    out = markdown.markdown(t)
    out = link_labels(out, labels)
    out = link_functions_in_text(out, resolve)
    return re.sub("\x00(\\d+)\x00", lambda m: esc(maths[int(m.group(1))]), out)


def code_html(lines, shell, labels, resolve, anchors):
    """Highlighted code (pygments), function names linked to their definitions, the definitions
    given an id, (label) in comments linked."""
    if not lines:
        return ""
    src = "\n".join(t for _, t in lines) + "\n"
    lexer = BashLexer(stripnl=False) if shell else CLexer(stripnl=False)   # keep blank first lines: numbering
    out = highlight(src, lexer, HtmlFormatter(nowrap=True))
    rows = out.split("\n")
    for k, (n, _) in enumerate(lines):
        if k >= len(rows):
            break
        row = rows[k]
        for name in anchors.get(n, ()):
            # the definition's name gets the id; pygments marks it "nf", or "n" when it cannot tell
            for cls in ("nf", "n"):
                span = '<span class="%s">%s</span>' % (cls, name)
                if span in row:
                    row = row.replace(span, '<span class="%s" id="fn-%s">%s</span>' % (cls, name, name), 1)
                    break
            else:
                row = '<span id="fn-%s"></span>' % name + row

        def sub(m):
            cls, name = m.group(1), m.group(2)
            href = resolve(name)
            if not href:
                return m.group(0)
            return '<a class="fn" href="%s"><span class="%s">%s</span></a>' % (href, cls, name)
        row = re.sub(r'<span class="(n|nf)">([A-Za-z_][A-Za-z0-9_]*)</span>', sub, row)
        rows[k] = '<span class="ln" id="L%d">%d</span>%s' % (n, n, row)
    return link_labels("\n".join(rows[:len(lines)]), labels)



# Pygments' own colours for its token classes (generated by pygments, not written by hand).
PYG_CSS = HtmlFormatter(style="default").get_style_defs(".code")

KATEX_HEAD = """<link rel="stylesheet" href="katex/katex.min.css">
<script defer src="katex/katex.min.js"></script>
<script defer src="katex/contrib/auto-render.min.js" onload="renderMathInElement(document.body, {
  delimiters: [{left: '\\\\[', right: '\\\\]', display: true}, {left: '\\\\(', right: '\\\\)', display: false}],
  throwOnError: false})"></script>"""


NAV = (("index.html", "Home"), ("statements.html", "Statements"), ("ledger.html", "Ledger"),
       ("equations.html", "Equations"), ("figures.html", "Figures"), ("live-fig2.html", "Live"))


def page(title, here, body, scripts=()):
    """A page of the site: the top bar (sections, the jump-to menu and the site-wide search that
    tools/web/site.js fills in), KaTeX, and any page scripts."""
    links = "".join('<a href="%s">%s</a>' % (h, t) for h, t in NAV)
    extra = "".join('<script defer src="%s"></script>' % esc(x) for x in scripts)
    return """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>%s</title>
<link rel="stylesheet" href="style.css">
%s
<script defer src="search_index.js"></script>
<script defer src="site.js"></script>%s
</head><body>
<nav class="top"><span class="links">%s</span><span class="tools"><select class="jump" aria-label="jump to">
<option value="">jump to&hellip;</option></select>
<input class="search" type="search" placeholder="search the site" aria-label="search the site">
<span class="here">%s</span></span><div class="results" hidden></div></nav>
%s
</body></html>
""" % (esc(title), KATEX_HEAD, extra, links, esc(here), body)


def read_methods(methods_tsv, wasm):
    """name -> row of build/methods.tsv (the registry's own table: name, family, source, ...).
    Without it, the names (and nothing else) from the WebAssembly module's registry."""
    if methods_tsv and os.path.exists(methods_tsv):
        with open(methods_tsv, encoding="utf-8") as f:
            return {r["name"]: r for r in csv.DictReader(f, delimiter="\t")}
    if wasm and os.path.exists(wasm):
        out = subprocess.run(["node", os.path.join(HERE, "wasm_methods.js"), wasm], check=True,
                             capture_output=True, text=True).stdout
        return {n: {"name": n} for n in out.split()}
    return {}


def write(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


# ---------------------------------------------------------------------------------------------

class Site:
    def __init__(self, args):
        self.out = args.out
        self.labels = read_labels(args.labels, args.paper)
        self.declared = read_declared(args.equations)
        self.restated = read_restatements(os.path.join(HERE, "equations.tex"))
        self.claims = read_claims(args.claims)
        self.figrules = read_figure_rules(os.path.join(HERE, "ledger_figures.tsv"))
        # any depth: the library may live in layer folders (src/core, src/methods, ...)
        def under(d, *exts):
            return sorted(f for e in exts for f in glob.glob("%s/**/*.%s" % (d, e), recursive=True))
        self.files = under("src", "c", "h") + under("tests", "c", "sh")
        self.wasm = args.wasm
        self.methods = read_methods(args.methods, args.wasm)
        self.st = statements.Statements(self.labels, self.claims, args.paper_dir,
                                        os.path.join(HERE, "statement_aliases.tsv"))
        self.defs = function_definitions(self.files)
        self.sections = {f: split_sections(f) for f in self.files}
        self.figures = sorted(os.path.basename(p)[:-4] for p in glob.glob("figures/*.png"))
        self.index_sections()
        self.index_claims()

    # where each label is implemented, cited, tested; which ledger lines measure it
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
                text = "\n".join(s.comment)
                for lab in dict.fromkeys(LABEL_RE.findall(text + "\n" + "\n".join(t for _, t in s.code))):
                    if lab in self.labels:
                        self.cited.setdefault(lab, []).append((f, k))
                # the equation map's rule (tools/eqmap.sh): a comment that starts with "(label)"
                # right before a function definition marks the function as its implementation
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

    def index_claims(self):
        file_labels = {}
        for lab, places in self.impl.items():
            for f, _, _ in places:
                file_labels.setdefault(f, []).append(lab)
        self.claim_labels = {}
        self.label_claims = {}
        for c in self.claims:
            labs = []
            # (label) in the reference or the quantity; statements (TeoL, PropoFinal) by name
            for lab in LABEL_RE.findall(c["paper_ref"] + " " + c["quantity"]):
                if lab in self.labels:
                    labs.append(lab)
            for w in WORD_RE.findall(c["paper_ref"]):
                if w in self.labels and self.labels[w][0] in THEOREM_KINDS:
                    labs.append(w)
            # the method the line measures: the equations its source file (build/methods.tsv) implements
            src = self.methods.get(self.claim_method(c["id"]) or "", {}).get("source", "")
            labs.extend(sorted(file_labels.get(src, [])))
            labs = list(dict.fromkeys(labs))
            self.claim_labels[c["id"]] = labs
            for lab in labs:
                self.label_claims.setdefault(lab, []).append(c)
        # the orders first (reduced, global, multiplier, then the others), then the rest in ledger order
        rank = ("reduced-order", "global-order", "lambda-order")
        for lab, claims in self.label_claims.items():
            self.label_claims[lab] = sorted(claims, key=lambda c: ([not c["id"].startswith(r) for r in rank],
                                                                   "order" not in c["id"], self.claims.index(c)))

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
            here = [p for p in places if p[0] == f]
            if here:
                return "#fn-" + name
            files = {p[0] for p in places}
            if len(files) == 1:
                return "%s#fn-%s" % (page_of(places[0][0]), name)
            return None
        return resolve

    # --- pages ------------------------------------------------------------------------------
    def claim_row_short(self, c):
        v = c["verdict"]
        return ('<tr><td><a href="ledger.html#claim-%s">%s</a></td><td class="num">%s</td><td class="num">%s</td>'
                '<td class="v-%s">%s</td></tr>' % (esc(c["id"]), esc(c["id"]), esc(c["measured"]), esc(c["expected"]),
                                                   v.replace(" ", "-"), esc(v)))

    def claims_table(self, claims, shown):
        """The first `shown` ledger lines as a table, the rest folded under it."""
        head = ('<table class="claims"><tr><th>claim</th><th>measured</th><th>expected</th>'
                '<th>verdict</th></tr>%s</table>')
        out = head % "".join(map(self.claim_row_short, claims[:shown]))
        if claims[shown:]:
            out += ('<details><summary>%d more ledger lines</summary>%s</details>'
                    % (len(claims) - shown, head % "".join(map(self.claim_row_short, claims[shown:]))))
        return out

    def label_box(self, lab):
        kind, number = self.labels[lab]
        tex, note = self.restated.get(lab, ("", ""))
        parts = ['<div class="box"><h4><a class="label" href="equations.html#eq-%s">(%s)</a>, %s in the paper</h4>'
                 % (esc(lab), esc(lab), esc(published(kind, number)))]
        if tex:
            parts.append('<div class="math">\\[%s\\]</div>' % esc(tex))
        claims = self.label_claims.get(lab, [])
        if claims:
            parts.append('<div>Ledger lines that measure it:</div>' + self.claims_table(claims, 4))
        parts.append("</div>")
        return "".join(parts)

    def source_page(self, f):
        shell = f.endswith(".sh")
        resolve = self.resolver(f)
        anchors = {}
        for name, places in self.defs.items():
            for pf, line in places:
                if pf == f:
                    anchors.setdefault(line, []).append(name)
        body = []
        for k, s in enumerate(self.sections[f]):
            prose = prose_html("\n".join(s.comment), self.labels, resolve) if s.comment else ""
            code, notes = inner_comments(s.code, shell)
            for line, text in notes:
                at = '<a class="at" href="#L%d">line %d</a> ' % (line, line) if line else ""
                prose += '<div class="inner">%s%s</div>' % (at, prose_html(text, self.labels, resolve))
            for lab in self.sec_impl.get((f, k), []):
                prose += self.label_box(lab)
            end = s.code[-1][0] if s.code else s.start
            body.append('<section class="sec" id="s%d"><div class="prose"><span class="secno"><a href="#s%d">&sect;%d</a> '
                        'lines %d&ndash;%d</span>%s</div><div class="code"><pre>%s</pre></div></section>'
                        % (k + 1, k + 1, k + 1, s.start, end, prose,
                           code_html(code, shell, self.labels, resolve, anchors)))
        write(os.path.join(self.out, page_of(f)), page(f, f, "<h1 style='padding:0 24px'>%s</h1>\n%s"
                                                     % (esc(f), "\n".join(body))))

    def section_link(self, f, k):
        return '<a href="%s#s%d">%s &sect;%d</a>' % (page_of(f), k + 1, esc(f), k + 1)

    def equations_page(self):
        out = ["<main class='text'><h1>The equations we implement</h1>",
               "<p class='note'>Each entry: the label and the number the paper prints for it (counted from the "
               "paper's LaTeX source), the equation as we restate it, the functions marked "
               "<code>/* (label) */</code> that implement it, the tests that name it and the claims-ledger lines "
               "that measure it. Numbers are counted from the paper's LaTeX source on arXiv (1506.01289) by "
               "<code>tools/paper_labels.py</code>, which asserts the numbers the findings cite against a list a "
               "reviewer of this project gave as the published numbering (J. Geom. Mech. 10(1), 2018); we have "
               "not consulted the published article ourselves. The restatements are ours.</p>"]
        for lab, desc in self.declared.items():
            out.append(self.equation_entry(lab, desc))
        others = sorted({lab for lab in list(self.cited) + list(self.label_claims) + list(REFERENCED)
                         if lab not in self.declared})
        out.append("<h2>Other statements of the paper cited in the code or the ledger</h2>")
        for lab in others:
            out.append(self.equation_entry(lab, None))
        out.append("</main>")
        write(os.path.join(self.out, "equations.html"), page("Equations", "equations", "\n".join(out)))

    def equation_entry(self, lab, desc):
        kind, number = self.labels.get(lab, ("?", "?"))
        tex, note = self.restated.get(lab, ("", ""))
        rows = []
        head = '<div class="eq" id="eq-%s"><h2>(%s) &mdash; %s in the paper</h2>' % (esc(lab), esc(lab),
                                                                                 esc(published(kind, number)))
        if desc:
            rows.append("<p>%s</p>" % esc(desc))
        if tex:
            rows.append('<div class="math">\\[%s\\]</div>' % esc(tex))
        if note:
            rows.append('<p class="note">%s</p>' % link_labels(esc(note), self.labels))
        dl = []
        impl = self.impl.get(lab, [])
        if desc is not None or impl:
            dl.append(("Implemented by", ", ".join(
                '<a class="impl" href="%s#fn-%s">%s</a> (%s)' % (page_of(f), esc(fn), esc(fn), esc(f))
                for f, fn, _ in impl) or "<b>no function is marked</b>"))
        cites = self.cited.get(lab, [])
        tests = [(f, k) for f, k in cites if f.startswith("tests/")]
        srcs = [(f, k) for f, k in cites if f.startswith("src/") and (f, k) not in {(a, c) for a, _, c in impl}]
        if desc is not None or tests:
            dl.append(("Tests that name it", ", ".join('<a class="test" href="%s#s%d">%s &sect;%d</a>'
                                                        % (page_of(f), k + 1, esc(f), k + 1) for f, k in tests)
                       or "<b>none</b>"))
        if srcs:
            dl.append(("Also cited in", ", ".join(self.section_link(f, k) for f, k in srcs)))
        claims = self.label_claims.get(lab, [])
        dl.append(("Ledger lines", self.claims_table(claims, 6) if claims else "none"))
        rows.append("<dl>%s</dl>" % "".join("<dt>%s</dt><dd>%s</dd>" % r for r in dl))
        return head + "".join(rows) + "</div>"

    def published_ref(self, text):
        """The ledger's paper_ref with each label replaced by what the paper prints (TeoL ->
        Proposition 5.1, linked to its page; (PerFin2) -> (45), linked to the equation)."""
        def sub(m):
            w = m.group(0)
            if w not in self.labels:
                return w
            kind, number = self.labels[w]
            if kind in statements.STATEMENT_KINDS:
                return '<a href="%s" title="%s">%s</a>' % (argument_pages.stmt_page(w), esc(w),
                                                          esc(self.st.name(w)))
            if kind == "equation":
                REFERENCED.add(w)
                return ('<a class="label" href="equations.html#eq-%s" title="%s">%s</a>'
                        % (esc(w), esc(w), esc(number)))
            return w
        out, rest = [], esc(text)
        words = r"[A-Za-z][A-Za-z0-9-]*"
        for phrase, lab in self.st.aliases:    # first: "Prop. general DSP" -> Proposition 5.2
            if lab in self.st.labels and esc(phrase) in rest:
                head, rest = rest.split(esc(phrase), 1)
                out += [re.sub(words, sub, head), '<a href="%s" title="%s">%s</a>' % (
                    argument_pages.stmt_page(lab), esc(phrase), esc(self.st.name(lab)))]
        return "".join(out) + re.sub(words, sub, rest)

    def source_link(self, c):
        """tests/FILE.c:LINE (claims.tsv's source column) -> that line on the file's page."""
        m = re.match(r"(.+):(\d+)$", c.get("source") or "")
        if not m or m.group(1) not in self.files:
            return "&ndash;"
        return '<a class="src" href="%s#L%s">%s</a>' % (page_of(m.group(1)), m.group(2), esc(c["source"]))

    @staticmethod
    def direction(c):
        """The test column's direction as a filter value: at most, at least, within."""
        t = (c.get("test") or "").strip()
        return "at most" if t.startswith("<") else "at least" if t.startswith(">") else "within" if t else ""

    def ledger_filters(self, has_test):
        """The ledger's search box and its filters: verdict, statement, method, test direction."""
        methods = sorted({m for m in (self.claim_method(c["id"]) for c in self.claims) if m})
        stmts = [lab for lab in self.st.order if self.st.claims_of(lab)]

        def options(name, values):
            opts = "".join('<option value="%s">%s</option>' % (esc(v), esc(t)) for v, t in values)
            return ('<label>%s <select data-filter="%s"><option value="">all</option>%s</select></label>'
                    % (name, name, opts))
        return "".join([
            '<label>search <input type="search" id="ledger-q" placeholder="id, Proposition 5.1, words">'
            '</label>',
            options("verdict", [(v, v) for v, _ in self.st.counts()]),
            options("statement", [(lab, self.st.name(lab)) for lab in stmts]),
            options("method", [(m, m) for m in methods]) if methods else "",
            options("test", [(d, d) for d in ("within", "at most", "at least")]) if has_test else ""])

    def ledger_row(self, c):
        labs = self.claim_labels.get(c["id"], [])
        fig = self.claim_figure(c["id"])
        stmts = self.st.of_claim[c["id"]]
        search = " ".join([c["id"], c["paper_ref"], c["quantity"]] + [self.st.name(lab) for lab in stmts])
        data = {"verdict": c["verdict"], "statement": " ".join(stmts),
                "method": self.claim_method(c["id"]) or "",
                "test": self.direction(c), "search": search.lower()}
        cells = [('cid', esc(c["id"])), ('', self.published_ref(c["paper_ref"])),
                 ('', link_labels(esc(c["quantity"]), self.labels))]
        cells += [('num', esc(c.get(k) or "")) for k in ("measured", "expected", "tolerance", "test")]
        cells += [('v-' + c["verdict"].replace(" ", "-"), esc(c["verdict"])), ('', self.source_link(c)),
                  ('', " ".join('<a class="label" href="equations.html#eq-%s">(%s)</a>' % (esc(lb), esc(lb))
                                for lb in labs) or "&ndash;"),
                  ('', '<a href="figures.html#fig-%s">%s</a>' % (esc(fig), esc(fig)) if fig else "&ndash;")]
        return '<tr id="claim-%s" %s>%s</tr>' % (
            esc(c["id"]), " ".join('data-%s="%s"' % (k, esc(v)) for k, v in data.items()),
            "".join('<td class="%s">%s</td>' % (cls, v) if cls else "<td>%s</td>" % v for cls, v in cells))

    def ledger_page(self):
        has_test = any("test" in c for c in self.claims)
        heads = ("claim", "paper", "quantity", "measured", "expected", "tolerance", "test", "verdict", "code",
                 "equation", "figure")
        out = ["<main class='text wide-page'><h1>The claims ledger</h1>",
               "<p class='note'>build/claims.tsv, one row per claim, as the claims program wrote it. The "
               "paper "
               "column gives the paper's own numbering; <i>test</i> is how the line is checked (x the "
               "measured "
               "value); <i>code</i> links to the line of test code that records it. Click a column head to "
               "sort.%s</p>" % ("" if has_test else " (This claims.tsv has no test and source columns yet.)"),
               "<form class='filters' onsubmit='return false'>%s <span id='ledger-count'></span></form>"
               % self.ledger_filters(has_test),
               "<div class='wide'><table class='ledger' id='ledger'><thead><tr>%s</tr></thead><tbody>"
               % "".join("<th>%s</th>" % h for h in heads)]
        out += [self.ledger_row(c) for c in self.claims]
        out.append("</tbody></table></div></main>")
        self.write_page("ledger.html", "Claims ledger", "ledger", "\n".join(out), ["ledger.js"])

    def write_page(self, name, title, here, body, scripts=()):
        write(os.path.join(self.out, name), page(title, here, body, scripts))

    def figure_program(self, name):
        """(source file, command) that draws figures/NAME.png."""
        if os.path.exists("src/prog/figure_%s.c" % name):
            return "src/prog/figure_%s.c" % name, "make figures/%s.pdf   # runs build/figure_%s figures data" % (name, name)
        for f in sorted(glob.glob("src/*/*.c")):
            with open(f, encoding="utf-8", errors="replace") as fh:
                text = fh.read()
            if re.search(r'"%%s/%s(\.png)?"' % re.escape(name), text):
                prog = os.path.basename(f)[:-2]
                target = {"bench": "make bench", "animation": "make animation"}.get(prog, "make %s" % prog)
                return f, "%s   # runs build/%s" % (target, prog)
        return None, None

    def figures_page(self):
        os.makedirs(os.path.join(self.out, "figures"), exist_ok=True)
        os.makedirs(os.path.join(self.out, "data"), exist_ok=True)
        out = ["<main class='text'><h1>Figures</h1><p class='note'>Each figure as drawn by its program, the caption "
               "file the program writes beside it (what exactly was run), the command that draws it again, and "
               "the numbers behind it.</p>"]
        def beside(name, ext, prog):
            """figures/NAME.EXT, else that of the name's stem (attitude_filmstrip -> attitude),
            else that of the program (bench -> data/bench.csv)."""
            stems = [name] + ["_".join(name.split("_")[:i]) for i in range(name.count("_"), 0, -1)]
            if prog:
                stems.append(os.path.basename(prog)[:-2])
            d = "figures" if ext == "txt" else "data"
            for s in stems:
                if os.path.exists("%s/%s.%s" % (d, s, ext)):
                    return "%s/%s.%s" % (d, s, ext)
            return None
        # the paper's figures first, then the others by name
        for name in sorted(self.figures, key=lambda n: (not re.match(r"fig\d", n), n)):
            shutil.copyfile("figures/%s.png" % name, os.path.join(self.out, "figures", name + ".png"))
            prog, cmd = self.figure_program(name)
            cap = beside(name, "txt", prog) or "figures/%s.txt" % name
            caption = ('<pre class="caption">%s</pre>' % link_labels(esc(open(cap, encoding="utf-8").read().strip()), self.labels)
                       if os.path.exists(cap) else
                       "<p class='note'>The committed preview. Its caption and data are written by the "
                       "command "
                       "below, which takes minutes and is not part of make web.</p>")
            csvf = beside(name, "csv", prog)
            if csvf:
                shutil.copyfile(csvf, os.path.join(self.out, csvf))
                data = '<a class="csv" href="%s">%s</a>' % (esc(csvf), esc(csvf))
            else:
                data = "written by the command above"
            claims = [c for c in self.claims if self.claim_figure(c["id"]) == name]
            out.append('<div class="fig" id="fig-%s"><h2>%s</h2>%s'
                       '<p>Drawn by: %s<br>Again: <code class="cmd">%s</code><br>Data: %s</p>%s<img src="figures/%s.png" alt="figure %s"></div>'
                       % (esc(name), esc(name), caption,
                          '<a href="%s">%s</a>' % (page_of(prog), esc(prog)) if prog else "(no program found)",
                          esc(cmd or "make figures"), data,
                          ("<p>Ledger lines: %s</p>" % ", ".join('<a href="ledger.html#claim-%s">%s</a>' % (esc(c["id"]), esc(c["id"]))
                                                                for c in claims)) if claims else "",
                          esc(name), esc(name)))
        out.append("</main>")
        write(os.path.join(self.out, "figures.html"), page("Figures", "figures", "\n".join(out)))

    def index_page(self):
        def first_sentence(f):
            secs = self.sections[f]
            if secs and secs[0].comment:
                t = " ".join(secs[0].comment[0].split())
                return t if len(t) <= 160 else t[:160].rsplit(" ", 1)[0] + " \u2026"
            return ""
        groups = [("The library and the programs (src/)", [f for f in self.files if f.startswith("src/")]),
                  ("Tests and the claims ledger (tests/)", [f for f in self.files if f.startswith("tests/")])]
        out = ["<main class='text'><h1>The Suslov companion</h1>",
               "<p>A reproduction of Jim&eacute;nez &amp; Scheurle, <i>On some aspects of the discretization "
               "of "
               "the Suslov problem</i> (J. Geom. Mech. 2018): every statement we could test is measured by a "
               "line "
               "of the claims ledger, and the integrators <a href='live-fig2.html'>run again in this "
               "browser</a> "
               "(Figure 2 at your own &epsilon;, <a href='live-convergence.html'>orders</a>, "
               "<a href='live-work.html'>work and precision</a>, <a href='live-attitude.html'>the attitude</a>)."
               "</p>",
               self.argument.summary_html(),
               "<h2 id='source'>The annotated source</h2><p>The C source of the reproducible companion to "
               "Jim&eacute;nez &amp; Scheurle, <i>On some aspects of "
               "the discretization of the Suslov problem</i>, laid out for reading beside the paper: on each source page "
               "the comments are on the left and the code on the right, section by section. Every "
               "<a class='label' href='equations.html#eq-taudyn'>(label)</a> links to the equation it cites; function "
               "names link to their definitions.</p><ul><li><a href='equations.html'>Equations</a>: each implemented label "
               "with the paper's number, our restatement, the code, the tests and the ledger lines.</li>"
               "<li><a href='ledger.html'>Claims ledger</a>: every measured claim with its verdict.</li>"
               "<li><a href='figures.html'>Figures</a>: each figure, its caption, the command and its data.</li></ul>"]
        for title, files in groups:
            out.append("<h2>%s</h2><ul class='files'>" % title)
            for f in files:
                out.append('<li><a href="%s">%s</a><div class="desc">%s</div></li>' % (page_of(f), esc(f),
                                                                                     esc(first_sentence(f))))
            out.append("</ul>")
        out.append("</main>")
        self.write_page("index.html", "Suslov companion", "index", "\n".join(out))

    def search_index(self):
        """search_index.js: every page, statement, ledger line, equation and function, for the
        site-wide search box (site.js); a script, not JSON, so that it loads from disk."""
        items = [[self.st.name(lab) + " " + lab, argument_pages.stmt_page(lab)] for lab in self.st.order]
        items += [["%s %s %s" % (c["id"], c["paper_ref"], " ".join(map(self.st.name, self.st.of_claim[c["id"]]))),
                   "ledger.html#claim-" + c["id"]] for c in self.claims]
        items += [["(%s) %s" % (lab, published(*self.labels[lab])), "equations.html#eq-" + lab]
                  for lab in self.declared if lab in self.labels]
        items += [[f, page_of(f)] for f in self.files]
        items += [["%s() %s" % (name, f), "%s#fn-%s" % (page_of(f), name)]
                  for name, places in sorted(self.defs.items()) for f, _ in places[:1]]
        items += [[t, h] for h, t in NAV] + [["Errata", "errata.html"], ["Not tested", "not-tested.html"]]
        write(os.path.join(self.out, "search_index.js"),
              "window.SEARCH_INDEX = %s;\n" % json.dumps(items, separators=(",", ":")))

    def copy_scripts(self):
        """The site's own scripts and, as a script (a page opened from disk may not fetch), the
        WebAssembly module of the integrators."""
        for f in glob.glob(os.path.join(HERE, "js", "*.js")):
            shutil.copyfile(f, os.path.join(self.out, os.path.basename(f)))
        if self.wasm:
            with open(self.wasm, "rb") as f:
                data = base64.b64encode(f.read()).decode("ascii")
            write(os.path.join(self.out, "suslov_wasm.js"), "window.SUSLOV_WASM = '%s';\n" % data)

    def build(self):
        os.makedirs(self.out, exist_ok=True)
        kdst = os.path.join(self.out, "katex")
        if os.path.exists(kdst):
            shutil.rmtree(kdst)
        os.makedirs(os.path.join(kdst, "contrib"))
        for f in ("katex.min.css", "katex.min.js"):
            shutil.copyfile(os.path.join(KATEX, f), os.path.join(kdst, f))
        shutil.copyfile(os.path.join(KATEX, "contrib", "auto-render.min.js"),
                        os.path.join(kdst, "contrib", "auto-render.min.js"))
        shutil.copytree(os.path.join(KATEX, "fonts"), os.path.join(kdst, "fonts"))
        with open(os.path.join(HERE, "style.css"), encoding="utf-8") as f:
            write(os.path.join(self.out, "style.css"), f.read() + PYG_CSS)
        for old in glob.glob(os.path.join(self.out, "*.html")):
            os.remove(old)      # a page of a file that no longer exists must not survive
        for f in self.files:
            self.source_page(f)
        self.copy_scripts()
        self.argument = argument_pages.ArgumentPages(self, self.st)
        self.argument.build()
        live_pages.build(self)
        self.ledger_page()
        self.figures_page()
        self.equations_page()   # after the pages that link to it: it has an entry for each label they cite
        self.search_index()
        self.index_page()       # last: make takes index.html as the whole site's time stamp


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--claims", required=True)
    ap.add_argument("--labels", default="paper/labels.tsv")
    ap.add_argument("--paper", default=None)
    ap.add_argument("--equations", default="paper/equations.txt")
    ap.add_argument("--paper-dir", default="paper", help="findings.tsv, errata.tsv, not_tested.tsv")
    ap.add_argument("--methods", default=None, help="build/methods.tsv (default: beside --claims)")
    ap.add_argument("--wasm", default=None, help="the integrators compiled to WebAssembly (make wasm)")
    args = ap.parse_args()
    if args.methods is None:
        args.methods = os.path.join(os.path.dirname(args.claims), "methods.tsv")
    if not os.path.isdir(KATEX):
        sys.exit("web: %s is missing: run make web-deps" % KATEX)
    Site(args).build()


if __name__ == "__main__":
    main()
