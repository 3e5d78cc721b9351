// make web-shots: screenshots of pages of the web edition at a phone's width (390 px) and a
// desktop's (1400 px), for a person to look at (nothing is checked here: make check-web checks).
// Each page is shot from the top, at most MAXH px tall, to OUTDIR/PAGE-WIDTH.png; a page named
// with an anchor (ledger.html#g-TeoL) is opened there and shot from that element down.
// Usage: node shots.js WEBDIR OUTDIR PAGE...
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {pathToFileURL} = require('url');
const {chromium} = require('playwright-core');

const MAXH = Number(process.env.SHOTS_MAXH || 2400);  // px, at most
const FLAGS =
    ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking'];

async function shoot(ctx, webdir, outdir, spec, width) {
    const [file, id] = spec.split('#');
    const tab = await ctx.newPage();
    await tab.setViewportSize({width, height: 900});
    await tab.goto(
        pathToFileURL(path.join(webdir, file)).href + (id ? '#' + id : ''), {waitUntil: 'load'});
    await tab.waitForTimeout(300);  // KaTeX's auto-render runs on load
    if (await tab.$('form.live'))   // a live page: its first run drawn
        await tab.waitForFunction(
            () => document.querySelector('form.live').dataset.runs, null,
            {polling: 50, timeout: 120000});
    const top = id ? await tab.evaluate((i) => {
        const e = document.getElementById(i);
        return e ? e.getBoundingClientRect().top + window.scrollY : 0;
    }, id) : 0;
    const full = await tab.evaluate(() => document.documentElement.scrollHeight);
    const h = Math.max(100, Math.min(MAXH, full - top));
    await tab.setViewportSize({width, height: Math.min(MAXH, full)});
    const name = file.replace(/\.html$/, '') + (id ? '-' + id.replace(/[^A-Za-z0-9-]/g, '') : '');
    const out = path.join(outdir, `${name}-${width}.png`);
    await tab.screenshot({path: out, fullPage: true, clip: {x: 0, y: top, width, height: h}});
    await tab.close();
    return out;
}

async function main() {
    const [webdir, outdir, ...pages] = process.argv.slice(2);
    if (!webdir || !outdir || !pages.length) {
        console.error('usage: node shots.js WEBDIR OUTDIR PAGE...');
        process.exit(2);
    }
    fs.mkdirSync(outdir, {recursive: true});
    const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'web-shots-'));
    const ctx = await chromium.launchPersistentContext(
        profile,
        {executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: FLAGS});
    try {
        for (const p of pages)
            for (const w of [390, 1400]) console.log(await shoot(ctx, webdir, outdir, p, w));
    } finally {
        await ctx.close();
        fs.rmSync(profile, {recursive: true, force: true});
    }
}
main().catch((e) => {
    console.error('web-shots: ' + (e && e.stack || e));
    process.exit(1);
});
