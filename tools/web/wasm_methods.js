// The registry's method names, one a line, read from the WebAssembly module (make wasm): what
// build.py uses when build/methods.tsv (written by the claims program) is not there.
// Usage: node wasm_methods.js SUSLOV.WASM
'use strict';
const fs = require('fs');
const nosys = () => 52;
const mod = new WebAssembly.Module(fs.readFileSync(process.argv[2]));
const imports = {};
for (const im of WebAssembly.Module.imports(mod))
    (imports[im.module] = imports[im.module] || {})[im.name] = nosys;
const e = new WebAssembly.Instance(mod, imports).exports;
const text = (p) => {
    const b = new Uint8Array(e.memory.buffer);
    let q = p;
    while (b[q]) q++;
    return Buffer.from(b.subarray(p, q)).toString();
};
for (let i = 0; i < e.wasm_method_count(); i++) console.log(text(e.wasm_method_name(i)));
