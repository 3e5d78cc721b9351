// Every page: the jump-to menu (the page's sections: functions on a source page, headings
// elsewhere) and the site-wide search over search_index.js (pages, statements, ledger lines,
// equations, functions).
'use strict';
(function() {
const nav = document.querySelector('nav.top');
const jump = nav.querySelector('select.jump');
const targets = document.querySelectorAll('.code [id^="fn-"]').length ?
    Array.from(document.querySelectorAll('.code [id^="fn-"]'))
        .map((e) => [e.id, e.id.slice(3) + '()']) :
    Array.from(document.querySelectorAll('main h2[id], main h2, .eq[id] h2')).map((h, i) => {
        const el = h.closest('[id]') && h.closest('[id]') !== document.body ? h.closest('[id]') : h;
        if (!el.id) el.id = 'h-' + i;
        return [el.id, h.textContent.slice(0, 60)];
    });
for (const [id, label] of targets) jump.add(new Option(label, id));
jump.hidden = targets.length === 0;
jump.onchange = () => {
    if (jump.value) location.hash = jump.value;
    jump.value = '';
};

const box = nav.querySelector('input.search'), out = nav.querySelector('.results');
const index = window.SEARCH_INDEX || [];
function find(q) {
    const words = q.toLowerCase().split(/\s+/).filter(Boolean);
    if (!words.length) return [];
    const hits = [];
    for (const [text, href] of index) {
        const t = text.toLowerCase();
        if (words.every((w) => t.includes(w)))
            hits.push([text, href, t.startsWith(words[0]) ? 0 : 1]);
        if (hits.length > 400) break;
    }
    return hits.sort((a, b) => a[2] - b[2] || a[0].length - b[0].length).slice(0, 30);
}
box.oninput = () => {
    const hits = find(box.value);
    out.hidden = hits.length === 0 && !box.value;
    out.innerHTML = hits.length ?
        hits.map(
                ([t, h]) =>
                    `<a href="${h}">${t.replace(/[<&]/g, (c) => c === '<' ? '&lt;' : '&amp;')}</a>`)
            .join('') :
        (box.value ? '<span>no match</span>' : '');
};
box.onkeydown = (e) => {
    if (e.key === 'Enter') {
        const a = out.querySelector('a');
        if (a) location.href = a.href;
    }
};
document.addEventListener('click', (e) => {
    if (!nav.contains(e.target)) out.hidden = true;
});
})();
