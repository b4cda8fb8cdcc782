// Speed of the three signal pages (#/cubic-path, #/pid-step, #/trapezoid-profile) in headless
// Chromium at 1920×1080, on the dist folder named by BSV_DIST (default dist/); it needs a wasm
// built with `--features bench` (window.__signalFrameMs: each input's recompute + redraw, ms):
// `make bench` (scripts/bench.sh) assembles one in target/bench-dist. Each page's slider dragged
// end to end, one pointer move per animation frame, at the recipe's default sizes and at
// 100,000 samples. Then a 400,000-row PID run computed a slice per frame: the main thread's long
// tasks while it runs (reported).
//
// Budgets: slider drag p95 < 4 ms at the default sizes, < 16 ms at 100,000 samples. With
// SIGNALS_BENCH_STRICT=1 the exit code is 1 when one is missed; otherwise this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, nextFrame, openWatched, runBench, takeLongTasks } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const table = new BenchTable();

/** [page, query, slider, budget p95 ms] */
const DRAGS = [
  ['cubic-path', '', 'q1', 4],
  ['cubic-path', '?T=2&dt=0.00002', 'q1', 16],
  ['pid-step', '', 'Kp', 4],
  ['pid-step', '?steps=100000', 'Kp', 16],
  ['trapezoid-profile', '', 'vmax', 4],
  ['trapezoid-profile', '?dt=0.000025', 'vmax', 16],
];

await runBench({ table, strict: 'SIGNALS_BENCH_STRICT' }, async (url) => {
  for (const [id, search, name, budget] of DRAGS) {
    const { page, close } = await openApp(url, `#/${id}${search}`, { viewport: VIEWPORT });
    try {
      if (!(await page.evaluate(() => Array.isArray(window.__signalFrameMs)))) {
        throw new Error('no window.__signalFrameMs: serve a dist built with --features bench (make bench)');
      }
      await page.evaluate(() => { window.__signalFrameMs.length = 0; });
      const box = await page.locator(`[data-slider="${name}"]`).boundingBox();
      await page.mouse.move(box.x + 4, box.y + box.height / 2);
      await page.mouse.down();
      for (let k = 0; k <= 120; k++) {
        await page.mouse.move(box.x + 4 + (k / 120) * (box.width - 8), box.y + box.height / 2);
        await nextFrame(page);
      }
      await page.mouse.up();
      table.report(`${id}${search} ${name} drag`, await page.evaluate(() => window.__signalFrameMs.slice()), budget);
    } finally {
      await close();
    }
  }

  // 400,000 PID steps, computed a slice per frame after a change.
  const { page, close } = await openWatched(url, '#/pid-step?Kp=2&Ki=4&Kd=0.05&tau=0.8&steps=400000', { viewport: VIEWPORT });
  try {
    const line = page.locator('[data-testid="pid-step-computing"]');
    await line.waitFor({ state: 'hidden', timeout: 20_000 });
    table.longTasks('pid-step 400,000 rows: the mount and first run', await takeLongTasks(page));
    await page.locator('[data-field="Kp"]').fill('3');
    await line.waitFor({ state: 'hidden', timeout: 20_000 });
    table.longTasks('pid-step 400,000 rows: a change, in slices', await takeLongTasks(page));
  } finally {
    await close();
  }
});
