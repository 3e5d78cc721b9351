// The attitude, live: the body frame R_k of a method (left) and the exact R(t_k) (right), drawn
// with WebGL as a wire box with its three axes, from one WebAssembly run; a slider picks k. The
// labels above the views name the method and its reconstruction; the key below names the axes.
'use strict';
(function() {
const form = document.querySelector('form.live'), canvas = document.getElementById('gl');
const slider = document.getElementById('k');
let runs = null;
// a box of half-sides (0.9, 0.6, 0.3): its 12 edges, then the axes (red e1, green e2, blue e3)
const box = [], col = [];
const c = [
    [-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1],
    [-1, 1, 1]
].map(([x, y, z]) => [0.9 * x, 0.6 * y, 0.3 * z]);
for (const [i, j] of [
         [0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [0, 4], [1, 5], [2, 6],
         [3, 7]]) {
    box.push(c[i], c[j]);
    col.push([0.3, 0.3, 0.3], [0.3, 0.3, 0.3]);
}
[[1.4, 0, 0], [0, 1.4, 0], [0, 0, 1.4]].forEach((a, i) => {
    box.push([0, 0, 0], a);
    const k = [0, 0, 0];
    k[i] = 0.85;
    col.push(k, k);
});

const gl = canvas.getContext('webgl', {antialias: true, preserveDrawingBuffer: true});
let prog = null;
if (gl) {
    const sh = (type, src) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, src);
        gl.compileShader(s);
        return s;
    };
    prog = gl.createProgram();
    gl.attachShader(
        prog,
        sh(gl.VERTEX_SHADER,
           'attribute vec3 p; attribute vec3 c; uniform mat3 R; varying vec3 v;' +
               'void main() { vec3 q = R * p;' +
               // a fixed view: the orthonormal rows (0.8, 0.6, 0) and (-0.36, 0.48, 0.8)
               'vec3 e = vec3(q.x * 0.8 + q.y * 0.6, -q.x * 0.36 + q.y * 0.48 + q.z * 0.8, 0.0);' +
               'gl_Position = vec4(e.x / 2.0, e.y / 2.0, 0.0, 1.0); v = c; }'));
    gl.attachShader(
        prog,
        sh(gl.FRAGMENT_SHADER,
           'precision mediump float; varying vec3 v;' +
               'void main() { gl_FragColor = vec4(v, 1.0); }'));
    gl.linkProgram(prog);
    for (const [name, data] of [['p', box], ['c', col]]) {
        gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
        gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data.flat()), gl.STATIC_DRAW);
        const loc = gl.getAttribLocation(prog, name);
        gl.enableVertexAttribArray(loc);
        gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
    }
} else {
    canvas.insertAdjacentHTML(
        'afterend', '<p class="error">WebGL is not available in this browser: no view.</p>');
}

// R from a row (R11 .. R33 at columns 7 .. 15), as WebGL's column-major mat3
const Rmat = (rows, k) => {
    const o = k * Live.NCOL + 7, r = rows.slice(o, o + 9);
    return new Float32Array([r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]]);
};

function show() {
    if (!runs) return;
    const k = Number(slider.value), [a, e] = runs;
    document.getElementById('kt').textContent =
        `= ${a.rows[k * Live.NCOL + 1].toPrecision(6)} (row ${k})`;
    let d = 0;
    for (let i = 7; i < 16; i++) d += (a.rows[k * Live.NCOL + i] - e.rows[k * Live.NCOL + i]) ** 2;
    document.getElementById('dist').textContent =
        `|R_k − R(t_k)| (Frobenius) = ${Math.sqrt(d).toExponential(3)}`;
    if (!gl) return;
    gl.useProgram(prog);
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    [a, e].forEach((r, side) => {
        gl.viewport(side * canvas.width / 2, 0, canvas.width / 2, canvas.height);
        gl.uniformMatrix3fv(gl.getUniformLocation(prog, 'R'), false, Rmat(r.rows, k));
        gl.drawArrays(gl.LINES, 0, box.length);
    });
}
slider.oninput = show;

async function draw(f) {
    const m = Number(f.m.value), eps = Live.number('--eps', f.eps.value),
          T = Live.number('--time', f.T.value);
    if (!(eps > 0)) throw new Error(`--eps must be positive, got ${eps}`);
    const steps = Math.round(T / eps);
    if (!(steps >= 1))
        throw new Error(`--time ${T} with --eps ${eps} gives ${steps} steps; need at least 1`);
    const every = Math.max(1, Math.ceil(steps / 600));
    const job = Object.assign(
        {kind: 'run', method: m, recon: Number(f.recon.value), eps, steps, every}, Live.body(f));
    runs = await Live.runAll([job, Object.assign({}, job, {method: -1})], f);
    const recon =
        f.recon.value === '-1' ? 'its own reconstruction' : f.recon.selectedOptions[0].text;
    document.getElementById('att-method').textContent =
        `${f.m.selectedOptions[0].text} (${recon}), \u03b5 = ${eps}`;
    slider.max = String(runs[0].rows.length / Live.NCOL - 1);
    slider.value = slider.max;
    show();
}
Live.bindForm(form, draw);
})();
