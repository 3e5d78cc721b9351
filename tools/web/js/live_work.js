// Work and precision, live: one method at one step to T; error at T against the exact solution
// and the time of the run in this browser (median, min, max of 5 after a warm-up).
'use strict';
(function() {
const form = document.querySelector('form.live');
async function draw(f) {
    const m = Number(f.m.value), eps0 = Live.number('--eps', f.eps.value),
          T = Live.number('--time', f.T.value);
    if (!(eps0 > 0)) throw new Error(`--eps must be positive, got ${eps0}`);
    const steps = Math.round(T / eps0);
    if (!(steps >= 1))
        throw new Error(`--time ${T} with --eps ${eps0} gives ${steps} steps; need at least 1`);
    const body = Live.body(f);
    const run =
        Object.assign({kind: 'run', method: m, recon: -1, eps: eps0, steps, every: steps}, body);
    const ex = Object.assign({}, run, {kind: 'omega'});
    const res = await Live.runAll([run, run, run, run, run, run, ex], f);
    const ms = res.slice(1, 6).map((r) => r.ms).sort((a, b) => a - b);
    const a = res[0].rows, b = res[6].rows, n = a.length - Live.NCOL;
    const err = Math.hypot(a[n + 2] - b[n + 2], a[n + 3] - b[n + 3]);
    document.getElementById('result').innerHTML =
        `${f.m.selectedOptions[0].text}, ε = ${eps0}, ${steps} steps: ` +
        `error |ω_N − ω(T)| = <b>${err.toExponential(3)}</b>; time <b>${ms[2].toFixed(2)} ms</b> ` +
        `(min ${ms[0].toFixed(2)}, max ${ms[4].toFixed(2)}; ${
            (1e3 * ms[2] / steps).toFixed(3)} µs a step)`;
}
Live.bindForm(form, draw);
})();
