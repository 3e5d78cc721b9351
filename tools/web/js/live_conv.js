// Convergence, live: a method's global error at T against the exact solution for
// eps = eps_max 2^-j, and the least-squares slope of log error on log eps (the fitted order), by
// the ledger's own fit (src/lab/orderfit.c in the WebAssembly module), above its round-off floor
// 1000 u |w(T)|.
'use strict';
(function() {
const form = document.querySelector('form.live');
// The runs: the method and the exact solution at each step eps_max 2^-j, to T.
function jobsOf(f) {
    const m = Number(f.m.value), emax = Live.number('eps max', f.epsmax.value),
          T = Live.number('--time', f.T.value);
    const nh = Live.number('halvings', f.halvings.value);
    if (!(emax > 0)) throw new Error(`--eps must be positive, got ${emax}`);
    if (!(nh >= 1 && nh <= 16 && Number.isInteger(nh)))
        throw new Error(`halvings: give a whole number from 1 to 16, got ${nh}`);
    const body = Live.body(f), jobs = [];
    for (let j = 0; j <= nh; j++) {
        const steps = Math.max(1, Math.round(T / (emax / 2 ** j))), eps = T / steps;
        jobs.push(
            Object.assign({kind: 'run', method: m, recon: -1, eps, steps, every: steps}, body));
        jobs.push(Object.assign({kind: 'omega', eps, steps, every: steps}, body));
    }
    return jobs;
}

// The fitted order in words, and the plot of the errors with the fitted points marked.
function show(f, pts, fit) {
    const [p, , used, lo, hi, floor] = fit;
    // the points the C fit took: those inside its eps range and above its floor
    pts.forEach((q) => {
        q.fitted = used > 0 && q.eps >= lo && q.eps <= hi && q.err > floor;
    });
    const use = pts.filter((q) => q.fitted);
    const order = document.getElementById('order');
    order.dataset.slope = String(p);
    order.textContent = used > 0 ?
        `fitted order ${p.toPrecision(6)} over ${used} points (ε from ${lo.toPrecision(3)} to ${
            hi.toPrecision(3)})` :
        'fewer than three points above the round-off floor: no order fitted';
    const xy = (qs) => ({x: qs.map((q) => q.eps), y: qs.map((q) => q.err)});
    Plot.plot(document.getElementById('panels'), {
        title: 'global error at T',
        xlabel: 'ε',
        ylabel: '|ω_N − ω(T)|',
        logx: true,
        logy: true,
        series: [
            Object.assign(
                xy(pts),
                {color: '#2457a6', line: true, dots: 3, label: f.m.selectedOptions[0].text}),
            Object.assign(xy(use), {color: '#c0392b', dots: 2, label: 'fitted'})
        ]
    });
    document.getElementById('points').innerHTML =
        '<tr><th>ε</th><th>error</th><th>fitted</th></tr>' +
        pts.map(
               (q) => `<tr><td class="num">${q.eps.toPrecision(6)}</td><td class="num">${
                   q.err.toExponential(3)}</td><td>${q.fitted ? 'yes' : 'round-off'}</td></tr>`)
            .join('');
}

async function draw(f) {
    const jobs = jobsOf(f);
    const res = await Live.runAll(jobs, f);
    const pts = [];
    let size = 0;
    for (let j = 0; j < res.length; j += 2) {
        const a = res[j].rows, b = res[j + 1].rows, n = a.length - Live.NCOL;
        pts.push({eps: jobs[j].eps, err: Math.hypot(a[n + 2] - b[n + 2], a[n + 3] - b[n + 3])});
        size = Math.max(size, Math.hypot(b[n + 2], b[n + 3]));
    }
    const fitJob = {
        kind: 'fit',
        eps: pts.map((q) => q.eps),
        err: pts.map((q) => q.err),
        epsMax: Infinity,
        size
    };
    const [fit] = await Live.runAll([fitJob], f);
    show(f, pts, fit.fit);
}
Live.bindForm(form, draw);
})();
