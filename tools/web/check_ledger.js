// make check-web, the ledger as a tool: its search finds a line by id and by the paper's number
// (Proposition 5.1 is TeoL in paper/labels.tsv), the site-wide search finds both, and every
// line's code link lands on a line of test code that holds the ledger call.
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

// The ledger as a tool: its search by id and by published number, the site search, the code links.
async function checkLedger(page, webdir, claimsTsv, lineText, check) {
    const url = pathToFileURL(path.join(webdir, 'ledger.html')).href;
    const rows =
        fs.readFileSync(claimsTsv, 'utf8').split('\n').filter((l) => l.trim()).map((l) => l.split('\t'));
    const head = rows.shift();
    const col = (name) => head.indexOf(name);
    await page.setViewportSize({width: 1400, height: 900});
    await page.goto(url, {waitUntil: 'load'});
    const visible = () => page.evaluate(
        () => Array.from(document.querySelectorAll('#ledger tbody tr'))
                  .filter((r) => !r.hidden)
                  .map((r) => r.id.slice(6)));
    const id = rows[Math.floor(rows.length / 2)][0];
    await page.fill('#ledger-q', id);
    const byId = await visible();
    check(
        byId.includes(id) && byId.every((v) => v.includes(id)), `ledger search by id finds ${id}`,
        byId.slice(0, 5).join(' '));
    // Proposition 5.1 is the label TeoL (paper/labels.tsv): the lines whose paper_ref names TeoL
    const teol = rows.filter((r) => /\bTeoL\b/.test(r[col('paper_ref')])).map((r) => r[0]);
    await page.fill('#ledger-q', 'Proposition 5.1');
    const byNum = await visible();
    check(
        teol.length > 0 && teol.every((t) => byNum.includes(t)),
        `ledger search "Proposition 5.1" finds the ${teol.length} TeoL lines`,
        `${byNum.length} shown; missing ${teol.filter((t) => !byNum.includes(t)).slice(0, 3).join(' ')}`);
    await page.fill('#ledger-q', '');
    for (const q of [id, 'Proposition 5.1']) {
        await page.fill('input.search', q);
        const hrefs = await page.evaluate(
            () =>
                Array.from(document.querySelectorAll('nav .results a')).map((a) => a.getAttribute('href')));
        const want = q === id ? 'ledger.html#claim-' + id : 'stmt-TeoL.html';
        check(hrefs.includes(want), `site search "${q}" lists ${want}`, hrefs.slice(0, 4).join(' '));
    }
    if (col('source') < 0) {
        console.log('check-web: claims.tsv has no source column: no code links to check');
        return;
    }
    const links = await page.evaluate(
        () => Array.from(document.querySelectorAll('#ledger a.src')).map((a) => a.getAttribute('href')));
    check(
        links.length === rows.length, `ledger: a code link on each of the ${rows.length} lines`,
        `${links.length} links`);
    const bad = links.filter((h) => {
        const [f, a] = h.split('#');
        return !/ledger_\w*\(/.test((lineText[f] || {})[a] || '');
    });
    check(
        bad.length === 0, `ledger: each of ${links.length} code links lands on a line with the ledger call`,
        bad.slice(0, 4).join(' '));
}

module.exports = {
    codeLines,
    checkLedger
};
