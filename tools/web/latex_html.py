"""LaTeX text to HTML for the pages, the math left to KaTeX: the companion's TSV fields and the
ledger's claims_tex.tsv (one line of text with $...$ math), and the paper's own statements
(paragraphs, lists, displays, font groups, references). Math is handed over as written, inside
\\( \\) or \\[ \\], which KaTeX's auto-render typesets in the browser; only what KaTeX lacks
(subequations, eqnarray, the paper's equation numbers) is rewritten. A reference (\\eqref,
\\ref, \\PaperRefParen) goes through the caller's ref(kind, label) function."""
import html
import re
import unicodedata

# Display environments: what KaTeX is given instead (starred: KaTeX would number the rows itself).
DISPLAY = {"equation": None, "equation*": None, "multline": "gathered", "multline*": "gathered",
           "align": "align*", "align*": "align*", "gather": "gather*", "gather*": "gather*",
           "eqnarray": "array", "eqnarray*": "array", "subequations": None}
ACCENTS = {"'": "\u0301", '"': "\u0308", "`": "\u0300", "^": "\u0302", "~": "\u0303", "c": "\u0327"}
FONT_GROUPS = {"rm": ('<span class="rm">', "</span>"), "it": ("<em>", "</em>"),
               "em": ("<em>", "</em>"), "bf": ("<b>", "</b>"), "sl": ("<em>", "</em>"),
               "tt": ("<code>", "</code>")}
WRAPS = {"emph": ("<em>", "</em>"), "textit": ("<em>", "</em>"), "textbf": ("<b>", "</b>"),
         "texttt": ("<code>", "</code>"), "mbox": ("", ""), "text": ("", ""), "textrm": ("", ""),
         "hbox": ("", ""), "footnote": ('<span class="footnote"> (Footnote: ', ")</span>")}
DROPPED = {"medskip", "smallskip", "bigskip", "noindent", "par", "hfill", "centering", "newline",
           "label", "nonumber", "notag", "hspace", "vspace", "includegraphics", "protect"}
THEOREMS = {"definition", "proposition", "theorem", "corollary", "remark", "algorithm", "lemma"}
SYMBOLS = {"ldots": "\u2026", "dots": "\u2026", "textbackslash": "\\", "S": "\u00a7",
           "ss": "\u00df", "quad": "\u2003", "qquad": "\u2003\u2003"}


def esc(s):
    return html.escape(s, quote=False)


def balanced(s, i, open_="{", close="}"):
    """The end (exclusive) of the group that opens at s[i]; len(s) when it never closes."""
    depth = 0
    for j in range(i, len(s)):
        if s[j] == "\\":
            continue
        if s[j] == open_ and (j == 0 or s[j - 1] != "\\"):
            depth += 1
        elif s[j] == close and (j == 0 or s[j - 1] != "\\"):
            depth -= 1
            if depth == 0:
                return j + 1
    return len(s)


def arg(s, i):
    """The {argument} at s[i] (after blanks): (its text, the index after it), or ("", i)."""
    j = i
    while j < len(s) and s[j] in " \t\n":
        j += 1
    if j < len(s) and s[j] == "{":
        k = balanced(s, j)
        return s[j + 1:k - 1], k
    return "", i


def find_end(s, i, env):
    """Where the \\end{env} that closes the \\begin{env} before s[i] is (nested ones skipped)."""
    depth, pat = 1, re.compile(r"\\(begin|end)\{%s\}" % re.escape(env))
    for m in pat.finditer(s, i):
        depth += 1 if m.group(1) == "begin" else -1
        if depth == 0:
            return m.start(), m.end()
    return len(s), len(s)


class Converter:
    def __init__(self, ref, eqnumber=lambda lab: None):
        self.ref = ref              # ref(kind, label) -> HTML; kind: eqref, ref, paren, or
        self.eqnumber = eqnumber    # label -> the number the paper prints, or None
        self.maths = []
        self.unknown = set()        # commands passed over (for the caller to report)
        self.nested = []            # headings of statements nested in the one being converted

    # --- math: taken out first, so that its braces and dollars never reach the text parser
    def keep(self, display, tex):
        self.maths.append((display, tex))
        return "\x00%d\x00" % (len(self.maths) - 1)

    def display_tex(self, env, body):
        """A display environment as KaTeX takes it: the paper's labels become its numbers."""
        if env == "subequations":
            m = re.search(r"\\begin\{([a-z]+\*?)\}", body)
            if not m:
                return self.display_tex("equation*", body)
            inner_end, _ = find_end(body, m.end(), m.group(1))
            return self.display_tex(m.group(1), body[m.end():inner_end])
        tags = []

        def label(m):
            num = self.eqnumber(m.group(1).strip())
            if num and env not in ("equation", "equation*", "multline", "multline*"):
                return "\\tag{%s}" % num
            if num:
                tags.append(num)
            return ""
        body = re.sub(r"\\label\{([^}]*)\}", label, body)
        body = re.sub(r"\\(nonumber|notag)\b", "", body).strip()
        target = DISPLAY.get(env)
        if target == "array":
            body = "\\begin{array}{rcl}%s\\end{array}" % body
        elif target:
            body = "\\begin{%s}%s\\end{%s}" % (target, body, target)
        return body + "".join("\\tag{%s}" % t for t in tags[:1])

    def protect_math(self, s):
        out, i = [], 0
        while i < len(s):
            m = re.compile(r"\\\[|\$\$?|\\begin\{([a-z]+\*?)\}|\\\$").search(s, i)
            if not m:
                out.append(s[i:])
                break
            out.append(s[i:m.start()])
            tok = m.group(0)
            if tok == "\\$":
                out.append(tok)
                i = m.end()
            elif m.group(1) is not None and m.group(1) not in DISPLAY:
                out.append(tok)
                i = m.end()
            elif m.group(1) is not None:
                a, b = find_end(s, m.end(), m.group(1))
                out.append(self.keep(True, self.display_tex(m.group(1), s[m.end():a])))
                i = b
            else:
                close = {"\\[": "\\]", "$$": "$$", "$": "$"}[tok]
                j = s.find(close, m.end())
                while close == "$" and j > 0 and s[j - 1] == "\\":
                    j = s.find(close, j + 1)
                j = len(s) if j < 0 else j
                body = s[m.end():j]
                display = tok != "$"
                tex = self.display_tex("equation*", body) if display else body
                out.append(self.keep(display, tex))
                i = j + len(close)
        return "".join(out)

    def restore(self, h):
        def sub(m):
            display, tex = self.maths[int(m.group(1))]
            if display:
                return '<span class="math display">\\[%s\\]</span>' % esc(tex)
            return "\\(%s\\)" % esc(tex.strip())
        return re.sub("\x00(\\d+)\x00", sub, h)

    # --- text: font groups, commands, lists, quotes and dashes, paragraphs ("\x01")
    def text(self, s):
        out, stack, lists, i = [], [], [], 0
        while i < len(s):
            c = s[i]
            if c == "{":
                m = re.match(r"\{\\(rm|it|em|bf|sl|tt)(?![A-Za-z])\s*", s[i:])
                pair = FONT_GROUPS[m.group(1)] if m else ("", "")
                out.append(pair[0])
                stack.append(pair)
                i += m.end() if m else 1
            elif c == "}":
                out.append(stack.pop()[1] if stack else "")
                i += 1
            elif c == "\\":
                i = self.command(s, i, out, stack, lists)
            else:
                i = self.plain(s, i, out, stack, lists)
        out += [closer for _, closer in reversed(stack)]
        out += ["</li></%s>" % tag for tag, _ in reversed(lists)]
        return "".join(out)

    def plain(self, s, i, out, stack, lists):
        for tok, rep in (("``", "\u201c"), ("''", "\u201d"), ("---", "\u2014"), ("--", "\u2013"),
                         ("~", "&nbsp;")):
            if s.startswith(tok, i):
                out.append(rep)
                return i + len(tok)
        m = re.compile(r"\n[ \t]*\n\s*").match(s, i)
        if m:   # a paragraph ends: the open groups close and open again in the next one
            out.append(" " if lists else "".join(c for _, c in reversed(stack)) + "\x01" +
                       "".join(o for o, _ in stack))
            return m.end()
        m = re.compile(r"\s+").match(s, i)
        if m:
            out.append(" ")
            return m.end()
        m = re.compile(r"[^\\{}~`'\-\s]+").match(s, i)
        out.append(esc(m.group(0) if m else s[i]))
        return m.end() if m else i + 1

    def symbol(self, sym, s, j, out):
        """\\' \\" \\^ (accents), \\\\ (a line break), \\, \\; (spaces), \\% \\_ (characters)."""
        if sym in ACCENTS:
            a, k = arg(s, j)
            if k == j and j < len(s) and s[j].isalpha():
                a, k = s[j], j + 1
            out.append(unicodedata.normalize("NFC", a + ACCENTS[sym]) if a else esc(sym))
            return k
        out.append({"\\": "<br>", ",": "\u2009", ";": " ", ":": " ", " ": " ", "/": "",
                    "-": ""}.get(sym, esc(sym)))
        return j

    def command(self, s, i, out, stack, lists):
        m = re.compile(r"\\([A-Za-z]+)\*?|\\(.)", re.S).match(s, i)
        j = m.end()
        if m.group(2) is not None:
            return self.symbol(m.group(2), s, j, out)
        name = m.group(1)
        if name in ("eqref", "ref", "PaperRefParen", "PaperRefOr"):
            a, j = arg(s, j)
            how = {"PaperRefParen": "paren", "PaperRefOr": "or"}.get(name, name)
            out.append(self.ref(how, a.strip()))
        elif name == "cite":
            j = s.find("]", j) + 1 if s.startswith("[", j) else j
            a, j = arg(s, j)
            out.append("[%s]" % esc(", ".join(k.strip() for k in a.split(","))))
        elif name in WRAPS:
            a, j = arg(s, j)
            out.append(WRAPS[name][0] + self.text(a) + WRAPS[name][1])
        elif name in ("begin", "end"):
            return self.environment(name, s, j, out, lists)
        elif name == "item":
            return self.item(s, j, out, lists)
        elif name in DROPPED:
            j = s.find("]", j) + 1 if s.startswith("[", j) else j
            if name in ("label", "hspace", "vspace", "includegraphics"):
                _, j = arg(s, j)
        elif name in SYMBOLS:
            out.append(SYMBOLS[name])
        elif name in FONT_GROUPS:   # \rm inside a group: to the group's end
            o, c = FONT_GROUPS[name]
            out.append(o)
            if stack:
                stack[-1] = (stack[-1][0] + o, c + stack[-1][1])
            else:
                out.append(c)
        else:
            self.unknown.add(name)
        return j

    def environment(self, which, s, j, out, lists):
        env, j = arg(s, j)
        tag = {"enumerate": "ol", "itemize": "ul"}.get(env)
        if tag and which == "begin":
            out.append("<%s>" % tag)
            lists.append([tag, False])
        elif tag and lists:
            out.append(("</li>" if lists[-1][1] else "") + "</%s>" % lists.pop()[0])
        elif env in THEOREMS:   # a statement inside another: its heading, its text set apart
            head = self.nested.pop(0) if self.nested and which == "begin" else env.capitalize()
            out.append('<span class="nested"><b>%s.</b> ' % esc(head) if which == "begin"
                       else "</span>")
        elif env == "minipage" and which == "begin":
            _, j = arg(s, j)
        elif env not in ("minipage", "center"):
            self.unknown.add("%s{%s}" % (which, env))
        return j

    def item(self, s, j, out, lists):
        label = None
        m = re.compile(r"\s*\[([^\]]*)\]").match(s, j)
        if m:
            label, j = m.group(1), m.end()
        if not lists:
            return j
        out.append("</li>" if lists[-1][1] else "")
        lists[-1][1] = True
        out.append('<li class="bare">' if label == "" else
                   '<li class="labelled"><b>%s</b> ' % self.text(label) if label else "<li>")
        return j

    # --- the two ways in
    def inline(self, s):
        """One line of text (a TSV field, a ledger quantity) as inline HTML."""
        self.maths = []
        return self.restore(self.text(self.protect_math(s)).replace("\x01", " ")).strip()

    def block(self, s):
        """A statement of the paper: paragraphs, lists and displays."""
        self.maths = []
        h = self.text(self.protect_math(s))
        h = re.sub(r'<li class="bare">\s*</li>', "", h)   # \item[]: a new line, no item
        paras = [p.strip() for p in h.split("\x01")]
        return "".join('<div class="para">%s</div>' % self.restore(p) for p in paras if p)
