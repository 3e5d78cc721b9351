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
// Ticks at multiples of the largest step 1, 2 or 5 x 10^k that puts at least four in [lo, hi]
// (so between four and about nine: enough to read a value off the axis).
function niceTicks(lo, hi) {
    const top = Math.pow(10, Math.ceil(Math.log10(hi - lo)));
    let step = top;
    for (let k = 0; k < 60; k++) {
        step = top / [1, 2, 5][k % 3] / Math.pow(10, Math.floor(k / 3));
        if (Math.floor(hi / step) - Math.ceil(lo / step) + 1 >= 4) break;
    }
    const out = [];
    for (let j = Math.ceil(lo / step); j <= Math.floor(hi / step); j++)
        out.push(Number((j * step).toPrecision(12)));
    return {ticks: out, step};
}
// Tick labels with the decimals the step needs. When the values are large against the step (an
// energy 0.225 that moves by 1e-7), the labels are offsets from the middle tick, which the axis
// title then names: "E - 0.2250000", ticks "-1e-7", "0", "+1e-7".
function tickLabels(ticks, step) {
    const dec = Math.max(0, Math.ceil(-Math.log10(step) - 1e-9));
    const big = Math.max(...ticks.map(Math.abs));
    if (big >= 1e5 || (dec > 0 && big < 1e-3))
        return {
            labels: ticks.map((v) => (v === 0 ? '0' : Number(v.toPrecision(4)).toExponential())),
            offset: null
        };
    if (dec <= 5 || big < 1e4 * step)
        return {labels: ticks.map((v) => v.toFixed(dec)), offset: null};
    const base = ticks[Math.floor(ticks.length / 2)];
    const off = (v) => {
        const d = Number((v - base).toPrecision(3));
        return d === 0 ? '0' : (d > 0 ? '+' : '\u2212') + Math.abs(d).toExponential();
    };
    return {labels: ticks.map(off), offset: base.toFixed(dec)};
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
            Math.floor(Math.log10(lo)),
            Math.max(Math.ceil(Math.log10(hi)), Math.floor(Math.log10(lo)) + 1)
        ];
    if (hi === lo) {
        const d = Math.abs(hi) * 1e-3 || 1;
        lo -= d;
        hi += d;
    }
    const pad = (hi - lo) * 0.04;
    return [lo - pad, hi + pad];
}
// An axis: its ticks and their labels (decades, with 2 and 5 times each when there are fewer than
// four; else nice ticks).
function axis(lo, hi, log) {
    if (!log) {
        const {ticks, step} = niceTicks(lo, hi);
        return Object.assign({ticks}, tickLabels(ticks, step));
    }
    const ticks = [];
    for (let d = lo; d <= hi; d++)
        for (const m of hi - lo < 3 ? [1, 2, 5] : [1])
            if (d + Math.log10(m) <= hi + 1e-9) ticks.push(m * Math.pow(10, d));
    const label = (v) => {
        const d = Math.floor(Math.log10(v) + 1e-9);
        return `${Math.round(v / Math.pow(10, d))}e${d}`;
    };
    return {ticks, labels: ticks.map(label), offset: null};
}

// The frame, the ticks and their labels, the axis titles (an offset axis names its offset).
function drawAxes(svg, box, spec, ax, ay) {
    const {W, H, L, R, T, B, tx, ty} = box;
    node('rect', {x: L, y: T, width: W - L - R, height: H - T - B, class: 'frame'}, svg);
    ax.ticks.forEach((v, i) => {
        const x = tx(v);
        node('line', {x1: x, x2: x, y1: H - B, y2: H - B + 4, class: 'tick'}, svg);
        node('text', {x, y: H - B + 15, 'text-anchor': 'middle'}, svg).textContent = ax.labels[i];
    });
    ay.ticks.forEach((v, i) => {
        const y = ty(v);
        node('line', {x1: L - 4, x2: L, y1: y, y2: y, class: 'tick'}, svg);
        node('text', {x: L - 6, y: y + 4, 'text-anchor': 'end'}, svg).textContent = ay.labels[i];
    });
    const named = (label, a) => (a.offset === null ? label : `${label} \u2212 ${a.offset}`);
    node('text', {x: (L + W - R) / 2, y: H - 4, 'text-anchor': 'middle', class: 'axis'}, svg)
        .textContent = named(spec.xlabel || '', ax);
    node('text', {x: 4, y: T - 8, class: 'axis'}, svg).textContent =
        (spec.title ? spec.title + '  ' : '') + named(spec.ylabel || '', ay);
}

// One series inside the frame: a line through its finite points, markers (at most ~400).
function drawSeries(g, box, spec, s) {
    const {tx, ty} = box;
    const ok = (i) =>
        Number.isFinite(s.y[i]) && (!spec.logy || s.y[i] > 0) && Number.isFinite(s.x[i]);
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
    if (!s.dots) return;
    const step = Math.max(1, Math.floor(s.x.length / 400));
    for (let i = 0; i < s.x.length; i += step) {
        if (!ok(i)) continue;
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
}

function plot(el, spec) {
    const W = 420, H = 260, L = 62, R = 10, T = 24, B = 38;
    el.textContent = '';
    const svg = node(
        'svg',
        {viewBox: `0 0 ${W} ${H}`, class: 'plot', role: 'img', 'aria-label': spec.title || ''}, el);
    const [x0, x1] = range(spec.series, 'x', spec.logx),
               [y0, y1] = range(spec.series, 'y', spec.logy);
    const tx = (v) => L + (W - L - R) * ((spec.logx ? Math.log10(v) : v) - x0) / (x1 - x0);
    const ty = (v) => H - B - (H - T - B) * ((spec.logy ? Math.log10(v) : v) - y0) / (y1 - y0);
    const box = {W, H, L, R, T, B, tx, ty};
    drawAxes(svg, box, spec, axis(x0, x1, spec.logx), axis(y0, y1, spec.logy));
    const clip = 'c' + Math.random().toString(36).slice(2);
    node(
        'rect', {x: L, y: T, width: W - L - R, height: H - T - B},
        node('clipPath', {id: clip}, svg));
    const g = node('g', {'clip-path': `url(#${clip})`}, svg);
    for (const s of spec.series) drawSeries(g, box, spec, s);
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
