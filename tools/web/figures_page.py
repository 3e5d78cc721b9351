"""The figures page: each figure as its program drew it, the caption file the program writes beside
it (what exactly was run), the command that draws it again, the numbers behind it and the ledger
lines it shows. Each image opens the PNG itself, full size."""
import glob
import os
import re
import shutil

import frame
from frame import esc, link_labels
from source_pages import page_of


def program(name):
    """(source file, command) that draws figures/NAME.png."""
    if os.path.exists("src/prog/figure_%s.c" % name):
        return ("src/prog/figure_%s.c" % name,
                "make figures/%s.pdf   # runs build/figure_%s figures data" % (name, name))
    for f in sorted(glob.glob("src/*/*.c")):
        with open(f, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        if re.search(r'"%%s/%s(\.png)?"' % re.escape(name), text):
            prog = os.path.basename(f)[:-2]
            target = {"bench": "make bench", "animation": "make animation"}.get(prog,
                                                                              "make %s" % prog)
            return f, "%s   # runs build/%s" % (target, prog)
    return None, None


def beside(name, ext, prog):
    """figures/NAME.EXT, else that of the name's stem (attitude_filmstrip -> attitude), else that
    of the program (bench -> data/bench.csv)."""
    stems = [name] + ["_".join(name.split("_")[:i]) for i in range(name.count("_"), 0, -1)]
    if prog:
        stems.append(os.path.basename(prog)[:-2])
    d = "figures" if ext == "txt" else "data"
    for s in stems:
        if os.path.exists("%s/%s.%s" % (d, s, ext)):
            return "%s/%s.%s" % (d, s, ext)
    return None


def title(name):
    """fig2 -> Figure 2 of the paper; others by their file name."""
    m = re.match(r"fig(\d+)$", name)
    return "Figure %s of the paper, redrawn" % m.group(1) if m else name.replace("_", " ")


def caption_text(name, prog):
    """The caption file's text, or None when only the committed preview exists."""
    cap = beside(name, "txt", prog) or "figures/%s.txt" % name
    if not os.path.exists(cap):
        return None
    with open(cap, encoding="utf-8") as f:
        return f.read().strip()


def entry(site, name):
    shutil.copyfile("figures/%s.png" % name, os.path.join(site.out, "figures", name + ".png"))
    prog, cmd = program(name)
    cap = caption_text(name, prog)
    caption = ('<pre class="caption">%s</pre>' % link_labels(esc(cap), site.labels) if cap else
               "<p class='note'>The committed preview. Its caption and data are written by the "
               "command below, which takes minutes and is not part of make web.</p>")
    csvf = beside(name, "csv", prog)
    if csvf:
        shutil.copyfile(csvf, os.path.join(site.out, csvf))
        data = '<a class="csv" href="%s">%s</a>' % (esc(csvf), esc(csvf))
    else:
        data = "written by the command above"
    claims = [c for c in site.claims if site.claim_figure(c["id"]) == name]
    lines = ("<p>Ledger lines: %s</p>" % ", ".join(
        '<a href="ledger.html#claim-%s">%s</a>' % (esc(c["id"]), esc(c["id"])) for c in claims)
        if claims else "")
    drawn = '<a href="%s">%s</a>' % (page_of(prog), esc(prog)) if prog else "(no program found)"
    return ('<div class="fig" id="fig-%s"><h2>%s <span class="lab">%s.png</span></h2>%s'
            '<p class="full-link"><a href="figures/%s.png">Open the figure at full size</a></p>%s'
            '<p>Drawn by: %s<br>Again: <code class="cmd">%s</code><br>Data: %s</p>%s</div>'
            % (esc(name), esc(title(name)), esc(name), frame.figure_img(name, "figure"), esc(name),
               caption, drawn, esc(cmd or "make figures"), data, lines))


def build(site):
    os.makedirs(os.path.join(site.out, "figures"), exist_ok=True)
    os.makedirs(os.path.join(site.out, "data"), exist_ok=True)
    out = ["<main class='text'><h1>Figures</h1><p class='note'>Each figure as drawn by its program "
           "(tap or click it for the full-size image), the caption file the program writes beside "
           "it (what exactly was run), the command that draws it again, and the numbers behind it."
           "</p>"]
    # the paper's figures first, then the others by name
    for name in sorted(site.figures, key=lambda n: (not re.match(r"fig\d", n), n)):
        out.append(entry(site, name))
    out.append("</main>")
    frame.write(os.path.join(site.out, "figures.html"),
                frame.page("Figures", "figures", "\n".join(out)))
