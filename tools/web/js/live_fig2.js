// Figure 2, live: method A (with the midpoint rule's reading), method B and the exact solution
// to T, drawn as the paper's panels (w1, w2, lambda, E) plus the distance to the steady rotation.
'use strict';
(function() {
const form = document.querySelector('form.live');
const names = {};
Live.methods().then((ms) => ms.forEach((m) => {
    names[m.index] = m.name;
}));

// The CLI's %.17g: 17 significant digits, trailing zeros dropped.
const g17 = (v) => Number.isFinite(v) ? String(Number(v.toPrecision(17))) : String(v);

function jobs(f) {
    const eps = Live.number('--eps', f.eps.value), T = Live.number('--time', f.T.value);
    if (!(eps > 0)) throw new Error(`--eps must be positive, got ${eps}`);
    const steps = Math.round(T / eps);
    if (!(steps >= 1))
        throw new Error(`--time ${T} with --eps ${eps} gives ${steps} steps; need at least 1`);
    const body = Live.body(f), a = Number(f.a.value), b = Number(f.b.value),
          n = Number(f.sweeps.value);
    // n > 0: method A is the midpoint rule solved by n fixed-point sweeps (suslov --sweeps n)
    const A = n > 0 ? {
        kind: 'sweeps',
        n,
        recon: -1,
        eps,
        steps,
        every: 1,
        label: `midpoint, ${n} sweep${n > 1 ? 's' : ''}`
    } :
                      {kind: 'run', method: a, recon: -1, eps, steps, every: 1, label: names[a]};
    const B = {kind: 'run', method: b, recon: -1, eps, steps, every: 1, label: names[b]};
    const ex = {kind: 'omega', eps: T / 4000, steps: 4000, every: 1, label: 'exact'};
    return [A, B, ex, {kind: 'limit'}].map((j) => Object.assign(j, body));
}

async function draw(f) {
    const js = jobs(f);
    const [ra, rb, re, lim] = await Live.runAll(js, f);
    const w = lim.limit, col = Live.column;
    const runs = [
        [re, '#c0392b', true, 0, 'exact'], [ra, '#1e8449', false, 3, js[0].label],
        [rb, '#2457a6', false, 2, js[1].label]
    ];
    const dist = (r) => {
        const t = col(r.rows, 2), u = col(r.rows, 3);
        return t.map((v, i) => Math.hypot(v - w[0], u[i] - w[1]));
    };
    const panels = [
        ['(a)', 'ω₁', (r) => col(r.rows, 2)], ['(b)', 'ω₂', (r) => col(r.rows, 3)],
        ['(c)', 'λ', (r) => col(r.rows, 5)], ['(d)', 'E', (r) => col(r.rows, 6)],
        ['(e)', '|ω_k − ω∞|', dist]
    ];
    const box = document.getElementById('panels');
    box.textContent = '';
    panels.forEach(([title, ylabel, get], p) => {
        const el = document.createElement('div');
        box.appendChild(el);
        Plot.plot(el, {
            title,
            ylabel,
            xlabel: 't',
            logy: p === 4,
            series: runs.map(
                ([r, color, line, dots, label]) =>
                    ({x: col(r.rows, 1), y: get(r), color, line, dots, open: dots === 3, label}))
        });
    });
    const last = (r) => r.rows.slice(r.rows.length - Live.NCOL);
    const head = '<tr>' +
        ['run', 'k', 't', 'ω₁', 'ω₂', 'λ', 'E', 'ms'].map((h) => `<th>${h}</th>`).join('') +
        '</tr>';
    document.getElementById('final').innerHTML = head +
        runs.map(([r, , , , label]) => {
                const x = last(r);
                return `<tr><td>${label}</td>` +
                    [0, 1, 2, 3, 5, 6].map((c) => `<td class="num">${g17(x[c])}</td>`).join('') +
                    `<td class="num">${r.ms.toFixed(1)}</td></tr>`;
            })
            .join('');
}
Live.bindForm(form, draw);
})();
