#!/usr/bin/env python3
"""Label -> published number table for the paper (Jimenez & Scheurle, J. Geom. Mech. 2018).

Usage: paper_labels.py PAPER.tex > paper/labels.tsv

Run once by hand; its output is stored as paper/labels.tsv (columns: label, kind, number,
section) and read by the companion (tools/paper.sh) and the web edition. It replays LaTeX's
counters over the source as amsart numbers it: \\section/\\subsection (not starred);
equations numbered globally (amsart without \\numberwithin), one number per equation and per
subequations group, whose align lines get a, b, ...; propositions per section; definition,
remark, theorem, algorithm and corollary sharing one counter per section (the \\newtheorem
lines of the source); figures globally. Numbered items without a \\label get the label
"nolabel:KIND-NUMBER" so that they can be cited too (e.g. the proposition on general DSPs).
Labels are stored without surrounding blanks (the source writes \label{ DSP}); the section
column is "Appendix" after the unnumbered appendix heading.
The numbers are counted from the arXiv source; the PUBLISHED sample below (the numbers the
companion's findings cite, as a list supplied for the published article gave them; the article
itself was not consulted) is asserted at the end (check_published), so a miscount fails loudly.
make paper re-runs this script on the source when the file is at hand (tools/paper.sh).
"""
import re
import sys

THEOREMS = {"proposition": "proposition", "definition": "definition", "remark": "definition",
            "theorem": "definition", "algorithm": "definition", "corollary": "definition"}

# Numbers of the published version (J. Geom. Mech. 10(1), 2018), as a list supplied for it gave them.
PUBLISHED = {"PropoCons1": "4.1", "TeoL": "5.1", "nolabel:proposition-5.2": "5.2",
             "PropoFinal": "5.3", "RemarkLambda": "5.5", "MetMat": "22", "ContDyn": "27",
             "LagMult": "28", "VSO3": "35", "cayinver": "36", "taudyn": "37", "taualg": "38",
             "CaySO3": "5.1", "Consistenci": "5.3", "dreps": "5.4", "GeneralDisc": "5.5",
             "nolabel:subsection-5.6": "5.6", "Fig1": "1", "Fig2": "2"}


def strip_comments(text):
    return "\n".join(re.sub(r"(?<!\\)%.*", "", line) for line in text.split("\n"))


def main(path):
    src = strip_comments(open(path, encoding="utf-8").read())
    src = src[src.index("\\begin{document}"):] if "\\begin{document}" in src else src
    token = re.compile(r"\\(section|subsection|subsubsection)(\*?)\s*(?:\[[^\]]*\])?\{"
                       r"|\\begin\{([A-Za-z]+\*?)\}|\\end\{([A-Za-z]+\*?)\}"
                       r"|\\label\{([^}]*)\}|(\\\\)|\\(nonumber|notag)\b")
    sec = [0, 0, 0]
    eq = 0
    fig = 0
    thm = {"proposition": 0, "definition": 0}
    stack = []          # open numbered environments: dicts with kind, number, label
    rows = []
    pending = None      # the last sectioning command, waiting for its \label
    sub = None          # inside subequations: [parent number, next letter index]
    appendix = False    # after the unnumbered \section*{Appendix: ...}

    def section_str():
        if appendix:
            return "Appendix"
        s = [str(x) for x in sec]
        while len(s) > 1 and s[-1] == "0":
            s.pop()
        return ".".join(s)

    def add(label, kind, number):
        rows.append((label, kind, number, section_str()))

    def close(item):
        if item is not None and item.get("number") and not item.get("labelled") and not item.get("silent"):
            add("nolabel:%s-%s" % (item["kind"], item["number"]), item["kind"], item["number"])

    def align_line(env):
        nonlocal eq
        if sub is not None:
            n = "%d%s" % (sub[0], "abcdefghijklmnop"[sub[1]])
            sub[1] += 1
        else:
            eq += 1
            n = str(eq)
        env["number"], env["labelled"] = n, False

    for m in token.finditer(src):
        cmd, star, begin, end, label, newline, nonum = m.groups()
        if cmd:
            close(pending)
            pending = None
            if star:
                appendix = cmd == "section" and src[m.end():m.end() + 8] == "Appendix"
                continue
            level = ["section", "subsection", "subsubsection"].index(cmd)
            sec[level] += 1
            for i in range(level + 1, 3):
                sec[i] = 0
            if level == 0:
                thm = {"proposition": 0, "definition": 0}
            pending = {"kind": cmd, "number": section_str(), "labelled": False}
        elif begin:
            close(pending)
            pending = None
            env = {"env": begin, "kind": None, "number": None, "labelled": False}
            if begin == "equation":
                eq += 1
                env.update(kind="equation", number=str(eq))
            elif begin == "subequations":
                eq += 1
                env.update(kind="equation", number=str(eq))
                sub = [eq, 0]
            elif begin in ("align", "eqnarray", "gather"):
                env["kind"] = "subequation" if sub is not None else "equation"
                align_line(env)
            elif begin in THEOREMS:
                c = THEOREMS[begin]
                thm[c] += 1
                env.update(kind=begin, number="%d.%d" % (sec[0], thm[c]))
            elif begin == "figure":
                fig += 1
                env.update(kind="figure", number=str(fig))
            stack.append(env)
        elif end:
            while stack:
                env = stack.pop()
                if env["env"] == "subequations":
                    sub = None
                close(env)
                if env["env"] == end:
                    break
        elif label:
            target = next((e for e in reversed(stack) if e["number"]), None)
            if target is None and pending is not None:
                target = pending
            if target is None:
                print("paper_labels: \\label{%s} outside any numbered item" % label, file=sys.stderr)
                sys.exit(1)
            add(label.strip(), target["kind"], target["number"])
            target["labelled"] = True
        elif newline or nonum:
            env = stack[-1] if stack else None
            if env is None or env["env"] not in ("align", "eqnarray", "gather"):
                continue
            if nonum:
                env["silent"] = True
                if env["kind"] == "equation" and sub is None:
                    eq -= 1
                elif sub is not None:
                    sub[1] -= 1
                continue
            close(env)
            env["silent"] = False
            align_line(env)
    close(pending)
    check_published(rows)
    print("label\tkind\tnumber\tsection")
    for r in rows:
        print("\t".join(r))


def check_published(rows):
    got = {r[0]: r[2] for r in rows}
    bad = [(k, v, got.get(k)) for k, v in PUBLISHED.items() if got.get(k) != v]
    for k, want, have in bad:
        print("paper_labels: %s is %s here, %s in the published paper" % (k, have, want), file=sys.stderr)
    if bad:
        sys.exit(1)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: paper_labels.py PAPER.tex", file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1])
