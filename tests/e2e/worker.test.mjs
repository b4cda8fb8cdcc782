// Long runs in the Web Worker, started from the drills page: `manip-grid 1024` and
// `rrt-2d 7 1000000 --goal-x 0.5 --goal-y 0.5` show progress (the progress bar's aria-valuenow
// moves) and can be cancelled (the last result stays); a completed worker run downloads
// exactly the CLI's bytes; the page takes input during a run. The main-thread tasks during
// these runs are figures of tests/bench/worker.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp } from './harness.mjs';
import { serveAppWithCli, cli, download, assertSameBytes } from './cli.mjs';

const server = serveAppWithCli();

async function openDrills(hash) {
  const app = await openApp(server.url, hash, { viewport: { width: 1280, height: 900 } });
  await app.page.waitForSelector('[data-testid="drills-page"]');
  return app;
}

const bar = (page) => page.locator('[data-testid="progress-bar"]');
const runCount = async (page) => Number(await page.locator('[data-testid="drills-output"]').getAttribute('data-run'));
const summary = async (page) => (await page.locator('[data-testid="drills-summary"]').innerText()).trim();

/** Starts the run and waits until the bar has moved twice. */
async function startAndWatch(page) {
  await page.locator('[data-testid="drills-run"]').click();
  await page.locator('[data-testid="progress"]').waitFor({ state: 'visible', timeout: 10000 });
  const values = new Set();
  const end = Date.now() + 60000;
  while (values.size < 3 && Date.now() < end) {
    const now = Number(await bar(page).getAttribute('aria-valuenow'));
    if (now > 0) values.add(now);
    await page.waitForTimeout(40);
  }
  const max = Number(await bar(page).getAttribute('aria-valuemax'));
  assert.ok(values.size >= 3, `aria-valuenow moved: ${[...values].join(', ')} of ${max}`);
  assert.ok([...values].every((v) => v <= max), 'done never passes the total');
  assert.equal(await bar(page).getAttribute('role'), 'progressbar');
  assert.equal(await bar(page).getAttribute('aria-valuemin'), '0');
  // The rows text groups digits and the page is in its running state.
  assert.match(await page.locator('[data-testid="progress-rows"]').innerText(), /^[\d,]+ of [\d,]+ rows \([\d.]+ %\)$/);
  assert.equal(await page.locator('[data-testid="drills-page"]').getAttribute('data-state'), 'running');
  // The page stays interactive: a button takes the focus during the run.
  const focused = await page.evaluate(() => {
    document.querySelector('[data-testid="drills-reset"]').focus();
    return document.activeElement?.dataset.testid;
  });
  assert.equal(focused, 'drills-reset', 'the main thread answers during the run');
  return [...values];
}

test('manip-grid 1024 runs in the worker with progress, can be cancelled, and downloads the CLI bytes', { timeout: 300_000 }, async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=manip-grid&n=1024');
  try {
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-status"]').textContent !== '');
    assert.equal(await runCount(page), 0, 'a large run does not start by itself');
    // Cancel: the panel goes, nothing is shown, the page is ready again.
    await startAndWatch(page);
    await page.locator('[data-testid="progress-cancel"]').click();
    await page.locator('[data-testid="progress"]').waitFor({ state: 'hidden' });
    assert.equal(await page.locator('[data-testid="drills-page"]').getAttribute('data-state'), 'ready');
    await page.waitForTimeout(500);
    assert.equal(await runCount(page), 0, 'a cancelled run shows no result');
    // A complete run.
    await startAndWatch(page);
    await page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > 0, null, { timeout: 240_000 });
    assert.ok(await page.locator('[data-testid="progress"]').isHidden());
    const want = cli(['manip-grid', '0.12', '0.10', '1024']);
    assert.equal(await summary(page), want.stdout);
    const got = await download(page, 'manip_ellipse.csv');
    assertSameBytes(got, want.files.get('manip_ellipse.csv'), 'manip-grid 1024 from the worker');
    // The preview reads the head; the size line counts the whole file.
    assert.match(await page.locator('[data-file="manip_ellipse.csv"]').innerText(), /1,048,576 rows/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// 50,000 iterations finish in about 0.2 s (too fast to watch or cancel): the long rrt-2d case
// is the form's limit, 1,000,000 iterations (~6 s).
test('rrt-2d 7 1000000 --goal-x 0.5 --goal-y 0.5 shows progress and Cancel keeps the last result', { timeout: 300_000 }, async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=rrt-2d');
  try {
    // The default (small) run shows by itself: that is the last result to keep.
    await page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > 0, null, { timeout: 20000 });
    const before = await summary(page);
    const runs = await runCount(page);
    await page.locator('[data-field="seed"]').fill('7');
    await page.locator('[data-field="max_iter"]').fill('1000000');
    await page.locator('[data-field="goal-x"]').fill('0.5');
    await page.locator('[data-field="goal-y"]').fill('0.5');
    await page.waitForTimeout(400);
    assert.equal(await runCount(page), runs, '1,000,000 iterations do not start by themselves');
    const seen = await startAndWatch(page);
    await page.waitForTimeout(500);
    const moved = Number(await bar(page).getAttribute('aria-valuenow'));
    assert.ok(moved >= Math.max(...seen), 'progress only goes forward');
    await page.locator('[data-testid="progress-cancel"]').click();
    await page.locator('[data-testid="progress"]').waitFor({ state: 'hidden' });
    await page.waitForTimeout(1000);
    assert.equal(await runCount(page), runs, 'the cancelled run never lands');
    assert.equal(await summary(page), before, 'the last result stays');
    assert.ok(await page.locator('[data-testid="drills-stale"]').isVisible(), 'and says the form has moved on');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a worker run shows its warnings in both languages and downloads the CLI bytes (rrt-2d 7 8000, goal in the obstacle)', { timeout: 300_000 }, async () => {
  // 8,000 iterations plan 128,000 rows: above the auto-run size, so Run sends it to the worker.
  const { page, errors, close } = await openDrills('#/drills?recipe=rrt-2d&seed=7&max_iter=8000&goal-x=0.5&goal-y=0.5');
  try {
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-status"]').textContent !== '');
    assert.equal(await runCount(page), 0, 'a large run does not start by itself');
    await page.locator('[data-testid="drills-run"]').click();
    await page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > 0, null, { timeout: 120_000 });
    const want = cli(['rrt-2d', '7', '8000', '--goal-x', '0.5', '--goal-y', '0.5']);
    assert.equal(await summary(page), want.stdout);
    const warnings = page.locator('[data-testid="drills-warnings"]');
    assert.ok(await warnings.isVisible(), 'the worker run warns');
    assert.match(await warnings.innerText(), /The goal \(0\.5, 0\.5\) is inside the obstacle/);
    for (const [name, bytes] of want.files) {
      assertSameBytes(await download(page, name), bytes, `rrt-2d ${name} from the worker`);
    }
    // The language switch re-renders the worker's warning from its Japanese text.
    await page.locator('[data-testid="lang-switch"]').click();
    assert.match(await warnings.innerText(), /ゴール（0\.5, 0\.5）が障害物の内側にあるため、どの経路も届きません。/);
    await page.locator('[data-testid="lang-switch"]').click();
    assert.match(await warnings.innerText(), /The goal \(0\.5, 0\.5\) is inside the obstacle/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** A trajectory CSV of `rows` data rows (t_s from 0 by 1 ms, one joint), over 4 MiB for
 * 300,000 rows: the drills page sizes such a file only by running it, in the worker. */
function bigTrajectory(rows, badRow) {
  const lines = ['t_s,q1'];
  for (let i = 0; i < rows; i += 1) lines.push(`${(i / 1000).toFixed(3)},${i === badRow ? 'abc' : Math.sin(i / 5000).toFixed(9)}`);
  return Buffer.from(`${lines.join('\n')}\n`);
}

test('a recipe error from a worker run shows beside its field, as a run on the page shows it', { timeout: 300_000 }, async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=traj-resample');
  try {
    await page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > 0, null, { timeout: 20000 });
    const file = page.locator('[data-testid="drills-file"]');
    const fileError = page.locator('[data-field-error="csv_path"]');
    const general = page.locator('[data-testid="drills-error"]');

    // A run on the page (small file): the bad cell's message beside the file picker.
    await file.setInputFiles({ name: 'small.csv', mimeType: 'text/csv', buffer: Buffer.from('t_s,q1\n0,0\n0.1,abc\n0.2,1\n') });
    await fileError.waitFor({ state: 'visible' });
    assert.equal(await fileError.innerText(), 'CSV line 3, column q1: “abc” is not a number.');

    // The same kind of error from a worker run (a 5 MB file, its last row bad): same place,
    // same words, the field marked, nothing under the form.
    const rows = 300_000;
    const big = bigTrajectory(rows, rows - 1);
    assert.ok(big.length > 4 * 1024 * 1024, `${big.length} bytes`);
    const runs = await runCount(page);
    await file.setInputFiles({ name: 'big.csv', mimeType: 'text/csv', buffer: big });
    await page.waitForFunction(() => /big\.csv/.test(document.querySelector('[data-testid="drills-file-status"]').textContent), null, { timeout: 20000 });
    await page.locator('[data-testid="drills-run"]').click();
    await page.waitForFunction(() => /CSV line/.test(document.querySelector('[data-field-error="csv_path"]').textContent), null, { timeout: 120_000 });
    // The row as the page's own run words it (the kernel's number, unformatted).
    assert.equal(await fileError.innerText(), `CSV line ${rows + 1}, column q1: “abc” is not a number.`);
    assert.equal(await fileError.isVisible(), true);
    assert.equal(await page.locator('[data-file-input]').getAttribute('aria-invalid'), 'true');
    assert.equal(await general.isVisible(), false, 'nothing under the form');
    assert.equal(await runCount(page), runs, 'no result from the failed run');
    await page.locator('[data-testid="lang-switch"]').click();
    assert.equal(await fileError.innerText(), `CSV の ${rows + 1} 行目、列 q1：「abc」は数値ではありません。`);
    await page.locator('[data-testid="lang-switch"]').click();

    // An error about an argument (too many output rows at this dt) goes beside that argument.
    await file.setInputFiles({ name: 'good.csv', mimeType: 'text/csv', buffer: bigTrajectory(rows, -1) });
    await page.waitForFunction(() => /good\.csv/.test(document.querySelector('[data-testid="drills-file-status"]').textContent), null, { timeout: 20000 });
    await page.locator('[data-field="dt"]').fill('0.00001');
    await page.locator('[data-testid="drills-run"]').click();
    const dtError = page.locator('[data-field-error="dt"]');
    await dtError.waitFor({ state: 'visible', timeout: 120_000 });
    assert.match(await dtError.innerText(), /the table would have [\d,]+ rows; the limit is 20,000,000/);
    assert.equal(await page.locator('[data-field="dt"]').getAttribute('aria-invalid'), 'true');
    assert.equal(await general.isVisible(), false, 'nothing under the form');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
