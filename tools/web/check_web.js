// make check-web: load every page of the web edition in headless Debian chromium (driven by
// playwright-core, pinned in tools/web/package-lock.json) and check what a reader relies on:
//   - a page loads with no failed request, no script error, and no request leaving file:// (no
//     network), and no element refers to an http(s):// resource;
//   - math has rendered: no raw \( \) \[ \] left in the text after KaTeX ran, no KaTeX error;
//   - every internal link resolves: the file exists and, for #anchor, the page has that id;
//   - every page at 390 px and at 1400 px wide has no horizontal page scroll; every figure opens
//     its PNG at full size; a label of the paper is shown by the number the paper prints;
//   - the home page, the statement pages and the equations (check_pages.js);
//   - every label of paper/equations.txt has an entry with its restatement typeset, a link to
//     the implementing code and a link to a test;
//   - the (taudyn) section shows the comment beside the code and links to the ledger line that
//     measures the order; a screenshot of it is written to WEB/shots/taudyn.png;
//   - the ledger: a card for every line of claims.tsv, readable at 390 and 1400 px, its search,
//     filters and code links (check_ledger.js); every figure decoded;
//   - the live pages compute what the CLI prints, with labelled views and readable axes
//     (check_live.js), when SUSLOV is given.
// Usage: node check_web.js WEBDIR EQUATIONS.TXT CLAIMS.TSV [SUSLOV]
// (paper/equations.txt's folder holds labels.tsv, findings.tsv and errata.tsv.)
// Last line: "check-web: N passed, N failed".
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {pathToFileURL} = require('url');
const {chromium} = require('playwright-core');

const [webdir, equationsTxt, claimsTsv, suslov] =
    process.argv.slice(2).map((p) => p && path.resolve(p));
const checkLive = require('./check_live.js');
const {codeLines, checkLedger} = require('./check_ledger.js');
const pages = require('./check_pages.js');
if (!webdir || !equationsTxt || !claimsTsv) {
    console.error('usage: node check_web.js WEBDIR EQUATIONS.TXT CLAIMS.TSV [SUSLOV]');
    process.exit(2);
}
const paperDir = path.dirname(equationsTxt);
let passed = 0, failed = 0;
function check(ok, what, detail) {
    if (ok)
        passed++;
    else {
        failed++;
        console.log(`FAIL ${what}${detail ? ': ' + detail : ''}`);
    }
    return ok;
}

// The flags that work on this machine (no sandbox as root, no GPU, no background traffic).
const FLAGS = [
    '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'
];

// In a page, after KaTeX ran: raw delimiters left, KaTeX errors, ids, and every href and src.
function pageInfo() {
    // code is shown as written (KaTeX leaves pre and code alone): look at the rest
    const prose = document.body.cloneNode(true);
    for (const el of prose.querySelectorAll('pre, code, script, style, .katex')) el.remove();
    const refs =
        Array.from(document.querySelectorAll('[href],[src]'))
            .map(
                (el) =>
                    [el.tagName.toLowerCase(), el.getAttribute('href') || el.getAttribute('src')]);
    return {
        raw: (prose.textContent.match(/\\\(|\\\)|\\\[|\\\]/g) || []).length,
        mathSource: document.querySelectorAll('.math').length,
        katex: document.querySelectorAll('.katex').length,
        katexErrors: Array.from(document.querySelectorAll('.katex-error'))
                         .map((e) => e.getAttribute('title') || e.textContent),
        ids: Array.from(document.querySelectorAll('[id]')).map((e) => e.id),
        refs,
    };
}

// One page in a fresh tab (nothing one page does counts against the next): loads, math, links
// out, widths, figures and labels. Returns its ids and references.
async function checkPage(ctx, file, lineText) {
    const offsite = [], badreq = [], errors = [];
    const tab = await ctx.newPage();
    tab.on('request', (r) => {
        if (!/^(file|data|blob):/.test(r.url())) offsite.push(r.url());
    });
    tab.on(
        'requestfailed', (r) => badreq.push(r.url() + ' (' + (r.failure() || {}).errorText + ')'));
    tab.on('pageerror', (e) => errors.push(String(e)));
    tab.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
    });
    await tab.goto(pathToFileURL(path.join(webdir, file)).href, {waitUntil: 'load'});
    const info = await tab.evaluate(pageInfo);
    check(offsite.length === 0, `${file}: no network request`, offsite.slice(0, 3).join(' '));
    check(badreq.length === 0, `${file}: every resource loads`, badreq.slice(0, 3).join(' '));
    check(errors.length === 0, `${file}: no script error`, errors.slice(0, 3).join(' | '));
    const remote = info.refs.filter(([, v]) => /^(https?:)?\/\//i.test(v));
    check(
        remote.length === 0, `${file}: no http(s):// reference`,
        remote.slice(0, 3).map((r) => r.join(' ')).join(', '));
    check(
        info.raw === 0 && info.katexErrors.length === 0 && info.katex >= info.mathSource,
        `${file}: math rendered`,
        `${info.raw} raw delimiters, ${info.katexErrors.length} KaTeX errors ` +
            `(${info.katexErrors.slice(0, 2).join('; ')}), ${info.katex} rendered of ${
                info.mathSource} blocks`);
    const facts = await tab.evaluate(pages.pageFacts);
    check(
        facts.unlinked.length === 0, `${file}: every figure opens its PNG full size`,
        facts.unlinked.join(' '));
    check(
        facts.bare.length === 0, `${file}: labels shown by the paper's numbers`,
        facts.bare.slice(0, 5).join(' '));
    if (/^tests-/.test(file)) lineText[file] = await tab.evaluate(codeLines);
    for (const width of [1400, 390]) {
        await tab.setViewportSize({width, height: 900});
        const sw = await tab.evaluate(() => document.documentElement.scrollWidth);
        check(
            sw <= width, `${file}: no horizontal page scroll at ${width} px`,
            `page is ${sw} px wide`);
    }
    await tab.close();
    return info;
}

// Style sheets fetch fonts and images too: none of them from the network.
function checkCss() {
    const css = [];
    (function walk(d) {
        for (const e of fs.readdirSync(d, {withFileTypes: true})) {
            const p = path.join(d, e.name);
            if (e.isDirectory())
                walk(p);
            else if (e.name.endsWith('.css'))
                css.push(p);
        }
    })(webdir);
    const remote =
        css.filter((f) => /url\(\s*['"]?(https?:)?\/\//i.test(fs.readFileSync(f, 'utf8')));
    check(
        css.length > 0 && remote.length === 0,
        `${css.length} style sheets: no url() to the network`,
        remote.map((f) => path.relative(webdir, f)).join(', '));
}

// Internal links: the target file exists, and the anchor is an id of the target page.
function checkLinks(files, ids, links) {
    const bad = {};
    let n = 0;
    for (const [from, href] of links) {
        if (/^(https?:)?\/\//i.test(href) || href.startsWith('data:')) continue;  // counted above
        n++;
        const [p, frag] = href.split('#');
        const target = p === '' ? from : decodeURIComponent(p.split('?')[0]);
        let why = null;
        if (!fs.existsSync(path.join(webdir, target)))
            why = 'no file ' + target;
        else if (
            frag && target.endsWith('.html') &&
            !(ids[target] || new Set()).has(decodeURIComponent(frag)))
            why = 'no anchor #' + frag + ' in ' + target;
        if (why) (bad[from] = bad[from] || []).push(`${href} (${why})`);
    }
    for (const f of files)
        check(!bad[f], `${f}: internal links resolve`, (bad[f] || []).slice(0, 5).join(', '));
    console.log(`check-web: ${files.length} pages loaded, ${n} internal links checked`);
}

// Every implemented label: an entry, its restatement typeset, a code link and a test link.
async function checkEntries(page) {
    const labels = [...new Set(fs.readFileSync(equationsTxt, 'utf8')
                                   .split('\n')
                                   .filter((l) => l.trim() && !l.startsWith('#'))
                                   .map((l) => l.trim().split(/\s+/)[0]))];
    await page.goto(pathToFileURL(path.join(webdir, 'equations.html')).href, {waitUntil: 'load'});
    for (const lab of labels) {
        const e = await page.evaluate((l) => {
            const d = document.getElementById('eq-' + l);
            if (!d) return null;
            return {
                impl: d.querySelectorAll('a.impl').length,
                test: d.querySelectorAll('a.test').length,
                katex: d.querySelectorAll('.restated .math .katex').length
            };
        }, lab);
        check(
            e && e.impl > 0 && e.test > 0 && e.katex > 0,
            `(${lab}): entry with code link, test link and typeset restatement`,
            e ? `${e.impl} code links, ${e.test} test links, ${e.katex} typeset` :
                'no entry #eq-' + lab);
    }
}

// The (taudyn) page: the comment beside the code, a working link to the ledger line that
// measures the order, and a screenshot for a person to look at.
async function checkTaudyn(page, ids) {
    await page.goto(pathToFileURL(path.join(webdir, 'equations.html')).href, {waitUntil: 'load'});
    const href = await page.evaluate(() => {
        const a = document.querySelector('#eq-taudyn a.impl');
        return a ? a.getAttribute('href') : null;
    });
    if (!check(href !== null, '(taudyn): implementing function linked from the equations page'))
        return;
    await page.goto(new URL(href, page.url()).href, {waitUntil: 'load'});
    const sec =
        page.locator('section.sec', {has: page.locator('[id="' + href.split('#')[1] + '"]')});
    const s = await sec.evaluate((el) => {
        const p = el.querySelector('.prose').getBoundingClientRect();
        const c = el.querySelector('.code').getBoundingClientRect();
        const order = Array.from(el.querySelectorAll('.prose a[href^="ledger.html#claim-"]'))
                          .map((a) => a.getAttribute('href'))
                          .filter((h) => /#claim-reduced-order-/.test(h));
        return {
            beside: p.right <= c.left + 1 && p.top < c.bottom && c.top < p.bottom,
            cites: !!el.querySelector('.prose a.label[href$="#eq-taudyn"]'),
            order
        };
    });
    check(s.beside && s.cites, '(taudyn) section: the comment beside the code', JSON.stringify(s));
    if (check(s.order.length > 0, '(taudyn) section: links to the ledger line of its order')) {
        const id = s.order[0].split('#')[1];
        check(
            ids['ledger.html'] && ids['ledger.html'].has(id),
            `(taudyn) section: ledger line ${id} exists`);
    }
    fs.mkdirSync(path.join(webdir, 'shots'), {recursive: true});
    await sec.scrollIntoViewIfNeeded();
    const shot = path.join(webdir, 'shots', 'taudyn.png');
    const b = await sec.boundingBox();
    await page.screenshot({
        path: shot,
        fullPage: false,
        clip: {x: 0, y: Math.max(0, b.y - 40), width: 1400, height: Math.min(900, b.height + 40)}
    });
    check(fs.statSync(shot).size > 10000, '(taudyn) screenshot written', shot);
    console.log(`check-web: screenshot ${path.relative(process.cwd(), shot)}`);
}

async function main() {
    const files = fs.readdirSync(webdir).filter((f) => f.endsWith('.html')).sort();
    const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'check-web-'));
    const ctx = await chromium.launchPersistentContext(profile, {
        executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
        headless: true,
        args: FLAGS,
        viewport: {width: 1400, height: 900},
    });
    const ids = {};       // page file -> Set of ids in its rendered DOM
    const lineText = {};  // test source page -> { L<n>: the text of code line n }
    const links = [];     // [from page, href]
    try {
        // nothing may leave the disk: a request for anything but file: or data: is aborted
        await ctx.route((url) => !/^(file|data|blob):/.test(url.href), (route) => route.abort());
        for (const file of files) {
            const info = await checkPage(ctx, file, lineText);
            ids[file] = new Set(info.ids);
            for (const [, v] of info.refs) links.push([file, v]);
        }
        checkCss();
        checkLinks(files, ids, links);
        const page = await ctx.newPage();
        await checkEntries(page);
        await checkTaudyn(page, ids);
        await pages.checkHome(ctx, webdir, paperDir, check);
        await pages.checkStatements(ctx, webdir, check);
        await pages.checkEquations(
            page, webdir, equationsTxt, path.join(paperDir, 'labels.tsv'), check);
        await checkLedger(ctx, webdir, claimsTsv, lineText, ids, check);
        if (suslov) {
            // id -> measured value as printed (%g), for the live pages' comparison with the ledger
            const measured = new Map(pages.tsv(claimsTsv).map((r) => [r.id, r.measured]));
            await checkLive.run(ctx, webdir, suslov, measured, check);
        } else
            console.log(
                'check-web: no SUSLOV given: the live pages were not compared with the CLI');
        await page.goto(pathToFileURL(path.join(webdir, 'figures.html')).href, {waitUntil: 'load'});
        const imgs = await page.evaluate(
            () => Array.from(document.images).map((i) => [i.getAttribute('src'), i.naturalWidth]));
        check(
            imgs.length > 0 && imgs.every(([, w]) => w > 0),
            `figures.html: ${imgs.length} figures decoded`,
            imgs.filter(([, w]) => !(w > 0)).map(([s]) => s).join(', '));
    } finally {
        await ctx.close();
        fs.rmSync(profile, {recursive: true, force: true});
    }
}

main().then(
    () => {
        console.log(`check-web: ${passed} passed, ${failed} failed`);
        process.exit(failed ? 1 : 0);
    },
    (e) => {
        console.error('check-web: ' + (e && e.stack || e));
        console.log(`check-web: ${passed} passed, ${failed + 1} failed`);
        process.exit(1);
    });
