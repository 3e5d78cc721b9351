#!/usr/bin/python3
"""Published numbers of the paper's \\label{}s, counted from its LaTeX source.

Usage: eqnumbers.py PAPER.tex        prints: label <TAB> kind <TAB> number

The paper uses amsart with no \\numberwithin, so equations are numbered (1), (2), ... through the
whole text; a subequations block takes one number and its rows get letters (2a), (2b); every
unstarred row of align/eqnarray/gather gets a number unless it says \\nonumber or \\notag.
Theorem-like environments are numbered within the section, with the counters the paper's
\\newtheorem lines declare (read here, not assumed).
"""
import re
import sys

ROWS = {"align", "eqnarray", "gather", "flalign", "alignat"}   # one number per row
SINGLE = {"equation", "multline"}                               # one number per block
TOKEN = re.compile(r"\\(begin|end)\{([^}]*)\}|\\label\{([^}]*)\}|\\(section|subsection)(\*?)\{"
                   r"|(\\\\)|\\(nonumber|notag)(?![A-Za-z])|\\tag\{([^}]*)\}")


class Numberer:
    def __init__(self, text):
        text = re.sub(r"(?<!\\)%.*", "", text)
        self.thm = {}   # environment -> (counter, printed name)
        for m in re.finditer(r"\\newtheorem\{(\w+)\}(?:\[(\w+)\])?\{([^}]*)\}", text):
            self.thm[m.group(1)] = (m.group(2) or m.group(1), m.group(3))
        start = max(text.find("\\begin{document}"), 0)
        self.body = text[start:]
        self.offset_line = text.count("\n", 0, start)
        self.eq = self.sec = self.fig = 0
        self.counters = {}
        self.stack = []
        self.labels = []
        self.blocks = []    # (kind, number, LaTeX between \\begin and \\end, its first line)
        self.section_label = None

    def equation_number(self):
        """The next equation number, lettered inside subequations."""
        sub = [e for e in self.stack if e["env"] == "subequations"]
        if sub:
            sub[-1]["sub"] += 1
            return sub[-1]["number"] + chr(ord("a") + sub[-1]["sub"] - 1)
        self.eq += 1
        return str(self.eq)

    def close_row(self, e):
        if e["skip"]:
            number = None
        elif e["tag"] is not None:
            number = e["tag"]
        else:
            number = self.equation_number()
        for label in e["row_labels"]:
            self.labels.append((label, "equation", number or "(unnumbered)"))
        e.update(skip=False, tag=None, row_labels=[])

    def run(self):
        for m in TOKEN.finditer(self.body):
            be, env, label, sect, star, newline, nonum, tag = m.groups()
            top = self.stack[-1] if self.stack else None
            rows = top if top is not None and top.get("rows") else None
            if sect:
                if sect == "section" and not star:
                    self.sec += 1
                    self.counters = {}
                    self.section_label = ("Section", str(self.sec))
                else:
                    self.section_label = None
            elif be == "begin":
                self.begin(env)
                self.stack[-1]["at"] = m.end()
            elif be == "end":
                if self.stack:
                    e = self.stack.pop()
                    if e.get("rows"):
                        self.close_row(e)
                    self.keep_block(e, m.start())
            elif newline:
                if rows is not None:
                    self.close_row(rows)
            elif nonum:
                if rows is not None:
                    rows["skip"] = True
            elif tag is not None:
                if rows is not None:
                    rows["tag"] = tag
                elif top is not None:
                    top["number"] = tag
            elif label is not None:
                self.label(label.strip(), rows)
        return self.labels

    def keep_block(self, e, end):
        """A theorem-like environment or a figure: its text, for quoting."""
        if e["kind"] and e["kind"] != "equation" and e["number"] is not None:
            line = self.offset_line + self.body.count("\n", 0, e["at"]) + 1
            self.blocks.append((e["kind"].lower(), e["number"], self.body[e["at"]:end], line))

    def begin(self, env):
        base, starred = env.rstrip("*"), env.endswith("*")
        e = {"env": env, "number": None, "kind": None}
        if base == "subequations":
            e.update(number=self.equation_number(), kind="equation", sub=0)
        elif base in SINGLE and not starred:
            e.update(number=self.equation_number(), kind="equation")
        elif base in ROWS and not starred:
            e.update(rows=True, skip=False, tag=None, row_labels=[])
        elif env in self.thm:
            counter, printed = self.thm[env]
            self.counters[counter] = self.counters.get(counter, 0) + 1
            e.update(number="%d.%d" % (self.sec, self.counters[counter]), kind=printed)
        elif env == "figure":
            self.fig += 1
            e.update(number=str(self.fig), kind="Figure")
        self.stack.append(e)

    def label(self, label, rows):
        if rows is not None:
            rows["row_labels"].append(label)
            return
        for e in reversed(self.stack):
            if e["number"] is not None:
                self.labels.append((label, e["kind"], e["number"]))
                return
        if self.section_label:
            self.labels.append((label,) + self.section_label)


def main():
    with open(sys.argv[1], encoding="utf-8", errors="replace") as f:
        labels = Numberer(f.read()).run()
    for label, kind, number in labels:
        print("%s\t%s\t%s" % (label, kind, number))


if __name__ == "__main__":
    main()
