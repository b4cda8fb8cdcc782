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
import { openApp, closeBrowser, startServer } from './harness.mjs';

const VIEWPORT = { width: 1920, height: 1080 };

function stats(values) {
  const v = [...values].filter(Number.isFinite).sort((a, b) => a - b);
  const q = (p) => v[Math.min(v.length - 1, Math.max(0, Math.ceil(p * v.length) - 1))];
  return { n: v.length, p50: q(0.5), p95: q(0.95), max: v[v.length - 1] };
}

const rows = [];
function report(name, values, budgetP95) {
  const s = stats(values);
  const ok = budgetP95 === undefined ? '' : s.p95 < budgetP95 ? 'ok' : 'OVER';
  rows.push({ name, ...s, budget: budgetP95 === undefined ? '' : `p95 < ${budgetP95} ms`, ok });
}

function printTable() {
  const f = (x) => (x === undefined ? '' : x.toFixed(2));
  const head = ['work', 'n', 'p50 ms', 'p95 ms', 'max ms', 'budget', ''];
  const body = rows.map((r) => [r.name, String(r.n), f(r.p50), f(r.p95), f(r.max), r.budget, r.ok]);
  const widths = head.map((h, i) => Math.max(h.length, ...body.map((b) => b[i].length)));
  const line = (cells) => cells.map((c, i) => (i === 0 || i === 5 ? c.padEnd(widths[i]) : c.padStart(widths[i]))).join('  ');
  console.log(line(head));
  console.log(widths.map((w) => '-'.repeat(w)).join('  '));
  for (const b of body) console.log(line(b));
}

const frame = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));

const server = await startServer();
try {
  const app = await openApp(server.url, '#/ik-2r', { viewport: VIEWPORT });
  const { page } = app;
  await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
  await frame(page);
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
    await frame(page);
  }
  await page.mouse.up();
  const real = await page.evaluate((c) => ({ frame: __ik2rTimings.frame.slice(c.frame), plot: __ik2rTimings.plot.slice(c.plot) }), counts);
  report('drag frame (real pointer)', real.frame, 4);
  report('sweep plot redraw (real)', real.plot);

  // The same work through the hook, synchronously.
  const hook = await page.evaluate(() => {
    const out = [];
    for (let k = 0; k < 1000; k++) {
      const r = 60 + 140 * (0.5 + 0.5 * Math.sin(k / 53));
      out.push(__ik2rBench.frame(r * Math.cos(k / 31), r * Math.sin(k / 31)));
    }
    return out;
  });
  report('drag frame (hook)', hook, 4);
  const plot = await page.evaluate(() => {
    const out = [];
    for (let k = 0; k < 300; k++) {
      __ik2rBench.frame(150 * Math.cos(k / 9), 150 * Math.sin(k / 9));
      out.push(__ik2rBench.plot());
    }
    return out;
  });
  report('sweep plot redraw (hook)', plot);

  for (const [n, reps, budget] of [[256, 30, 16], [512, 15, 50], [1024, 6, undefined]]) {
    const ms = await page.evaluate(({ n, reps }) => {
      __ik2rBench.heatmap(n);
      const out = [];
      for (let k = 0; k < reps; k++) out.push(__ik2rBench.heatmap(n));
      return out;
    }, { n, reps });
    report(`heatmap ${n}×${n} recompute + paint`, ms, budget);
  }
  await app.close();

  // The largest workspace grid the form allows (1001 × 1001 cells).
  const ws = await openApp(server.url, '#/ik-2r?ws=1&half_mm=500&step_mm=1', { viewport: VIEWPORT });
  await ws.page.waitForFunction(() => window.__ik2rTimings?.workspace?.length > 0, null, { timeout: 60000 });
  report('workspace 1001×1001 (ik_workspace::compute)', await ws.page.evaluate(() => __ik2rTimings.workspace));
  await ws.close();
} finally {
  await closeBrowser();
  await server.close();
}

printTable();
if (process.env.IK2R_BENCH_STRICT === '1' && rows.some((r) => r.ok === 'OVER')) process.exitCode = 1;
