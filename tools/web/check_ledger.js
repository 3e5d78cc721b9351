// make check-web, the ledger as a tool: a card for every line of claims.tsv, folded in groups that
// a link to a line opens; at 390 and 1400 px every card fits, its measured value and verdict in
// sight; what is measured and the test are typeset from claims_tex.tsv; the search finds a line by
// its id and by the paper's number (Proposition 5.1 is TeoL in paper/labels.tsv), a verdict filter
// in the URL shows exactly that verdict's lines, the site-wide search finds both, and every line's
// code link lands on a line of test code that holds the ledger call.
'use strict';
const fs = require('fs');
const path = require('path');
const {pathToFileURL} = require('url');

// In a source page: each code line's text, by the id of its line-number span.
function codeLines() {
    const out = {};
    for (const ln of document.querySelectorAll('.code .ln[id]')) {
        let t = '';
        for (let n = ln.nextSibling; n; n = n.nextSibling) {
            const s = n.textContent;
            if (s.includes('\n')) {
                t += s.split('\n')[0];
                break;
            }
            t += s;
        }
        out[ln.id] = t;
    }
    return out;
}

// The ids of the lines a reader sees: the card and its group not hidden.
const visible = (page) => page.evaluate(
    () => Array.from(document.querySelectorAll('#ledger article.claim'))
              .filter(
                  (r) => !r.hidden && !r.closest('details').hidden &&
                      !r.closest('details.group').hidden)
              .map((r) => r.id.slice(6)));

// With every group open: cards wider than the page, and cells cut off or out of the card.
function layout() {
    document.getElementById('ledger-open').click();
    const W = document.documentElement.clientWidth, out = [];
    for (const card of document.querySelectorAll('#ledger article.claim:not(.head)')) {
        const c = card.getBoundingClientRect();
        if (c.right > W + 1) out.push(`${card.id} ends at ${c.right}`);
        for (const cell of card.querySelectorAll('.c-m, .c-v, .c-id, .c-q, .c-t')) {
            const r = cell.getBoundingClientRect();
            if (r.left < c.left - 1 || r.right > c.right + 1 ||
                cell.scrollWidth > cell.clientWidth + 1)
                out.push(`${card.id} .${cell.className} at ${r.left}..${r.right} of ${c.left}..${
                    c.right}`);
        }
    }
    return {bad: out, sw: document.documentElement.scrollWidth, W};
}

async function checkLayout(page, url, check) {
    for (const width of [390, 1400]) {
        await page.setViewportSize({width, height: 900});
        await page.goto(url, {waitUntil: 'load'});
        const closed = await page.evaluate(
            () => Array.from(document.querySelectorAll('#ledger details.group'))
                      .every((g) => !g.open));
        check(closed, `ledger.html at ${width} px: every group folded at first`);
        const l = await page.evaluate(layout);
        check(
            l.bad.length === 0 && l.sw <= width,
            `ledger.html at ${
                width} px, every group open: each card fits, measured and verdict in sight`,
            `page ${l.sw} px; ${l.bad.length} cells out: ${l.bad.slice(0, 3).join('; ')}`);
    }
    await page.setViewportSize({width: 1400, height: 900});
}

// What is measured and the test, typeset: each card whose LaTeX holds math shows KaTeX there.
async function checkTypeset(page, url, claimsTsv, check) {
    const texTsv = path.join(path.dirname(claimsTsv), 'claims_tex.tsv');
    if (!fs.existsSync(texTsv)) {
        console.log('check-web: no claims_tex.tsv: the quantities are plain text');
        return;
    }
    const rows = fs.readFileSync(texTsv, 'utf8')
                     .split('\n')
                     .slice(1)
                     .filter((l) => l.trim())
                     .map((l) => l.split('\t'));
    await page.goto(url, {waitUntil: 'load'});
    const got = await page.evaluate(
        () => Object.fromEntries(Array.from(document.querySelectorAll('#ledger article.claim[id]'))
                                     .map((c) => [c.id.slice(6), {
                                              q: c.querySelectorAll('.c-q .katex').length,
                                              t: c.querySelectorAll('.c-t .katex').length,
                                              err: c.querySelectorAll('.katex-error').length,
                                              dollar: /\$/.test(c.querySelector('.c-q').textContent)
                                          }])));
    const bad = rows.filter(([id, q, t]) => {
                        const g = got[id];
                        return !g || g.err || g.dollar || (q.includes('$') && !g.q) ||
                            (t.includes('$') && !g.t);
                    })
                    .map((r) => r[0]);
    check(
        bad.length === 0,
        `ledger: what is measured and the test typeset on all ${rows.length} lines`,
        bad.slice(0, 4).join(' '));
}

// A link to one line opens its group and brings the line into view; a verdict in the URL shows
// exactly that verdict's lines.
async function checkNavigation(page, url, rows, col, check) {
    const id = rows[Math.floor(rows.length / 3)][0];
    await page.goto(url + '#claim-' + id, {waitUntil: 'load'});
    const seen = await page.evaluate((i) => {
        const el = document.getElementById('claim-' + i), r = el.getBoundingClientRect();
        return el.closest('details').open && el.closest('details.group').open && r.top >= 0 &&
            r.top < window.innerHeight;
    }, id);
    check(seen, `ledger.html#claim-${id}: its group opens and the line is in view`);
    const want = rows.filter((r) => r[col('verdict')] === 'not reproduced').map((r) => r[0]);
    await page.goto(url + '?verdict=not+reproduced', {waitUntil: 'load'});
    const shown = await visible(page);
    check(
        want.length > 0 && shown.length === want.length && want.every((w) => shown.includes(w)),
        `ledger.html?verdict=not+reproduced shows the ${want.length} not-reproduced lines`,
        `${shown.length} shown`);
}

async function checkSearch(page, url, rows, col, check) {
    await page.goto(url, {waitUntil: 'load'});
    const id = rows[Math.floor(rows.length / 2)][0];
    await page.fill('#ledger-q', id);
    const byId = await visible(page);
    check(
        byId.includes(id) && byId.every((v) => v.includes(id)), `ledger search by id finds ${id}`,
        byId.slice(0, 5).join(' '));
    // Proposition 5.1 is the label TeoL (paper/labels.tsv): the lines whose paper_ref names TeoL
    const teol = rows.filter((r) => /\bTeoL\b/.test(r[col('paper_ref')])).map((r) => r[0]);
    await page.fill('#ledger-q', 'Proposition 5.1');
    const byNum = await visible(page);
    check(
        teol.length > 0 && teol.every((t) => byNum.includes(t)),
        `ledger search "Proposition 5.1" finds the ${teol.length} TeoL lines`,
        `${byNum.length} shown; missing ${
            teol.filter((t) => !byNum.includes(t)).slice(0, 3).join(' ')}`);
    await page.fill('#ledger-q', '');
    for (const q of [id, 'Proposition 5.1']) {
        await page.fill('input.search', q);
        const hrefs = await page.evaluate(
            () => Array.from(document.querySelectorAll('nav .results a'))
                      .map((a) => a.getAttribute('href')));
        const want = q === id ? 'ledger.html#claim-' + id : 'stmt-TeoL.html';
        check(
            hrefs.includes(want), `site search "${q}" lists ${want}`, hrefs.slice(0, 4).join(' '));
    }
}

async function checkCodeLinks(page, url, rows, col, lineText, check) {
    if (col('source') < 0) {
        console.log('check-web: claims.tsv has no source column: no code links to check');
        return;
    }
    await page.goto(url, {waitUntil: 'load'});
    const links = await page.evaluate(
        () => Array.from(document.querySelectorAll('#ledger a.src'))
                  .map((a) => a.getAttribute('href')));
    check(
        links.length === rows.length, `ledger: a code link on each of the ${rows.length} lines`,
        `${links.length} links`);
    const bad = links.filter((h) => {
        const [f, a] = h.split('#');
        return !/ledger_\w*\(/.test((lineText[f] || {})[a] || '');
    });
    check(
        bad.length === 0,
        `ledger: each of ${links.length} code links lands on a line with the ledger call`,
        bad.slice(0, 4).join(' '));
}

async function checkLedger(ctx, webdir, claimsTsv, lineText, ids, check) {
    const url = pathToFileURL(path.join(webdir, 'ledger.html')).href;
    const rows = fs.readFileSync(claimsTsv, 'utf8')
                     .split('\n')
                     .filter((l) => l.trim())
                     .map((l) => l.split('\t'));
    const head = rows.shift();
    const col = (name) => head.indexOf(name);
    const missing =
        rows.map((r) => r[0]).filter((c) => !(ids['ledger.html'] || new Set()).has('claim-' + c));
    check(
        missing.length === 0, `ledger.html: a card for each of the ${rows.length} lines`,
        missing.slice(0, 5).join(', '));
    const page = await ctx.newPage();
    await checkLayout(page, url, check);
    await checkTypeset(page, url, claimsTsv, check);
    await checkNavigation(page, url, rows, col, check);
    await checkSearch(page, url, rows, col, check);
    await checkCodeLinks(page, url, rows, col, lineText, check);
    await page.close();
}

module.exports = {
    codeLines,
    checkLedger
};
