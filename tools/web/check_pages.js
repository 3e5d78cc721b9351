// make check-web, the pages a reader meets first: the home page opens with the findings of
// paper/findings.tsv and paper/errata.tsv and a figure; each statement page is headed by the
// paper's number and quotes the statement from the paper's source (or, built without it, says so);
// each equation entry is headed by its number and shows the display as printed; every figure opens
// its PNG at full size; a label of the paper is shown by the number the paper prints.
'use strict';
const fs = require('fs');
const path = require('path');
const {pathToFileURL} = require('url');

// Rows of a tab-separated table with a header row, as objects.
function tsv(file) {
    if (!fs.existsSync(file)) return [];
    const [head, ...rows] = fs.readFileSync(file, 'utf8').split('\n').filter((l) => l.trim());
    const keys = head.split('\t');
    return rows.map((r) => Object.fromEntries(r.split('\t').map((v, i) => [keys[i], v])));
}

// A heading that starts with the paper's own name and number of a statement.
const NAMED =
    /^(Definition|Proposition|Theorem|Corollary|Remark|Algorithm|Figure|Lemma) \d+(\.\d+)?/;

// Was the site built with the paper's source? Then paper_macros.js holds its macros.
function quoted(webdir) {
    const f = path.join(webdir, 'paper_macros.js');
    return fs.existsSync(f) && /PAPER_MACROS = \{"/.test(fs.readFileSync(f, 'utf8'));
}

// In any page: figures not inside a link to their own PNG, and label links in prose whose text is
// a LaTeX label rather than the paper's number ((37), 37, Proposition 5.1).
function pageFacts() {
    const figs =
        Array.from(document.images).filter((i) => /^figures\/.*\.png$/.test(i.getAttribute('src')));
    const unlinked = figs.filter((i) => {
                             const a = i.closest('a');
                             return !a || a.getAttribute('href') !== i.getAttribute('src');
                         })
                         .map((i) => i.getAttribute('src'));
    const bare = Array.from(document.querySelectorAll('a.label'))
                     .filter((a) => !a.closest('pre, .code'))
                     .map((a) => a.textContent.trim())
                     .filter((t) => !/^(\(\d|\d|[A-Z][a-z]+ \d)/.test(t));
    return {unlinked, bare};
}

async function checkHome(ctx, webdir, paperDir, check) {
    const findings = tsv(path.join(paperDir, 'findings.tsv'));
    const errata = tsv(path.join(paperDir, 'errata.tsv'));
    const want = findings.filter((f) => f.verdict === 'not reproduced').map((f) => f.id);
    const tab = await ctx.newPage();
    for (const width of [390, 1400]) {
        await tab.setViewportSize({width, height: 900});
        await tab.goto(pathToFileURL(path.join(webdir, 'index.html')).href, {waitUntil: 'load'});
        const h = await tab.evaluate(() => {
            const top = (el) => (el ? el.getBoundingClientRect().top + window.scrollY : Infinity);
            const hl = document.querySelector('section.headline');
            const img = hl && hl.querySelector('img');
            const ids = (sel) =>
                Array.from(document.querySelectorAll(sel)).map((b) => b.textContent);
            return {
                firstH2: (document.querySelector('main h2') || {}).textContent,
                top: top(hl),
                errataTop: top(document.querySelector('.hl-erratum')),
                notReproduced: ids('.hl-not-reproduced li > a > b'),
                errata: ids('.hl-erratum li > a > b'),
                img: img && {
                    w: img.naturalWidth,
                    top: top(img),
                    src: img.getAttribute('src'),
                    href: img.closest('a') && img.closest('a').getAttribute('href')
                },
            };
        });
        check(
            h.firstH2 === 'What we found' && h.top < 900,
            `index.html at ${width} px: opens with what was found`,
            JSON.stringify(h).slice(0, 200));
        check(
            want.every((id) => h.notReproduced.includes(id)),
            `index.html: the ${want.length} not-reproduced findings in the headline`,
            h.notReproduced.join(' '));
        check(
            errata.every((e) => h.errata.includes(e.id)),
            `index.html: the ${errata.length} errata in the headline`, h.errata.join(' '));
        check(
            h.img && h.img.w > 0 && h.img.href === h.img.src && h.img.top < h.errataTop,
            `index.html at ${width} px: a figure, linked full size, before the errata`,
            JSON.stringify(h.img));
    }
    await tab.close();
}

async function checkStatements(ctx, webdir, check) {
    const withSource = quoted(webdir);
    const files = fs.readdirSync(webdir).filter((f) => /^stmt-.*\.html$/.test(f));
    const tab = await ctx.newPage();
    let good = 0;
    const bad = [];
    for (const f of files) {
        await tab.goto(pathToFileURL(path.join(webdir, f)).href, {waitUntil: 'load'});
        const s = await tab.evaluate(() => {
            const q = document.querySelector('blockquote.quote');
            return {
                h1: document.querySelector('main h1').textContent,
                head: q && q.querySelector('.qhead').textContent,
                text: q ? q.textContent.length : 0,
                noquote: !!document.querySelector('p.noquote'),
                errors: q ? q.querySelectorAll('.katex-error').length : 0
            };
        });
        const name = (s.h1.match(NAMED) || [''])[0];
        const ok = name &&
            (withSource ? s.head === name + '.' && s.text > name.length + 40 && s.errors === 0 :
                          s.noquote);
        if (ok)
            good++;
        else
            bad.push(`${f}: ${JSON.stringify(s)}`);
    }
    check(
        files.length > 0 && good === files.length,
        `${files.length} statement pages: headed by the paper's number, ` +
            (withSource ? 'the statement quoted from its source' :
                          'saying that the source was missing'),
        bad.slice(0, 3).join('; '));
    await tab.close();
}

// Each implemented label's entry: headed by its number; with the source, the display as printed.
async function checkEquations(page, webdir, equationsTxt, labelsTsv, check) {
    const kinds = Object.fromEntries(tsv(labelsTsv).map((r) => [r.label.trim(), r.kind]));
    const labels = [...new Set(fs.readFileSync(equationsTxt, 'utf8')
                                   .split('\n')
                                   .filter((l) => l.trim() && !l.startsWith('#'))
                                   .map((l) => l.trim().split(/\s+/)[0]))];
    await page.goto(pathToFileURL(path.join(webdir, 'equations.html')).href, {waitUntil: 'load'});
    const bad = [];
    for (const lab of labels) {
        const e = await page.evaluate((l) => {
            const d = document.getElementById('eq-' + l);
            return d && {
                h2: d.querySelector('h2').textContent,
                printed: d.querySelectorAll('.printed .katex').length
            };
        }, lab);
        const numbered = e && /^(Equation \(\d|[A-Z][a-z]+ \d)/.test(e.h2);
        const printed =
            !quoted(webdir) || !/equation/.test(kinds[lab] || '') || (e && e.printed > 0);
        if (!numbered || !printed) bad.push(`${lab}: ${JSON.stringify(e)}`);
    }
    check(
        bad.length === 0,
        `equations.html: ${labels.length} entries headed by the paper's number` +
            (quoted(webdir) ? ', each equation as printed' : ''),
        bad.slice(0, 3).join('; '));
}

module.exports = {
    pageFacts,
    checkHome,
    checkStatements,
    checkEquations,
    tsv
};
