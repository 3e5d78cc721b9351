// The live pages' runner: the integrators compiled to WebAssembly (make wasm; suslov_wasm.js holds
// the module) run in a Web Worker, so that a long run never freezes the page and can be stopped.
// A run returns the rows the suslov command prints (k, t, w1, w2, w3, lambda, E, R11 .. R33), or
// the library's one-line message and the CLI's exit status (2 bad input, 3 failed step).
'use strict';
(function() {
const NCOL = 16;

// Runs inside the worker: instantiate the module, then answer each list of jobs.
function workerMain() {
    let e = null;
    const text = (p) => {
        const b = new Uint8Array(e.memory.buffer);
        let q = p;
        while (b[q]) q++;
        return new TextDecoder().decode(b.subarray(p, q));
    };
    // The C fit of orderfit.c over the points (eps, err): slope, intercept, used, eps range, floor.
    function fit(j) {
        const FIT_MAX = 64,
              buf = new Float64Array(e.memory.buffer, e.wasm_fit_input(), 2 * FIT_MAX);
        buf.set(j.eps);
        buf.set(j.err, FIT_MAX);
        return {
            rc: 0,
            fit: Array.from(
                new Float64Array(e.memory.buffer, e.wasm_fit(j.eps.length, j.epsMax, j.size), 6))
        };
    }
    function job(j) {
        if (j.kind === 'fit') return fit(j);
        new Float64Array(e.memory.buffer, e.wasm_input(), 11).set(j.w0.concat(j.inertia));
        if (j.column) e.wasm_inertia_column();
        if (j.kind === 'limit')
            return {rc: 0, limit: Array.from(new Float64Array(e.memory.buffer, e.wasm_limit(), 2))};
        const t0 = performance.now();
        const rc = j.kind === 'sweeps' ? e.wasm_sweeps(j.n, j.recon, j.eps, j.steps, j.every) :
            j.kind === 'omega'         ? e.wasm_exact_omega(j.eps, j.steps, j.every) :
                                         e.wasm_run(j.method, j.recon, j.eps, j.steps, j.every);
        const ms = performance.now() - t0;
        const n = Number(e.wasm_nrows());
        const rows = rc === 2 ? new Float64Array(0) :
                                new Float64Array(e.memory.buffer, e.wasm_rows(), n * 16).slice();
        return {rc, ms, rows, message: text(e.wasm_message())};
    }
    self.onmessage = (ev) => {
        if (ev.data.wasm) {
            const bytes = Uint8Array.from(atob(ev.data.wasm), (c) => c.charCodeAt(0));
            const mod = new WebAssembly.Module(bytes);
            const imports = {};
            // the library calls no system function; an import (stdio's) only says "not supported"
            for (const im of WebAssembly.Module.imports(mod))
                (imports[im.module] = imports[im.module] || {})[im.name] = () => 52;
            e = new WebAssembly.Instance(mod, imports).exports;
            const methods = [];
            for (let i = 0; i < e.wasm_method_count(); i++)
                methods.push({
                    name: text(e.wasm_method_name(i)),
                    about: text(e.wasm_method_about(i)),
                    recon: e.wasm_method_recon(i),
                    index: i
                });
            const recons = [];
            for (let i = 0; i < e.wasm_recon_count(); i++) recons.push(text(e.wasm_recon_name(i)));
            self.postMessage({ready: true, methods, recons});
            return;
        }
        const out = [];
        for (const j of ev.data.jobs) {
            const r = job(j);
            out.push(r);
            self.postMessage({progress: out.length, of: ev.data.jobs.length});
            if (r.rc && !j.mayFail) break;
        }
        self.postMessage({id: ev.data.id, results: out});
    };
}

let worker = null, ready = null, pending = null, nextId = 1, reconNames = [];
function start() {
    const blob = new Blob(['(' + workerMain.toString() + ')()'], {type: 'text/javascript'});
    worker = new Worker(URL.createObjectURL(blob));
    ready = new Promise((resolve) => {
        worker.onmessage = (ev) => {
            if (ev.data.ready) {
                reconNames = ev.data.recons;
                resolve(ev.data.methods);
                return;
            }
            if (ev.data.progress && pending && pending.onProgress)
                pending.onProgress(ev.data.progress, ev.data.of);
            if (ev.data.results && pending && pending.id === ev.data.id) {
                const p = pending;
                pending = null;
                p.resolve(ev.data.results);
            }
        };
    });
    worker.postMessage({wasm: window.SUSLOV_WASM});
}

// Runs a list of jobs; resolves with one result per job (stopping after the first failure).
function run(jobs, onProgress) {
    if (!worker) start();
    return ready.then(() => new Promise((resolve, reject) => {
                          const id = nextId++;
                          pending = {id, resolve, reject, onProgress};
                          worker.postMessage({id, jobs});
                      }));
}

// Stops a run that takes too long: the worker is ended and a fresh one started.
function stop() {
    if (!worker) return;
    worker.terminate();
    worker = null;
    if (pending) {
        const p = pending;
        pending = null;
        p.reject(new Error('stopped'));
    }
}

function methods() {
    if (!worker) start();
    return ready;
}

// Column c of the rows (c: 0 k, 1 t, 2 w1, 3 w2, 4 w3, 5 lambda, 6 E, 7.. R by rows).
function column(rows, c) {
    const n = rows.length / NCOL, out = new Float64Array(n);
    for (let i = 0; i < n; i++) out[i] = rows[i * NCOL + c];
    return out;
}

// An input field as a number, with the CLI's message when it is not one.
function number(opt, s) {
    const v = Number(String(s).trim());
    if (String(s).trim() === '' || Number.isNaN(v))
        throw new Error(`${opt}: '${s}' is not a number`);
    if (!Number.isFinite(v)) throw new Error(`${opt}: '${s}' is not a finite number`);
    return v;
}
function list(opt, s, n) {
    const parts = String(s).split(',');
    if (parts.length !== n)
        throw new Error(`${opt} takes ${n} comma-separated numbers, got ${parts.length} in '${s}'`);
    return parts.map((p) => number(opt, p));
}

// The body fields every live form has: w(0), the inertia as typed and its reading.
function body(form) {
    return {
        w0: list('--omega0', form.omega0.value, 2),
        inertia: list('--inertia', form.inertia.value, 9),
        column: form.reading.value === 'col'
    };
}

// Wires a live form: the method lists from the module's registry, Run (handler(form) does
// the work and throws the one-line message on bad input), Stop, a running clock. The form's
// data-runs counts finished runs (the browser tests wait on it).
function bindForm(form, handler) {
    const status = form.querySelector('.status'), err = form.querySelector('.error');
    methods().then((ms) => {
        for (const sel of form.querySelectorAll('select[data-methods]')) {
            for (const m of ms)
                sel.add(new Option(m.name, m.index, false, m.name === sel.dataset.default));
            sel.title = 'registered methods of src/methods/registry.c';
        }
        // the reconstructions of src/core/reconstruct.c, after "the method's own" (-1)
        for (const sel of form.querySelectorAll('select[data-recons]'))
            reconNames.forEach((r, i) => sel.add(new Option(r, i)));
        form.dataset.ready = '1';
    });
    form.stop.onclick = () => {
        stop();
        status.textContent = 'stopped';
    };
    let runs = 0;
    form.onsubmit = async (ev) => {
        ev.preventDefault();
        err.hidden = true;
        form.stop.disabled = false;
        const t0 = performance.now();
        const clock = setInterval(() => {
            status.textContent = `running ${((performance.now() - t0) / 1000).toFixed(1)} s`;
        }, 100);
        status.textContent = 'running';
        try {
            await handler(form);
            status.textContent = `done in ${(performance.now() - t0).toFixed(0)} ms`;
        } catch (e) {
            err.textContent = e.message;
            err.hidden = false;
            status.textContent = '';
        } finally {
            clearInterval(clock);
            form.stop.disabled = true;
            form.dataset.runs = String(++runs);
        }
    };
    methods().then(() => form.requestSubmit());
}

// The results of a list of jobs, or the first failure's message as an error.
async function runAll(jobs, form) {
    const res = await run(jobs, (k, n) => {
        form.querySelector('.status').textContent = `running: ${k} of ${n} runs`;
    });
    window.LIVE_LAST = {jobs, results: res};
    const bad = res.find((r) => r.rc);
    if (bad) throw new Error(bad.message);
    return res;
}

window.Live = {
    run,
    runAll,
    stop,
    methods,
    column,
    number,
    list,
    body,
    bindForm,
    NCOL
};
})();
