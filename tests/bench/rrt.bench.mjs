// Speed of the RRT stepper (#/rrt-2d) in headless Chromium, on the dist folder named by BSV_DIST
// (default dist/). Prints, against their budgets:
//
// - frame work while playing as fast as possible to 50,000 nodes (the goal walled in), then on
//   to 100,000: the page's record of each frame (advance + draw + panel, window.__rrtFrameMs)
//   and of its drawing alone (window.__rrtDrawMs); these need a wasm built with `--features bench`
//   (`make bench` assembles one in target/bench-dist) and are left out without it;
// - opening the page, the default and a 20,000-iteration run with the goal walled in, from the
//   IK page and as a fresh load (the wasm's compiled code cached, as for a returning visitor):
//   the longest main-thread task of each of five opens (the canvases are sized and drawn in the
//   first frame, the run grows in slices after it) and the time to the first frame;
// - a 1,000,000-iteration walled-goal run: its main-thread tasks at the mount, while it grows
//   to its end in slices, at End (a cursor into the finished run, no copy) and while the CSVs
//   are written (the 864k-row nodes file in slices).
//
// Long tasks are wall-clock: a machine shared beyond its cores stretches any task. The rows
// "plain 10 ms / 20 ms tasks", before and after the figures, say how much it does meanwhile.
//
// RRT_BENCH_ONLY=frames runs the frame work alone.
//
// Budgets: frame work p95 < 2 ms; opening: longest task p50 < 50 ms; the 1,000,000 run: no
// task of 100 ms while it grows, at End or writing the CSVs. With RRT_BENCH_STRICT=1 the exit
// code is 1 when a budget is missed; otherwise this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, openWatched, runBench, takeLongTasks, stretchedTasks } from './bench-table.mjs';

const VIEWPORT = { width: 1280, height: 800 };
const OPENS = Number(process.env.RRT_BENCH_OPENS ?? 5);
const WALLS = ['0.7,0.7,0.9,0.72', '0.7,0.88,0.9,0.9', '0.7,0.7,0.72,0.9', '0.88,0.7,0.9,0.9'];
const walled = (maxIter) => `#/rrt-2d?max_iter=${maxIter}&${WALLS.map((w) => `obstacle=${w}`).join('&')}&goal=0.8,0.8`;
const table = new BenchTable();
const notes = [];

const ready = (page) => page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20_000 });
const done = (page, timeout = 60_000) =>
  page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="done"]', { state: 'attached', timeout });

/** Frame work playing as fast as possible to 50,000 nodes (bench builds only). */
async function frameWork(url) {
  const { page, close } = await openApp(url, walled(200_000), { viewport: VIEWPORT });
  try {
    if (!(await page.evaluate(() => Array.isArray(window.__rrtFrameMs)))) {
      notes.push('frame work: no window.__rrtFrameMs in this build (serve a dist built with --features bench)');
      return;
    }
    await page.locator('[data-stepper="speed"]').selectOption({ index: 4 });
    await page.evaluate(() => { window.__rrtFrameMs.length = 0; window.__rrtDrawMs.length = 0; });
    const t0 = Date.now();
    await page.locator('[data-action="run"]').click();
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="nodes"]').textContent.replace(/,/g, '')) >= 50000, null, { timeout: 60_000 });
    const seconds = (Date.now() - t0) / 1000;
    await page.locator('[data-action="run"]').click();
    table.report('frame work (advance + draw + panel)', await page.evaluate(() => window.__rrtFrameMs.slice()), { p95: 2 });
    table.report('frame drawing alone', await page.evaluate(() => window.__rrtDrawMs.slice()));
    notes.push(`50,000 nodes in ${seconds.toFixed(1)} s playing as fast as possible`);
    // On to 100,000 nodes: a frame's work does not grow with the tree (new edges are appended
    // to the tree's layer; the tree is drawn whole only on a change of view).
    await page.evaluate(() => { window.__rrtFrameMs.length = 0; window.__rrtDrawMs.length = 0; });
    await page.locator('[data-action="run"]').click();
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="nodes"]').textContent.replace(/,/g, '')) >= 100000, null, { timeout: 60_000 });
    await page.locator('[data-action="run"]').click();
    table.report('frame work, 50,000 to 100,000 nodes', await page.evaluate(() => window.__rrtFrameMs.slice()), { p95: 2 });
  } finally {
    await close();
  }
}

/** Opening the page from the IK page and as a fresh load, OPENS times each case. */
async function opening(url) {
  const { page, context, close } = await openWatched(url, '#/', { viewport: VIEWPORT });
  try {
    await context.addInitScript(() => {
      new MutationObserver((_, observer) => {
        if (document.documentElement?.dataset.appReady === '1') {
          observer.disconnect();
          requestAnimationFrame(() => { window.__firstFrameMs = performance.now(); });
        }
      }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-app-ready'] });
    });
    const load = async (hash) => {
      await page.goto('about:blank');
      await page.goto(`${url}/${hash}`);
      await ready(page);
    };
    await load('#/ik-2r');
    table.longTasks('plain 10 ms tasks, before (this machine\'s stretch)', await stretchedTasks(page, 10));
    for (const [label, hash] of [['default', '#/rrt-2d'], ['20,000 walled', walled(20_000)]]) {
      const fromIk = { tasks: [], frame: [] };
      const fresh = { tasks: [], frame: [] };
      for (let k = 0; k < OPENS; k++) {
        await load('#/ik-2r');
        await page.waitForTimeout(500);
        await takeLongTasks(page);
        fromIk.frame.push(await page.evaluate(async (h) => {
          const t0 = performance.now();
          location.hash = h;
          await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
          return performance.now() - t0;
        }, hash));
        await done(page);
        await page.waitForTimeout(500);
        fromIk.tasks.push(Math.max(0, ...(await takeLongTasks(page))));

        await load(hash);
        await page.waitForFunction(() => typeof window.__firstFrameMs === 'number', null, { timeout: 20_000 });
        fresh.frame.push(await page.evaluate(() => window.__firstFrameMs));
        await done(page);
        await page.waitForTimeout(500);
        fresh.tasks.push(Math.max(0, ...(await takeLongTasks(page))));
      }
      table.report(`opening from the IK page, ${label}: longest task`, fromIk.tasks, { p50: 50 });
      table.report(`opening from the IK page, ${label}: first frame`, fromIk.frame);
      table.report(`fresh load, ${label}: longest task`, fresh.tasks, { p50: 50 });
      table.report(`fresh load, ${label}: first frame after navigation`, fresh.frame);
    }
    table.longTasks('plain 10 ms tasks, after', await stretchedTasks(page, 10));
  } finally {
    await close();
  }
}

/** The 1,000,000-iteration walled-goal run: long tasks while it grows, at End, writing the CSVs. */
async function millionRun(url) {
  const { page, close } = await openWatched(url, '#/', { viewport: VIEWPORT });
  try {
    table.longTasks('plain 20 ms tasks, before (this machine\'s stretch)', await stretchedTasks(page, 20));
    await page.evaluate((h) => { location.hash = h; }, walled(1_000_000));
    await page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="running"]', { timeout: 20_000 });
    table.longTasks('1,000,000 walled: the mount', await takeLongTasks(page));
    const t0 = Date.now();
    await done(page, 300_000);
    notes.push(`1,000,000 walled: grown to its end in ${((Date.now() - t0) / 1000).toFixed(1)} s`);
    table.longTasks('1,000,000 walled: growing to its end', await takeLongTasks(page), 100);
    const t1 = Date.now();
    await page.locator('[data-action="end"]').click();
    const endMs = Date.now() - t1;
    // The tree layer of a big tree is drawn over several tasks.
    await page.waitForTimeout(6000);
    table.longTasks('1,000,000 walled: End and its drawing', await takeLongTasks(page), 100);
    const t2 = Date.now();
    for (const file of ['rrt_nodes.csv', 'rrt_path.csv']) {
      const [dl] = await Promise.all([page.waitForEvent('download'), page.locator(`[data-download="${file}"]`).click()]);
      await dl.path();
    }
    const csvMs = Date.now() - t2;
    await page.waitForTimeout(300);
    table.longTasks('1,000,000 walled: writing the CSVs', await takeLongTasks(page), 100);
    table.longTasks('plain 20 ms tasks, after', await stretchedTasks(page, 20));
    notes.push(`1,000,000 walled: End's click ${endMs} ms, the two CSVs ${csvMs} ms`);
  } finally {
    await close();
  }
}

await runBench({ table, notes, strict: 'RRT_BENCH_STRICT' }, async (url) => {
  await frameWork(url);
  if (process.env.RRT_BENCH_ONLY === 'frames') return;
  await opening(url);
  await millionRun(url);
});
