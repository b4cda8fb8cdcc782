// What the page benchmarks (`tests/bench/*.bench.mjs`, run by `make bench`) share: order
// statistics of a run of timings, a table of them against their budgets, waiting for the next
// animation frame of a page, the main thread's long tasks (the 'longtask' entries of a
// PerformanceObserver: every task of 50 ms or more, wall-clock), and the frame of a bench
// script (serve, run, close, print, exit code).
import { openApp, closeBrowser, startServer } from '../e2e/harness.mjs';

/** n, p50, p95 and max of the finite values (nearest-rank quantiles). */
export function stats(values) {
  const v = [...values].filter(Number.isFinite).sort((a, b) => a - b);
  const q = (p) => v[Math.min(v.length - 1, Math.max(0, Math.ceil(p * v.length) - 1))];
  return { n: v.length, p50: q(0.5), p95: q(0.95), max: v[v.length - 1] };
}

/** Resolves after the page's next animation frame. */
export const nextFrame = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));

/**
 * Init script (`context.addInitScript(watchLongTasks)`): from before the app starts, every long
 * task of the page goes to window.__longTasks as [startTime, duration] (ms).
 */
export function watchLongTasks() {
  window.__longTasks = [];
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) window.__longTasks.push([e.startTime, e.duration]);
  }).observe({ type: 'longtask', buffered: true });
}

/** The app at `hash` in a fresh context whose pages record their long tasks from the start. */
export async function openWatched(url, hash, options = {}) {
  const app = await openApp(url, hash, options);
  await app.context.addInitScript(watchLongTasks);
  await app.page.reload();
  await app.page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20_000 });
  return app;
}

/** Durations (ms, rounded) of the long tasks seen since the last call; clears them. */
export const takeLongTasks = (page) => page.evaluate(() => window.__longTasks.splice(0).map(([, d]) => Math.round(d)));

/**
 * Runs `count` plain tasks of `ms` each, one after the other, on the page's main thread: the
 * long tasks (ms) the observer saw meanwhile, how much this machine stretches a task at the
 * moment (none when it does not). Clears the page's long tasks first.
 */
export async function stretchedTasks(page, ms, count = 20) {
  await takeLongTasks(page);
  await page.evaluate(async ({ ms, count }) => {
    for (let i = 0; i < count; i++) {
      await new Promise((r) => setTimeout(() => {
        const end = performance.now() + ms;
        while (performance.now() < end);
        r();
      }, 0));
    }
    await new Promise((r) => setTimeout(r, 300));
  }, { ms, count });
  return takeLongTasks(page);
}

/** The statistic a budget bounds and its limit (ms): a number is a bound on the p95. */
const bound = (budget) => (typeof budget === 'number' ? ['p95', budget] : Object.entries(budget)[0]);

/** Rows of "work, n, p50, p95, max, budget, ok/OVER", printed as one aligned table. */
export class BenchTable {
  rows = [];

  /**
   * Adds the timings `values` (ms) of `name`. With a `budget` the row says ok or OVER: a number
   * bounds the p95 (`4`: p95 < 4 ms), `{ p50: 4 }` or `{ max: 100 }` another statistic.
   */
  report(name, values, budget) {
    this.add(name, stats(values), budget);
  }

  /**
   * Adds the long tasks `durations` (ms) seen while `name` ran: n is how many reached 50 ms,
   * max the longest (0 without one). `budgetMs` bounds the longest.
   */
  longTasks(name, durations, budgetMs) {
    this.add(name, { n: durations.length, max: Math.max(0, ...durations) }, budgetMs === undefined ? undefined : { max: budgetMs });
  }

  add(name, s, budget) {
    if (budget === undefined) {
      this.rows.push({ name, ...s, budget: '', ok: '' });
      return;
    }
    const [stat, limit] = bound(budget);
    const ok = s[stat] < limit ? 'ok' : 'OVER';
    this.rows.push({ name, ...s, budget: `${stat} < ${limit} ms`, ok });
  }

  /** Whether a row missed its budget. */
  over() {
    return this.rows.some((r) => r.ok === 'OVER');
  }

  print() {
    const f = (x) => (x === undefined ? '' : x.toFixed(2));
    const head = ['work', 'n', 'p50 ms', 'p95 ms', 'max ms', 'budget', ''];
    const body = this.rows.map((r) => [r.name, String(r.n), f(r.p50), f(r.p95), f(r.max), r.budget, r.ok]);
    const widths = head.map((h, i) => Math.max(h.length, ...body.map((b) => b[i].length)));
    const line = (cells) => cells.map((c, i) => (i === 0 || i === 5 ? c.padEnd(widths[i]) : c.padStart(widths[i]))).join('  ');
    console.log(line(head));
    console.log(widths.map((w) => '-'.repeat(w)).join('  '));
    for (const b of body) console.log(line(b));
  }
}

/**
 * Runs a bench script: serves DIST, runs `body(url)`, closes the browser and the server, prints
 * `table` and then `notes` (lines). With the environment variable `strict` set to 1 the exit
 * code is 1 when a row missed its budget; otherwise the bench only reports.
 */
export async function runBench({ table, notes = [], strict }, body) {
  const server = await startServer();
  try {
    await body(server.url);
  } finally {
    await closeBrowser();
    await server.close();
  }
  table.print();
  for (const note of notes) console.log(note);
  if (process.env[strict] === '1' && table.over()) process.exitCode = 1;
}
