#!/usr/bin/env python3
"""make mutants-ops: a generated operator-mutation campaign over the library.

Mutants are made mechanically from the C tokens of the library files (comments, strings, character
constants and preprocessor lines are skipped):
  lit*    every floating literal scaled by 1 + 1e-6 and by 2
  +/-     every binary + <-> - (and += <-> -=)
  * /     every binary * <-> / (and *= <-> /=)
  [i+-1]  every array index i -> i + 1 and i - 1 (not in declarations)
  cmp     every comparison negated: < >=, > <=, <= >, >= <, == !=
A token-level heuristic cannot always tell a binary operator from a unary one or a pointer
declarator; a mutant that does not compile is counted as did-not-build, never as killed.

Each mutant is applied to a scratch copy of the tree (as tools/mutants.sh does). First the mutated
file is compiled alone with -g0 and its object compared with the unmutated one: identical machine
code is a proof of equivalence (reason "same object code"). Otherwise the copy is rebuilt
incrementally and the tests run in fast-fail order (unit tests, the CLI value tests, the claims
ledger, then the slow CLI interface tests, which see the numbers least); the
first test that fails beyond the unmutated tree's own failures kills the mutant. Mutants listed in
tests/build/mutants_equivalent (with a proof) count as equivalent when they survive.

Usage: mutants_ops.py [--sample N --seed S] [--files F ...] [--out FILE] [--list]
Last line: "mutants-ops: generated N, killed K, equivalent E, survived S, did-not-build B, score X".
Exit status 1 when a mutant survives unexplained.
"""
import argparse
import glob
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

LAYERS = ("util", "core", "methods", "exp", "render", "prog")  # src/ folders, lowest first
# The library files in priority order (the campaign may be cut short: the first ones matter most).
FILES = ["src/core/model.c", "src/core/model.h", "src/core/so3.c", "src/core/quaternion.c",
         "src/core/reconstruct.c", "src/core/exact.c", "src/core/refattitude.c",
         "src/methods/step_euler.c", "src/methods/step_midpoint.c", "src/methods/step_variational.c",
         "src/methods/step_rk4.c", "src/methods/step_composition.c", "src/methods/composition.c",
         "src/methods/composition_coeffs.c", "src/methods/step_taylor.c", "src/methods/taylor.h",
         "src/core/driver.c"]

TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<string>"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*')
  | (?P<number>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fFlLuU]*)
  | (?P<ident>[A-Za-z_]\w*)
  | (?P<op>\+\+|--|->|<<=|>>=|<<|>>|<=|>=|==|!=|&&|\|\||[-+*/%&|^!=<>]=?|[?:;,.()\[\]{}~#])
""", re.S | re.X)

TYPES = {"void", "char", "short", "int", "long", "float", "double", "signed", "unsigned", "const",
         "static", "struct", "union", "enum", "volatile", "register", "inline", "extern", "size_t",
         "typedef", "restrict", "_Bool", "v2d"}
KEYWORDS = TYPES | {"return", "if", "else", "for", "while", "do", "switch", "case", "sizeof", "goto",
                    "break", "continue", "default"}
NEGATE = {"<": ">=", ">": "<=", "<=": ">", ">=": "<", "==": "!=", "!=": "=="}
SWAP = {"+": "-", "-": "+", "*": "/", "/": "*", "+=": "-=", "-=": "+=", "*=": "/=", "/=": "*="}


def tokens(text):
    """The C tokens of text as (kind, value, offset), preprocessor lines and comments dropped."""
    out, pos, line_start = [], 0, True
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:
            pos += 1
            continue
        kind, val = m.lastgroup, m.group()
        if kind == "op" and val == "#" and line_start:
            end = pos
            while True:  # a directive runs to an unescaped newline
                end = text.find("\n", end)
                if end < 0 or text[end - 1] != "\\":
                    break
                end += 1
            pos = len(text) if end < 0 else end
            continue
        if kind not in ("ws", "comment"):
            out.append((kind, val, pos))
        line_start = (kind == "ws" and "\n" in val) or (line_start and kind in ("ws", "comment"))
        pos = m.end()
    return out


def typedef_names(paths):
    """Type names declared by typedef in the headers (so that `sus_model *m` is no product)."""
    names = set()
    for p in paths:
        toks = tokens(open(p).read())
        for i, (k, v, _) in enumerate(toks):
            if v == "typedef":
                depth, j = 0, i + 1
                while j < len(toks) and not (toks[j][1] == ";" and depth == 0):
                    depth += toks[j][1] == "{"
                    depth -= toks[j][1] == "}"
                    j += 1
                idents = [t for t in toks[i:j] if t[0] == "ident"]
                if idents:
                    names.add(idents[-1][1])
    return names


def is_operand_end(tok, types):
    kind, val, _ = tok
    return kind == "number" or val in (")", "]") or (kind == "ident" and val not in KEYWORDS | types)


def scaled(lit, factor):
    """A floating literal times factor (0.0 has no such mutant: the generator skips it)."""
    return repr(float(re.match(r"[0-9.eE+-]+", lit).group()) * factor)


def index_mutants(toks, i, types):
    """[expr] -> [expr + 1], [expr - 1] where expr is an index in an expression, not a declarator."""
    j, depth = i + 1, 0
    while j < len(toks) and not (toks[j][1] == "]" and depth == 0):
        depth += toks[j][1] in "([{"
        depth -= toks[j][1] in ")}" or (toks[j][1] == "]")
        j += 1
    if j >= len(toks) or j == i + 1:
        return None
    k = i - 1  # a declaration: the statement starts with a type word before any '='
    while k >= 0 and toks[k][1] not in (";", "{", "}", "=", "(", ","):
        k -= 1
    stmt = toks[k + 1:i]
    if stmt and (stmt[0][1] in TYPES or stmt[0][1] in types) and not any(t[1] == "=" for t in stmt):
        if toks[k][1] != "(" or any(t[1] in TYPES or t[1] in types for t in stmt):
            return None
    return toks[j][2]


def generate(path, types):
    """Every mutant of one file: (path, offset, length, replacement, kind)."""
    text = open(path).read()
    toks = tokens(text)
    out = []
    for i, (kind, val, off) in enumerate(toks):
        prev = toks[i - 1] if i else ("op", ";", 0)
        floating = kind == "number" and re.search(r"[.eE]", val)
        if floating and float(re.match(r"[0-9.eE+-]+", val).group()) != 0:
            out.append((path, off, len(val), scaled(val, 1 + 1e-6), "lit*(1+1e-6)"))
            out.append((path, off, len(val), scaled(val, 2), "lit*2"))
        elif val in SWAP and val in ("+=", "-=", "*=", "/="):
            out.append((path, off, len(val), SWAP[val], "op" + val))
        elif val in SWAP and is_operand_end(prev, types):
            out.append((path, off, len(val), SWAP[val], "op" + val))
        elif val in NEGATE and is_operand_end(prev, types):
            out.append((path, off, len(val), NEGATE[val], "cmp"))
        elif val == "[" and prev[0] == "ident" or (val == "[" and prev[1] in (")", "]")):
            end = index_mutants(toks, i, types)
            if end is not None:
                out.append((path, end, 0, " + 1", "index+1"))
                out.append((path, end, 0, " - 1", "index-1"))
    return out


def describe(mut, text):
    path, off, length, rep, kind = mut
    line = text.count("\n", 0, off) + 1
    start = text.rfind("\n", 0, off) + 1
    end = text.find("\n", off)
    orig = text[start:end].strip()
    new = (text[start:off] + rep + text[off + length:end]).strip()
    return line, orig, new


def load_equivalents(path):
    """tests/build/mutants_equivalent: FILE | original line | mutated line | proof (one line each)."""
    eq = {}
    if os.path.exists(path):
        for raw in open(path):
            if raw.strip() and not raw.lstrip().startswith("#"):
                f = raw.rstrip("\n").split(" | ")
                if len(f) == 4 and f[3].strip():
                    eq[(f[0], f[1], f[2])] = f[3]
    return eq


class Scratch:
    """A scratch copy of the tree, built once; then one incremental rebuild per mutant."""

    def __init__(self, root):
        self.dir = tempfile.mkdtemp(prefix="mutops.")
        for d in ("src", "tests", "tools", "paper"):
            shutil.copytree(os.path.join(root, d), os.path.join(self.dir, d))
        shutil.copy(os.path.join(root, "Makefile"), self.dir)
        os.makedirs(os.path.join(self.dir, "data"), exist_ok=True)
        os.makedirs(os.path.join(self.dir, "figures"), exist_ok=True)
        cfg = os.path.join(root, "data", "animation.cfg")
        if os.path.exists(cfg):
            shutil.copy(cfg, os.path.join(self.dir, "data"))
        self.env = {k: v for k, v in os.environ.items()
                    if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "SAN", "BUILD")}
        self.b = "build/mut"
        pkg = ["pkg-config", "--cflags", "gsl", "cairo", "osmesa"]
        self.cflags = ["-std=c17", "-O2", "-g0"] + ["-Isrc/" + d for d in LAYERS] + \
            subprocess.run(pkg, capture_output=True, text=True).stdout.split()
        self.tests = []

    def sh(self, args, timeout=None):
        return subprocess.run(args, cwd=self.dir, env=self.env, capture_output=True, text=True,
                              timeout=timeout)

    def targets(self):
        unit_dir = os.path.join(self.dir, "tests", "unit")
        units = sorted("%s/test_%s" % (self.b, f[5:-2]) for f in os.listdir(unit_dir)
                       if f.startswith("test_") and f.endswith(".c"))
        return units + ["%s/suslov" % self.b, "%s/animation" % self.b, "%s/claims" % self.b]

    def build(self, targets=None):
        targets = self.targets() if targets is None else targets
        return self.sh(["make", "-s", "BUILD=" + self.b, "-j2"] + targets).returncode == 0

    def object(self, src):
        """The -g0 object code of a source file, b"" for a header (its includers are many: a
        header's mutants go straight to the build), None when it does not compile."""
        if not src.endswith(".c"):
            return b""
        obj = os.path.join(self.dir, "g0.o")
        if self.sh(["cc"] + self.cflags + ["-c", src, "-o", obj]).returncode != 0:
            return None
        with open(obj, "rb") as f:
            return f.read()

    def setup_tests(self):
        """The test commands, quick unit tests first; each with a timeout from its own run time."""
        # test_mutant_kills first: it checks the formulas directly, in milliseconds
        units = sorted(([os.path.basename(t), [t], [t]] for t in self.targets() if "/test_" in t),
                       key=lambda u: (u[0] != "test_mutant_kills", u[0]))
        b = self.b
        cmds = units + [("test_cli_values", ["sh", "tests/cli/test_cli_values.sh", b], [b + "/suslov"]),
                        ("claims", [b + "/claims", b + "/claims.tsv"], [b + "/claims"]),
                        ("test_cli", ["sh", "tests/cli/test_cli.sh", b], [b + "/suslov", b + "/animation"])]
        for name, cmd, needs in cmds:
            t0 = time.time()
            r = self.sh(cmd, timeout=1800)
            secs = time.time() - t0
            base = signature(r.stdout + r.stderr) if r.returncode else None
            self.tests.append((name, cmd, needs, 30 + 5 * secs, base))
            print("mutants-ops: baseline %s %.1f s%s" % (name, secs, "" if base is None else " (FAILS)"),
                  flush=True)

    def run_tests(self):
        """The first test that fails beyond the baseline, or None; "" when a program does not link.
        Each test's programs are relinked just before it runs, so that a mutant a unit test kills
        costs one link, not all of them."""
        for name, cmd, needs, secs, base in self.tests:
            if not self.build(needs):
                return ""
            try:
                r = self.sh(cmd, timeout=secs)
            except subprocess.TimeoutExpired:
                return name + " (timeout)"
            if r.returncode == 0:
                continue
            sig = signature(r.stdout + r.stderr)
            new = sig - base if base is not None else sig
            if base is None or new or not sig:
                first = sorted(new)[0][:60] if new else "exit status %d" % r.returncode
                return "%s (%s)" % (name, first)
        return None


def signature(log):
    """A failing test's FAIL lines without their numbers (as tools/mutants.sh)."""
    return {re.sub(r"[0-9]", "", l[4:].strip()) for l in log.splitlines() if l.startswith("FAIL")}


def run_one(sc, mut, texts, ref_objs, eq):
    path, off, length, rep, kind = mut
    text = texts[path]
    line, orig, new = describe(mut, text)
    label = "%s:%d %s: %s  ->  %s" % (path, line, kind, orig, new)
    target = os.path.join(sc.dir, path)
    with open(target, "w") as f:
        f.write(text[:off] + rep + text[off + length:])
    try:
        obj = sc.object(path)
        if obj is None:
            return "did-not-build", label, "does not compile"
        if obj and obj == ref_objs[path]:
            return "equivalent", label, "same object code (cc -O2 -g0)"
        killer = sc.run_tests()
        if killer == "":
            return "did-not-build", label, "does not link"
        if killer:
            return "killed", label, killer
        proof = eq.get((path, orig, new))
        return ("equivalent", label, proof) if proof else ("survived", label, "")
    finally:
        with open(target, "w") as f:  # a new mtime: the next build recompiles what changed
            f.write(text)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--files", nargs="*", default=FILES)
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--seed", type=int, default=20261123)
    ap.add_argument("--out", default="")
    ap.add_argument("--first", type=int, default=1, help="start at this mutant (1-based): resume a run")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--equivalent", default="tests/build/mutants_equivalent")
    a = ap.parse_args()
    types = typedef_names(sorted(glob.glob("src/*/*.h") + glob.glob("src/*/*.c")))
    texts = {p: open(p).read() for p in a.files}
    muts = [m for p in a.files for m in generate(p, types)]
    if a.sample and a.sample < len(muts):
        pick = sorted(random.Random(a.seed).sample(range(len(muts)), a.sample))
        muts = [muts[i] for i in pick]
    muts = muts[a.first - 1:]
    if a.list:
        for m in muts:
            line, orig, new = describe(m, texts[m[0]])
            print("%s:%d %s: %s  ->  %s" % (m[0], line, m[4], orig, new))
        print("mutants-ops: %d mutants" % len(muts))
        return 0
    eq = load_equivalents(a.equivalent)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # so that the scratch copy goes too
    sc = Scratch(os.getcwd())
    try:
        return campaign(a, sc, muts, texts, eq)
    finally:
        shutil.rmtree(sc.dir, ignore_errors=True)


def campaign(a, sc, muts, texts, eq):
    print("mutants-ops: %d mutants over %s; building the scratch copy in %s"
          % (len(muts), " ".join(a.files), sc.dir), flush=True)
    if not sc.build():
        print("mutants-ops: the unmutated tree does not build")
        return 2
    sc.setup_tests()
    ref = {p: sc.object(p) for p in a.files}
    counts = {"killed": 0, "equivalent": 0, "survived": 0, "did-not-build": 0}
    lines, t0 = [], time.time()
    for n, m in enumerate(muts, 1):
        verdict, label, why = run_one(sc, m, texts, ref, eq)
        counts[verdict] += 1
        lines.append("%-13s %s%s" % (verdict.upper(), label, "  [%s]" % why if why else ""))
        print("%d/%d %s" % (n, len(muts), lines[-1]), flush=True)
        if a.out and n % 5 == 0:
            write_result(a, counts, lines, time.time() - t0, n, len(muts))
    summary = write_result(a, counts, lines, time.time() - t0, len(muts), len(muts))
    print(summary)
    return 1 if counts["survived"] else 0


def write_result(a, c, lines, secs, done, total):
    live = len(lines) - c["equivalent"] - c["did-not-build"]
    score = "%.4f" % (c["killed"] / live) if live else "n/a"
    summary = ("mutants-ops: generated %d, killed %d, equivalent %d, survived %d, did-not-build %d, score %s"
               % (len(lines), c["killed"], c["equivalent"], c["survived"], c["did-not-build"], score))
    if a.out:
        commit = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True).stdout.strip()
        head = ["# make mutants-ops (tools/mutants_ops.py): the generated operator-mutation campaign",
                "# commit %s, %s UTC, %.0f s for %d of %d mutants%s" % (
                    commit or "unknown", time.strftime("%Y-%m-%d %H:%M", time.gmtime()), secs, done, total,
                    "" if done == total else " (INCOMPLETE: cut short)"),
                "# files: " + " ".join(a.files),
                "# sample: %s" % ("all" if not a.sample else "%d, seed %d" % (a.sample, a.seed)),
                summary, ""]
        tmp = a.out + ".tmp"
        with open(tmp, "w") as f:
            f.write("\n".join(head + lines) + "\n")
        os.replace(tmp, a.out)
    return summary


if __name__ == "__main__":
    sys.exit(main())
