// Convergence, live: a method's global error at T against the exact solution for
// eps = eps_max 2^-j, and the least-squares slope of log error on log eps (the fitted order).
'use strict';
(function() {
const form = document.querySelector('form.live');
const U = Math.pow(2, -53), FLOOR = 1e3;  // points below FLOOR u |w(T)| are round-off, not fitted

function slope(xs, ys) {
    const n = xs.length, mx = xs.reduce((a, b) => a + b, 0) / n, my = ys.reduce((a, b) => a + b, 0) / n;
    let sxy = 0, sxx = 0;
    for (let i = 0; i < n; i++) {
        sxy += (xs[i] - mx) * (ys[i] - my);
        sxx += (xs[i] - mx) ** 2;
    }
    return sxy / sxx;
}

async function draw(f) {
    const m = Number(f.m.value), emax = Live.number('eps max', f.epsmax.value),
          T = Live.number('--time', f.T.value);
    const nh = Live.number('halvings', f.halvings.value);
    if (!(emax > 0)) throw new Error(`--eps must be positive, got ${emax}`);
    if (!(nh >= 1 && nh <= 16 && Number.isInteger(nh)))
        throw new Error(`halvings: give a whole number from 1 to 16, got ${nh}`);
    const body = Live.body(f), jobs = [];
    for (let j = 0; j <= nh; j++) {
        const steps = Math.max(1, Math.round(T / (emax / 2 ** j))), eps = T / steps;
        jobs.push(Object.assign({kind: 'run', method: m, recon: -1, eps, steps, every: steps}, body));
        jobs.push(Object.assign({kind: 'omega', eps, steps, every: steps}, body));
    }
    const res = await Live.runAll(jobs, f);
    const pts = [];
    for (let j = 0; j < res.length; j += 2) {
        const a = res[j].rows, b = res[j + 1].rows, n = a.length - Live.NCOL;
        const err = Math.hypot(a[n + 2] - b[n + 2], a[n + 3] - b[n + 3]);
        pts.push({eps: jobs[j].eps, err, fitted: err > FLOOR * U * Math.hypot(b[n + 2], b[n + 3])});
    }
    const use = pts.filter((p) => p.fitted);
    const p =
        use.length >= 2 ? slope(use.map((q) => Math.log(q.eps)), use.map((q) => Math.log(q.err))) : NaN;
    document.getElementById('order').textContent = use.length >= 2 ?
        `fitted order ${p.toFixed(3)} over ${use.length} points (ε from ${
            use[use.length - 1].eps.toPrecision(3)} to ${use[0].eps.toPrecision(3)})` :
        'fewer than two points above the round-off floor: no order fitted';
    Plot.plot(document.getElementById('panels'), {
        title: 'global error at T',
        xlabel: 'ε',
        ylabel: '|ω_N − ω(T)|',
        logx: true,
        logy: true,
        series: [
            {
                x: pts.map((q) => q.eps),
                y: pts.map((q) => q.err),
                color: '#2457a6',
                line: true,
                dots: 3,
                label: f.m.selectedOptions[0].text
            },
            {x: use.map((q) => q.eps), y: use.map((q) => q.err), color: '#c0392b', dots: 2, label: 'fitted'}
        ]
    });
    document.getElementById('points').innerHTML = '<tr><th>ε</th><th>error</th><th>fitted</th></tr>' +
        pts.map(
               (q) => `<tr><td class="num">${q.eps.toPrecision(6)}</td><td class="num">${
                   q.err.toExponential(3)}</td><td>${q.fitted ? 'yes' : 'round-off'}</td></tr>`)
            .join('');
}
Live.bindForm(form, draw);
})();
