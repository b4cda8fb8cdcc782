// What the page benchmarks (`tests/e2e/*.bench.mjs`, run by `make bench`) share: order
// statistics of a run of timings, a table of them against their budgets, and waiting for the
// next animation frame of a page.

/** n, p50, p95 and max of the finite values (nearest-rank quantiles). */
export function stats(values) {
  const v = [...values].filter(Number.isFinite).sort((a, b) => a - b);
  const q = (p) => v[Math.min(v.length - 1, Math.max(0, Math.ceil(p * v.length) - 1))];
  return { n: v.length, p50: q(0.5), p95: q(0.95), max: v[v.length - 1] };
}

/** Resolves after the page's next animation frame. */
export const nextFrame = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));

/** Rows of "work, n, p50, p95, max, budget, ok/OVER", printed as one aligned table. */
export class BenchTable {
  rows = [];

  /** Adds the timings `values` of `name`; with `budgetP95` (ms) the row says ok or OVER. */
  report(name, values, budgetP95) {
    const s = stats(values);
    const ok = budgetP95 === undefined ? '' : s.p95 < budgetP95 ? 'ok' : 'OVER';
    this.rows.push({ name, ...s, budget: budgetP95 === undefined ? '' : `p95 < ${budgetP95} ms`, ok });
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
