"""The annotated source: one page per source file in docco's layout, the comments as prose on the
left and the code on the right, section by section. Prose goes through python3-markdown, code
through pygments; function definitions are found with universal-ctags. A (label) of the paper in a
comment links to its equations-page entry, shown by the paper's number in the prose; a function
name links to its definition."""
import os
import re
import subprocess
import textwrap

import markdown
from pygments import highlight
from pygments.formatters import HtmlFormatter
from pygments.lexers import BashLexer, CLexer

from frame import esc, link_labels, page, write

WORD_RE = re.compile(r"\b([A-Za-z_][A-Za-z0-9_]*)\b")


def page_of(path):
    """src/core/so3.c -> src-core-so3.c.html: one flat directory, every link a plain file name."""
    return path.replace("/", "-") + ".html"


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
    notes = [(next((n for n in shown if n > end), shown[-1] if shown else None), text)
             for end, text in notes]
    return kept, notes


# A formula written in ASCII inside a comment (w^{k+1}, lambda_{k+1}, R_k, I_m): a short name
# with sub- or superscripts, typeset by KaTeX. A C identifier (sus_run) is not one: after a
# one-letter subscript no letter, digit or underscore may follow.
FORMULA_RE = re.compile(r"(?<![\\\w])([A-Za-z]{1,6}\d?)"
                        r"((?:[_^](?:\{[^{}\s]{1,24}\}|-?[A-Za-z0-9](?![A-Za-z0-9_])))+)(?![\w(])")
GREEK = {"lambda", "omega", "mu", "xi", "tau", "psi", "sigma", "rho", "gamma", "phi", "alpha",
         "beta", "delta", "eta"}


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
    # stripnl=False keeps blank first lines, so that the numbering holds
    lexer = BashLexer(stripnl=False) if shell else CLexer(stripnl=False)
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
                    row = row.replace(span, '<span class="%s" id="fn-%s">%s</span>'
                                      % (cls, name, name), 1)
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
    return link_labels("\n".join(rows[:len(lines)]), labels, in_code=True)


def label_box(site, lab):
    """Beside the function that implements a label: the equation as we restate it and the ledger
    lines that measure it."""
    tex, _ = site.restated.get(lab, ("", ""))
    parts = ['<div class="box"><h4>Implements %s</h4>'
             % link_labels("(%s)" % esc(lab), site.labels)]
    if tex:
        parts.append('<div class="math">\\[%s\\]</div>' % esc(tex))
    claims = site.label_claims.get(lab, [])
    if claims:
        parts.append('<div>Ledger lines that measure it:</div>' + site.claims_table(claims, 4))
    parts.append("</div>")
    return "".join(parts)


def section_html(site, f, k, s, resolve, anchors):
    shell = f.endswith(".sh")
    prose = prose_html("\n".join(s.comment), site.labels, resolve) if s.comment else ""
    code, notes = inner_comments(s.code, shell)
    for line, text in notes:
        at = '<a class="at" href="#L%d">line %d</a> ' % (line, line) if line else ""
        prose += '<div class="inner">%s%s</div>' % (at, prose_html(text, site.labels, resolve))
    for lab in site.sec_impl.get((f, k), []):
        prose += label_box(site, lab)
    end = s.code[-1][0] if s.code else s.start
    return ('<section class="sec" id="s%d"><div class="prose"><span class="secno"><a href="#s%d">'
            '&sect;%d</a> lines %d&ndash;%d</span>%s</div><div class="code"><pre>%s</pre></div>'
            '</section>'
            % (k + 1, k + 1, k + 1, s.start, end, prose,
               code_html(code, shell, site.labels, resolve, anchors)))


def source_page(site, f):
    """The page of one source file, section by section."""
    anchors = {}
    for name, places in site.defs.items():
        for pf, line in places:
            if pf == f:
                anchors.setdefault(line, []).append(name)
    resolve = site.resolver(f)
    body = [section_html(site, f, k, s, resolve, anchors) for k, s in enumerate(site.sections[f])]
    write(os.path.join(site.out, page_of(f)),
          page(f, f, "<h1 class='file'>%s</h1>\n%s" % (esc(f), "\n".join(body))))

