// The app's size, each file gzipped at level 9 as a static host would send it:
// - the whole app: every file of a built dist/ (wasm chunks, js, css, html, service worker,
//   manifest, icon) but the first-visit packs, which hold the same modules as pkg/chunks/
//   (scripts/split-link.mjs) and the same text as locales/ (scripts/boot-table.mjs), so each
//   module and file counts once;
// - each route's first load: what the browser fetches before the route's first frame, from the
//   build's own lists (pkg/routes.json): index.html, the stylesheet, the boot scripts and the
//   route table, the glue and the loader, the main wasm, the route's strings pack in one
//   language (English: the Fluent files the route needs, in one file), the page's own
//   stylesheet if it has one, and the route's pack.
//
//   node scripts/size.mjs [dist]           prints the tables (make bench)
//   node scripts/size.mjs [dist] --check   also exits 1 when a sum is over its ceiling (make test)
//
// BUDGET and routeBudget are the goals; CEILING and ROUTE_CEILINGS are what `make test`
// enforces: the sizes now plus a little room, so that no change makes the app or a first load
// bigger unnoticed. Lower a ceiling as the app shrinks; never raise it without saying why in
// the commit.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative, sep } from 'node:path';
import { gzipSync } from 'node:zlib';
import { isStringsPack, stringsPack } from './boot-table.mjs';
import { isPack } from './sw-build.mjs';

export const KB = 1024;
export const BUDGET = 350 * KB;
export const CEILING = 1665 * KB;

/** The first-load goal of a route: 250 KB for the IK playground and home, 350 KB elsewhere. */
export function routeBudget(route) {
  return (route === 'ik-2r' || route === 'home' ? 250 : 350) * KB;
}
/** What `make test` allows each route's first load: its size now plus about 10 KB, and never
 * more than its budget once it is within it. */
export const ROUTE_CEILINGS = {
  home: 200,
  'ik-2r': 249,
  'dh-fk': 307,
  'se3-relative': 312,
  'umeyama-2d': 324,
  'pendulum-energy': 307,
  'pid-step': 293,
  'cubic-path': 300,
  'trapezoid-profile': 296,
  'traj-resample': 315,
  'rrt-2d': 290,
  teleop: 327,
  so101: 350,
  drills: 307,
  lesson: 252,
};
/** The ceiling of a route (a route not in the table has the largest). */
export function routeCeiling(route) {
  return (ROUTE_CEILINGS[route] ?? Math.max(...Object.values(ROUTE_CEILINGS))) * KB;
}

/** The files every first load fetches besides the route's strings and pack. */
export const SHELL_FILES = [
  'index.html',
  'www/app.css',
  'www/boot.js',
  'www/bootstrap.js',
  'pkg/bsv_playground.js',
  'pkg/__wasm_split.js',
  'pkg/bsv_playground_bg.wasm',
];

/** Each route's first load: `[{ route, files, gzip }]` (gzip-9 bytes of the files). */
export function firstLoads(dist) {
  const table = JSON.parse(readFileSync(join(dist, 'pkg', 'routes.json'), 'utf8'));
  const gz = (file) => gzipSync(readFileSync(join(dist, file)), { level: 9 }).length;
  const sizes = new Map();
  const size = (file) => (sizes.has(file) ? sizes.get(file) : sizes.set(file, gz(file)).get(file));
  return Object.entries(table.routes).map(([route, pack]) => {
    const sheet = table.sheets?.[route];
    const files = [...SHELL_FILES, stringsPack('en', route), ...(sheet ? [sheet] : []), `pkg/${pack}`];
    return { route, files, gzip: files.reduce((sum, f) => sum + size(f), 0) };
  });
}

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
  const firstVisit = (file) => isPack(file) || isStringsPack(file);
  const rows = files(dist)
    .map((path) => ({ path, file: relative(dist, path).split(sep).join('/') }))
    .filter(({ file }) => !firstVisit(file))
    .map(({ path, file }) => {
      const bytes = readFileSync(path);
      return { file, raw: bytes.length, gzip: gzipSync(bytes, { level: 9 }).length };
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
  let failed = check && gzip > CEILING;
  if (failed) {
    console.error(`the app is ${kb(gzip)} gzipped, over the ceiling of ${kb(CEILING)} in scripts/size.mjs`);
  }
  console.log('\nfirst load of each route (gzip -9, English strings)');
  for (const { route, gzip: bytes } of firstLoads(dist)) {
    const budget = routeBudget(route);
    const ceiling = routeCeiling(route);
    const over = bytes > ceiling;
    console.log(
      `${route.padEnd(20)} ${kb(bytes).padStart(10)}  budget ${kb(budget)}: ${bytes > budget ? `OVER by ${kb(bytes - budget)}` : 'ok'}` +
        `; ceiling ${kb(ceiling)}: ${over ? 'OVER' : 'ok'}`,
    );
    if (check && over) {
      console.error(`route ${route}: first load ${kb(bytes)}, over its ceiling of ${kb(ceiling)}`);
      failed = true;
    }
  }
  if (failed) process.exit(1);
};

if (import.meta.url === `file://${process.argv[1]}`) main();
