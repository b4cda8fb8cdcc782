// A phone's first visit: each route of the release dist/ (BSV_DIST) opened cold under
// Lighthouse's mobile profile, through the DevTools protocol: 150 ms round trip, 1.6 Mbps
// down, 750 kbps up, CPU slowed 4×; files served gzipped (scripts/serve.mjs), a new browser
// context per load (empty HTTP cache, service worker blocked). Per route, the median of
// FIRSTLOAD_LOADS loads (5) of the time from navigation to the first animation frame after the
// route is settled (html[data-app-ready]: its page mounted) and the bytes on the wire until
// then, against the first-load budgets: `#/` and `#/ik-2r` 2.0 s and 250 KB, every other
// route 2.5 s and 350 KB. Then the second visit: the same route with the service worker
// installed, the median of as many loads (budget 1.0 s). With FIRSTLOAD_STRICT=1 the exit
// code is 1 when a budget is missed.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { browser, closeBrowser, startServer, throttle, watchFirstFrame, DIST } from '../e2e/harness.mjs';
import { stats } from './bench-table.mjs';

const LOADS = Number(process.env.FIRSTLOAD_LOADS ?? 5);
const KB = 1024;
const table = JSON.parse(readFileSync(join(DIST, 'pkg', 'routes.json'), 'utf8'));
const ROUTES = (process.env.FIRSTLOAD_ROUTES ?? Object.keys(table.routes).join(',')).split(',');
const budget = (route) =>
  route === 'home' || route === 'ik-2r' ? { ms: 2000, bytes: 250 * KB } : { ms: 2500, bytes: 350 * KB };
const hashOf = (route) => (route === 'home' ? '#/' : `#/${route}`);

/** One cold load of `url`: { ms, bytes } to the first interactive frame. */
async function coldLoad(url) {
  const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 }, serviceWorkers: 'block' });
  try {
    await context.addInitScript(watchFirstFrame);
    const page = await context.newPage();
    const net = await throttle(context, page, { cpu: true });
    await page.goto(url);
    await page.waitForFunction(() => typeof window.__firstFrameMs === 'number', null, { timeout: 60000 });
    const ms = await page.evaluate(() => window.__firstFrameMs);
    // Bytes of the responses finished by then (the background loading comes after).
    return { ms, bytes: net.bytes() };
  } finally {
    await context.close();
  }
}

/** A second visit: the service worker installed by a first one, then a throttled reload. */
async function secondVisit(url) {
  const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 } });
  try {
    const page = await context.newPage();
    await page.goto(url);
    await page.waitForFunction(() => navigator.serviceWorker?.controller != null, null, { timeout: 60000 });
    await context.addInitScript(watchFirstFrame);
    await throttle(context, page, { cpu: true });
    await page.reload();
    await page.waitForFunction(() => typeof window.__firstFrameMs === 'number', null, { timeout: 60000 });
    return await page.evaluate(() => window.__firstFrameMs);
  } finally {
    await context.close();
  }
}

const server = await startServer({ gzip: true });
let over = false;
try {
  await coldLoad(`${server.url}/#/`);
  console.log(`${'route'.padEnd(20)}  ${'ms (median)'.padStart(11)}  ${'KB on wire'.padStart(10)}  budget            2nd visit ms  budget`);
  for (const route of ROUTES) {
    const loads = [];
    for (let i = 0; i < LOADS; i++) loads.push(await coldLoad(`${server.url}/${hashOf(route)}`));
    const ms = stats(loads.map((l) => l.ms)).p50;
    const bytes = stats(loads.map((l) => l.bytes)).p50;
    const b = budget(route);
    const seconds = [];
    for (let i = 0; i < LOADS; i++) seconds.push(await secondVisit(`${server.url}/${hashOf(route)}`));
    const second = stats(seconds).p50;
    const ok = ms <= b.ms && bytes <= b.bytes;
    const ok2 = second <= 1000;
    over ||= !ok || !ok2;
    console.log(
      `${route.padEnd(20)}  ${ms.toFixed(0).padStart(11)}  ${(bytes / KB).toFixed(1).padStart(10)}  ` +
        `${`≤ ${b.ms} ms, ${b.bytes / KB} KB`.padEnd(18)}${(ok ? 'ok' : 'OVER').padEnd(5)}` +
        `${second.toFixed(0).padStart(8)}  ≤ 1000 ms ${ok2 ? 'ok' : 'OVER'}`,
    );
  }
} finally {
  await closeBrowser();
  await server.close();
}
if (over && process.env.FIRSTLOAD_STRICT === '1') process.exit(1);
