// The ledger as a tool: free-text search (id, paper number such as "Proposition 5.1", words) and
// filters by verdict, statement, method and test direction. The lines are grouped by statement,
// each group folded (the lines beyond the paper folded again by the first word of their ids): a
// search or a filter opens the groups that hold a match and hides the others; a link to one line
// (#claim-ID) opens its groups. The state is kept in the URL's query
// (?q=...&verdict=...) so that a view can be linked.
'use strict';
(function() {
const groups = Array.from(document.querySelectorAll('#ledger details.group'));
const subs = Array.from(document.querySelectorAll('#ledger details.sub'));
const cards = Array.from(document.querySelectorAll('#ledger article.claim'));
const q = document.getElementById('ledger-q');
const selects = Array.from(document.querySelectorAll('select[data-filter]'));
const count = document.getElementById('ledger-count');

function matches(r, words) {
    if (!words.every((w) => r.dataset.search.includes(w))) return false;
    for (const s of selects) {
        const want = s.value, have = r.dataset[s.dataset.filter] || '';
        if (want &&
            !(s.dataset.filter === 'statement' ? have.split(' ').includes(want) : have === want))
            return false;
    }
    return true;
}

function apply() {
    const words = q.value.toLowerCase().split(/\s+/).filter(Boolean);
    const active = words.length > 0 || selects.some((s) => s.value);
    let shown = 0;
    for (const g of groups.concat(subs)) {
        let here = 0;
        for (const r of g.querySelectorAll('article.claim')) {
            r.hidden = !matches(r, words);
            here += !r.hidden;
        }
        if (g.classList.contains('group')) shown += here;
        g.hidden = here === 0;
        if (active && here) g.open = true;
        const n = g.querySelector('.g-count');
        n.dataset.all = n.dataset.all || n.textContent;
        n.textContent = active ? `${here} of ${n.dataset.all}` : n.dataset.all;
    }
    count.textContent = `${shown} of ${cards.length} lines`;
    const p = new URLSearchParams();
    if (q.value) p.set('q', q.value);
    for (const s of selects)
        if (s.value) p.set(s.dataset.filter, s.value);
    history.replaceState(null, '', (p.toString() ? '?' + p : location.pathname) + location.hash);
}

// A link to a line or a group: open the group, then bring the line into view.
function follow() {
    const el = location.hash && document.getElementById(decodeURIComponent(location.hash.slice(1)));
    if (!el) return;
    for (let d = el.closest('details'); d; d = d.parentElement.closest('details')) {
        d.hidden = false;
        d.open = true;
    }
    if (el.hidden) {  // filtered out: show it anyway
        el.hidden = false;
    }
    el.scrollIntoView();
}

const params = new URLSearchParams(location.search);
q.value = params.get('q') || '';
for (const s of selects) s.value = params.get(s.dataset.filter) || '';
q.oninput = apply;
for (const s of selects) s.onchange = apply;
const all = groups.concat(subs);
document.getElementById('ledger-open').onclick = () => all.forEach((g) => g.open = !g.hidden);
document.getElementById('ledger-close').onclick = () => all.forEach((g) => g.open = false);
window.addEventListener('hashchange', follow);
apply();
follow();
})();
