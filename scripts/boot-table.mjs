// Writes, at the head of DIST's www/boot.js, the table that script reads (`self.bsvRoutes`):
// the pack and the Fluent files each route needs first and the markup of its head (from
// pkg/routes.json, written by scripts/split-link.mjs) and the main wasm's file and size, which boot.js watches to ask for
// the route's pack as the main wasm nears its end. Run once the main wasm is final (after
// scripts/short-imports.mjs): one script, fetched with the wasm, instead of two run one after
// the other.
//
//   node scripts/boot-table.mjs DIST
import { readFileSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const dist = process.argv[2];
if (!dist) throw new Error('usage: node scripts/boot-table.mjs DIST');
const { routes, strings, heads } = JSON.parse(readFileSync(join(dist, 'pkg', 'routes.json'), 'utf8'));
const file = 'pkg/bsv_playground_bg.wasm';
const table = { routes, strings, heads, main: { file, bytes: statSync(join(dist, file)).size } };
const boot = join(dist, 'www', 'boot.js');
writeFileSync(
  boot,
  '// Written by scripts/boot-table.mjs: what each route needs first, and the main wasm.\n' +
    `self.bsvRoutes=${JSON.stringify(table)};\n` +
    readFileSync(boot, 'utf8'),
);
console.log(`boot-table: ${Object.keys(routes).length} routes, main wasm ${table.main.bytes} B`);
