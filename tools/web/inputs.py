"""What the web edition reads: the paper's numbering (paper/labels.tsv, checked against a count of
the paper's LaTeX source when that is at hand), the implemented labels and our restatements, the
claims ledger and its LaTeX form, the figure rules and the method registry's table."""
import csv
import hashlib
import os
import subprocess
import sys

import eqnumbers

HERE = os.path.dirname(os.path.abspath(__file__))


class Numbering:
    """label -> (kind, number), and where the numbers come from, in words for the pages."""

    def __init__(self, labels_tsv, paper_tex):
        self.source = paper_tex if paper_tex and os.path.exists(paper_tex) else None
        self.text = None
        if self.source:
            with open(self.source, encoding="utf-8", errors="replace") as f:
                self.text = f.read()
            with open(self.source, "rb") as f:
                self.sha256 = hashlib.sha256(f.read()).hexdigest()
        self.labels_tsv = labels_tsv if labels_tsv and os.path.exists(labels_tsv) else None
        if self.labels_tsv:
            with open(self.labels_tsv, encoding="utf-8") as f:
                rows = [(r["label"], r["kind"], r["number"])
                        for r in csv.DictReader(f, delimiter="\t")]
        elif self.text is not None:
            rows = eqnumbers.Numberer(self.text).run()
        else:
            sys.exit("web: need paper/labels.tsv or the paper's LaTeX source (--paper) for the "
                     "paper's numbers")
        self.disagree = self.recount(rows) if self.labels_tsv and self.text is not None else []
        self.labels = {}
        for label, kind, number in rows:
            label = label.strip()
            if label.startswith("nolabel:") or not label:
                continue
            kind = kind.lower()
            self.labels.setdefault(label, ("equation" if kind == "subequation" else kind, number))

    def recount(self, rows):
        """Labels whose number in labels.tsv differs from a count of the source (none expected:
        both replay LaTeX's counters over the same file)."""
        ours = {lab.strip(): num for lab, _, num in eqnumbers.Numberer(self.text).run()}
        return [(lab, num, ours[lab.strip()]) for lab, _, num in rows
                if lab.strip() in ours and ours[lab.strip()] != num]

    def provenance_html(self, esc):
        """Where the numbers come from, for the equations page."""
        base = ("The numbers are LaTeX's counters replayed over the paper's source, as amsart "
                "numbers it, by <code>tools/paper_labels.py</code> into "
                "<code>paper/labels.tsv</code>")
        if self.source and self.labels_tsv:
            check = ("this build read the source, <code>%s</code> (SHA-256 "
                     "<code class='hash'>%s</code>), counted again with "
                     "<code>tools/web/eqnumbers.py</code> and %s"
                     % (esc(os.path.basename(self.source)), self.sha256,
                        "found every number the same" if not self.disagree else
                        "found %d numbers that differ (listed by make web)" % len(self.disagree)))
        elif self.source:
            check = ("this build counted them from <code>%s</code> (SHA-256 "
                     "<code class='hash'>%s</code>)"
                     % (esc(os.path.basename(self.source)), self.sha256))
        else:
            check = ("this build did not have the source and took <code>paper/labels.tsv</code> as "
                     "it is (<code>tools/paper.sh</code> names the source file by its SHA-256)")
        return base + "; " + check + "."


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


def read_tsv(path):
    with open(path, encoding="utf-8") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def read_claims(path):
    if not os.path.exists(path):
        sys.exit("web: %s is missing (make builds it from the claims program)" % path)
    return read_tsv(path)


def read_claims_tex(path):
    """id -> {quantity, test} in LaTeX (the ledger's claims_tex.tsv), or None without the file."""
    if not os.path.exists(path):
        return None
    return {r["id"]: r for r in read_tsv(path)}


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


def read_methods(methods_tsv, wasm):
    """name -> row of build/methods.tsv (the registry's own table: name, family, source, ...).
    Without it, the names (and nothing else) from the WebAssembly module's registry."""
    if methods_tsv and os.path.exists(methods_tsv):
        return {r["name"]: r for r in read_tsv(methods_tsv)}
    if wasm and os.path.exists(wasm):
        out = subprocess.run(["node", os.path.join(HERE, "wasm_methods.js"), wasm], check=True,
                             capture_output=True, text=True).stdout
        return {n: {"name": n} for n in out.split()}
    return {}
