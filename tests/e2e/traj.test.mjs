// The trajectory-resampling page (#/traj-resample) in headless Chromium: the labeled sample and
// a URL dt download exactly what `bsv traj-resample` writes; a CRLF file with a byte-order mark,
// a file dropped on the page, a bad cell (its row and column named, the last plot kept), a bad
// dt and a file that is not UTF-8; a file over 4 MiB dropped (the worker, progress, the CLI's
// CSV); a file over 128 MiB refused with the page's message; nine joints on nine panels; a
// ~57 MB, 1,000,000-row file resampled at dt = 0.001 in the worker (progress shown, CSV equal
// to the CLI's); the Japanese page leaves no English UI string; screenshots to tests/e2e/out/.
// The main-thread tasks of the 1,000,000-row run are a figure of tests/bench/traj.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { openApp, OUT, screenshots } from './harness.mjs';
import { BSV, serveAppWithCli, cli, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

const server = serveAppWithCli();

async function openTraj(hash = '#/traj-resample', opts = {}) {
  const app = await openApp(server.url, hash, opts);
  await app.page.waitForSelector('[data-testid="traj-resample-page"]');
  return app;
}

const readout = async (page, key) => (await page.locator(`[data-readout="${key}"]`).innerText()).trim();
const fileError = (page) => page.locator('[data-field-error="csv_path"]');

/** Waits until the readouts say `rows` input rows. */
async function waitRows(page, rows, timeout = 20000) {
  await page.waitForFunction((r) => document.querySelector('[data-readout="rows_in"]')?.textContent === r, rows, { timeout });
}

/** Runs `bsv traj-resample <file bytes as name> <dt>` in a fresh folder: stdout and files. */
function cliOnBytes(name, bytes, dt) {
  const dir = mkdtempSync(join(tmpdir(), 'traj-cli-'));
  try {
    writeFileSync(join(dir, name), bytes);
    const out = join(dir, 'out');
    const args = ['traj-resample', name, ...(dt ? [dt] : []), '--out', out];
    const run = spawnSync(BSV, args, { cwd: dir, maxBuffer: 1 << 30 });
    assert.equal(run.status, 0, String(run.stderr));
    return { stdout: String(run.stdout).trim(), csv: readFileSync(join(out, 'traj_resampled.csv')) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

test('the labeled sample and a URL dt give the CLI bytes; readouts count rows, joints and the span', async () => {
  const { page, errors, close } = await openTraj();
  try {
    await waitRows(page, '5');
    assert.equal(await readout(page, 'joints'), '2');
    assert.equal(await readout(page, 'span'), '0 s to 0.55 s');
    assert.equal(await readout(page, 'duration'), '0.55 s');
    assert.equal(await readout(page, 'rows_out'), '28');
    assert.equal(await page.locator('[data-testid="traj-resample-canvas"]').count(), 1);
    const want = cli(['traj-resample']);
    assertSameBytes(await download(page, 'traj_resampled.csv'), want.files.get('traj_resampled.csv'), 'defaults');
    assertSameBytes(await download(page, 'traj_sample_labeled.csv'), want.files.get('traj_sample_labeled.csv'), 'the sample');
    assert.equal((await page.locator('[data-testid="traj-cmd-bsv"]').innerText()).trim(), 'bsv traj-resample');
    // The PNG of the plot.
    const [png] = await Promise.all([page.waitForEvent('download'), page.locator('[data-testid="traj-png"]').click()]);
    assert.equal(png.suggestedFilename(), 'traj_resample_plot.png');
    // A dt typed in the field: the URL and the command line follow, the download is the CLI's.
    await page.locator('[data-field="dt"]').fill('0.05');
    await page.waitForFunction(() => document.querySelector('[data-readout="rows_out"]').textContent === '12');
    await page.waitForFunction(() => location.hash === '#/traj-resample?dt=0.05');
    const at = cli(['traj-resample', '', '0.05']);
    assertSameBytes(await download(page, 'traj_resampled.csv'), at.files.get('traj_resampled.csv'), 'dt 0.05');
    // A bad dt: its message beside the field, the last plot and download stay.
    await page.locator('[data-field="dt"]').fill('-1');
    await page.locator('[data-field-error="dt"]').waitFor({ state: 'visible' });
    assert.match(await page.locator('[data-field-error="dt"]').innerText(), /Time step dt \(s\)/);
    assert.equal(await page.locator('[data-field="dt"]').getAttribute('aria-invalid'), 'true');
    assert.equal(await readout(page, 'rows_out'), '12');
    assertSameBytes(await download(page, 'traj_resampled.csv'), at.files.get('traj_resampled.csv'), 'kept');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  // A link with another dt.
  const linked = await openTraj('#/traj-resample?dt=0.01&zoom=3');
  try {
    await linked.page.waitForFunction(() => document.querySelector('[data-readout="rows_out"]').textContent === '56');
    const want = cli(['traj-resample', '', '0.01']);
    assertSameBytes(await download(linked.page, 'traj_resampled.csv'), want.files.get('traj_resampled.csv'), 'URL dt 0.01');
    assert.match(await linked.page.locator('[data-testid="traj-url-notice"]').innerText(), /ignored: zoom/);
    assert.deepEqual(linked.errors, []);
  } finally {
    await linked.close();
  }
});

test('a CRLF file with a BOM, a dropped file, a bad cell, a file that is not UTF-8', async () => {
  const { page, errors, close } = await openTraj('#/traj-resample?dt=0.05');
  try {
    await waitRows(page, '5');
    const crlf = Buffer.from('\ufefft_s,q1,q2,q3\r\n0.0,0.0,1.0,-1.0\r\n0.13,0.5,0.9,-0.5\r\n0.3,0.7,0.2,0.25\r\n0.71,1.5,-0.4,0.0\r\n');
    await page.locator('[data-testid="traj-file"]').setInputFiles({ name: 'walk.csv', mimeType: 'text/csv', buffer: crlf });
    await waitRows(page, '4');
    assert.equal(await readout(page, 'joints'), '3');
    assert.equal(await readout(page, 'span'), '0 s to 0.71 s');
    const want = cliOnBytes('walk.csv', crlf, '0.05');
    assertSameBytes(await download(page, 'traj_resampled.csv'), want.csv, 'CRLF + BOM');
    assert.equal((await page.locator('[data-testid="traj-cmd-bsv"]').innerText()).trim(), 'bsv traj-resample walk.csv 0.05');
    await page.waitForFunction(() => location.hash === '#/traj-resample?csv_path=walk.csv&dt=0.05');

    // Dropped on the page.
    await page.evaluate(() => {
      const data = new DataTransfer();
      data.items.add(new File(['t_s,q1\n0,0\n1,2\n2,3\n'], 'dropped.csv', { type: 'text/csv' }));
      const stage = document.querySelector('[data-testid="traj-resample-canvas"]');
      stage.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
      stage.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    });
    await waitRows(page, '3');
    assert.equal(await readout(page, 'rows_out'), '41');

    // A bad cell: row and column named beside the file picker; the last plot stays.
    await page.locator('[data-testid="traj-file"]').setInputFiles({ name: 'bad.csv', mimeType: 'text/csv', buffer: Buffer.from('t_s,q1,q2\n0,0,0\n0.1,0.5,x1\n0.2,1,1\n') });
    await fileError(page).waitFor({ state: 'visible' });
    assert.equal(await fileError(page).innerText(), 'CSV line 3, column q2: “x1” is not a number.');
    assert.equal(await readout(page, 'rows_in'), '3', 'the last good readouts stay');
    await page.locator('[data-testid="lang-switch"]').click();
    assert.equal(await fileError(page).innerText(), 'CSV の 3 行目、列 q2：「x1」は数値ではありません。');
    await page.locator('[data-testid="lang-switch"]').click();
    // The rest of the page still works: dt answers, the sample comes back.
    await page.locator('[data-testid="traj-use-sample"]').click();
    await waitRows(page, '5');
    assert.equal(await fileError(page).isVisible(), false);

    // Not UTF-8: refused with the byte offset, as bsv refuses it.
    const latin1 = Buffer.from([...Buffer.from('t_s,q1,note\n0.0,0.0,caf'), 0xe9, ...Buffer.from('\n0.1,1.0,x\n')]);
    await page.locator('[data-testid="traj-file"]').setInputFiles({ name: 'latin1.csv', mimeType: 'text/csv', buffer: latin1 });
    await fileError(page).waitFor({ state: 'visible' });
    assert.match(await fileError(page).innerText(), /“latin1\.csv” is not UTF-8 text: the byte at offset 23/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Drops a file of `text` named `name` on the plot, as a browser's drag and drop does. */
async function dropFile(page, name, text) {
  await page.evaluate(([n, t]) => {
    const data = new DataTransfer();
    data.items.add(new File([t], n, { type: 'text/csv' }));
    const stage = document.querySelector('[data-testid="traj-resample-canvas"]');
    stage.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
    stage.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
  }, [name, text]);
}

test('a file over 4 MiB dropped on the page resamples in the worker with progress; the CSV is the CLI\'s', { timeout: 300_000 }, async () => {
  const lines = ['t_s,q1,q2,q3'];
  for (let i = 0; i < 130_000; i += 1) {
    const t = i / 500;
    lines.push(`${t.toFixed(4)},${Math.sin(t).toFixed(9)},${Math.cos(t / 2).toFixed(9)},${(t % 3).toFixed(6)}`);
  }
  const text = `${lines.join('\n')}\n`;
  assert.ok(text.length > 4 * 1024 * 1024, `${text.length} bytes`);
  const { page, errors, close } = await openTraj('#/traj-resample?dt=0.01');
  try {
    await waitRows(page, '5');
    // What the progress panel and the page's state did, seen as they happen.
    await page.evaluate(() => {
      window.__seen = { progress: false, running: false };
      const progress = document.querySelector('[data-testid="progress"]');
      const root = document.querySelector('[data-testid="traj-resample-page"]');
      new MutationObserver(() => {
        window.__seen.progress ||= !progress.hidden;
        window.__seen.running ||= root.dataset.state === 'running';
      }).observe(document.body, { attributes: true, subtree: true, attributeFilter: ['hidden', 'data-state'] });
    });
    await dropFile(page, 'dropped-big.csv', text);
    await waitRows(page, '130,000', 120_000);
    assert.deepEqual(await page.evaluate(() => window.__seen), { progress: true, running: true });
    assert.match(await page.locator('[data-testid="traj-status"]').innerText(), /in the background/);
    assert.equal(await readout(page, 'joints'), '3');
    const want = cliOnBytes('dropped-big.csv', Buffer.from(text), '0.01');
    assertSameBytes(await download(page, 'traj_resampled.csv'), want.csv, 'dropped, over 4 MiB');
    assert.equal((await page.locator('[data-testid="traj-cmd-bsv"]').innerText()).trim(), 'bsv traj-resample dropped-big.csv 0.01');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a file over 128 MiB is refused unread with the page\'s message in MiB (EN and JA)', async () => {
  const { page, errors, close } = await openTraj();
  try {
    await waitRows(page, '5');
    // A small file the page sees as 200 MiB: its `size` is what the page reads first.
    await page.evaluate(() => {
      const real = Object.getOwnPropertyDescriptor(Blob.prototype, 'size');
      Object.defineProperty(Blob.prototype, 'size', {
        configurable: true,
        get() { return this.name === 'huge.csv' ? 200 * 1024 * 1024 : real.get.call(this); },
      });
    });
    await page.locator('[data-testid="traj-file"]').setInputFiles({ name: 'huge.csv', mimeType: 'text/csv', buffer: Buffer.from('t_s,q1\n0,0\n1,1\n') });
    await fileError(page).waitFor({ state: 'visible' });
    assert.equal(await fileError(page).innerText(), '“huge.csv” is 200.0 MiB: over the 128 MiB a trajectory may have here (bsv has the same limit). Split the file or resample a part of it.');
    assert.equal(await readout(page, 'rows_in'), '5', 'the last result stays');
    assert.equal(await page.locator('[data-testid="progress"]').isHidden(), true, 'nothing ran');
    await page.locator('[data-testid="lang-switch"]').click();
    assert.equal(await fileError(page).innerText(), '「huge.csv」は 200.0 MiB で、ここで扱える軌道の上限 128 MiB（bsv と同じ）を超えています。ファイルを分けるか、一部だけをリサンプリングしてください。');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('every joint is plotted: nine joints, nine panels, the stage grows', async () => {
  const names = Array.from({ length: 9 }, (_, k) => `q${k + 1}`);
  const rows = [`t_s,${names.join(',')}`];
  for (let i = 0; i <= 40; i += 1) rows.push([i / 20, ...names.map((_, k) => Math.sin(i / 10 + k).toFixed(6))].join(','));
  const { page, errors, close } = await openTraj('#/traj-resample', { viewport: { width: 1280, height: 800 } });
  try {
    await waitRows(page, '5');
    const before = (await page.locator('.traj-stage').boundingBox()).height;
    await dropFile(page, 'nine.csv', `${rows.join('\n')}\n`);
    await waitRows(page, '41');
    assert.equal(await readout(page, 'joints'), '9');
    const canvas = page.locator('[data-testid="traj-resample-canvas"]');
    await page.waitForFunction(() => document.querySelector('[data-testid="traj-resample-canvas"]').dataset.panels === '9');
    const height = (await page.locator('.traj-stage').boundingBox()).height;
    assert.ok(height >= 9 * 96 + 48 && height > before, `stage ${before} → ${height} px`);
    // The last joint's panel has its resampled line (blue) drawn.
    await page.waitForTimeout(300);
    const blue = await page.evaluate(() => {
      const layer = document.querySelectorAll('.traj-stage canvas')[1];
      const { width, height } = layer;
      const img = layer.getContext('2d').getImageData(0, Math.round(height * 0.89), width, Math.round(height * 0.08)).data;
      let n = 0;
      for (let i = 0; i < img.length; i += 4) if (Math.abs(img[i] - 31) < 30 && Math.abs(img[i + 1] - 119) < 30 && Math.abs(img[i + 2] - 180) < 30) n += 1;
      return n;
    });
    assert.ok(blue > 50, `${blue} blue pixels in the last panel`);
    assert.equal(await canvas.count(), 1);
    await page.locator('.traj-stage').screenshot({ path: join(OUT, 'traj-nine-joints-plot.png'), caret: 'initial' });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a 1,000,000-row, ~57 MB file resamples in the worker with progress and Cancel; the CSV is the CLI\'s', { timeout: 600_000 }, async () => {
  // t from 0 by 1 ms, five joints: about 57 MB.
  const rows = 1_000_000;
  const lines = ['t_s,q1,q2,q3,q4,q5'];
  for (let i = 0; i < rows; i += 1) {
    const t = i / 1000;
    lines.push(`${t.toFixed(3)},${Math.sin(t).toFixed(9)},${Math.cos(t / 3).toFixed(9)},${(t % 7).toFixed(6)},${(i % 1000 === 0 ? 2 : 0.5).toFixed(1)},${Math.sin(3 * t).toFixed(9)}`);
  }
  const bytes = Buffer.from(`${lines.join('\n')}\n`);
  assert.ok(bytes.length > 50e6, `${bytes.length} bytes`);
  const dir = mkdtempSync(join(tmpdir(), 'traj-big-'));
  const path = join(dir, 'big.csv');
  writeFileSync(path, bytes);
  const { page, errors, close } = await openApp(server.url, '#/traj-resample?dt=0.001', { viewport: { width: 1280, height: 900 } });
  try {
    await waitRows(page, '5');
    await page.locator('[data-testid="traj-file"]').setInputFiles(path);
    await page.locator('[data-testid="progress"]').waitFor({ state: 'visible', timeout: 20000 });
    const seen = new Set();
    const end = Date.now() + 120_000;
    while (Date.now() < end) {
      const now = Number(await page.locator('[data-testid="progress-bar"]').getAttribute('aria-valuenow'));
      if (now > 0) seen.add(now);
      if (await page.locator('[data-testid="progress"]').isHidden()) break;
      await page.waitForTimeout(50);
    }
    assert.ok(seen.size >= 2, `progress moved: ${[...seen].join(', ')}`);
    await waitRows(page, '1,000,000', 240_000);
    assert.equal(await readout(page, 'joints'), '5');
    assert.equal(await readout(page, 'rows_out'), '1,000,000');
    const want = cliOnBytes('big.csv', bytes, '0.001');
    assertSameBytes(await download(page, 'traj_resampled.csv'), want.csv, '1,000,000 rows');
    // Another dt starts a new worker run; Cancel stops it and the last result stays.
    await page.locator('[data-field="dt"]').fill('0.0005');
    await page.locator('[data-testid="progress"]').waitFor({ state: 'visible', timeout: 20000 });
    const status = await page.locator('[data-testid="traj-status"]').innerText();
    assert.equal(await page.locator('[data-testid="traj-resample-page"]').getAttribute('data-state'), 'running', status);
    await page.locator('[data-testid="progress-cancel"]').click();
    await page.locator('[data-testid="progress"]').waitFor({ state: 'hidden' });
    await page.waitForTimeout(1500);
    assert.equal(await page.locator('[data-testid="traj-resample-page"]').getAttribute('data-state'), 'ready');
    assert.equal(await readout(page, 'rows_out'), '1,000,000', 'the cancelled run never lands');
    assertSameBytes(await download(page, 'traj_resampled.csv'), want.csv, 'kept after Cancel');
    assert.deepEqual(errors, []);
  } finally {
    await close();
    rmSync(dir, { recursive: true, force: true });
  }
});

test('with Japanese selected no English UI string remains on the page', async () => {
  const english = englishStrings();
  assert.ok(english.includes('Drop a CSV file anywhere on this page to open it.'), 'traj.ftl is read');
  const { page, errors, close } = await openTraj('#/traj-resample?lang=ja&dt=0.05&bogus=1');
  try {
    await waitRows(page, '5');
    await page.locator('[data-field="dt"]').fill('0');
    await page.locator('[data-field-error="dt"]').waitFor({ state: 'visible' });
    const text = await page.evaluate(() => {
      const hidden = [...document.querySelectorAll('code')];
      hidden.forEach((el) => { el.style.display = 'none'; });
      return document.body.innerText;
    });
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /軌道のリサンプリング/);
    assert.match(text, /無視しました：bogus/);
    assert.match(text, /レシピがすること/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1280×800, projector 1920×1080, phone 390 px', async () => {
  const shots = [
    ['traj-en-1280.png', '#/traj-resample', { viewport: { width: 1280, height: 800 } }],
    ['traj-ja-1280.png', '#/traj-resample?lang=ja', { viewport: { width: 1280, height: 800 } }],
    ['traj-projector-1920.png', '#/traj-resample', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['traj-phone-390.png', '#/traj-resample?lang=ja', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots, {
    prepare: async (page) => {
      await page.waitForSelector('[data-testid="traj-resample-page"]');
      await waitRows(page, '5');
      await page.waitForTimeout(300);
    },
    // Playwright's caret-hiding style is an inline style the page's CSP refuses.
    shot: { caret: 'initial' },
    then: (page, file) => page.locator('.traj-stage').screenshot({ path: join(OUT, file.replace('.png', '-plot.png')), caret: 'initial' }),
  });
});
