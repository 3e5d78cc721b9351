// The ledger as a tool: free-text search (id, paper number such as "Proposition 5.1", words),
// filters by verdict, statement, method and test direction, and sortable columns (numbers
// numerically). The state is kept in the URL's query (?q=...&verdict=...) so that a view can be linked.
'use strict';
(function() {
const table = document.getElementById('ledger'), body = table.tBodies[0];
const rows = Array.from(body.rows), q = document.getElementById('ledger-q');
const selects = Array.from(document.querySelectorAll('select[data-filter]'));
const count = document.getElementById('ledger-count');
function apply() {
    const words = q.value.toLowerCase().split(/\s+/).filter(Boolean);
    let shown = 0;
    for (const r of rows) {
        let ok = words.every((w) => r.dataset.search.includes(w));
        for (const s of selects) {
            const want = s.value, have = r.dataset[s.dataset.filter] || '';
            if (want &&
                !(s.dataset.filter === 'statement' ? have.split(' ').includes(want) : have === want))
                ok = false;
        }
        r.hidden = !ok;
        shown += ok;
    }
    count.textContent = `${shown} of ${rows.length} lines`;
    const p = new URLSearchParams();
    if (q.value) p.set('q', q.value);
    for (const s of selects)
        if (s.value) p.set(s.dataset.filter, s.value);
    history.replaceState(null, '', (p.toString() ? '?' + p : location.pathname) + location.hash);
}
const params = new URLSearchParams(location.search);
q.value = params.get('q') || '';
for (const s of selects) s.value = params.get(s.dataset.filter) || '';
q.oninput = apply;
for (const s of selects) s.onchange = apply;

const num = (t) => {
    const v = parseFloat(t);
    return Number.isNaN(v) ? null : v;
};
Array.from(table.tHead.rows[0].cells).forEach((th, k) => {
    th.tabIndex = 0;
    th.title = 'sort';
    const sort = () => {
        const dir = th.dataset.dir === 'asc' ? -1 : 1;
        for (const h of table.tHead.rows[0].cells) delete h.dataset.dir;
        th.dataset.dir = dir === 1 ? 'asc' : 'desc';
        const key = (r) => r.cells[k].textContent.trim();
        rows.sort((a, b) => {
            const x = num(key(a)), y = num(key(b));
            return dir * (x !== null && y !== null ? x - y : key(a).localeCompare(key(b)));
        });
        for (const r of rows) body.appendChild(r);
    };
    th.onclick = sort;
    th.onkeydown = (e) => {
        if (e.key === 'Enter') sort();
    };
});
apply();
})();
