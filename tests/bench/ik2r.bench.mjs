// Speed of the IK page (#/ik-2r) in headless Chromium at 1920×1080, on the dist folder named by
// BSV_DIST (default dist/); it needs a wasm built with `--features bench` (the timing hooks are
// not in the app build): `make bench` (scripts/bench.sh) assembles one in target/bench-dist.
// Prints p50 / p95 / max per kind of work:
//
// - drag frame (real): mouse drags of the tip, one move per animation frame; the page's own
//   record of each frame's work (IK, Jacobian, readouts, arm layer, ellipse, heatmap marker);
// - drag frame (hook): the same work run synchronously by window.__ik2rBench.frame(x, y);
// - sweep plot: the jacobian-2r series redraw that follows each frame;
// - heatmap n×n: recompute (|det J| grid), paint (ImageData) and background draw;
// - workspace: ik_workspace::compute on a 1001 × 1001 grid.
//
// Budgets: drag frame p95 < 4 ms, heatmap 256 < 16 ms, 512 < 50 ms. With IK2R_BENCH_STRICT=1
// the exit code is 1 when a budget is missed; otherwise this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, nextFrame, runBench } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const table = new BenchTable();

await runBench({ table, strict: 'IK2R_BENCH_STRICT' }, async (url) => {
  const app = await openApp(url, '#/ik-2r', { viewport: VIEWPORT });
  const { page } = app;
  await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
  await page.waitForSelector('[data-testid="ik-2r-heatmap"][data-marker-q1]');
  await nextFrame(page);
  if (!(await page.evaluate(() => typeof window.__ik2rBench === 'object'))) {
    throw new Error('no window.__ik2rBench: serve a dist built with --features bench (make bench)');
  }

  // Real drags: the tip around circles of several radii, one pointer move per frame.
  const g = await page.evaluate(() => {
    const c = document.querySelector('[data-testid="ik-2r-canvas"]');
    const r = c.getBoundingClientRect();
    return { left: r.left, top: r.top, ox: +c.dataset.originX, oy: +c.dataset.originY, s: +c.dataset.pxPerM, tipX: +c.dataset.tipX, tipY: +c.dataset.tipY };
  });
  const at = (x, y) => [g.left + g.ox + x * g.s, g.top + g.oy - y * g.s];
  const counts = await page.evaluate(() => ({ frame: __ik2rTimings.frame.length, plot: __ik2rTimings.plot.length }));
  await page.mouse.move(g.left + g.tipX, g.top + g.tipY);
  await page.mouse.down();
  for (let k = 0; k < 400; k++) {
    const r = 0.05 + 0.15 * (0.5 + 0.5 * Math.sin(k / 37));
    const [x, y] = at(r * Math.cos(k / 20), r * Math.sin(k / 20));
    await page.mouse.move(x, y);
    await nextFrame(page);
  }
  await page.mouse.up();
  const real = await page.evaluate((c) => ({ frame: __ik2rTimings.frame.slice(c.frame), plot: __ik2rTimings.plot.slice(c.plot) }), counts);
  table.report('drag frame (real pointer)', real.frame, 4);
  table.report('sweep plot redraw (real)', real.plot);

  // The same work through the hook, synchronously.
  const hook = await page.evaluate(() => {
    const out = [];
    for (let k = 0; k < 1000; k++) {
      const r = 60 + 140 * (0.5 + 0.5 * Math.sin(k / 53));
      out.push(__ik2rBench.frame(r * Math.cos(k / 31), r * Math.sin(k / 31)));
    }
    return out;
  });
  table.report('drag frame (hook)', hook, 4);
  const plot = await page.evaluate(() => {
    const out = [];
    for (let k = 0; k < 300; k++) {
      __ik2rBench.frame(150 * Math.cos(k / 9), 150 * Math.sin(k / 9));
      out.push(__ik2rBench.plot());
    }
    return out;
  });
  table.report('sweep plot redraw (hook)', plot);

  for (const [n, reps, budget] of [[256, 30, 16], [512, 15, 50], [1024, 6, undefined]]) {
    const ms = await page.evaluate(({ n, reps }) => {
      __ik2rBench.heatmap(n);
      const out = [];
      for (let k = 0; k < reps; k++) out.push(__ik2rBench.heatmap(n));
      return out;
    }, { n, reps });
    table.report(`heatmap ${n}×${n} recompute + paint`, ms, budget);
  }
  await app.close();

  // The largest workspace grid the form allows (1001 × 1001 cells).
  const ws = await openApp(url, '#/ik-2r?ws=1&half_mm=500&step_mm=1', { viewport: VIEWPORT });
  await ws.page.waitForFunction(() => window.__ik2rTimings?.workspace?.length > 0, null, { timeout: 60000 });
  table.report('workspace 1001×1001 (ik_workspace::compute)', await ws.page.evaluate(() => __ik2rTimings.workspace));
  await ws.close();
});
