// Speed of the pendulum page (#/pendulum-energy) in headless Chromium at 1920×1080, on the dist
// folder named by BSV_DIST (default dist/); it needs a wasm built with `--features bench` (the
// timing hooks are not in the app build): `make bench` (scripts/bench.sh) assembles one in
// target/bench-dist. The case: 10× speed, timestep 0.001 s, both integrators (compare on), a
// 20 s run. Prints p50 / p95 / max of:
//
// - frame work (real): the page's own record of each animation frame while playing: advance
//   both tracks, draw the pendulum, append to the plots (time panels and phase portrait),
//   readouts;
// - frame interval (real): time between animation frames while playing (the browser's view);
// - frame work (hook): the same work run synchronously by window.__pendulumBench.frame(167),
//   167 steps being one 60 Hz frame at 10× real time with h = 0.001 s;
// - playing at 10×: the wall time from the start to t = 15 s.
//
// Budgets: frame work p95 < 4 ms; playing at 10× reaches t = 15 s within 6 s of wall time (2.5×
// real time at least). With PENDULUM_BENCH_STRICT=1 the exit code is 1 when one is missed;
// otherwise this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, runBench } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const table = new BenchTable();
const HASH = '#/pendulum-energy?timestep=0.001&compare=1&duration_s=20';
const STEPS_PER_FRAME = 167;

await runBench({ table, strict: 'PENDULUM_BENCH_STRICT' }, async (url) => {
  const { page, close } = await openApp(url, HASH, { viewport: VIEWPORT });
  if (!(await page.evaluate(() => typeof window.__pendulumBench === 'object'))) {
    throw new Error('no window.__pendulumBench: serve a dist built with --features bench (make bench)');
  }
  // Real frames: from the start at 10×, for 5 s of wall time (50 s of simulated time would
  // pass the 20 s end, so the run is restarted at its end).
  await page.locator('[data-action="reset"]').click();
  await page.locator('[data-stepper="speed"]').selectOption({ index: 6 });
  await page.evaluate(() => {
    window.__pendulumFrameMs.length = 0;
    window.__benchIntervals = [];
    let last;
    const tick = (t) => {
      if (last !== undefined) window.__benchIntervals.push(t - last);
      last = t;
      if (window.__benchIntervals.length < 100000) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const work = [];
  const intervals = [];
  const wall = [];
  for (let round = 0; round < 3; round++) {
    const t0 = Date.now();
    await page.locator('[data-action="run"]').click();
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) > 15, null, { timeout: 30000 });
    await page.locator('[data-action="run"]').click();
    wall.push(Date.now() - t0);
    const got = await page.evaluate(() => {
      const out = { work: window.__pendulumFrameMs.splice(0), intervals: window.__benchIntervals.splice(0) };
      return out;
    });
    work.push(...got.work.slice(1));
    intervals.push(...got.intervals.slice(1));
    await page.locator('[data-action="reset"]').click();
    await page.evaluate(() => { window.__pendulumFrameMs.length = 0; window.__benchIntervals.length = 0; });
  }
  table.report('frame work (real, playing 10×)', work, 4);
  table.report('frame interval (real, playing 10×)', intervals);
  // 15 s at 10× is 1.5 s of wall time: within 6 s, playing goes at 2.5× real time at least.
  table.report('playing 10× from the start to t = 15 s (wall time)', wall, { max: 6000 });

  // The same work through the hook, synchronously, over whole runs.
  const hook = await page.evaluate((steps) => {
    const out = [];
    for (let k = 0; k < 600; k++) out.push(window.__pendulumBench.frame(steps));
    return out;
  }, STEPS_PER_FRAME);
  table.report(`frame work (hook, ${STEPS_PER_FRAME} steps)`, hook, 4);
  await close();
});
