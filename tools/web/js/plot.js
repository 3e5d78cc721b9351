// A small SVG plotter for the live pages: one panel with axes, "nice" ticks (1, 2, 5 times a power
// of ten) or log decades, lines and markers, a legend. plot(el, spec) replaces el's content.
//   spec = { title, xlabel, ylabel, logx, logy, series: [{ x, y, color, line, dots, label }] }
'use strict';
(function() {
const NS = 'http://www.w3.org/2000/svg';
function node(tag, attrs, parent) {
    const n = document.createElementNS(NS, tag);
    for (const k in attrs) n.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(n);
    return n;
}
function niceTicks(lo, hi) {
    const span = hi - lo, raw = span / 5, mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => span / s <= 6);
    const out = [];
    for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step)
        out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return out;
}
function range(series, key, log) {
    let lo = Infinity, hi = -Infinity;
    for (const s of series)
        for (const v of s[key])
            if (Number.isFinite(v) && (!log || v > 0)) {
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
    if (!(lo <= hi)) {
        lo = log ? 1e-16 : 0;
        hi = log ? 1 : 1;
    }
    if (log)
        return [
            Math.floor(Math.log10(lo)), Math.max(Math.ceil(Math.log10(hi)), Math.floor(Math.log10(lo)) + 1)
        ];
    if (hi === lo) {
        const d = Math.abs(hi) * 1e-3 || 1;
        lo -= d;
        hi += d;
    }
    const pad = (hi - lo) * 0.04;
    return [lo - pad, hi + pad];
}
const fmt = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-3)) ? v.toExponential(0) :
                                                                             String(+v.toPrecision(6));

function plot(el, spec) {
    const W = 420, H = 260, L = 62, R = 10, T = 24, B = 38;
    el.textContent = '';
    const svg = node(
        'svg', {viewBox: `0 0 ${W} ${H}`, class: 'plot', role: 'img', 'aria-label': spec.title || ''}, el);
    const [x0, x1] = range(spec.series, 'x', spec.logx), [y0, y1] = range(spec.series, 'y', spec.logy);
    const tx = (v) => L + (W - L - R) * ((spec.logx ? Math.log10(v) : v) - x0) / (x1 - x0);
    const ty = (v) => H - B - (H - T - B) * ((spec.logy ? Math.log10(v) : v) - y0) / (y1 - y0);
    node('rect', {x: L, y: T, width: W - L - R, height: H - T - B, class: 'frame'}, svg);
    const ticks = (lo, hi, log) =>
        log ? Array.from({length: hi - lo + 1}, (_, i) => Math.pow(10, lo + i)) : niceTicks(lo, hi);
    for (const v of ticks(x0, x1, spec.logx)) {
        const x = tx(v);
        node('line', {x1: x, x2: x, y1: H - B, y2: H - B + 4, class: 'tick'}, svg);
        node('text', {x, y: H - B + 15, 'text-anchor': 'middle'}, svg).textContent =
            spec.logx ? `1e${Math.round(Math.log10(v))}` : fmt(v);
    }
    for (const v of ticks(y0, y1, spec.logy)) {
        const y = ty(v);
        node('line', {x1: L - 4, x2: L, y1: y, y2: y, class: 'tick'}, svg);
        node('text', {x: L - 6, y: y + 4, 'text-anchor': 'end'}, svg).textContent =
            spec.logy ? `1e${Math.round(Math.log10(v))}` : fmt(v);
    }
    node('text', {x: (L + W - R) / 2, y: H - 4, 'text-anchor': 'middle', class: 'axis'}, svg).textContent =
        spec.xlabel || '';
    node('text', {x: 4, y: T - 8, class: 'axis'}, svg).textContent =
        (spec.title ? spec.title + '  ' : '') + (spec.ylabel || '');
    const clip = 'c' + Math.random().toString(36).slice(2);
    node('rect', {x: L, y: T, width: W - L - R, height: H - T - B}, node('clipPath', {id: clip}, svg));
    const g = node('g', {'clip-path': `url(#${clip})`}, svg);
    spec.series.forEach((s, k) => {
        const ok = (i) => Number.isFinite(s.y[i]) && (!spec.logy || s.y[i] > 0) && Number.isFinite(s.x[i]);
        if (s.line) {
            let d = '', pen = false;
            for (let i = 0; i < s.x.length; i++) {
                if (!ok(i)) {
                    pen = false;
                    continue;
                }
                d += (pen ? 'L' : 'M') + tx(s.x[i]).toFixed(1) + ' ' + ty(s.y[i]).toFixed(1);
                pen = true;
            }
            node('path', {d, stroke: s.color, fill: 'none', 'stroke-width': 1.4}, g);
        }
        if (s.dots) {
            const step = Math.max(1, Math.floor(s.x.length / 400));  // at most ~400 markers
            for (let i = 0; i < s.x.length; i += step)
                if (ok(i))
                    node(
                        'circle', {
                            cx: tx(s.x[i]).toFixed(1),
                            cy: ty(s.y[i]).toFixed(1),
                            r: s.dots,
                            fill: s.open ? 'none' : s.color,
                            stroke: s.color
                        },
                        g);
        }
    });
    // the legend in the top margin, right-aligned, so that it never hides data
    let lx = W - R;
    for (const s of spec.series.slice().reverse()) {
        lx -= 14 + 6.2 * (s.label || '').length;
        node('rect', {x: lx, y: T - 15, width: 9, height: 8, fill: s.color}, svg);
        node('text', {x: lx + 12, y: T - 8, class: 'legend'}, svg).textContent = s.label || '';
    }
}
window.Plot = {plot};
})();
