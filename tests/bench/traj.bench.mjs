// Speed of the trajectory-resampling page (#/traj-resample) in headless Chromium, on the dist
// folder named by BSV_DIST (default dist/): a ~57 MB file of 1,000,000 rows (t from 0 by 1 ms,
// five joints) chosen on the page and resampled at dt = 0.001 in the worker, then plotted. The
// main thread's long tasks from the file's choice to the plotted result (a 'longtask' observer
// installed before the app starts), the wall time of it, and the same for a change of dt.
//
// Budget: no main-thread task of 100 ms while the file is read, resampled and plotted. With
// TRAJ_BENCH_STRICT=1 the exit code is 1 when it is missed; otherwise this only reports.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { BenchTable, openWatched, runBench, takeLongTasks } from './bench-table.mjs';

const ROWS = 1_000_000;
const table = new BenchTable();
const notes = [];

const rowsIn = (page, rows, timeout) =>
  page.waitForFunction((r) => document.querySelector('[data-readout="rows_in"]')?.textContent === r, rows, { timeout });
const rowsOut = (page, rows, timeout) =>
  page.waitForFunction((r) => document.querySelector('[data-readout="rows_out"]')?.textContent === r, rows, { timeout });

const lines = ['t_s,q1,q2,q3,q4,q5'];
for (let i = 0; i < ROWS; i += 1) {
  const t = i / 1000;
  lines.push(`${t.toFixed(3)},${Math.sin(t).toFixed(9)},${Math.cos(t / 3).toFixed(9)},${(t % 7).toFixed(6)},${(i % 1000 === 0 ? 2 : 0.5).toFixed(1)},${Math.sin(3 * t).toFixed(9)}`);
}
const dir = mkdtempSync(join(tmpdir(), 'traj-bench-'));
const path = join(dir, 'big.csv');
writeFileSync(path, `${lines.join('\n')}\n`);

try {
  await runBench({ table, notes, strict: 'TRAJ_BENCH_STRICT' }, async (url) => {
    const { page, close } = await openWatched(url, '#/traj-resample?dt=0.001', { viewport: { width: 1280, height: 900 } });
    try {
      await rowsIn(page, '5', 20_000);
      await page.waitForTimeout(500);
      table.longTasks('the mount and the sample', await takeLongTasks(page));
      let t0 = Date.now();
      await page.locator('[data-testid="traj-file"]').setInputFiles(path);
      await rowsIn(page, '1,000,000', 240_000);
      await rowsOut(page, '1,000,000', 240_000);
      await page.waitForTimeout(300);
      notes.push(`1,000,000 rows read, resampled and plotted in ${Date.now() - t0} ms`);
      table.longTasks('1,000,000 rows: read, resample, plot', await takeLongTasks(page), 100);
      t0 = Date.now();
      await page.locator('[data-field="dt"]').fill('0.002');
      await page.waitForFunction(() => document.querySelector('[data-readout="rows_out"]')?.textContent !== '1,000,000', null, { timeout: 240_000 });
      await page.locator('[data-testid="progress"]').waitFor({ state: 'hidden', timeout: 240_000 });
      await page.waitForTimeout(300);
      notes.push(`dt 0.002: resampled and plotted in ${Date.now() - t0} ms`);
      table.longTasks('1,000,000 rows: another dt', await takeLongTasks(page), 100);
    } finally {
      await close();
    }
  });
} finally {
  rmSync(dir, { recursive: true, force: true });
}
