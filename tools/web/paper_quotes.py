"""The paper's own words, cut from its LaTeX source at build time (nothing of the paper is stored in
the project): each statement (definition, proposition, theorem, corollary, remark, algorithm) and
each figure's caption, found by the number the paper prints (the counters eqnumbers.Numberer
replays, the same as paper/labels.tsv's), the display that holds each equation label, and the
macros of the preamble, for KaTeX."""
import json
import re

import eqnumbers
import latex_html

DISPLAY_RE = re.compile(r"\\begin\{(equation|align|eqnarray|gather|multline|subequations)(\*?)\}")
NEWCOMMAND_RE = re.compile(r"\\(?:re)?newcommand\*?\{?(\\[A-Za-z]+)\}?(?:\[(\d)\])?\{")
# What KaTeX lacks, said in what it has.
KATEX_MISSING = {"\\mbox": "\\text", "\\mathds": "\\mathbb"}


class Quotes:
    def __init__(self, text, converter):
        self.conv = converter
        n = eqnumbers.Numberer(text)
        n.run()
        self.blocks = {}        # (kind, number) -> (LaTeX, first line, [headings of nested blocks])
        for kind, number, body, line in n.blocks:
            self.blocks[(kind, number)] = (body, line, self.nested_heads(n.blocks, body, line))
        self.body = n.body
        self.displays = self.find_displays(n.body)
        self.macros = self.preamble_macros(text[:max(text.find("\\begin{document}"), 0)])

    @staticmethod
    def nested_heads(blocks, body, line):
        """The headings of the statements inside this one (Algorithm 5.4 inside Remark 5.3)."""
        last = line + body.count("\n")
        return ["%s %s" % (k.capitalize(), num) for k, num, b, ln in blocks if line < ln <= last]

    @staticmethod
    def find_displays(body):
        """label -> the display environment (its whole LaTeX) that holds the label."""
        out, i = {}, 0
        while True:
            m = DISPLAY_RE.search(body, i)
            if not m:
                return out
            env = m.group(1) + m.group(2)
            _, end = latex_html.find_end(body, m.end(), env)
            block = body[m.start():end]
            for lab in re.findall(r"\\label\{([^}]*)\}", block):
                out.setdefault(lab.strip(), block)
            i = end

    @staticmethod
    def preamble_macros(preamble):
        """\\newcommand{\\name}[n]{body} of the preamble -> {"\\name": "body"} (KaTeX's #1 is
        LaTeX's), with what KaTeX lacks added."""
        out = dict(KATEX_MISSING)
        for m in NEWCOMMAND_RE.finditer(preamble):
            end = latex_html.balanced(preamble, m.end() - 1)
            out[m.group(1)] = preamble[m.end():end - 1].strip()
        return out

    def macros_js(self):
        return "window.PAPER_MACROS = %s;\n" % json.dumps(self.macros, sort_keys=True)

    def statement(self, kind, number):
        """(HTML of the statement's body, its first line in the source), or None."""
        got = self.blocks.get((kind, number))
        if not got:
            return None
        body, line, heads = got
        if kind == "figure":
            i = body.find("\\caption")
            if i < 0:
                return None
            body, _ = latex_html.arg(body, i + len("\\caption"))
        self.conv.nested = list(heads)
        return self.conv.block(body), line

    def display(self, label):
        """The display that holds an equation label, as printed, or None."""
        block = self.displays.get(label)
        if block is None:
            return None
        return '<div class="quote">%s</div>' % self.conv.block(block)
