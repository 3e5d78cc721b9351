"""The argument of the web edition: which statement of the paper each ledger line, finding, erratum
and not-tested entry is about, and the verdict of each statement. Reads the companion's tables
(paper/findings.tsv, paper/errata.tsv, paper/not_tested.tsv) and build/claims.tsv: nothing here
restates a finding, the pages are generated from those files as the PDF is."""
import csv
import os
import re

# the kinds of labels that are statements (a page each), in the paper's order
STATEMENT_KINDS = ("definition", "proposition", "theorem", "corollary", "remark", "algorithm",
                   "figure")
# how the ledger, the findings and the errata abbreviate a statement's kind
KIND_WORDS = {"proposition": "proposition", "propositions": "proposition", "prop": "proposition",
              "theorem": "theorem", "theorems": "theorem", "theo": "theorem",
              "corollary": "corollary", "cor": "corollary", "remark": "remark",
              "definition": "definition", "def": "definition", "algorithm": "algorithm",
              "figure": "figure", "fig": "figure"}
NAMED_RE = re.compile(r"\b(%s)\.?\s*(\d+(?:\.\d+)?)(?:\s*[-\u2013]\s*(\d+(?:\.\d+)?))?"
                      % "|".join(KIND_WORDS), re.I)
VERDICT_RANK = ("not reproduced", "erratum", "reproduced", "by definition", "by construction",
                "extension", "not tested", "no ledger line")


def read_tsv(path):
    """Rows of a tab-separated table with a header row; [] when the file does not exist."""
    if not path or not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def read_aliases(path):
    """tools/web/statement_aliases.tsv: a phrase of the ledger's paper_ref -> the label it means."""
    out = []
    for r in read_tsv(path):
        out.append((r["phrase"], r["label"]))
    return out


def number_range(a, b):
    """'6.1', '6.3' -> ['6.1', '6.2', '6.3'] (same chapter); a lone number -> [a]."""
    if not b:
        return [a]
    pa, pb = a.split("."), b.split(".")
    if len(pa) == 2 and len(pb) == 2 and pa[0] == pb[0] and int(pa[1]) <= int(pb[1]):
        return ["%s.%d" % (pa[0], i) for i in range(int(pa[1]), int(pb[1]) + 1)]
    return [a, b]


def statement_labels(labels, labels_tsv):
    """The labels plus the unlabelled statements of paper/labels.tsv (nolabel:proposition-5.2),
    which have a number and a page but nothing can cite them by label."""
    out = dict(labels)
    for r in read_tsv(labels_tsv):
        if r["label"].startswith("nolabel:") and r["kind"].lower() in STATEMENT_KINDS:
            out[r["label"]] = (r["kind"].lower(), r["number"])
    order = {r["label"]: i for i, r in enumerate(read_tsv(labels_tsv))}
    return dict(sorted(out.items(), key=lambda kv: order.get(kv[0], len(order))))


class Statements:
    def __init__(self, labels, claims, paper_dir, aliases_tsv):
        self.labels = statement_labels(labels, os.path.join(paper_dir, "labels.tsv"))
        self.order = [lab for lab, (kind, _) in self.labels.items() if kind in STATEMENT_KINDS]
        self.by_name = {self.labels[lab]: lab for lab in self.order}
        self.aliases = read_aliases(aliases_tsv)
        self.findings = read_tsv(os.path.join(paper_dir, "findings.tsv"))
        self.errata = read_tsv(os.path.join(paper_dir, "errata.tsv"))
        self.not_tested = read_tsv(os.path.join(paper_dir, "not_tested.tsv"))
        self.claims = claims
        self.claim_by_id = {c["id"]: c for c in claims}
        self.of_claim = {c["id"]: self.mentioned(c["paper_ref"]) for c in claims}
        self.of_finding = {}
        for fd in self.findings:
            # the title and the ledger lines decide; a statement the summary only cites is not
            # its subject
            labs = self.mentioned(fd["title"])
            for cid in self.finding_claims(fd):
                labs += self.of_claim.get(cid, [])
            self.of_finding[fd["id"]] = list(dict.fromkeys(labs))
        self.of_erratum = {e["id"]: self.mentioned(e["location"]) for e in self.errata}

    def mentioned(self, text):
        """The statements a piece of text names: by label (TeoL), by published name
        (Proposition 5.1, Fig. 2, Theorems 6.1-6.3) or by an alias of the ledger."""
        words = [w.rstrip(":-") for w in re.findall(r"[A-Za-z][A-Za-z0-9:-]*", text)]  # "TeoL: ..."
        labs = [w for w in words if w in self.labels and self.labels[w][0] in STATEMENT_KINDS]
        for m in NAMED_RE.finditer(text):
            kind = KIND_WORDS[m.group(1).lower()]
            for num in number_range(m.group(2), m.group(3)):
                lab = self.by_name.get((kind, num))
                if lab:
                    labs.append(lab)
        labs += [lab for phrase, lab in self.aliases if phrase in text and lab in self.labels]
        return list(dict.fromkeys(labs))

    def finding_claims(self, fd):
        # space-separated ids
        return [i for i in re.split(r"[\s,]+", fd["ledger_ids"]) if i in self.claim_by_id]

    def name(self, lab):
        kind, number = self.labels[lab]
        return "%s %s" % (kind.capitalize(), number)

    def claims_of(self, lab):
        return [c for c in self.claims if lab in self.of_claim[c["id"]]]

    def findings_of(self, lab):
        return [fd for fd in self.findings if lab in self.of_finding[fd["id"]]]

    def errata_of(self, lab):
        return [e for e in self.errata if lab in self.of_erratum[e["id"]]]

    def not_tested_of(self, lab):
        return [r for r in self.not_tested if r["label"] == lab]

    def verdict(self, lab):
        """The worst verdict of its ledger lines (an extension line does not decide a statement);
        else of its findings; else extension, not tested, or no ledger line."""
        vs = [c["verdict"] for c in self.claims_of(lab) if c["verdict"] != "extension"]
        vs = vs or [fd["verdict"] for fd in self.findings_of(lab)]
        vs = vs or ["extension" for _ in self.claims_of(lab)[:1]]
        if not vs:
            vs = ["not tested"] if self.not_tested_of(lab) else ["no ledger line"]
        return min(vs, key=lambda v: VERDICT_RANK.index(v) if v in VERDICT_RANK else 0)

    def counts(self):
        """Ledger lines by verdict, in the order of VERDICT_RANK."""
        out = {}
        for c in self.claims:
            out[c["verdict"]] = out.get(c["verdict"], 0) + 1
        return sorted(out.items(),
                      key=lambda kv: VERDICT_RANK.index(kv[0]) if kv[0] in VERDICT_RANK else 9)
