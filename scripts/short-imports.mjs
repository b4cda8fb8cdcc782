// Gives the main wasm's imports from its glue short names, in the wasm and in the glue alike:
// wasm-bindgen names each `__wbg_<name>_<16 hex digits>`, and those random digits, written
// twice (import section and glue), are several KB gzipped of every first load. An import `n`
// (0, 1, ...) becomes `n.toString(36)`; nothing else changes. The build fails if an import's
// name is not exactly one key of the glue's import object.
//
//   node scripts/short-imports.mjs dist/pkg/bsv_playground_bg.wasm dist/pkg/bsv_playground.js
import { readFileSync, writeFileSync } from 'node:fs';
import { leb } from './wasm-strip.mjs';

/** The glue's module name in the wasm's imports (`wasm-bindgen --out-name bsv_playground`). */
const GLUE = './bsv_playground_bg.js';

function u32(value) {
  const out = [];
  do {
    let byte = value & 0x7f;
    value = Math.floor(value / 128);
    if (value) byte |= 0x80;
    out.push(byte);
  } while (value);
  return Buffer.from(out);
}

function name(text) {
  const bytes = Buffer.from(text, 'utf8');
  return Buffer.concat([u32(bytes.length), bytes]);
}

/** Skips a limits entry (table, memory) at `at`. */
function skipLimits(bytes, at) {
  const flags = bytes[at++];
  [, at] = leb(bytes, at);
  if (flags & 1) [, at] = leb(bytes, at);
  return at;
}

/** `wasm` with its import section rewritten by `rename(module, field)` (a new field name or
 * `undefined` to keep it); the renames made, old → new. */
export function renameImports(wasm, rename) {
  const renamed = new Map();
  let at = 8;
  while (at < wasm.length) {
    const id = wasm[at];
    const [size, body] = leb(wasm, at + 1);
    const end = body + size;
    if (id !== 2) {
      at = end;
      continue;
    }
    let [count, p] = leb(wasm, body);
    const parts = [u32(count)];
    for (let i = 0; i < count; i++) {
      const [moduleLength, m] = leb(wasm, p);
      const module = wasm.subarray(m, m + moduleLength).toString('utf8');
      const [fieldLength, f] = leb(wasm, m + moduleLength);
      const field = wasm.subarray(f, f + fieldLength).toString('utf8');
      let q = f + fieldLength;
      const kind = wasm[q++];
      if (kind === 0) [, q] = leb(wasm, q);
      else if (kind === 1) q = skipLimits(wasm, q + 1);
      else if (kind === 2) q = skipLimits(wasm, q);
      else if (kind === 3) q += 2;
      else if (kind === 4) [, q] = leb(wasm, q + 1);
      else throw new Error(`import ${module}.${field}: unknown kind ${kind}`);
      const short = rename(module, field);
      if (short !== undefined) renamed.set(field, short);
      parts.push(name(module), name(short ?? field), wasm.subarray(f + fieldLength, q));
      p = q;
    }
    if (p !== end) throw new Error('import section: length does not match its entries');
    const section = Buffer.concat(parts);
    return {
      wasm: Buffer.concat([wasm.subarray(0, at), Buffer.from([2]), u32(section.length), section, wasm.subarray(end)]),
      renamed,
    };
  }
  throw new Error('no import section');
}

function main() {
  const [wasmFile, glueFile] = process.argv.slice(2);
  if (!glueFile) throw new Error('usage: node scripts/short-imports.mjs WASM GLUE');
  let glue = readFileSync(glueFile, 'utf8');
  let n = 0;
  const { wasm, renamed } = renameImports(readFileSync(wasmFile), (module) =>
    module === GLUE ? (n++).toString(36) : undefined,
  );
  for (const [field, short] of renamed) {
    // Object keys of the import object: `field:` after `{` or `,` (the glue is minified).
    const key = new RegExp(`([{,])${field.replace(/\$/g, '\\$')}:`, 'g');
    const found = glue.match(key)?.length ?? 0;
    if (found !== 1 || glue.split(field).length !== 2) {
      throw new Error(`${glueFile}: import ${field} is not exactly one key of the import object`);
    }
    glue = glue.replace(key, `$1${JSON.stringify(short)}:`);
  }
  writeFileSync(wasmFile, wasm);
  writeFileSync(glueFile, glue);
  new WebAssembly.Module(wasm);
  console.log(`short-imports: ${renamed.size} imports renamed`);
}

if (import.meta.url === `file://${process.argv[1]}`) main();
