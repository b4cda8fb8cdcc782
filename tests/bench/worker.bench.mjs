// Long runs in the Web Worker, started from the drills page in headless Chromium, on the dist
// folder named by BSV_DIST (default dist/): `manip-grid 1024` to its end and
// `rrt-2d 7 1000000 --goal-x 0.5 --goal-y 0.5` for its first seconds. The main thread's long
// tasks during each run (a 'longtask' observer installed before the app starts; a 150 ms task
// of the page's own shows that it sees them), the run's wall time, and how long a button takes
// to take the focus while a run goes.
//
// Budget: no main-thread task of 100 ms during a worker run. With WORKER_BENCH_STRICT=1 the
// exit code is 1 when it is missed; otherwise this only reports.
import { BenchTable, openWatched, runBench, takeLongTasks } from './bench-table.mjs';

const table = new BenchTable();
const notes = [];

/** The drills page at `hash`, its long tasks watched from before the app starts. */
async function openDrills(url, hash) {
  const app = await openWatched(url, hash, { viewport: { width: 1280, height: 900 } });
  await app.page.waitForSelector('[data-testid="drills-page"]');
  await app.page.waitForFunction(() => document.querySelector('[data-testid="drills-status"]').textContent !== '');
  return app;
}

const runs = (page) => page.evaluate(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run));

/** Clicks Run, then times a focus change on the page while the run goes. */
async function start(page) {
  await takeLongTasks(page);
  await page.locator('[data-testid="drills-run"]').click();
  await page.locator('[data-testid="progress"]').waitFor({ state: 'visible', timeout: 10_000 });
  await page.waitForTimeout(300);
  const t0 = Date.now();
  await page.evaluate(() => document.querySelector('[data-testid="drills-reset"]').focus());
  return Date.now() - t0;
}

await runBench({ table, notes, strict: 'WORKER_BENCH_STRICT' }, async (url) => {
  {
    const { page, close } = await openDrills(url, '#/drills?recipe=manip-grid&n=1024');
    try {
      await takeLongTasks(page);
      const seen = await page.evaluate(async () => {
        setTimeout(() => {
          const end = performance.now() + 150;
          while (performance.now() < end);
        }, 0);
        await new Promise((r) => setTimeout(r, 400));
      }).then(() => takeLongTasks(page));
      table.longTasks('a 150 ms task of the page (the observer sees it)', seen);
      const before = await runs(page);
      const t0 = Date.now();
      const focusMs = await start(page);
      await page.waitForFunction((n) => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > n, before, { timeout: 240_000 });
      notes.push(`manip-grid 1024: ${Date.now() - t0} ms to the result; focus during the run ${focusMs} ms`);
      table.longTasks('manip-grid 1024 in the worker', await takeLongTasks(page), 100);
    } finally {
      await close();
    }
  }
  {
    const { page, close } = await openDrills(url, '#/drills?recipe=rrt-2d&seed=7&max_iter=1000000&goal-x=0.5&goal-y=0.5');
    try {
      const focusMs = await start(page);
      await page.waitForTimeout(3000);
      table.longTasks('rrt-2d 7 1000000 in the worker (3 s, then Cancel)', await takeLongTasks(page), 100);
      await page.locator('[data-testid="progress-cancel"]').click();
      await page.locator('[data-testid="progress"]').waitFor({ state: 'hidden' });
      notes.push(`rrt-2d 7 1000000: focus during the run ${focusMs} ms`);
    } finally {
      await close();
    }
  }
});
