// Writes, at the head of DIST's www/boot.js, the table that script reads (`self.bsvRoutes`):
// the pack, the stylesheet and the Fluent files each route needs first and the markup of its
// head (from pkg/routes.json, written by scripts/split-link.mjs), the words of every head in
// each language (`texts`: the messages its `data-i18n` names and `page-loading`, copied from
// DIST's locales/, so that boot.js paints the frame without a request), and the main wasm's
// file and size, which boot.js watches to ask for the route's pack as the main wasm nears its
// end. Run once the main wasm is final (after scripts/short-imports.mjs): one script, fetched
// with the wasm, instead of two run one after the other.
// Beside it, per route and language, the route's strings pack (`stringsPack`): the Fluent files
// the route needs first in one JSON object, file name → text, that boot.js asks for on a first
// visit in one request instead of one per file. A phone's browser opens six connections to a
// server; the six or seven files would take them all while the route's wasm pack waits for one.
//
//   node scripts/boot-table.mjs DIST
import { readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const LANGS = ['en', 'ja'];

/** The value of message `id` in Fluent source `text` when it is one line of plain text (as
 * every head's is: tests/e2e/boot_frame.test.mjs), else null. */
export function plainMessage(text, id) {
  const found = new RegExp(`^${id} *= *(.*)$`, 'm').exec(text);
  if (!found || /[{}]/.test(found[1])) return null;
  const next = text.slice(found.index + found[0].length + 1).split('\n')[0];
  return /^[ \t]+[^\s.]/.test(next) ? null : found[1];
}

/** Per language, each message the heads name (and `page-loading`): its one line of text. */
export function headTexts(dist, heads) {
  const ids = new Set(['page-loading']);
  for (const head of Object.values(heads)) {
    for (const m of head.matchAll(/data-i18n="([^"]+)"/g)) ids.add(m[1]);
  }
  const texts = {};
  for (const lang of LANGS) {
    const dir = join(dist, 'locales', lang);
    const sources = readdirSync(dir)
      .filter((f) => f.endsWith('.ftl'))
      .sort()
      .map((f) => readFileSync(join(dir, f), 'utf8'));
    texts[lang] = {};
    for (const id of ids) {
      const values = sources.map((s) => plainMessage(s, id)).filter((v) => v !== null);
      if (values.length !== 1) {
        throw new Error(`boot-table: ${lang} message ${id}: ${values.length} plain one-line values`);
      }
      texts[lang][id] = values[0];
    }
  }
  return texts;
}

/** DIST-relative path of the strings pack of `route` in `lang` (read by www/boot.js). */
export function stringsPack(lang, route) {
  return `locales/${lang}/pack_${route}.json`;
}

/** Whether DIST-relative `file` is a strings pack: a first visit's file, which the service
 * worker does not cache (it caches the Fluent files the pack holds). */
export function isStringsPack(file) {
  return /^locales\/[^/]+\/pack_[^/]*\.json$/.test(file);
}

/** Writes every route's strings pack in each language; returns how many. */
export function writeStringsPacks(dist, strings) {
  let count = 0;
  for (const lang of LANGS) {
    for (const [route, own] of Object.entries(strings.routes)) {
      const files = [...strings.first, ...own];
      const text = (f) => readFileSync(join(dist, 'locales', lang, f), 'utf8');
      const pack = Object.fromEntries(files.map((f) => [f, text(f)]));
      writeFileSync(join(dist, stringsPack(lang, route)), JSON.stringify(pack));
      count += 1;
    }
  }
  return count;
}

function main() {
  const dist = process.argv[2];
  if (!dist) throw new Error('usage: node scripts/boot-table.mjs DIST');
  const { routes, strings, heads, sheets } = JSON.parse(readFileSync(join(dist, 'pkg', 'routes.json'), 'utf8'));
  const file = 'pkg/bsv_playground_bg.wasm';
  const texts = headTexts(dist, heads);
  const table = { routes, sheets, strings, heads, texts, main: { file, bytes: statSync(join(dist, file)).size } };
  const boot = join(dist, 'www', 'boot.js');
  writeFileSync(
    boot,
    '// Written by scripts/boot-table.mjs: what each route needs first, and the main wasm.\n' +
      `self.bsvRoutes=${JSON.stringify(table)};\n` +
      readFileSync(boot, 'utf8'),
  );
  const packs = writeStringsPacks(dist, strings);
  console.log(
    `boot-table: ${Object.keys(routes).length} routes, ${packs} strings packs, main wasm ${table.main.bytes} B`,
  );
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) main();
