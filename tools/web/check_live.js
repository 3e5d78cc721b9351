// make check-web, the live pages: the numbers the Figure 2 page computes in the browser (the
// library compiled to WebAssembly) against the suslov command's CSV for the same method, step,
// body and w(0), to the last printed digit (%.17g prints every double exactly, so the test is
// bit equality), the midpoint rule by fixed-point sweeps against suslov --sweeps, the convergence
// page's fitted order against the ledger's; bad input gets the CLI's message (the CLI's own check
// for the inertia); a re-run of Figure 2 to t = 200 is timed
// (a PASS/MISS line against 200 ms, never a failure); every axis of the panels has ticks enough to
// read a value, and the attitude page names the method it shows.
'use strict';
const {execFileSync, spawnSync} = require('child_process');
const path = require('path');
const {pathToFileURL} = require('url');

// (method A, method B, eps, T, body by rows, w0): the paper's body and general bodies.
const POINTS = [
    ['midpoint', 'variational', '1', '200', '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1', '0.4,0.5'],
    ['euler', 'rk4', '0.1', '20', '2,0.3,0.1,0.3,1.5,0.2,0.4,-0.3,1', '0.7,-0.2'],
    ['taylor12', 'comp6-kl', '0.25', '30', '1.3,-0.2,0.5,-0.2,0.9,0.1,-0.3,0.6,1.1', '-0.5,0.3'],
    ['comp4-s5', 'taylor8', '0.5', '40', '3,1,0,1,2,0,0.5,0.7,1', '0.2,0.9'],
];
// Columns of a row: k t w1 w2 w3 lambda E | R11 .. R33
const W_COLS = 7;

// The CLI's rows for the options `how` (--method M, and --sweeps N) and the rest.
function cli(suslov, how, eps, steps, body, w0, every) {
    const out = execFileSync(
        suslov, how.concat([
            '--eps', eps, '--steps', String(steps), '--inertia', body, '--omega0', w0, '--every',
            String(every || 1), '--quiet'
        ]),
        {encoding: 'utf8', maxBuffer: 1 << 28});
    return out.split('\n')
        .filter((l) => l && !l.startsWith('#'))
        .slice(1)
        .map((l) => l.split(',').map(Number));
}

// How far two doubles are apart in units in the last place (0: the same bits).
function ulps(a, b) {
    if (Object.is(a, b)) return 0;
    const buf = new DataView(new ArrayBuffer(16));
    buf.setFloat64(0, a);
    buf.setFloat64(8, b);
    const ia = buf.getBigInt64(0), ib = buf.getBigInt64(8);
    const ord = (i) => (i < 0n ? -(i & 0x7fffffffffffffffn) : i);
    const d = ord(ia) - ord(ib);
    return Number(d < 0n ? -d : d);
}

async function submit(page, fields) {
    await page.waitForFunction(
        () => document.querySelector('form.live').dataset.runs, null, {polling: 10});
    const before =
        await page.evaluate(() => Number(document.querySelector('form.live').dataset.runs));
    await page.evaluate((f) => {
        const form = document.querySelector('form.live');
        for (const [k, v] of Object.entries(f)) {
            const el = form.elements[k];
            if (el.tagName === 'SELECT')
                el.value = Array.from(el.options).find((o) => o.text === v || o.value === v).value;
            else
                el.value = v;
        }
        form.requestSubmit();
    }, fields);
    await page.waitForFunction(
        (n) => Number(document.querySelector('form.live').dataset.runs) > n, before, {polling: 10});
    return page.evaluate(
        () => ({
            error: document.querySelector('form.live .error').hidden ?
                '' :
                document.querySelector('form.live .error').textContent,
            last: window.LIVE_LAST &&
                {
                    jobs: window.LIVE_LAST.jobs,
                        results: window.LIVE_LAST.results.map(
                            (r) => ({rc: r.rc, ms: r.ms, rows: r.rows ? Array.from(r.rows) : []}))
                }
        }));
}

// Every column of every row, bit for bit: the browser's module and the CLI compile the same C
// and compute the same bits (the exponential map's sin and cos are the project's own,
// src/core/so3_trig.c, not the two C libraries'), so any difference is a defect.
function compareRun(check, label, want, got) {
    let bad = 0, umax = 0;
    want.forEach((row, i) => row.forEach((v, c) => {
        const u = ulps(got[i * 16 + c], v);
        bad += u !== 0;
        umax = Math.max(umax, u);
    }));
    check(
        got.length === want.length * 16 && bad === 0,
        `${label}: all 16 columns of ${want.length} rows equal the CLI's CSV bit for bit`,
        `${bad} of ${want.length * 16} values differ, by at most ${umax} ulp; ${
            got.length / 16} rows`);
}

async function comparePoints(page, suslov, check) {
    for (const [a, b, eps, T, body, w0] of POINTS) {
        const r = await submit(
            page, {a, b, eps, T, reading: 'custom', inertia: body, omega0: w0, sweeps: '0'});
        if (!check(r.error === '', `live Figure 2 runs ${a}, ${b} at eps ${eps}`, r.error))
            continue;
        const steps = Math.round(Number(T) / Number(eps));
        [a, b].forEach((m, j) => {
            compareRun(
                check, `live ${m} eps ${eps} body ${body}`,
                cli(suslov, ['--method', m], eps, steps, body, w0), r.last.results[j].rows);
        });
    }
}

// Figure 2's other readings of the midpoint rule: method A by n fixed-point sweeps against
// suslov --method midpoint --sweeps n (k, t, w, lambda, E and R).
const SWEEP_POINTS = [
    ['1', '1', '200', '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1', '0.4,0.5'],
    ['2', '1', '200', '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1', '0.4,0.5'],
    ['5', '0.5', '40', '1.3,-0.2,0.5,-0.2,0.9,0.1,-0.3,0.6,1.1', '-0.5,0.3'],
];
async function compareSweeps(page, suslov, check) {
    for (const [n, eps, T, body, w0] of SWEEP_POINTS) {
        const r = await submit(page, {
            a: 'midpoint',
            b: 'variational',
            eps,
            T,
            reading: 'custom',
            inertia: body,
            omega0: w0,
            sweeps: n
        });
        if (!check(
                r.error === '', `live Figure 2 runs the midpoint rule by ${n} sweeps at eps ${eps}`,
                r.error))
            continue;
        const steps = Math.round(Number(T) / Number(eps));
        compareRun(
            check, `live midpoint, ${n} sweeps, eps ${eps} body ${body}`,
            cli(suslov, ['--method', 'midpoint', '--sweeps', n], eps, steps, body, w0),
            r.last.results[0].rows);
    }
}

// The panels of a live page: each axis's tick labels (the title and the legend left out).
function axes() {
    return Array.from(document.querySelectorAll('#panels svg.plot')).map((svg) => {
        const texts = Array.from(svg.querySelectorAll('text:not(.axis):not(.legend)'));
        const at = (a) =>
            texts.filter((t) => t.getAttribute('text-anchor') === a).map((t) => t.textContent);
        return {panel: svg.getAttribute('aria-label'), x: at('middle'), y: at('end')};
    });
}

// Enough ticks to read a value: at least four on every axis, no two labels alike, on the paper's
// Figure 2 and on a short run whose energy moves by little (the labels then name an offset).
async function checkAxes(page, check) {
    for (const [eps, T] of [['1', '200'], ['0.02', '2']]) {
        const r = await submit(page, {
            eps,
            T,
            a: 'midpoint',
            b: 'variational',
            reading: 'row',
            sweeps: '0',
            inertia: '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1',
            omega0: '0.4,0.5'
        });
        const panels = await page.evaluate(axes);
        const bad = panels.filter(
            (p) => [p.x, p.y].some((l) => l.length < 4 || new Set(l).size !== l.length));
        check(
            r.error === '' && panels.length > 0 && bad.length === 0,
            `live Figure 2, eps ${eps}, T ${T}: every axis has at least four distinct tick labels`,
            r.error || JSON.stringify(bad[0] || ''));
    }
}

// The attitude page, where the reader picks the reconstruction: each one on a general body,
// against suslov --reconstruct R (rows every ceil(N / 600)-th step, as the page keeps them).
const RECON_POINTS = [
    ['midpoint', 'cayley-mid', '0.5', '60', '3,1,0,1,2,0,0.5,0.7,1', '0.2,0.9'],
    ['rk4', 'exp-mid', '0.25', '30', '1.3,-0.2,0.5,-0.2,0.9,0.1,-0.3,0.6,1.1', '-0.5,0.3'],
    ['comp4-s5', 'cayley', '0.5', '40', '2,0.3,0.1,0.3,1.5,0.2,0.4,-0.3,1', '0.7,-0.2'],
    ['variational', 'exp-mid', '0.1', '200', '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1', '0.4,0.5'],
];
async function compareRecons(ctx, webdir, suslov, check) {
    const page = await ctx.newPage();
    await page.goto(
        pathToFileURL(path.join(webdir, 'live-attitude.html')).href, {waitUntil: 'load'});
    for (const [m, recon, eps, T, body, w0] of RECON_POINTS) {
        const r =
            await submit(page, {m, recon, eps, T, reading: 'custom', inertia: body, omega0: w0});
        if (!check(r.error === '', `live attitude runs ${m} with ${recon} at eps ${eps}`, r.error))
            continue;
        const label = await page.evaluate(() => document.getElementById('att-method').textContent);
        check(
            label.startsWith(m + ' (' + recon + ')'),
            `live attitude: the left view is labelled ${m} (${recon})`, label);
        const steps = Math.round(Number(T) / Number(eps)),
              every = Math.max(1, Math.ceil(steps / 600));
        compareRun(
            check, `live ${m} + ${recon} eps ${eps} body ${body}`,
            cli(suslov, ['--method', m, '--reconstruct', recon], eps, steps, body, w0, every),
            r.last.results[0].rows);
    }
    await page.close();
}

// The convergence page's fitted order (the C fit, orderfit.c, in the module) for the ledger's
// data: the paper's body, eps = 2^-2 .. 2^-10 (T/N with N = round(T/eps)), T = 10. It must equal
// the ledger's global-order line to the ledger's printed digits, and equal bit for bit the same
// fit of the errors computed from the CLI's CSV (method and exact runs) for the same eps.
async function compareFit(ctx, webdir, suslov, claims, check) {
    const page = await ctx.newPage();
    await page.goto(
        pathToFileURL(path.join(webdir, 'live-convergence.html')).href, {waitUntil: 'load'});
    for (const m of ['euler', 'midpoint', 'rk4', 'variational']) {
        const r = await submit(page, {
            m,
            epsmax: '0.25',
            halvings: '8',
            T: '10',
            reading: 'row',
            inertia: '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1',
            omega0: '0.4,0.5'
        });
        const slope =
            Number(await page.evaluate(() => document.getElementById('order').dataset.slope));
        const ledger = claims.get(`global-order-${m}`);
        if (!check(
                r.error === '' && ledger !== undefined, `live convergence runs ${m}`,
                r.error || 'no ledger line'))
            continue;
        check(
            Number(slope.toPrecision(6)) === Number(ledger),
            `live convergence, ${m}: fitted order ${slope} is the ledger's global-order-${m} (${
                ledger})`,
            '');
        const eps = [], err = [];
        let size = 0;
        for (let j = 0; j <= 8; j++) {
            const N = Math.round(10 / (0.25 / 2 ** j)), h = String(10 / N);
            const a =
                cli(suslov, ['--method', m], h, N, '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1', '0.4,0.5', N)
                    .pop();
            const b = cli(suslov, ['--method', 'exact'], h, N, '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1',
                          '0.4,0.5', N)
                          .pop();
            eps.push(10 / N);
            err.push(Math.hypot(a[2] - b[2], a[3] - b[3]));
            size = Math.max(size, Math.hypot(b[2], b[3]));
        }
        const fit = await page.evaluate(
            (j) => Live.run([j]).then((res) => res[0].fit),
            {kind: 'fit', eps, err, epsMax: Infinity, size});
        check(
            Object.is(fit[0], slope),
            `live convergence, ${
                m}: the same fit of the CLI's errors gives the page's order bit for bit`,
            `CLI data ${fit[0]}, page ${slope}`);
    }
    await page.close();
}

// Bad input: the page shows what the CLI says on its one line (without "suslov: error: " and
// "(see suslov --help)"), and nothing hangs.
async function badInput(page, suslov, check) {
    const cases = [
        [{eps: '-1'}, ['--method', 'midpoint', '--eps', '-1', '--steps', '10']],
        [{eps: 'abc'}, ['--method', 'midpoint', '--eps', 'abc', '--steps', '10']],
        [
            {eps: '1', reading: 'custom', inertia: '1,2,0,2,1,0,0.2,0.1,1'},
            [
                '--method', 'midpoint', '--eps', '1', '--steps', '10', '--inertia',
                '1,2,0,2,1,0,0.2,0.1,1'
            ]
        ],
        ...['0,0,0,0,0,0,0.2,0.1,1', '1,0.1,0.2,0.10000000000001,1,0.2,0.2,0.1,1',
            '1e200,0,0,0,1e200,0,0,0,1']
            .map(
                (I) =>
                    [{eps: '1', reading: 'custom', inertia: I},
                     ['--method', 'midpoint', '--eps', '1', '--steps', '10', '--inertia', I]]),
        [{eps: '1e-9', inertia: '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1'}, null],
    ];
    for (const [fields, argv] of cases) {
        const r = await submit(
            page,
            Object.assign({T: '200', a: 'midpoint', b: 'variational', reading: 'row'}, fields));
        if (!argv) {
            check(
                /rows to keep/.test(r.error),
                `live Figure 2, eps ${fields.eps}: a bounded run, refused in one line`, r.error);
            continue;
        }
        const line = spawnSync(suslov, argv, {encoding: 'utf8'}).stderr.trim();
        const core = line.replace(/^suslov: error: /, '').replace(/ \(see suslov --help\)$/, '');
        check(
            r.error === core, `live Figure 2, ${JSON.stringify(fields)}: the CLI's message`,
            `page "${r.error}", CLI "${line}"`);
    }
}

async function run(ctx, webdir, suslov, claims, check) {
    const page = await ctx.newPage();
    await page.goto(pathToFileURL(path.join(webdir, 'live-fig2.html')).href, {waitUntil: 'load'});
    await comparePoints(page, suslov, check);
    await checkAxes(page, check);
    await compareSweeps(page, suslov, check);
    await badInput(page, suslov, check);
    // A re-run of the paper's Figure 2 to t = 200, from Run to the panels drawn, as the page
    // times it (performance.now); median of 5 (2 cores shared by other work: say so).
    const times = [];
    for (let i = 0; i < 5; i++) {
        const r = await submit(page, {
            eps: '1',
            T: '200',
            a: 'midpoint',
            b: 'variational',
            reading: 'row',
            inertia: '1,0.1,0.2,0.1,1,0.2,0.2,0.1,1',
            omega0: '0.4,0.5',
            sweeps: '0'
        });
        const ms = await page.evaluate(
            () => Number((
                document.querySelector('form.live .status').textContent.match(/done in (\d+) ms/) ||
                [])[1]));
        if (r.error || !(ms >= 0)) break;
        times.push(ms);
    }
    times.sort((x, y) => x - y);
    const med = times[Math.floor(times.length / 2)];
    console.log(`check-web: Figure 2 re-run to t = 200 in the page: median ${med} ms (min ${
        times[0]}, max ${times[times.length - 1]})`);
    // a speed target, not a test (timings on a shared machine are noisy): a PASS/MISS line
    const ok = times.length === 5 && med < 200;
    console.log(
        `check-web: ${ok ? 'PASS' : 'MISS'} Figure 2 re-run to t = 200 under 200 ms (median of 5)`);
    await page.close();
    await compareFit(ctx, webdir, suslov, claims, check);
    await compareRecons(ctx, webdir, suslov, check);
}

module.exports = {run};
