// Packs the wasm chunks of the split build (scripts/build-dist.sh) for the browser, and says
// what each route loads before its first frame.
//
// The splitter (wasm-split-cli) cuts the app's wasm into the main module (the shell), one
// module per split point (`page!` lines, the worker's kernels) and many small shared chunks,
// with a loader (`__wasm_split.js`) that fetches every chunk as a file of its own: about a
// hundred requests for one page. Here every module is written once, without its name section,
// as `chunks/<module>.wasm`; each split point's modules (its chunks, then itself; in the pack,
// itself first) are also written together as one pack, `pack_<split>.bin`; and the loader is
// rewritten to instantiate each module once per tab and to fetch a split point's missing
// modules in one request (its pack) when none of them is in yet, else, with a service worker,
// in one request for the missing ones (`?only=`, made by the worker from its cached modules),
// and without one each missing module from its file, reporting progress
// (`bsv-chunk-progress` events: split, loaded, total).
// The packs only serve first visits: the service worker caches the modules, not the packs
// (scripts/sw-build.mjs), and the app's size counts them once (scripts/size.mjs).
//
// Writes into PKG: `chunks/`, the packs, `__wasm_split.js`, `splits.json` (the modules of each
// split point, which the loader fetches once a tab's first split point is in), and
// `routes.json` (route id → its split, its pack and the Fluent files it needs;
// scripts/boot-table.mjs puts it at the head of boot.js).
//
//   node scripts/split-link.mjs SPLIT_DIR PKG_DIR
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import binaryen from 'binaryen';
import { stripCustomSections } from './wasm-strip.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');

/** The splitter's loader: its shared part (imports from the main module, the callback into
 * wasm), each chunk's file and each split point's file and chunks. */
export function parseLoader(js) {
  const first = js.indexOf('/* ');
  if (first < 0) throw new Error('__wasm_split.js: no chunk found');
  const header = js.slice(0, first);
  const chunkRe = /const (__chunk_\d+) = makeLoad\(\(\) => \{\n\s*const src = fetch\(new URL\("\.\/(chunk_\d+)\.wasm", import\.meta\.url\)\);[\s\S]*?\n, \[([^\]]*)\]\);/g;
  const chunks = new Map();
  for (const m of js.matchAll(chunkRe)) {
    chunks.set(m[1], { file: m[2], deps: names(m[3]) });
  }
  const splitRe = /export const __wasm_split_load_(\w+) = wrapAsyncCb\(makeLoad\(\(\) => \{\n\s*const src = fetch\(new URL\("\.\/(split_\w+)\.wasm", import\.meta\.url\)\);[\s\S]*?\n, \[([^\]]*)\]\)\);/g;
  const splits = new Map();
  for (const m of js.matchAll(splitRe)) {
    splits.set(m[1], { file: m[2], deps: names(m[3]) });
  }
  if (splits.size === 0) throw new Error('__wasm_split.js: no split point found');
  return { header, chunks, splits };
}

/** What rustc's wasm32 target emits (and browsers run without flags); binaryen writes newer
 * encodings, such as compact imports, only when they are enabled. */
const FEATURES =
  binaryen.Features.MutableGlobals |
  binaryen.Features.NontrappingFPToInt |
  binaryen.Features.BulkMemory |
  binaryen.Features.BulkMemoryOpt |
  binaryen.Features.SignExt |
  binaryen.Features.ReferenceTypes |
  binaryen.Features.Multivalue |
  binaryen.Features.CallIndirectOverlong;

/** Module `bytes` as the browser gets it: without custom sections (names), and written again
 * by binaryen (no optimisation pass, which could drop what only the table reaches), which keeps
 * only the types the module uses: the splitter gives every chunk the whole program's. */
export function slim(bytes) {
  // BSV_NAMES=1 (a build for profiling; scripts/build-dist.sh) keeps the functions' names.
  const names = process.env.BSV_NAMES === '1';
  binaryen.setDebugInfo(names);
  const module = binaryen.readBinary(names ? bytes : stripCustomSections(bytes));
  try {
    module.setFeatures(FEATURES);
    const emitted = Buffer.from(module.emitBinary());
    const out = names ? emitted : stripCustomSections(emitted);
    // Fails the build, not a visitor's page, if the module does not compile.
    new WebAssembly.Module(out);
    return out;
  } finally {
    module.dispose();
  }
}

function names(list) {
  return list.split(',').map((s) => s.trim()).filter(Boolean);
}

/** The module files of split `name`, its chunks (with theirs) first, itself last. */
export function modulesOf(loader, name) {
  const out = [];
  const seen = new Set();
  const visit = (chunk) => {
    if (seen.has(chunk)) return;
    seen.add(chunk);
    const entry = loader.chunks.get(chunk);
    if (!entry) throw new Error(`__wasm_split.js: unknown chunk ${chunk}`);
    entry.deps.forEach(visit);
    out.push(entry.file);
  };
  const split = loader.splits.get(name);
  split.deps.forEach(visit);
  out.push(split.file);
  return out;
}

/** A pack: `BSVP`, the module count (u32 LE), then per module its name's length, its name
 * (UTF-8), its length and its bytes (lengths u32 LE). */
export function pack(modules) {
  const parts = [Buffer.from('BSVP'), u32(modules.length)];
  // The split point's own module (the last of `modules`, much the largest) first: the loader
  // compiles each module as it arrives, so the last bytes in are small chunks, quick to compile.
  // The chunks keep their order (reordered by size, they gzip up to 2 KB worse).
  const order = [modules.at(-1), ...modules.slice(0, -1)];
  for (const { name, bytes } of order) {
    const id = Buffer.from(name);
    parts.push(u32(id.length), id, u32(bytes.length), bytes);
  }
  return Buffer.concat(parts);
}

function u32(n) {
  const b = Buffer.alloc(4);
  b.writeUInt32LE(n);
  return b;
}

/** The split points a page loads by itself once it is shown (its later part), by the page's
 * split point: each gets a pack of the modules it adds to the page's, for a first visit. */
export const FOLLOW_ON = {
  home_page: ['home_cards'],
  ik2r_page: ['ik2r_more'],
  umeyama_page: ['umeyama_more'],
  teleop_page: ['teleop_files'],
  so101_page: ['so101_files'],
};

/** Route id → `{ split, head, strings }` (its split point, the markup of its head with the ids
 * of its heading's and lede's messages, and the Fluent files it needs beyond the first ones),
 * from the page table's `page!(split, Type, id, title, head, nav, [files])` lines and its
 * `const …_HEAD: &str` lines. */
export function routesOfPageTable() {
  const table = readFileSync(join(ROOT, 'src/ui/pages/mod.rs'), 'utf8');
  const router = ['src/ui/router.rs', 'src/view/url.rs']
    .map((file) => readFileSync(join(ROOT, file), 'utf8'))
    .join('\n');
  const consts = Object.fromEntries(
    [...router.matchAll(/pub const (\w+): &str = "([^"]*)";/g)].map((m) => [m[1], m[2]]),
  );
  const heads = Object.fromEntries(
    [...table.matchAll(/^const (\w+_HEAD): &str = "((?:[^"\\]|\\.)*)";$/gm)].map((m) => [m[1], m[2].replace(/\\(.)/g, '$1')]),
  );
  const routes = {};
  for (const m of table.matchAll(/^\s*page!\((\w+),\s*[^,]+?,\s*("([^"]*)"|(\w+)),\s*"[^"]*",\s*(\w+),.*\[([^\]]*)\](?:,\s*"([^"]+)")?\),\s*$/gm)) {
    const id = m[3] ?? consts[m[4]];
    if (id === undefined) throw new Error(`page table: cannot resolve ${m[2]}`);
    const head = heads[m[5]];
    if (head === undefined) throw new Error(`page table: cannot resolve ${m[5]}`);
    routes[id] = { split: m[1], head, strings: [...m[6].matchAll(/"([^"]+)"/g)].map((f) => f[1]), sheet: m[7] ?? null };
  }
  if (Object.keys(routes).length === 0) throw new Error('page table: no page! line found');
  return routes;
}

/** The Fluent files every page needs first (`FIRST_FILES` of src/i18n.rs). */
export function firstStrings() {
  const source = readFileSync(join(ROOT, 'src/i18n.rs'), 'utf8');
  const list = /pub const FIRST_FILES: &\[&str\] = &\[([^\]]*)\]/.exec(source);
  if (!list) throw new Error('src/i18n.rs: no FIRST_FILES');
  return [...list[1].matchAll(/"([^"]+)"/g)].map((f) => f[1]);
}

const LOADER = `
// Each module is instantiated once per tab; a split point's modules come in one request (its
// pack) when none of them is here yet, else the missing ones in one request made by the
// service worker (\`?only=\`) or, without one, each from its file (scripts/split-link.mjs).
// PACKS[s]: the bytes of split point s's pack (pack_<s>.bin). Which modules each split point
// needs is in splits.json (SIZES[n]: the bytes of chunks/chunk_<n>.wasm; SPLITS[s].chunks: the
// chunks of split point s as ranges ("19-27,29"), before its own module split_<s>, SPLITS[s].own
// bytes): the first split point of a tab needs none of it (every module is missing, and the pack
// names its modules), so the table is fetched once that first split point is in, not before.
// AFTER[s]: the split points after which a pack of s's other modules stands,
// pack_<s>-after-<first>.bin: the part a page loads by itself once it is shown, after the
// tab's first split point (its page), in one request where the service worker is not there yet.
const PACKS = __PACKS__;
const AFTER = __AFTER__;
const instantiated = new Map();
let firstSplit;
let table;
function splitTable() {
    if (table === undefined) {
        table = fetch(new URL('./splits.json', import.meta.url)).then((response) => {
            if (!response.ok) throw new Error('splits.json: HTTP ' + response.status);
            return response.json();
        });
        table.catch(() => { table = undefined; });
    }
    return table;
}
async function modulesOf(split) {
    const { sizes, splits } = await splitTable();
    const { chunks, own } = splits[split];
    const out = [];
    for (const range of chunks ? chunks.split(',') : []) {
        const [first, last = first] = range.split('-').map(Number);
        for (let n = first; n <= last; n++) out.push(['chunk_' + n, sizes[n]]);
    }
    out.push(['split_' + split, own]);
    return out;
}
function progress(split, loaded, total) {
    if (typeof CustomEvent === 'function' && typeof globalThis.dispatchEvent === 'function') {
        globalThis.dispatchEvent(new CustomEvent('bsv-chunk-progress', { detail: { split, loaded, total } }));
    }
}
async function fetchBytes(file, count) {
    const response = await fetch(new URL('./' + file, import.meta.url));
    if (!response.ok) throw new Error(file + ': HTTP ' + response.status);
    const bytes = new Uint8Array(await response.arrayBuffer());
    count(bytes.length);
    return bytes;
}
// A pack ("BSVP", its module count, then per module its id's length, id, length, bytes; little
// endian u32s) read as it arrives: \`add(id, bytes)\` is given each module as soon as its bytes
// are in, so that compiling (and instantiating) overlaps the download. Returns the pack's ids.
async function fetchPack(file, count, add) {
    const response = await fetch(new URL('./' + file, import.meta.url));
    if (!response.ok) throw new Error(file + ': HTTP ' + response.status);
    const ids = [];
    let buffer = new Uint8Array(0);
    let at = 0;
    let left = -1;
    const take = (n) => {
        if (buffer.length - at < n) return null;
        const out = buffer.subarray(at, at + n);
        at += n;
        return out;
    };
    const u32 = (bytes) => new DataView(bytes.buffer, bytes.byteOffset, 4).getUint32(0, true);
    // Takes every whole entry from the buffer.
    const parse = () => {
        if (left < 0) {
            const head = take(8);
            if (!head) return;
            if (String.fromCharCode(...head.subarray(0, 4)) !== 'BSVP') throw new Error(file + ': not a pack');
            left = u32(head.subarray(4));
        }
        while (left > 0) {
            const start = at;
            const idLength = take(4);
            const id = idLength && take(u32(idLength));
            const length = id && take(4);
            const bytes = length && take(u32(length));
            if (!bytes) { at = start; return; }
            const name = new TextDecoder().decode(id);
            ids.push(name);
            add(name, bytes);
            left--;
        }
    };
    const append = (chunk) => {
        count(chunk.length);
        const rest = buffer.subarray(at);
        buffer = new Uint8Array(rest.length + chunk.length);
        buffer.set(rest);
        buffer.set(chunk, rest.length);
        at = 0;
        parse();
    };
    if (response.body && typeof response.body.getReader === 'function') {
        const reader = response.body.getReader();
        for (;;) {
            const { done, value } = await reader.read();
            if (done) break;
            append(value);
        }
    } else {
        append(new Uint8Array(await response.arrayBuffer()));
    }
    if (left !== 0 || at !== buffer.length) throw new Error(file + ': the pack is cut short');
    return ids;
}
// Fetches the modules of split point \`split\` that are not here yet, giving \`add\` each one (its
// id, its bytes or their promise); { ids: all of the split point's modules, first: whether it
// is the tab's first }. Some of them here already: with a service worker, one request still
// (\`pack_<split>.bin?only=...\`, which the worker makes from its cached modules; the network's
// answer, the whole pack, would do too), else one per module.
async function fetchModules(split, add) {
    let loaded = 0;
    const counter = (total) => (n) => { loaded += n; progress(split, loaded, total); };
    if (instantiated.size === 0) {
        firstSplit = split;
        // After www/boot.js's frame of the route is painted (in a worker, at once).
        await globalThis.bsvFramePainted;
        progress(split, 0, PACKS[split]);
        const ids = await fetchPack('pack_' + split + '.bin', counter(PACKS[split]), add);
        return { ids, first: true };
    }
    const modules = await modulesOf(split);
    const ids = modules.map(([id]) => id);
    const missing = modules.filter(([id]) => !instantiated.has(id));
    // The pack when none of them is here (the service worker makes it from its cached modules).
    if (missing.length === modules.length) {
        progress(split, 0, PACKS[split]);
        await fetchPack('pack_' + split + '.bin', counter(PACKS[split]), add);
        return { ids, first: false };
    }
    const total = missing.reduce((sum, [, bytes]) => sum + bytes, 0);
    const count = counter(total);
    progress(split, 0, total);
    if (missing.length > 1 && globalThis.navigator?.serviceWorker?.controller) {
        await fetchPack('pack_' + split + '.bin?only=' + missing.map(([id]) => id).join(','), count, add);
        return { ids, first: false };
    }
    // The pack of what this split point adds to the tab's first one, if it holds every missing
    // module (it may hold some that came since: add() skips them).
    if (missing.length > 1 && (AFTER[split] ?? []).includes(firstSplit)) {
        const theirs = new Set((await modulesOf(firstSplit)).map(([id]) => id));
        if (missing.every(([id]) => !theirs.has(id))) {
            await fetchPack('pack_' + split + '-after-' + firstSplit + '.bin', count, add);
            return { ids, first: false };
        }
    }
    await Promise.all(missing.map(([id]) => {
        const bytes = fetchBytes('chunks/' + id + '.wasm', count);
        add(id, bytes);
        return bytes;
    }));
    return { ids, first: false };
}
// Each module is compiled and instantiated as soon as its bytes are in (with the imports the
// splitter's makeLoad gives at once: the main module's memory, table and shared functions),
// unless it is here already; the split point is in when all of its modules are.
function loadSplit(split) {
    return makeLoad(() => {
        let give;
        const imports = new Promise((resolve) => { give = resolve; });
        const mine = new Map();
        const add = (id, bytes) => {
            if (instantiated.has(id)) return;
            // compile() copies the bytes before it returns.
            const module = Promise.resolve(bytes).then((b) => WebAssembly.compile(b));
            const done = Promise.all([module, imports]).then(([m, i]) => WebAssembly.instantiate(m, i));
            instantiated.set(id, done);
            mine.set(id, done);
            done.catch(() => instantiated.delete(id));
        };
        const listed = fetchModules(split, add);
        listed.catch(() => {});
        return async (given) => {
            give(given);
            const { ids, first } = await listed;
            await Promise.all(ids.map((id) => mine.get(id) ?? instantiated.get(id)));
            // The table, for the next split point: asked for once the first one's frame is
            // painted (in a worker, at once), so that it does not compete with that frame.
            if (first && typeof requestAnimationFrame === 'function') {
                requestAnimationFrame(() => setTimeout(() => splitTable().catch(() => {}), 0));
            } else if (first) {
                splitTable().catch(() => {});
            }
        };
    }, []);
}
`;

/** Split point `name`'s modules as the loader lists them: its chunks as ranges of their
 * numbers (`"19-27,29"`, each chunk's size once in `sizes`) and the size of its own module
 * (`split_<name>`, last). */
export function listOf(name, modules, sizes) {
  const own = modules.at(-1);
  if (own.name !== `split_${name}`) throw new Error(`split ${name}: its own module is ${own.name}`);
  const numbers = modules.slice(0, -1).map(({ name: file, bytes }) => {
    const m = /^chunk_(\d+)$/.exec(file);
    if (!m) throw new Error(`split ${name}: module ${file} is not a chunk`);
    const n = Number(m[1]);
    sizes[n] = bytes.length;
    return n;
  });
  const sorted = [...numbers].sort((a, b) => a - b);
  const ranges = [];
  for (const n of sorted) {
    const last = ranges.at(-1);
    if (last && n === last[1] + 1) last[1] = n;
    else ranges.push([n, n]);
  }
  const chunks = ranges.map(([a, b]) => (a === b ? `${a}` : `${a}-${b}`)).join(',');
  return { chunks, own: own.bytes.length };
}

function main() {
  const [splitDir, pkgDir] = process.argv.slice(2);
  if (!pkgDir) throw new Error('usage: node scripts/split-link.mjs SPLIT_DIR PKG_DIR');
  const js = readFileSync(join(splitDir, '__wasm_split.js'), 'utf8');
  const loader = parseLoader(js);
  mkdirSync(join(pkgDir, 'chunks'), { recursive: true });
  const packs = {};
  const splits = {};
  const sizes = [];
  const written = new Set();
  const slims = new Map();
  const slimmed = (file) => {
    if (!slims.has(file)) slims.set(file, slim(readFileSync(join(splitDir, `${file}.wasm`))));
    return slims.get(file);
  };
  for (const name of [...loader.splits.keys()].sort()) {
    const modules = modulesOf(loader, name).map((file) => ({
      name: file,
      bytes: slimmed(file),
    }));
    for (const { name: file, bytes } of modules) {
      if (!written.has(file)) writeFileSync(join(pkgDir, 'chunks', `${file}.wasm`), bytes);
      written.add(file);
    }
    const bytes = pack(modules);
    const file = `pack_${name}.bin`;
    writeFileSync(join(pkgDir, file), bytes);
    packs[name] = { file, bytes: bytes.length };
    splits[name] = listOf(name, modules, sizes);
  }
  // The part each page loads by itself once it is shown, after its page's own modules.
  const after = {};
  for (const [first, laters] of Object.entries(FOLLOW_ON)) {
    for (const later of laters) {
      if (!packs[first] || !packs[later]) throw new Error(`FOLLOW_ON: no split point ${packs[first] ? later : first}`);
      const theirs = new Set(modulesOf(loader, first));
      const modules = modulesOf(loader, later)
        .filter((file) => !theirs.has(file))
        .map((file) => ({ name: file, bytes: slimmed(file) }));
      writeFileSync(join(pkgDir, `pack_${later}-after-${first}.bin`), pack(modules));
      (after[later] ??= []).push(first);
    }
  }
  const header = loader.header.replace(
    'console.error(e);',
    "console.warn('BSV Playground: a part of the app could not be loaded:', e);",
  );
  const exports = Object.keys(packs)
    .map((name) => `export const __wasm_split_load_${name} = wrapAsyncCb(loadSplit(${JSON.stringify(name)}));`)
    .join('\n');
  writeFileSync(
    join(pkgDir, '__wasm_split.js'),
    header +
      LOADER.replace('__PACKS__', JSON.stringify(Object.fromEntries(Object.entries(packs).map(([n, p]) => [n, p.bytes]))))
        .replace('__AFTER__', JSON.stringify(after)) +
      exports +
      '\n',
  );
  writeFileSync(
    join(pkgDir, 'splits.json'),
    JSON.stringify({ sizes: Array.from(sizes, (n) => n ?? 0), splits }) + '\n',
  );
  const routes = routesOfPageTable();
  for (const [route, { split }] of Object.entries(routes)) {
    if (!packs[split]) throw new Error(`route ${route}: no pack for split ${split}`);
  }
  const table = {
    routes: Object.fromEntries(Object.entries(routes).map(([r, { split }]) => [r, packs[split].file])),
    strings: {
      first: firstStrings(),
      routes: Object.fromEntries(Object.entries(routes).map(([r, { strings }]) => [r, strings])),
    },
    heads: Object.fromEntries(Object.entries(routes).map(([r, { head }]) => [r, head])),
    sheets: Object.fromEntries(
      Object.entries(routes)
        .filter(([, { sheet }]) => sheet)
        .map(([r, { sheet }]) => [r, `www/${sheet}.css`]),
    ),
  };
  const splitsOf = Object.fromEntries(Object.entries(routes).map(([r, { split }]) => [r, split]));
  writeFileSync(join(pkgDir, 'routes.json'), JSON.stringify({ ...table, splits: splitsOf }, null, 2) + '\n');
  const total = Object.values(packs).reduce((sum, p) => sum + p.bytes, 0);
  console.log(`split-link: ${written.size} modules, ${Object.keys(packs).length} packs (${total} B)`);
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) main();
