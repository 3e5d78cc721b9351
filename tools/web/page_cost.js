// What each live page costs a reader: the bytes it loads (every file: request, by the file's
// size on disk) and the time of a first load in headless chromium, from navigation to the
// load event, to the WebAssembly module ready (the method lists filled) and to the first run
// drawn. Each of R rounds opens a fresh browser profile (no cache) and visits the pages in
// turn, so that the pages are interleaved; it prints the median, min and max. Timings on a
// shared machine are noisy: report them with the machine and its load.
// Usage: node page_cost.js WEBDIR [ROUNDS]
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {fileURLToPath, pathToFileURL} = require('url');
const {chromium} = require('playwright-core');

const PAGES = ['live-fig2.html', 'live-convergence.html', 'live-work.html', 'live-attitude.html'];
const FLAGS =
    ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking'];

async function visit(ctx, file) {
    const tab = await ctx.newPage();
    const files = new Set();
    tab.on('request', (r) => {
        if (r.url().startsWith('file:')) files.add(fileURLToPath(r.url()));
    });
    const t0 = Date.now();
    await tab.goto(pathToFileURL(file).href, {waitUntil: 'load'});
    const load = Date.now() - t0;
    await tab.waitForFunction(
        () => document.querySelector('form.live').dataset.ready, null, {polling: 5});
    const ready = Date.now() - t0;
    await tab.waitForFunction(
        () => document.querySelector('form.live').dataset.runs, null,
        {polling: 5, timeout: 120000});
    const run = Date.now() - t0;
    await tab.close();
    let bytes = 0;
    for (const f of files) bytes += fs.statSync(f).size;
    return {bytes, load, ready, run};
}

const stats = (xs) => {
    const s = xs.slice().sort((a, b) => a - b);
    return `${s[Math.floor(s.length / 2)]} (${s[0]}..${s[s.length - 1]})`;
};

async function main() {
    const [webdir, rounds] = [process.argv[2], Number(process.argv[3] || 5)];
    const res = Object.fromEntries(PAGES.map((p) => [p, []]));
    for (let r = 0; r < rounds; r++) {
        const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'page-cost-'));
        const ctx = await chromium.launchPersistentContext(profile, {
            executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
            headless: true,
            args: FLAGS
        });
        for (const p of PAGES) res[p].push(await visit(ctx, path.resolve(webdir, p)));
        await ctx.close();
        fs.rmSync(profile, {recursive: true, force: true});
    }
    console.log('page\tbytes\tload ms\tmodule ready ms\tfirst run drawn ms (median (min..max))');
    for (const p of PAGES) {
        const v = res[p];
        console.log([
            p, v[0].bytes, stats(v.map((x) => x.load)), stats(v.map((x) => x.ready)),
            stats(v.map((x) => x.run))
        ].join('\t'));
    }
}
main().catch((e) => {
    console.error(e);
    process.exit(1);
});
