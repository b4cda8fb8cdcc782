// The app's size: every file of a built dist/ (wasm, js, css, html, service worker, manifest,
// icon; the Fluent strings of both languages are compiled into the wasm), each gzipped at
// level 9 as a static host would send it, and their sum, against the app's budget.
//
//   node scripts/size.mjs [dist]           prints the table (make bench)
//   node scripts/size.mjs [dist] --check   also exits 1 when the sum is over the ceiling (make test)
//
// Two limits. BUDGET is the goal for the whole app, 350 KB gzipped; the app is over it (see the
// README, "Size and first frame"), so the check cannot fail on it without failing every build.
// CEILING is what `make test` enforces: the app's size plus a little room, so that no change
// makes the app bigger unnoticed. Lower CEILING as the app shrinks; never raise it without
// saying why in the commit.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { gzipSync } from 'node:zlib';

export const KB = 1024;
export const BUDGET = 350 * KB;
export const CEILING = 1085 * KB;

/** Every file under `dir`, sorted by path. */
function files(dir) {
  return readdirSync(dir)
    .sort()
    .flatMap((name) => {
      const path = join(dir, name);
      return statSync(path).isDirectory() ? files(path) : [path];
    });
}

/** Raw and gzip-9 bytes of every file of `dist`, and their sums. */
export function measure(dist) {
  const rows = files(dist).map((path) => {
    const bytes = readFileSync(path);
    return { file: relative(dist, path), raw: bytes.length, gzip: gzipSync(bytes, { level: 9 }).length };
  });
  const sum = (k) => rows.reduce((s, r) => s + r[k], 0);
  return { rows, raw: sum('raw'), gzip: sum('gzip') };
}

const main = () => {
  const args = process.argv.slice(2);
  const check = args.includes('--check');
  const dist = args.find((a) => !a.startsWith('--')) ?? 'dist';
  const { rows, raw, gzip } = measure(dist);
  const kb = (n) => `${(n / KB).toFixed(1)} KB`;
  const width = Math.max(...rows.map((r) => r.file.length), 5);
  console.log(`${'file'.padEnd(width)}  ${'raw'.padStart(10)}  ${'gzip -9'.padStart(10)}`);
  for (const r of rows) console.log(`${r.file.padEnd(width)}  ${kb(r.raw).padStart(10)}  ${kb(r.gzip).padStart(10)}`);
  console.log(`${'total'.padEnd(width)}  ${kb(raw).padStart(10)}  ${kb(gzip).padStart(10)}`);
  const gap = gzip - BUDGET;
  console.log(
    `budget (whole app): ${kb(BUDGET)} gzip: ${gap > 0 ? `OVER by ${kb(gap)}` : 'ok'}; ` +
      `ceiling (make test): ${kb(CEILING)}: ${gzip > CEILING ? 'OVER' : 'ok'}`,
  );
  if (check && gzip > CEILING) {
    console.error(`the app is ${kb(gzip)} gzipped, over the ceiling of ${kb(CEILING)} in scripts/size.mjs`);
    process.exit(1);
  }
};

if (import.meta.url === `file://${process.argv[1]}`) main();
