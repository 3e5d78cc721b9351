// make check-web: load every page of the web edition in headless Debian chromium (driven by
// playwright-core, pinned in tools/web/package-lock.json) and check what a reader relies on:
//   - a page loads with no failed request, no script error, and no request leaving file:// (no
//     network), and no element refers to an http(s):// resource;
//   - math has rendered: no raw \( \) \[ \] left in the text after KaTeX ran, no KaTeX error;
//   - every internal link resolves: the file exists and, for #anchor, the page has that id;
//   - every label of paper/equations.txt has an entry with its restatement typeset, a link to
//     the implementing code and a link to a test;
//   - the (taudyn) section shows the comment beside the code and links to the ledger line that
//     measures the order; a screenshot of it is written to WEB/shots/taudyn.png;
//   - every ledger line of claims.tsv has its row, every figure its image;
//   - every page at 390 px and at 1400 px wide has no horizontal page scroll;
//   - the ledger's search finds a line by its id and by the paper's number (Proposition 5.1), and
//     the site-wide search finds it too; every ledger line's code link lands on a line of test code
//     that holds the ledger call;
//   - the live pages compute what the CLI prints (check_live.js), when SUSLOV is given.
// Usage: node check_web.js WEBDIR EQUATIONS.TXT CLAIMS.TSV [SUSLOV]
// Last line: "check-web: N passed, N failed".
'use strict';
const fs = require('fs');
const path = require('path');
const { pathToFileURL } = require('url');
const { chromium } = require('playwright-core');

const [webdir, equationsTxt, claimsTsv, suslov] = process.argv.slice(2).map((p) => p && path.resolve(p));
const checkLive = require('./check_live.js');
const { codeLines, checkLedger } = require('./check_ledger.js');
if (!webdir || !equationsTxt || !claimsTsv) {
    console.error('usage: node check_web.js WEBDIR EQUATIONS.TXT CLAIMS.TSV');
    process.exit(2);
}
let passed = 0, failed = 0;
function check(ok, what, detail) {
    if (ok) passed++;
    else { failed++; console.log(`FAIL ${what}${detail ? ': ' + detail : ''}`); }
    return ok;
}

// The flags that work on this machine (no sandbox as root, no GPU, no background traffic).
const FLAGS = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'];

async function main() {
    const pages = fs.readdirSync(webdir).filter((f) => f.endsWith('.html')).sort();
    const profile = fs.mkdtempSync(path.join(require('os').tmpdir(), 'check-web-'));
    const ctx = await chromium.launchPersistentContext(profile, {
        executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true, args: FLAGS,
        viewport: { width: 1400, height: 900 },
    });
    const ids = {};          // page file -> Set of ids in its rendered DOM
    const lineText = {};     // test source page -> { L<n>: the text of code line n }
    const links = [];        // [from page, href]
    try {
        // nothing may leave the disk: a request for anything but file: or data: is recorded and aborted
        await ctx.route((url) => !/^(file|data|blob):/.test(url.href), (route) => route.abort());
        for (const file of pages) {
            // a fresh tab per page, so that nothing one page does is counted against the next
            const offsite = [], badreq = [], errors = [];
            const tab = await ctx.newPage();
            tab.on('request', (r) => { if (!/^(file|data|blob):/.test(r.url())) offsite.push(r.url()); });
            tab.on('requestfailed', (r) => badreq.push(r.url() + ' (' + (r.failure() || {}).errorText + ')'));
            tab.on('pageerror', (e) => errors.push(String(e)));
            tab.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
            await tab.goto(pathToFileURL(path.join(webdir, file)).href, { waitUntil: 'load' });
            const info = await tab.evaluate(() => {
                // code is shown as written (KaTeX leaves pre and code alone): look at the rest
                const prose = document.body.cloneNode(true);
                for (const el of prose.querySelectorAll('pre, code, script, style')) el.remove();
                for (const el of prose.querySelectorAll('.katex')) el.remove();
                const text = prose.textContent;
                const refs = [];
                for (const el of document.querySelectorAll('[href],[src]')) {
                    const v = el.getAttribute('href') || el.getAttribute('src');
                    refs.push([el.tagName.toLowerCase(), v]);
                }
                return {
                    raw: (text.match(/\\\(|\\\)|\\\[|\\\]/g) || []).length,
                    mathSource: document.querySelectorAll('.math').length,
                    katex: document.querySelectorAll('.katex').length,
                    katexErrors: Array.from(document.querySelectorAll('.katex-error')).map((e) => e.getAttribute('title') || e.textContent),
                    ids: Array.from(document.querySelectorAll('[id]')).map((e) => e.id),
                    refs,
                };
            });
            check(offsite.length === 0, `${file}: no network request`, offsite.slice(0, 3).join(' '));
            check(badreq.length === 0, `${file}: every resource loads`, badreq.slice(0, 3).join(' '));
            check(errors.length === 0, `${file}: no script error`, errors.slice(0, 3).join(' | '));
            const remote = info.refs.filter(([, v]) => /^(https?:)?\/\//i.test(v));
            check(remote.length === 0, `${file}: no http(s):// reference`, remote.slice(0, 3).map((r) => r.join(' ')).join(', '));
            check(info.raw === 0 && info.katexErrors.length === 0 && info.katex >= info.mathSource,
                `${file}: math rendered`, `${info.raw} raw delimiters, ${info.katexErrors.length} KaTeX errors ` +
                `(${info.katexErrors.slice(0, 2).join('; ')}), ${info.katex} rendered of ${info.mathSource} blocks`);
            ids[file] = new Set(info.ids);
            for (const [, v] of info.refs) links.push([file, v]);
            if (/^tests-/.test(file)) lineText[file] = await tab.evaluate(codeLines);
            for (const width of [1400, 390]) {
                await tab.setViewportSize({ width, height: 900 });
                const sw = await tab.evaluate(() => document.documentElement.scrollWidth);
                check(sw <= width, `${file}: no horizontal page scroll at ${width} px`,
                    `page is ${sw} px wide`);
            }
            await tab.close();
        }
        const page = await ctx.newPage();

        // Style sheets fetch fonts and images too: none of them from the network.
        const css = [];
        (function walk(d) {
            for (const e of fs.readdirSync(d, { withFileTypes: true })) {
                const p = path.join(d, e.name);
                if (e.isDirectory()) walk(p); else if (e.name.endsWith('.css')) css.push(p);
            }
        })(webdir);
        const remoteCss = css.filter((f) => /url\(\s*['"]?(https?:)?\/\//i.test(fs.readFileSync(f, 'utf8')));
        check(css.length > 0 && remoteCss.length === 0, `${css.length} style sheets: no url() to the network`,
            remoteCss.map((f) => path.relative(webdir, f)).join(', '));

        // Internal links: the target file exists, and the anchor is an id of the target page.
        const bad = {};
        let nlinks = 0;
        for (const [from, href] of links) {
            if (/^(https?:)?\/\//i.test(href) || href.startsWith('data:')) continue;   // counted above
            nlinks++;
            const [p, frag] = href.split('#');
            const target = p === '' ? from : decodeURIComponent(p);
            const full = path.join(webdir, target);
            let why = null;
            if (!fs.existsSync(full)) why = 'no file ' + target;
            else if (frag && target.endsWith('.html') && !(ids[target] || new Set()).has(decodeURIComponent(frag))) why = 'no anchor #' + frag + ' in ' + target;
            if (why) (bad[from] = bad[from] || []).push(`${href} (${why})`);
        }
        for (const file of pages) check(!bad[file], `${file}: internal links resolve`, (bad[file] || []).slice(0, 5).join(', '));
        console.log(`check-web: ${pages.length} pages loaded, ${nlinks} internal links checked`);

        // Every implemented label: an entry, its restatement typeset, a code link and a test link.
        const labels = fs.readFileSync(equationsTxt, 'utf8').split('\n')
            .filter((l) => l.trim() && !l.startsWith('#')).map((l) => l.trim().split(/\s+/)[0])
            .filter((l, i, all) => all.indexOf(l) === i);
        await page.goto(pathToFileURL(path.join(webdir, 'equations.html')).href, { waitUntil: 'load' });
        for (const lab of labels) {
            const e = await page.evaluate((l) => {
                const d = document.getElementById('eq-' + l);
                if (!d) return null;
                return { impl: d.querySelectorAll('a.impl').length, test: d.querySelectorAll('a.test').length,
                    katex: d.querySelectorAll('.math .katex').length };
            }, lab);
            check(e && e.impl > 0 && e.test > 0 && e.katex > 0, `(${lab}): entry with code link, test link and typeset restatement`,
                e ? `${e.impl} code links, ${e.test} test links, ${e.katex} typeset` : 'no entry #eq-' + lab);
        }

        // The (taudyn) page: the comment beside the code, a working link to the ledger line that
        // measures the order, and a screenshot for a person to look at.
        const implHref = await page.evaluate(() => {
            const a = document.querySelector('#eq-taudyn a.impl');
            return a ? a.getAttribute('href') : null;
        });
        if (check(implHref !== null, '(taudyn): implementing function linked from the equations page')) {
            await page.goto(new URL(implHref, page.url()).href, { waitUntil: 'load' });
            const sec = page.locator('section.sec', { has: page.locator('[id="' + implHref.split('#')[1] + '"]') });
            const s = await sec.evaluate((el) => {
                const p = el.querySelector('.prose').getBoundingClientRect();
                const c = el.querySelector('.code').getBoundingClientRect();
                const order = Array.from(el.querySelectorAll('.prose a[href^="ledger.html#claim-"]'))
                    .map((a) => a.getAttribute('href')).filter((h) => /#claim-reduced-order-/.test(h));
                return { beside: p.right <= c.left + 1 && p.top < c.bottom && c.top < p.bottom,
                    cites: /\(taudyn\)/.test(el.querySelector('.prose').innerText), order };
            });
            check(s.beside && s.cites, '(taudyn) section: the comment beside the code', JSON.stringify(s));
            if (check(s.order.length > 0, '(taudyn) section: links to the ledger line of its order')) {
                const id = s.order[0].split('#')[1];
                check(ids['ledger.html'] && ids['ledger.html'].has(id), `(taudyn) section: ledger line ${id} exists`);
            }
            fs.mkdirSync(path.join(webdir, 'shots'), { recursive: true });
            await sec.scrollIntoViewIfNeeded();
            const shot = path.join(webdir, 'shots', 'taudyn.png');
            await page.screenshot({ path: shot, fullPage: false, clip: await sec.boundingBox().then((b) => ({
                x: 0, y: Math.max(0, b.y - 40), width: 1400, height: Math.min(900, b.height + 40) })) });
            check(fs.statSync(shot).size > 10000, '(taudyn) screenshot written', shot);
            console.log(`check-web: screenshot ${path.relative(process.cwd(), shot)}`);
        }

        // The ledger: one row per line of claims.tsv; the figures: every image decoded.
        const claims = fs.readFileSync(claimsTsv, 'utf8').split('\n').slice(1).filter((l) => l.trim()).map((l) => l.split('\t')[0]);
        const missing = claims.filter((c) => !(ids['ledger.html'] || new Set()).has('claim-' + c));
        check(missing.length === 0, `ledger.html: a row for each of the ${claims.length} claims`, missing.slice(0, 5).join(', '));
        await checkLedger(page, webdir, claimsTsv, lineText, check);
        if (suslov) {
            // id -> measured value as printed (%g), for the live pages' comparison with the ledger
            const measured = new Map(fs.readFileSync(claimsTsv, 'utf8').split('\n').slice(1)
                                         .filter((l) => l.trim()).map((l) => l.split('\t')).map((f) => [f[0], f[3]]));
            await checkLive.run(ctx, webdir, suslov, measured, check);
        }
        else console.log('check-web: no SUSLOV given: the live pages were not compared with the CLI');
        await page.goto(pathToFileURL(path.join(webdir, 'figures.html')).href, { waitUntil: 'load' });
        const imgs = await page.evaluate(() => Array.from(document.images).map((i) => [i.getAttribute('src'), i.naturalWidth]));
        check(imgs.length > 0 && imgs.every(([, w]) => w > 0), `figures.html: ${imgs.length} figures decoded`,
            imgs.filter(([, w]) => !(w > 0)).map(([s]) => s).join(', '));
    } finally {
        await ctx.close();
        fs.rmSync(profile, { recursive: true, force: true });
    }
}

main().then(() => {
    console.log(`check-web: ${passed} passed, ${failed} failed`);
    process.exit(failed ? 1 : 0);
}, (e) => {
    console.error('check-web: ' + (e && e.stack || e));
    console.log(`check-web: ${passed} passed, ${failed + 1} failed`);
    process.exit(1);
});
