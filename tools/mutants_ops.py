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

Each mutant is applied to a scratch copy of the tree, built once with CFLAGS=-O2 -g0 and array
bounds checked (-fsanitize=bounds, as in SAN=1). The mutated
file alone is compiled (with the Makefile's flags) to its object: identical machine code is a proof
of equivalence (reason "same object code"). A mutant that draws a compiler warning is killed by
the build that CI runs (WERROR=1): -fsanitize=bounds checks only arrays whose bound the type holds,
so an index -1 into an array parameter (a pointer) reaches no check, but cc's -Warray-bounds sees
it. Otherwise the object replaces the original in its
layer's archive and the tests run, each program relinked just before it runs, in fast-fail order:
the tests that have killed most of this file's mutants per second of their run time first, then
test_mutant_kills and test_guards, the
other unit tests quickest first, the CLI value tests, the claims ledger, the CLI interface tests;
each test has a timeout (a mutant that hangs is killed by it). The first test that fails beyond
the unmutated tree's own failures kills the mutant. A header that no test includes is compiled
into its library includers, swapped in as a .c file's object; any other header's mutant first meets
the unit tests that call its inline functions, compiled with it; if they do not kill it, make
rebuilds the tree.
Each verdict is appended to --log as it comes, so a campaign cut short resumes (--resume); the
result file is written from the log, and a survivor listed in tests/build/mutants_equivalent (with
a proof) counts there as equivalent.

The campaign's log and result are generated files (make mutants-ops writes them under build/). The
record of the last complete campaign is committed: its log compressed (RECORD_LOG) and the head of
its result, the counts, as a short summary (RECORD_SUMMARY); --record writes both from --log, by
hand, once a campaign is complete. A resumed campaign whose log does not exist yet starts from the
record (--from-log). Any log whose name ends in .gz is read through gzip.

Usage: mutants_ops.py [--sample N --seed S] [--files F ...] [--out FILE] [--log FILE [--resume [--new-only]]]
       [--from-log FILE] [--survivors | --only TEXT] [--summarize [--note TEXT]] [--record] [--list]
Last line: "mutants-ops: generated N, killed K, equivalent E, survived S, did-not-build B, score X,
round-off survivors R" (S counts only the survivors neither list explains).
Exit status 1 when a mutant survives unexplained.
"""
import argparse
import glob
import gzip
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

# Every object is built with array bounds checked: an index one past an array (a mutated size or
# index) then stops the test that reaches it, instead of landing silently in a neighbour.
BOUNDS = "-fsanitize=bounds -fno-sanitize-recover=bounds"
LAYERS = ("util", "core", "methods", "lab", "render", "prog")  # src/ folders, lowest first
# The library files in priority order (the campaign may be cut short: the first ones matter most).
FILES = ["src/core/model.c", "src/core/model.h", "src/core/so3.c", "src/core/quaternion.c",
         "src/core/reconstruct.c", "src/core/exact.c", "src/core/refattitude.c",
         "src/methods/step_euler.c", "src/methods/step_midpoint.c", "src/methods/step_variational.c",
         "src/methods/step_rk4.c", "src/methods/step_composition.c", "src/methods/composition.c",
         "src/methods/composition_coeffs.c", "src/methods/step_taylor.c", "src/methods/taylor.h",
         "src/core/driver.c", "src/methods/step_gauss4.c", "src/methods/taylor_series.h",
         "src/core/so3_trig.c", "src/methods/step_taylor_adaptive.c", "src/core/driver_tol.c"]

# The committed record of the last complete campaign (see --record).
RECORD_LOG = "data/mutants_ops_log.tsv.gz"
RECORD_SUMMARY = "tests/build/mutants_ops_summary.txt"
RECORD_WHERE = ("log: %s; resume: make mutants-ops MUTANTS_OPS_RESUME=1 (it starts from this log); "
                "every verdict: python3 tools/mutants_ops.py --summarize --log %s --out "
                "build/mutants_ops_result.txt (at the commit above)" % (RECORD_LOG, RECORD_LOG))

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
    if toks[k][1] == ",":  # a later declarator of a declaration (double xi[3], D[3][3];) is none either
        depth = 0
        while k >= 0 and not (depth == 0 and toks[k][1] in (";", "{", "}", "(", "[")):
            depth += toks[k][1] in (")", "]")
            depth -= toks[k][1] in ("(", "[")
            k -= 1
            if depth == 0 and toks[k][1] == "}":  # an initializer's braces (x[2] = {..}, q[4]) are skipped
                b, nest = k - 1, 1
                while b >= 0 and nest:
                    nest += (toks[b][1] == "}") - (toks[b][1] == "{")
                    b -= 1
                if b >= 0 and toks[b][1] == "=":
                    k = b
        if (k < 0 or toks[k][1] in (";", "{", "}")) and (toks[k + 1][1] in TYPES or toks[k + 1][1] in types):
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
    """A scratch copy of the tree, built once (CFLAGS=-O2 -g0 and BOUNDS, so that the object a
    mutant compiles to is also the one compared with the original). A mutated .c file is then
    compiled alone, replaced in its layer's archive, and each test program relinked just before it
    runs: no make per mutant (make's own start costs about a second). A header's mutants meet the
    unit tests compiled with them first, then make (their includers are many)."""

    def __init__(self, root):
        self.dir = tempfile.mkdtemp(prefix="mutops.")
        for d in ("src", "tests", "tools", "paper", "docs"):
            shutil.copytree(os.path.join(root, d), os.path.join(self.dir, d))
        shutil.copy(os.path.join(root, "Makefile"), self.dir)
        os.makedirs(os.path.join(self.dir, "data"), exist_ok=True)
        os.makedirs(os.path.join(self.dir, "figures"), exist_ok=True)
        cfg = os.path.join(root, "data", "animation.cfg")
        if os.path.exists(cfg):
            shutil.copy(cfg, os.path.join(self.dir, "data"))
        rec = os.path.join(root, "data", "bench-recorded")  # the recorded bench run (test_bench_record)
        if os.path.isdir(rec):
            shutil.copytree(rec, os.path.join(self.dir, "data", "bench-recorded"))
        self.env = {k: v for k, v in os.environ.items()
                    if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "SAN", "BUILD", "CFLAGS")}
        # the build is sanitized (BOUNDS): test_cli.sh then leaves out its address-space limit check,
        # which a sanitizer's shadow reservations exceed, as under SAN=1
        self.env["SUSLOV_SAN"] = "1"
        self.b = "build/mut"
        pkg = ["pkg-config", "--cflags", "gsl", "cairo", "osmesa", "libpng"]
        self.pkg_cflags = subprocess.run(pkg, capture_output=True, text=True).stdout.split()
        pkg[1] = "--libs"
        self.pkg_libs = subprocess.run(pkg, capture_output=True, text=True).stdout.split()
        self.tests = []
        self.kills = {}  # (file, test name) -> kills so far: a file's best killers run first
        self.warning = ""  # the first warning the last object() drew
        # a test program is relinked for every mutant it meets: gold links it 4-5 times faster than
        # the default ld.bfd (measured), so use it where cc has it
        gold = subprocess.run(["cc", "-fuse-ld=gold", "-Wl,--version", "-o", os.devnull], capture_output=True)
        self.fast_ld = ["-fuse-ld=gold"] if gold.returncode == 0 else []

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
        return self.sh(["make", "-s", "BUILD=" + self.b, "CFLAGS=-O2 -g0 " + BOUNDS, "LDFLAGS=" + BOUNDS,
                        "-j2"] + targets).returncode == 0

    def obj_path(self, src):
        return "%s/obj/%s.o" % (self.b, src[len("src/"):-2])

    def object(self, src):
        """The object code of a library source file as the Makefile compiles it (flags as
        CFLAGS_OF, with -g0), written in place in the scratch build; b"" for a header; None
        when it does not compile."""
        if not src.endswith(".c"):
            return b""
        layer = src.split("/")[1]
        inc = ["-Isrc/" + d for d in LAYERS[:LAYERS.index(layer) + 1]]
        cmd = ["cc", "-std=c17", "-Wall", "-Wextra", "-Wshadow", "-Wstrict-prototypes", "-ffp-contract=off",
               "-O2", "-g0"] + BOUNDS.split() + inc + self.pkg_cflags + ["-c", src, "-o", self.obj_path(src)]
        r = self.sh(cmd)
        if r.returncode != 0:
            return None
        warnings = [l.split("warning: ", 1)[1] for l in r.stderr.splitlines() if "warning: " in l]
        self.warning = warnings[0] if warnings else ""
        with open(os.path.join(self.dir, self.obj_path(src)), "rb") as f:
            return f.read()

    def archive(self, src, obj):
        """Put obj (the bytes of src's object) in place and into its layer's archive."""
        with open(os.path.join(self.dir, self.obj_path(src)), "wb") as f:
            f.write(obj)
        lib = "%s/libsus_%s.a" % (self.b, src.split("/")[1])
        return self.sh(["ar", "rcs", lib, self.obj_path(src)]).returncode == 0

    def link_cmd(self, prog):
        """The link line of one test program, as the Makefile's."""
        b = self.b
        libs = ["%s/libsus_%s.a" % (b, l) for l in reversed(LAYERS)]
        if prog.startswith(b + "/test_"):
            objs = ["%s/tobj/unit/%s.o" % (b, os.path.basename(prog))]
        elif prog == b + "/claims":
            objs = sorted("%s/tobj/ledger/%s.o" % (b, f[:-2])
                          for f in os.listdir(os.path.join(self.dir, "tests", "ledger")) if f.endswith(".c"))
        else:
            objs = ["%s/obj/prog/%s.o" % (b, os.path.basename(prog))]
        return ["cc"] + self.fast_ld + [BOUNDS.split()[0]] + objs + libs + self.pkg_libs + ["-lm", "-o", prog]

    def setup_tests(self):
        """The test commands, quick unit tests first; each with a timeout from its own run time."""
        b = self.b
        units = [(os.path.basename(t), [t], [t]) for t in self.targets() if "/test_" in t]
        cmds = units + [("test_cli_values", ["sh", "tests/cli/test_cli_values.sh", b], [b + "/suslov"]),
                        ("claims", [b + "/claims", b + "/claims.tsv"], [b + "/claims"]),
                        ("test_cli", ["sh", "tests/cli/test_cli.sh", b], [b + "/suslov", b + "/animation"])]
        for name, cmd, needs in cmds:
            t0 = time.time()
            r = self.sh(cmd, timeout=1800)
            secs = time.time() - t0
            base = signature(r.stdout + r.stderr) if r.returncode else None
            self.tests.append((name, cmd, [self.link_cmd(p) for p in needs], 30 + 5 * secs, base, secs))
            print("mutants-ops: baseline %s %.1f s%s" % (name, secs, "" if base is None else " (FAILS)"),
                  flush=True)
        # test_mutant_kills and test_guards first (formulas and bounds checked directly, in
        # milliseconds), then the other unit tests quickest first, then the CLI value tests, the
        # ledger, the CLI interface tests
        rank = {n: i for i, n in enumerate(["test_mutant_kills", "test_guards"])}
        self.tests.sort(key=lambda t: (not t[0].startswith("test_") or t[0] == "test_cli",
                                       rank.get(t[0], 2), t[5] if t[0].startswith("test_") else 0))

    def run_tests(self, path, relink=True):
        """The first test that fails beyond the baseline, or None; "" when a program does not link.
        The tests that have killed most of this file's mutants per second of run time run first."""
        # by kills per second of run time (a kill counted one more: a quick test that has killed
        # nothing yet still runs before the ledger, which one kill would otherwise put first)
        def rate(i):
            return (1 + self.kills.get((path, self.tests[i][0]), 0)) / max(self.tests[i][5], 0.05)
        order = sorted(range(len(self.tests)), key=lambda i: -rate(i))
        for i in order:
            name, cmd, links, secs, base, _ = self.tests[i]
            if relink and any(self.sh(l).returncode for l in links):
                return ""
            killer = self.verdict(path, name, cmd, secs, base)
            if killer:
                return killer
        return None

    def includers(self, header):
        """The library's .c files (below src/prog) that include header, directly or through other
        headers; None when a test or a program includes it too (then make rebuilds them all)."""
        files = glob.glob("src/*/*.[ch]", root_dir=self.dir) + glob.glob("tests/*/*.[ch]", root_dir=self.dir)
        texts = {f: open(os.path.join(self.dir, f)).read() for f in files}
        names = {os.path.basename(header)}

        def includes(t):
            return any('#include "%s"' % n in t for n in names)
        while True:
            new = {os.path.basename(f) for f, t in texts.items() if f.endswith(".h") and includes(t)} - names
            if not new:
                break
            names |= new
        users = sorted(f for f, t in texts.items() if f.endswith(".c") and includes(t))
        return None if any(not u.startswith("src/") or u.startswith("src/prog/") for u in users) else users

    def header_quick(self, path):
        """A header's mutant against the unit tests that call its inline functions themselves:
        each is compiled with the mutated header into a program of its own (the library keeps
        its unmutated copies), so that most of a header's mutants cost no rebuild. The killer,
        None, or "" when the header does not compile."""
        for name in ("test_mutant_kills", "test_model"):
            test = next(t for t in self.tests if t[0] == name)
            prog, obj = "%s/quick/%s" % (self.b, name), "%s/quick/%s.o" % (self.b, name)
            os.makedirs(os.path.join(self.dir, self.b, "quick"), exist_ok=True)
            cmd = ["cc", "-std=c17", "-O2", "-g0"] + BOUNDS.split() + ["-Isrc/" + d for d in LAYERS] + \
                ["-Itests/unit", "-Itests/ledger"] + self.pkg_cflags + \
                ["-c", "tests/unit/%s.c" % name, "-o", obj]
            if self.sh(cmd).returncode:
                return ""
            link = self.link_cmd("%s/%s" % (self.b, name))
            link[link.index("%s/tobj/unit/%s.o" % (self.b, name))] = obj
            link[link.index("-o") + 1] = prog
            if self.sh(link).returncode:
                return ""
            killer = self.verdict(path, name, [prog], test[3], test[4])
            if killer:
                return killer + ", the test's own copy of the header"
        return None

    def verdict(self, path, name, cmd, secs, base):
        """The killer's description when the test fails beyond its baseline, else None."""
        try:
            r = self.sh(cmd, timeout=secs)
        except subprocess.TimeoutExpired:
            return self.killed(path, name, name + " (timeout)")
        if r.returncode == 0:
            return None
        sig = signature(r.stdout + r.stderr)
        new = sig - base if base is not None else sig
        if base is None or new or not sig:
            first = sorted(new)[0][:60] if new else "exit status %d" % r.returncode
            return self.killed(path, name, "%s (%s)" % (name, first))
        return None

    def killed(self, path, name, why):
        self.kills[(path, name)] = self.kills.get((path, name), 0) + 1
        return why


def signature(log):
    """A failing test's FAIL lines without their numbers (as tools/mutants.sh)."""
    return {re.sub(r"[0-9]", "", l[4:].strip()) for l in log.splitlines() if l.startswith("FAIL")}


def label_of(mut, text):
    path, off, length, rep, kind = mut
    line, orig, new = describe(mut, text)
    return "%s:%d %s: %s  ->  %s" % (path, line, kind, orig, new), orig, new


def run_header_fast(sc, mut, texts, ref_objs, users):
    """A header's mutant when no test program includes it: its includers in the library are
    compiled with it and swapped into their archives, as a .c file's mutant (no make)."""
    path, off, length, rep, kind = mut
    text = texts[path]
    target = os.path.join(sc.dir, path)
    with open(target, "w") as f:
        f.write(text[:off] + rep + text[off + length:])
    try:
        objs, warning = {}, ""
        for c in users:
            objs[c] = sc.object(c)
            if objs[c] is None:
                return "did-not-build", "does not compile (%s)" % c
            warning = warning or sc.warning
        if all(objs[c] == ref_objs[c] for c in users):
            return "equivalent", "same object code of every includer (cc -O2 -g0)"
        if warning:
            return "killed", "cc -Werror (WERROR=1, as CI builds): " + warning[:80]
        if not all(sc.archive(c, objs[c]) for c in users):
            return "did-not-build", "does not link"
        killer = sc.run_tests(path)
        if killer == "":
            return "did-not-build", "does not link"
        return ("killed", killer) if killer else ("survived", "")
    finally:
        with open(target, "w") as f:
            f.write(text)
        for c in users:
            sc.archive(c, ref_objs[c])


def run_one(sc, mut, texts, ref_objs):
    """verdict ("killed", "survived", "equivalent", "did-not-build") and why, for one mutant."""
    path, off, length, rep, kind = mut
    users = None if path.endswith(".c") else sc.includers(path)
    if users:
        return run_header_fast(sc, mut, texts, ref_objs, users)
    text = texts[path]
    target = os.path.join(sc.dir, path)
    with open(target, "w") as f:
        f.write(text[:off] + rep + text[off + length:])
    header = rebuilt = not path.endswith(".c")
    try:
        if header:
            quick = sc.header_quick(path)
            rebuilt = quick is None
            if quick is not None:
                return ("killed", quick) if quick else ("did-not-build", "does not compile")
        obj = sc.object(path)
        if obj is None:
            return "did-not-build", "does not compile"
        if obj and obj == ref_objs[path]:
            return "equivalent", "same object code (cc -O2 -g0)"
        if obj and sc.warning:  # e.g. an index -1 into an array parameter, which BOUNDS cannot check
            return "killed", "cc -Werror (WERROR=1, as CI builds): " + sc.warning[:80]
        if (header and not sc.build()) or (not header and not sc.archive(path, obj)):
            return "did-not-build", "does not link"
        killer = sc.run_tests(path, relink=not header)
        if killer == "":
            return "did-not-build", "does not link"
        return ("killed", killer) if killer else ("survived", "")
    finally:
        with open(target, "w") as f:  # a new mtime: a header's includers are rebuilt
            f.write(text)
        if rebuilt:
            sc.build()
        elif not header and ref_objs[path]:
            sc.archive(path, ref_objs[path])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--files", nargs="*", default=FILES)
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--seed", type=int, default=20261123)
    ap.add_argument("--out", default="", help="the result file, rewritten from the log as the run goes")
    ap.add_argument("--log", default="", help="one line per mutant run, appended as it finishes")
    ap.add_argument("--resume", action="store_true", help="skip the mutants the log holds, but survivors")
    ap.add_argument("--survivors", action="store_true", help="run only the survivors the log holds")
    ap.add_argument("--new-only", action="store_true", help="with --resume: run only mutants the log lacks "
                    "(its survivors wait for a --survivors run, once their tests are written)")
    ap.add_argument("--only", default="", help="run only the mutants whose label holds this text")
    ap.add_argument("--shard", default="", help="K/N: run only every N-th mutant to run, from the K-th "
                    "(0-based), so that N workers can share one file and one log")
    ap.add_argument("--summarize", action="store_true", help="write --out from --log, run nothing")
    ap.add_argument("--from-log", default="", help="with --resume: the log a campaign starts from when "
                    "--log does not exist yet (the committed record, %s)" % RECORD_LOG)
    ap.add_argument("--record", action="store_true", help="write the committed record (%s, %s) from "
                    "--log, run nothing" % (RECORD_LOG, RECORD_SUMMARY))
    ap.add_argument("--note", default="", help="a line for the result file's head (e.g. the commits run at)")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--equivalent", default="tests/build/mutants_equivalent")
    ap.add_argument("--roundoff", default="tests/build/mutants_roundoff")
    a = ap.parse_args()
    types = typedef_names(sorted(glob.glob("src/*/*.h") + glob.glob("src/*/*.c")))
    texts = {p: open(p).read() for p in a.files}
    muts = [m for p in a.files for m in generate(p, types)]
    if a.sample and a.sample < len(muts):
        pick = sorted(random.Random(a.seed).sample(range(len(muts)), a.sample))
        muts = [muts[i] for i in pick]
    labels = [label_of(m, texts[m[0]])[0] for m in muts]
    if a.list:
        print("\n".join(labels))
        print("mutants-ops: %d mutants" % len(muts))
        return 0
    if a.summarize:
        print(write_result(a, labels, texts, muts))
        return 0
    if a.record:
        return record(a, labels, texts, muts)
    if a.log.endswith(".gz"):
        print("mutants-ops: the log a campaign appends to is plain text (%s)" % a.log)
        return 2
    if a.log and a.resume and a.from_log and not os.path.exists(a.log):
        with open_log(a.from_log) as src, open(a.log, "w") as dst:
            shutil.copyfileobj(src, dst)
    if a.log and not a.resume and not a.only and not a.survivors:
        open(a.log, "w").close()
    done = read_log(a.log) if a.log else {}
    # a survivor runs again on resume: a test may have been added for it since
    todo = [m for m, l in zip(muts, labels)
            if (a.only in l if a.only else done.get(l, ("survived",))[0] == "survived")
            and not (a.new_only and l in done)
            and (not a.survivors or done.get(l, ("",))[0] == "survived")]
    if a.shard:
        k, n = (int(x) for x in a.shard.split("/"))
        todo = todo[k::n]
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # so that the scratch copy goes too
    sc = Scratch(os.getcwd())
    try:
        return campaign(a, sc, todo, texts, labels, muts)
    finally:
        shutil.rmtree(sc.dir, ignore_errors=True)


def open_log(path):
    """A log for reading, through gzip when its name ends in .gz."""
    return gzip.open(path, "rt") if path.endswith(".gz") else open(path)


def read_log(path):
    """label -> (verdict, why) from a campaign log; a mutant run again keeps its last verdict."""
    out = {}
    if path and os.path.exists(path):
        for raw in open_log(path):
            f = raw.rstrip("\n").split("\t")
            if len(f) == 3:
                out[f[1]] = (f[0], f[2])
    return out


def campaign(a, sc, todo, texts, labels, muts):
    print("mutants-ops: %d mutants to run over %s; building the scratch copy in %s"
          % (len(todo), " ".join(a.files), sc.dir), flush=True)
    if not sc.build():
        print("mutants-ops: the unmutated tree does not build")
        return 2
    sc.setup_tests()
    ref = {p: sc.object(p) for p in a.files}
    for h in [p for p in a.files if not p.endswith(".c")]:
        ref.update({c: sc.object(c) for c in sc.includers(h) or [] if c not in ref})
    for p, obj in ref.items():
        if obj:
            sc.archive(p, obj)
    log = open(a.log or os.devnull, "a")
    for n, m in enumerate(todo, 1):
        t0 = time.time()
        label = label_of(m, texts[m[0]])[0]
        verdict, why = run_one(sc, m, texts, ref)
        log.write("%s\t%s\t%s\n" % (verdict, label, why))
        log.flush()
        print("%d/%d %-13s %s  [%s] %.1f s" % (n, len(todo), verdict.upper(), label, why, time.time() - t0),
              flush=True)
        if a.out and a.log and n % 20 == 0:
            write_result(a, labels, texts, muts)
    log.close()
    summary = write_result(a, labels, texts, muts) if a.log else "mutants-ops: no log"
    print(summary)
    return 1 if " survived 0," not in summary else 0


def tally(a, labels, texts, muts):
    """The verdicts of the log: counts over every file and per file, one line a mutant, and the
    summary line. A logged survivor whose mutant tests/build/mutants_equivalent lists (with its
    proof) counts as equivalent, one listed in tests/build/mutants_roundoff (why no test can see it)
    as a round-off survivor; a mutant not yet run is counted as not run."""
    done, eq, ro = read_log(a.log), load_equivalents(a.equivalent), load_equivalents(a.roundoff)
    kinds = ("killed", "equivalent", "round-off", "survived", "did-not-build", "not-run")
    total, per_file, lines = dict.fromkeys(kinds, 0), {}, []
    for m, label in zip(muts, labels):
        verdict, why = done.get(label, ("not-run", ""))
        if verdict == "survived":
            _, orig, new = label_of(m, texts[m[0]])
            if (m[0], orig, new) in eq:
                verdict, why = "equivalent", eq[(m[0], orig, new)]
            elif (m[0], orig, new) in ro:
                verdict, why = "round-off", ro[(m[0], orig, new)]
        total[verdict] += 1
        per_file.setdefault(m[0], dict.fromkeys(kinds, 0))[verdict] += 1
        if verdict != "not-run":
            lines.append("%-13s %s%s" % (verdict.upper(), label, "  [%s]" % why if why else ""))
    return total, per_file, lines, "mutants-ops: " + counts_text(total, len(muts))


def write_result(a, labels, texts, muts):
    """The result file (--out) from the log: its head (result_head), then one line a mutant.
    Returns the summary line."""
    total, per_file, lines, summary = tally(a, labels, texts, muts)
    if a.out:
        where = RECORD_WHERE if a.log.endswith(".gz") else (
            "log: %s; resume: python3 tools/mutants_ops.py --resume --log %s --out %s [--files ...]"
            % (a.log, a.log, a.out))
        head = result_head(a, total, per_file, summary, where)
        write_atomic(a.out, "\n".join(head + [""] + lines) + "\n")
    return summary


def result_head(a, total, per_file, summary, where):
    """What was run, where its log is (where), the counts over every file and per file."""
    commit = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True).stdout.strip()
    written = time.strftime("%Y-%m-%d %H:%M", time.gmtime())
    return ["# make mutants-ops (tools/mutants_ops.py): the generated operator-mutation campaign",
            "# commit %s, written %s UTC%s" % (commit or "unknown", written,
                                               "" if not total["not-run"] else " (INCOMPLETE)"),
            "# sample: %s" % ("all" if not a.sample else "%d, seed %d" % (a.sample, a.seed))] + \
        (["# " + a.note] if a.note else []) + [
            "# " + where, summary, "# per file:"] + \
        ["#   %s: %s" % (p, counts_text(c, sum(c.values()))) for p, c in per_file.items()]


def write_atomic(path, data, binary=False):
    tmp = path + ".tmp"
    with open(tmp, "wb" if binary else "w") as f:
        f.write(data)
    os.replace(tmp, path)


def record(a, labels, texts, muts):
    """The committed record of a complete campaign: its log compressed (RECORD_LOG, reproducible:
    no name, no time in the gzip header) and its result's head (RECORD_SUMMARY). Every verdict is
    written again by --summarize --log RECORD_LOG at the commit the summary names."""
    if not a.log or a.log.endswith(".gz") or not os.path.exists(a.log):
        print("mutants-ops: --record needs the campaign's plain log (--log)")
        return 2
    total, per_file, _, summary = tally(a, labels, texts, muts)
    if total["not-run"] or a.sample:
        print("mutants-ops: not recorded: the campaign is incomplete (%s)" % summary)
        return 1
    head = result_head(a, total, per_file, summary, RECORD_WHERE)
    with open(a.log, "rb") as f:
        write_atomic(RECORD_LOG, gzip.compress(f.read(), compresslevel=9, mtime=0), binary=True)
    write_atomic(RECORD_SUMMARY, "\n".join(head) + "\n")
    print("mutants-ops: recorded %s and %s; %s" % (RECORD_LOG, RECORD_SUMMARY, summary))
    return 0


def counts_text(c, n):
    """The score is K / (N - E - B): a round-off survivor is a live mutant that no test kills."""
    live = c["killed"] + c["survived"] + c["round-off"]
    score = "%.4f" % (c["killed"] / live) if live else "n/a"
    return ("generated %d, killed %d, equivalent %d, survived %d, did-not-build %d, score %s, "
            "round-off survivors %d%s"
            % (n, c["killed"], c["equivalent"], c["survived"], c["did-not-build"], score, c["round-off"],
               ", not run %d" % c["not-run"] if c["not-run"] else ""))


if __name__ == "__main__":
    sys.exit(main())
