"""The live pages: forms around the integrators compiled to WebAssembly (tools/web/js/live.js runs
them in a Web Worker; js/plot.js draws). The numbers come from the same C sources as the suslov
command; each page says so and names the committed figure it can be compared with."""
import frame

BODY = "1,0.1,0.2,0.1,1,0.2,0.2,0.1,1"
COMMON = ["suslov_wasm.js", "live.js", "plot.js"]


def field(name, label, value, size=8):
    return ('<label>%s <input name="%s" value="%s" size="%d" autocomplete="off"></label>'
            % (label, name, value, size))


def method_select(name, label, default):
    """Filled by the page script from the module's registry (no list of names here)."""
    return ('<label>%s <select name="%s" data-methods data-default="%s"></select></label>'
            % (label, name, default))


def body_fields():
    return ('<label>inertia <select name="reading"><option value="row">third row as printed'
            '</option><option value="col">third column (symmetric)</option>'
            '<option value="custom">as typed</option></select></label>'
            + field("inertia", "I by rows", BODY, 30)
            + field("omega0", "&omega;(0)", "0.4,0.5"))


def run_fields(eps, T, default):
    return [method_select("m", "method", default), field("eps", "&epsilon;", eps, 6),
            field("T", "T", T, 5)]


def form(fields):
    return ('<form class="live" onsubmit="return false">%s'
            '<button type="submit" name="run">Run</button>'
            '<button type="button" name="stop" disabled>Stop</button>'
            '<span class="status" aria-live="polite"></span><p class="error" hidden></p></form>'
            % "".join(fields))


def fig_img(site, name):
    if name not in site.figures:
        return ""
    return ('<figure>%s<figcaption>The committed <a href="figures.html#fig-%s">%s</a>, drawn by '
            'the C program (<a href="figures/%s.png">full size</a>).</figcaption></figure>'
            % (frame.figure_img(name), name, name, name))


def fig2_page(site):
    sweeps = "".join('<option value="%d">%d sweep%s</option>' % (n, n, "s" if n > 1 else "")
                     for n in range(1, 9))
    return [
        "<h1>Figure 2, run again in your browser</h1>",
        "<p>The paper's Figure 2 compares the midpoint rule and the variational integrator at "
        "&epsilon; = 1. Choose &epsilon;, the two methods, the reading of the midpoint rule "
        "(Newton, as the registry's <code>midpoint</code>, or a fixed number of fixed-point "
        "sweeps, which then takes method A's place) and the reading of the printed, "
        "non-symmetric inertia; the panels are recomputed here by the library's C code compiled "
        "to WebAssembly, the same sources as <code>build/suslov</code>, whose CSV these numbers "
        "equal.</p>",
        form([field("eps", "&epsilon;", "1", 6), field("T", "T", "200", 6),
              method_select("a", "method A", "midpoint"),
              '<label>or A = midpoint rule by <select name="sweeps">'
              '<option value="0">Newton (method A)</option>%s</select></label>' % sweeps,
              method_select("b", "method B", "variational"), body_fields()]),
        "<div class='panels' id='panels'></div>"
        "<div class='wide'><table class='claims' id='final'></table></div>",
        fig_img(site, "fig2")]


def convergence_page(site):
    return [
        "<h1>Orders, measured in your browser</h1>",
        "<p>Pick a method and a range of steps &epsilon; = &epsilon;<sub>max</sub> "
        "2<sup>&minus;j</sup>; each run goes to T and its error |&omega;<sub>N</sub> &minus; "
        "&omega;(T)| against the exact solution is plotted. The fitted order is the least-squares "
        "slope of log error against log &epsilon; over the points above the round-off floor "
        "(error &gt; 10<sup>3</sup> u |&omega;(T)|, u = 2<sup>&minus;53</sup>; at least three), "
        "computed by the ledger's own fit, <code>src/lab/orderfit.c</code>, in the WebAssembly "
        "module.</p>",
        form([method_select("m", "method", "rk4"), field("epsmax", "&epsilon; max", "0.25", 6),
              field("halvings", "halvings", "8", 4), field("T", "T", "10", 5), body_fields()]),
        "<div class='panels' id='panels'></div><p id='order' class='result'></p>"
        "<div class='wide'><table class='claims' id='points'></table></div>",
        fig_img(site, "convergence")]


def work_page(site):
    return [
        "<h1>Work and precision, one point at a time</h1>",
        "<p>Run a method at a chosen step to T: the page shows its error at T against the exact "
        "solution and its time in this browser (median, min and max of 5 runs, after one warm-up "
        "run), beside the committed chart, which <code>make bench</code> measures natively.</p>",
        form(run_fields("0.01", "10", "comp6-kl") + [body_fields()]),
        "<p id='result' class='result'></p>", fig_img(site, "work_precision")]


def attitude_page(site):
    return [
        "<h1>The attitude R<sub>k</sub>, live</h1>",
        "<p>The body frame reconstructed by a method (left) beside the exact attitude R(t) "
        "(right), from the same WebAssembly run; move the slider through time. The OSMesa "
        "animation (<code>make animation</code>) stays the reference rendering.</p>",
        form(run_fields("0.5", "60", "midpoint") + [
            '<label>reconstruction <select name="recon" data-recons>'
            '<option value="-1">the method\'s own</option></select></label>', body_fields()]),
        "<div class='attitude'><div class='att-labels'><span id='att-method'>the method</span>"
        "<span>the exact attitude R(t)</span></div><canvas id='gl' width='640' height='320' "
        "role='img' aria-label='left: the method; right: the exact attitude'></canvas>"
        "<p class='att-key'>Both views look along the same fixed direction of space. The arrows "
        "are the body's axes R e<sub>1</sub> <span class='ax1'>(red)</span>, R e<sub>2</sub> "
        "<span class='ax2'>(green)</span> and R e<sub>3</sub> <span class='ax3'>(blue)</span>, the "
        "columns of R; the grey box, of half-sides 0.9, 0.6 and 0.3 along them, is fixed in the "
        "body.</p></div>"
        "<label class='slider'>t <input type='range' id='k' min='0' max='0' value='0'> "
        "<span id='kt'></span></label><p id='dist' class='result'></p>",
        fig_img(site, "attitude_filmstrip")]


PAGES = (("live-fig2.html", "Figure 2, live", fig2_page, "live_fig2.js"),
         ("live-convergence.html", "Convergence, live", convergence_page, "live_conv.js"),
         ("live-work.html", "Work and precision, live", work_page, "live_work.js"),
         ("live-attitude.html", "The attitude, live", attitude_page, "live_attitude.js"))


def build(site):
    for name, title, parts, script in PAGES:
        body = "<main class='text'>%s</main>" % "\n".join(parts(site))
        site.write_page(name, title, "live", body, COMMON + [script])
    return [p[0] for p in PAGES]
