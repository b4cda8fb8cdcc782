// First interactive frame, on the dist folder named by BSV_DIST (default dist/), served from
// localhost: cold loads in headless Chromium, each in a new browser context (empty HTTP cache,
// no service worker), 1280×800. The time is from the navigation's start to the first animation
// frame after the shell set html[data-app-ready] (the route mounted and its listeners
// installed: the page answers input from that frame on). Printed per route: n, median, p95 and
// max, against the budget of a 500 ms median. Also the sizes of the dist (scripts/size.mjs).
// With FIRSTFRAME_STRICT=1 the exit code is 1 when the budget is missed; otherwise this only
// reports.
import { browser, closeBrowser, startServer, watchFirstFrame, DIST } from '../e2e/harness.mjs';
import { stats } from './bench-table.mjs';
import { measure, KB, BUDGET } from '../../scripts/size.mjs';

const ROUTES = ['#/', '#/ik-2r', '#/rrt-2d', '#/pendulum-energy', '#/teleop', '#/ik-2r?lang=ja'];
const LOADS = Number(process.env.FIRSTFRAME_LOADS ?? 9);
const BUDGET_MS = 500;

/**
 * Milliseconds from navigation start to the first frame after the app is ready, in a fresh
 * context, with the phases before it (bootstrap.js sets the marks).
 */
async function coldLoad(url) {
  const context = await (await browser()).newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  try {
    await context.addInitScript(watchFirstFrame);
    const page = await context.newPage();
    await page.goto(url);
    await page.waitForFunction(() => typeof window.__firstFrameMs === 'number', null, { timeout: 20000 });
    return await page.evaluate(() => {
      const mark = (name) => performance.getEntriesByName(name)[0]?.startTime ?? NaN;
      const wasm = performance.getEntriesByType('resource').find((r) => r.name.endsWith('.wasm'));
      return {
        css: performance.getEntriesByType('resource').find((r) => r.name.endsWith('app.css'))?.responseEnd ?? NaN,
        wasmLoaded: wasm?.responseEnd ?? NaN,
        wasmReady: mark('bsv-wasm-ready'),
        appReady: mark('bsv-app-ready'),
        frame: window.__firstFrameMs,
      };
    });
  } finally {
    await context.close();
  }
}

const { gzip, rows } = measure(DIST);
const wasm = rows.find((r) => r.file.endsWith('.wasm'));
console.log(
  `dist: ${(gzip / KB).toFixed(1)} KB gzip in ${rows.length} files (wasm ${(wasm.raw / KB).toFixed(1)} KB, ` +
    `${(wasm.gzip / KB).toFixed(1)} KB gzip); budget ${(BUDGET / KB).toFixed(0)} KB (node scripts/size.mjs for the table)`,
);

const server = await startServer();
let over = false;
try {
  // One load first so that Chromium itself is warm (its own start is not the app's).
  await coldLoad(`${server.url}/#/`);
  console.log(
    `${'route'.padEnd(22)}  ${'n'.padStart(2)}  ${'median ms'.padStart(9)}  ${'p95 ms'.padStart(7)}  ${'max ms'.padStart(7)}  budget` +
      '                 medians: css loaded, wasm loaded, wasm instantiated, app mounted',
  );
  for (const route of ROUTES) {
    const loads = [];
    for (let i = 0; i < LOADS; i++) loads.push(await coldLoad(`${server.url}/${route}`));
    const s = stats(loads.map((l) => l.frame));
    const phases = ['css', 'wasmLoaded', 'wasmReady', 'appReady'].map((k) => stats(loads.map((l) => l[k])).p50.toFixed(0)).join(' / ');
    const ok = s.p50 <= BUDGET_MS;
    over ||= !ok;
    console.log(
      `${route.padEnd(22)}  ${String(s.n).padStart(2)}  ${s.p50.toFixed(0).padStart(9)}  ${s.p95.toFixed(0).padStart(7)}  ` +
        `${s.max.toFixed(0).padStart(7)}  median ≤ ${BUDGET_MS} ms ${(ok ? 'ok' : 'OVER').padEnd(4)}  ${phases}`,
    );
  }
} finally {
  await closeBrowser();
  await server.close();
}
if (over && process.env.FIRSTFRAME_STRICT === '1') process.exit(1);
