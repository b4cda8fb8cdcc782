// Drops the custom sections (names, producers, debug info) of wasm modules, in place: the
// split chunks come out of the splitter with their function names, which the app never needs.
//
//   node scripts/wasm-strip.mjs a.wasm b.wasm ...
import { readFileSync, writeFileSync } from 'node:fs';

/** Reads an unsigned LEB128 at `pos`: [value, next position]. */
export function leb(bytes, pos) {
  let value = 0;
  let shift = 0;
  for (;;) {
    const byte = bytes[pos++];
    value += (byte & 0x7f) * 2 ** shift;
    shift += 7;
    if (byte < 0x80) return [value, pos];
  }
}

/** `bytes` (a wasm module) without its custom sections. */
export function stripCustomSections(bytes) {
  if (bytes.length < 8 || bytes.readUInt32LE(0) !== 0x6d736100) throw new Error('not a wasm module');
  const parts = [bytes.subarray(0, 8)];
  let pos = 8;
  while (pos < bytes.length) {
    const start = pos;
    const id = bytes[pos++];
    const [size, body] = leb(bytes, pos);
    pos = body + size;
    if (id !== 0) parts.push(bytes.subarray(start, pos));
  }
  return Buffer.concat(parts);
}

if (import.meta.url === `file://${process.argv[1]}`) {
  for (const file of process.argv.slice(2)) {
    writeFileSync(file, stripCustomSections(readFileSync(file)));
  }
}
