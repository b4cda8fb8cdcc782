// A phone's first seconds as Lighthouse measures them: every route of the release dist/
// (BSV_DIST), in English and in Japanese (`?lang=ja`), through Lighthouse 12.2.3's default
// mobile preset (a simulated Moto G Power: 150 ms round trip, 1.6 Mbps, CPU 4× slower), files
// served gzipped (scripts/serve.mjs). Per route and language the median run of
// LIGHTHOUSE_RUNS (3, Lighthouse's own median: by FCP and TTI), one row: the four category
// scores, FCP, LCP, TBT, CLS and speed index, against the goals (performance ≥ 95, TBT ≤ 100 ms,
// CLS ≤ 0.02, LCP ≤ 2.0 s, the other categories 100). LIGHTHOUSE_ROUTES narrows the routes
// (comma-separated ids; `home` is `#/`); LIGHTHOUSE_LANGS the languages (`en,ja`). With
// LIGHTHOUSE_STRICT=1 the exit code is 1 when a goal is missed.
//
// Lighthouse is not a dependency of the app or of `make test`: scripts/bench.sh installs it
// pinned into target/lighthouse (`npm i -E lighthouse@12.2.3`; 13.x needs Node 22), and it
// drives Debian's chromium (CHROME_PATH).
import { readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { startStaticServer } from '../../scripts/serve.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const DIST = resolve(ROOT, process.env.BSV_DIST || 'dist');

const PREFIX = join(ROOT, 'target', 'lighthouse');
const require = createRequire(join(PREFIX, 'package.json'));
const { default: lighthouse } = await import(pathToFileURL(require.resolve('lighthouse')).href);
const { computeMedianRun } = await import(
  pathToFileURL(join(PREFIX, 'node_modules', 'lighthouse', 'core', 'lib', 'median-run.js')).href
);
const chromeLauncher = await import(pathToFileURL(require.resolve('chrome-launcher')).href);

const RUNS = Number(process.env.LIGHTHOUSE_RUNS ?? 3);
const table = JSON.parse(readFileSync(join(DIST, 'pkg', 'routes.json'), 'utf8'));
const ROUTES = (process.env.LIGHTHOUSE_ROUTES ?? Object.keys(table.routes).join(',')).split(',');
const LANGS = (process.env.LIGHTHOUSE_LANGS ?? 'en,ja').split(',');
const GOALS = { performance: 95, tbt: 100, cls: 0.02, lcp: 2000, others: 100 };
const CATEGORIES = ['performance', 'accessibility', 'best-practices', 'seo'];

const hashOf = (route, lang) => {
  const path = route === 'home' ? '#/' : `#/${route}`;
  return lang === 'en' ? path : `${path}?lang=${lang}`;
};

const server = await startStaticServer(DIST, 0, '127.0.0.1', { gzip: true });
// The flags the issue measured with (`--chrome-flags="--headless=new --no-sandbox"`), nothing
// more: the tests' --disable-gpu would move the canvases' compositing onto the main thread and
// triple the blocking time of an animated page.
const chrome = await chromeLauncher.launch({
  chromePath: process.env.CHROME_PATH || '/usr/bin/chromium',
  chromeFlags: ['--headless=new', '--no-sandbox'],
});

// Every run is a first visit: Lighthouse clears the origin's caches and service worker before
// a run but keeps its local storage, where a pilot page keeps the session of an earlier run;
// a page that finds one waits for the code that reads it, which is a returning visitor's load.
const CLEAR = ['file_systems', 'shader_cache', 'service_workers', 'cache_storage', 'local_storage', 'indexeddb'];

/** One Lighthouse run of `url` (mobile preset, the four categories): its result. */
async function run(url) {
  const result = await lighthouse(url, {
    port: chrome.port,
    output: 'json',
    logLevel: 'error',
    onlyCategories: CATEGORIES,
    clearStorageTypes: CLEAR,
  });
  return result.lhr;
}

const pad = (s, n) => String(s).padStart(n);
const rows = [];
let missed = false;
try {
  console.log(
    `${'route'.padEnd(28)} perf  a11y  bp  seo    FCP ms   LCP ms  TBT ms    CLS     SI ms  goals`,
  );
  for (const route of ROUTES) {
    for (const lang of LANGS) {
      const hash = hashOf(route, lang);
      const runs = [];
      for (let i = 0; i < RUNS; i++) runs.push(await run(`${server.url}/${hash}`));
      const lhr = computeMedianRun(runs);
      const score = (id) => Math.round((lhr.categories[id]?.score ?? 0) * 100);
      const value = (id) => lhr.audits[id]?.numericValue ?? NaN;
      const row = {
        route: hash,
        performance: score('performance'),
        accessibility: score('accessibility'),
        bestPractices: score('best-practices'),
        seo: score('seo'),
        fcp: value('first-contentful-paint'),
        lcp: value('largest-contentful-paint'),
        tbt: value('total-blocking-time'),
        cls: value('cumulative-layout-shift'),
        si: value('speed-index'),
        performanceRuns: runs.map((r) => Math.round((r.categories.performance?.score ?? 0) * 100)),
      };
      const misses = [];
      if (row.performance < GOALS.performance) misses.push('perf');
      if (row.tbt > GOALS.tbt) misses.push('TBT');
      if (row.cls > GOALS.cls) misses.push('CLS');
      if (row.lcp > GOALS.lcp) misses.push('LCP');
      if ([row.accessibility, row.bestPractices, row.seo].some((s) => s < GOALS.others)) misses.push('a11y/bp/seo');
      missed ||= misses.length > 0;
      rows.push(row);
      console.log(
        `${hash.padEnd(28)} ${pad(row.performance, 4)}  ${pad(row.accessibility, 4)} ${pad(row.bestPractices, 3)} ` +
          `${pad(row.seo, 4)}  ${pad(row.fcp.toFixed(0), 8)} ${pad(row.lcp.toFixed(0), 8)} ${pad(row.tbt.toFixed(0), 7)} ` +
          `${pad(row.cls.toFixed(3), 6)}  ${pad(row.si.toFixed(0), 8)}  ${misses.length ? `MISSED ${misses.join(' ')}` : 'ok'}` +
          `  (runs: ${row.performanceRuns.join(' ')})`,
      );
    }
  }
} finally {
  await chrome.kill();
  await server.close();
}
if (process.env.LIGHTHOUSE_JSON) writeFileSync(process.env.LIGHTHOUSE_JSON, JSON.stringify(rows, null, 2) + '\n');
if (missed && process.env.LIGHTHOUSE_STRICT === '1') process.exit(1);
