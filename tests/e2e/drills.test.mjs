// The drills page (#/drills) in headless Chromium: every recipe runs in the browser and every
// CSV it offers is byte for byte what `target/debug/bsv <id> --out DIR` writes, with the summary
// line the CLI prints; non-default arguments (fields, options, a user's CSV file) give the CLI's
// bytes for the same arguments and live in the URL; invalid values are flagged beside their
// field in English and Japanese while the last result stays; big runs wait for Run and show
// "Running…"; keys; the Japanese page leaves no English UI string; phone width; screenshots
// (1280×800 English and Japanese, 390×844) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { openApp, OUT, ROOT } from './harness.mjs';
import { serveAppWithCli, BSV, cli, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

const RESAMPLE_INPUT = join(ROOT, 'tests', 'golden', 'resample_3joint', 'input.csv');
// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

/** The twelve recipe ids and the files each writes with its defaults. */
const RECIPES = [
  ['pendulum-energy', ['pendulum_energy.csv']],
  ['ik-workspace', ['ik_workspace.csv']],
  ['traj-resample', ['traj_resampled.csv', 'traj_sample_labeled.csv']],
  ['dh-fk', ['dh_fk.csv']],
  ['jacobian-2r', ['jacobian_2r.csv']],
  ['cubic-path', ['cubic_path.csv']],
  ['se3-relative', ['se3_relative.csv']],
  ['rrt-2d', ['rrt_path.csv', 'rrt_nodes.csv']],
  ['pid-step', ['pid_step.csv']],
  ['manip-grid', ['manip_ellipse.csv']],
  ['trapezoid-profile', ['trap_profile.csv']],
  ['umeyama-2d', ['umeyama_2d.csv']],
];

// ---------- Helpers ----------

const output = (page) => page.locator('[data-testid="drills-output"]');
const runCount = async (page) => Number(await output(page).getAttribute('data-run'));

/** Waits until the result panel has shown more than `n` runs. */
async function waitRuns(page, n) {
  await page.waitForFunction((k) => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > k, n, { timeout: 20000 });
}

/** Clicks Run and waits for the run to finish. */
async function run(page) {
  const n = await runCount(page);
  await page.locator('[data-testid="drills-run"]').click();
  await waitRuns(page, n);
}

async function openDrills(hash, opts = {}) {
  const app = await openApp(server.url, hash, opts);
  await app.page.waitForSelector('[data-testid="drills-page"]');
  return app;
}

const summary = async (page) => (await page.locator('[data-testid="drills-summary"]').innerText()).trim();
const bsvCommand = async (page) => (await page.locator('[data-testid="drills-cmd-bsv"]').innerText()).trim();

/** The words of a shown command line after `bsv <id>` (quotes as the page writes them). */
function commandArgs(line) {
  const words = [];
  for (const m of line.matchAll(/'((?:[^']|'\\'')*)'|(\S+)/g)) words.push(m[1] !== undefined ? m[1].replace(/'\\''/g, "'") : m[2]);
  return words.slice(2);
}

/** Downloads every file the page offers and compares it with the CLI run of the shown command. */
async function assertMatchesCli(page, id, expectedArgs, label) {
  const shown = await bsvCommand(page);
  assert.equal(shown.split(/\s+/)[1], id, `${label}: command ${shown}`);
  const args = commandArgs(shown);
  if (expectedArgs) assert.deepEqual(args, expectedArgs, `${label}: the command shows the run's arguments`);
  const want = cli([id, ...args]);
  const offered = await page.locator('[data-download]').evaluateAll((bs) => bs.map((b) => b.dataset.download));
  assert.deepEqual([...offered].sort(), [...want.files.keys()].sort(), `${label}: the same files as the CLI`);
  for (const file of offered) {
    assertSameBytes(await download(page, file), want.files.get(file), `${label} ${file}`);
  }
  assert.equal(await summary(page), want.stdout, `${label}: the summary is the CLI's stdout`);
  return want;
}

// ---------- Every recipe ----------

/**
 * Opens drill `id`, runs it with its defaults and checks each offered file against
 * `bsv <id> --out DIR`, the summary against its stdout, the command line and the preview.
 */
async function checkDefaults(id, files) {
  const { page, errors, close } = await openDrills(`#/drills?recipe=${id}`);
  try {
    // Defaults are small: the page runs them as soon as it opens. Run runs them again.
    await waitRuns(page, 0);
    assert.equal(await page.locator('[data-testid="drills-recipe"]').inputValue(), id);
    await run(page);
    assert.equal(await output(page).getAttribute('data-recipe'), id);
    const offered = await page.locator('[data-download]').evaluateAll((bs) => bs.map((b) => b.dataset.download));
    assert.deepEqual(offered, files, `${id}: the recipe's files, in its order`);
    // bsv <id> with no arguments is the recipe with its defaults.
    const want = cli([id]);
    for (const file of files) {
      assertSameBytes(await download(page, file), want.files.get(file), `${id} ${file}`);
    }
    assert.equal(await summary(page), want.stdout, `${id}: summary`);
    // The command lines under the result run the same thing.
    const shownArgs = commandArgs(await bsvCommand(page));
    const again = cli([id, ...shownArgs]);
    for (const file of files) assert.ok(again.files.get(file).equals(want.files.get(file)), `${id}: shown command`);
    // The preview shows the header and says how many rows the file has.
    const first = files[0];
    const header = await page.locator(`[data-preview="${first}"] thead th`).allInnerTexts();
    assert.deepEqual(header.slice(1), want.files.get(first).toString('utf8').split(/\r?\n/)[0].split(',').slice(0, 12));
    const rows = want.files.get(first).toString('utf8').split(/\r?\n/).filter((l) => l !== '').length - 1;
    assert.equal(await page.locator(`[data-preview="${first}"] tbody tr`).count(), Math.min(rows, 50));
    const note = await page.locator(`[data-file="${first}"] .drills-preview-note`).innerText();
    if (rows > 50) assert.match(note, new RegExp(`first 50 of ${rows.toLocaleString('en-US')} rows`));
    assert.ok(await page.locator('[data-testid="drills-about"]').innerText() !== '');
    assert.deepEqual(errors, [], `${id}: console errors`);
  } finally {
    await close();
  }
}

test('every drill runs with its defaults and each download is byte for byte the CLI output', async () => {
  for (const [id, files] of RECIPES) {
    await checkDefaults(id, files);
  }
});

// ---------- Arguments other than the defaults ----------

test('pid-step Kp=2 steps=120: typed values run on Enter, give the CLI bytes, and live in the URL', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=pid-step');
  try {
    await waitRuns(page, 0);
    await page.locator('[data-field="Kp"]').fill('2');
    await page.locator('[data-field="steps"]').fill('120');
    const n = await runCount(page);
    await page.locator('[data-field="steps"]').press('Enter');
    await waitRuns(page, n);
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-cmd-bsv"]').textContent.endsWith(' 120'));
    await assertMatchesCli(page, 'pid-step', ['2', '0.4', '0.05', '0.8', '120'], 'pid-step');
    assert.match(await summary(page), /^wrote 120 PID samples final_y=/);
    assert.equal((await page.locator('[data-testid="drills-cmd-python"]').innerText()).trim(), 'python pid_step_response.py 2 0.4 0.05 0.8 120');
    await page.waitForFunction(() => location.hash === '#/drills?recipe=pid-step&Kp=2&steps=120', null, { timeout: 3000 });
    const url = page.url();
    const before = await summary(page);
    const again = await openDrills(url.slice(url.indexOf('#')));
    try {
      await waitRuns(again.page, 0);
      assert.equal(await again.page.locator('[data-field="Kp"]').inputValue(), '2');
      assert.equal(await again.page.locator('[data-field="steps"]').inputValue(), '120');
      assert.equal(await again.page.locator('[data-field="Ki"]').inputValue(), '0.4');
      assert.equal(await summary(again.page), before);
      assert.deepEqual(again.errors, []);
    } finally {
      await again.close();
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('rrt-2d with seed 42 and pendulum-energy 2 with --integrator rk4 give the CLI bytes', async () => {
  {
    const { page, errors, close } = await openDrills('#/drills?recipe=rrt-2d');
    try {
      await waitRuns(page, 0);
      const n = await runCount(page);
      await page.locator('[data-field="seed"]').fill('42');
      await waitRuns(page, n); // small: it runs by itself shortly after typing
      const want = await assertMatchesCli(page, 'rrt-2d', ['42', '800'], 'rrt-2d 42');
      assert.match(want.stdout, /^RRT nodes=\d+ path_pts=\d+ length=/);
      await page.waitForFunction(() => location.hash.endsWith('recipe=rrt-2d&seed=42'));
      // A goal inside the obstacle is never reached: header-only path, length nan (a quirk).
      await page.locator('[data-field="goal-x"]').fill('0.5');
      await page.locator('[data-field="goal-y"]').fill('0.5');
      await page.locator('[data-field="goal-y"]').press('Enter');
      await page.waitForFunction(() => /length=nan/.test(document.querySelector('[data-testid="drills-summary"]').textContent));
      await assertMatchesCli(page, 'rrt-2d', ['42', '800', '--goal-x', '0.5', '--goal-y', '0.5'], 'rrt-2d goal in box');
      assert.match(await page.locator('[data-file="rrt_path.csv"]').innerText(), /Header only/);
      assert.match(await page.locator('[data-testid="drills-quirks"]').innerText(), /12 evenly spaced points/);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  {
    const { page, errors, close } = await openDrills('#/drills?recipe=pendulum-energy');
    try {
      await waitRuns(page, 0);
      await page.locator('[data-field="duration_s"]').fill('2');
      const n = await runCount(page);
      await page.locator('[data-field="integrator"]').selectOption('rk4');
      await waitRuns(page, n);
      await page.waitForFunction(() => document.querySelector('[data-testid="drills-cmd-bsv"]').textContent.includes('rk4'));
      await assertMatchesCli(page, 'pendulum-energy', ['2', '--integrator', 'rk4'], 'pendulum rk4');
      assert.match(await summary(page), /^wrote 1000 rows -> pendulum_energy\.csv/);
      // The Python recipe has no options: its line omits them and the page says so.
      assert.equal((await page.locator('[data-testid="drills-cmd-python"]').innerText()).trim(), 'python mujoco_pendulum_energy.py 2');
      assert.match(await page.locator('[data-drills="python-note"]').innerText(), /--integrator rk4/);
      await page.waitForFunction(() => location.hash.endsWith('recipe=pendulum-energy&duration_s=2&integrator=rk4'));
      const url = page.url();
      const again = await openDrills(url.slice(url.indexOf('#')));
      try {
        await waitRuns(again.page, 0);
        assert.equal(await again.page.locator('[data-field="integrator"]').inputValue(), 'rk4');
        assert.equal(await again.page.locator('[data-field="duration_s"]').inputValue(), '2');
        assert.equal(await summary(again.page), await summary(page));
      } finally {
        await again.close();
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('a big run waits for Run, shows "Running…" first, then gives the CLI bytes', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=manip-grid&n=300');
  try {
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-status"]').textContent !== '');
    assert.equal(await runCount(page), 0, '90,000 rows do not run by themselves');
    assert.match(await page.locator('[data-testid="drills-status"]').innerText(), /A large run: press Run/);
    assert.match(await page.locator('[data-testid="drills-output"]').innerText(), /Nothing computed yet/);
    // The click paints the running state before the kernel starts.
    const state = await page.evaluate(() => {
      document.querySelector('[data-testid="drills-run"]').click();
      return {
        state: document.querySelector('[data-testid="drills-page"]').dataset.state,
        status: document.querySelector('[data-testid="drills-status"]').textContent,
      };
    });
    assert.deepEqual(state, { state: 'running', status: 'Running…' });
    await waitRuns(page, 0);
    assert.equal(await page.locator('[data-testid="drills-page"]').getAttribute('data-state'), 'ready');
    assert.match(await page.locator('[data-testid="drills-status"]').innerText(), /^Done in \d+ ms\.$/);
    await assertMatchesCli(page, 'manip-grid', ['0.12', '0.10', '300'], 'manip-grid 300');
    assert.match(await page.locator('[data-file="manip_ellipse.csv"]').innerText(), /90,000 rows/);
    // Typing more keeps the result and says it is stale; Run brings it up to date.
    await page.locator('[data-field="n"]').fill('301');
    assert.equal(await page.locator('[data-testid="drills-stale"]').isVisible(), true);
    await page.keyboard.press('Enter');
    await waitRuns(page, 1);
    assert.equal(await page.locator('[data-testid="drills-stale"]').isVisible(), false);
    assert.match(await summary(page), /^wrote 90601 configs/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- traj-resample with a file ----------

test('traj-resample: a user CSV gives the CLI bytes; a bad CSV names its row; the sample comes back', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=traj-resample');
  try {
    await waitRuns(page, 0);
    assert.match(await page.locator('[data-testid="drills-file-status"]').innerText(), /built-in labeled sample \(traj_sample_labeled\.csv, 5 rows\)/);
    await page.locator('[data-field="dt"]').fill('0.05');
    let n = await runCount(page);
    await page.locator('[data-testid="drills-file"]').setInputFiles(RESAMPLE_INPUT);
    await page.waitForFunction(() => /resampled 40 -> 79 rows at dt=0\.05s/.test(document.querySelector('[data-testid="drills-summary"]').textContent));
    assert.ok((await runCount(page)) > n);
    assert.match(await page.locator('[data-testid="drills-file-status"]').innerText(), /input\.csv \(.*, 40 rows, 3 joint columns\)/);
    assert.equal(await bsvCommand(page), 'bsv traj-resample input.csv 0.05');
    assert.match(await page.locator('[data-drills="file-note"]').innerText(), /folder that holds input\.csv/);
    // The CLI reads the same file from disk.
    const dir = mkdtempSync(join(tmpdir(), 'drills-in-'));
    execFileSync('cp', [RESAMPLE_INPUT, join(dir, 'input.csv')]);
    const outDir = mkdtempSync(join(tmpdir(), 'drills-out-'));
    const stdout = execFileSync(BSV, ['traj-resample', 'input.csv', '0.05', '--out', outDir], { cwd: dir, encoding: 'utf8' });
    assert.deepEqual(await page.locator('[data-download]').evaluateAll((bs) => bs.map((b) => b.dataset.download)), ['traj_resampled.csv']);
    assertSameBytes(await download(page, 'traj_resampled.csv'), readFileSync(join(outDir, 'traj_resampled.csv')), 'traj_resampled.csv');
    assertSameBytes(await download(page, 'traj_resampled.csv'), readFileSync(join(ROOT, 'tests', 'golden', 'resample_3joint', 'traj_resampled.csv')), 'golden');
    assert.equal(await summary(page), stdout.trim());
    await page.waitForFunction(() => location.hash.endsWith('recipe=traj-resample&csv_path=input.csv&dt=0.05'));

    // Time that does not increase: the message names the CSV line, beside the file picker; the
    // last good result stays.
    const good = await summary(page);
    n = await runCount(page);
    await page.locator('[data-testid="drills-file"]').setInputFiles({
      name: 'bad.csv', mimeType: 'text/csv', buffer: Buffer.from('t_s,q1\n0.0,0.0\n0.1,1.0\n0.1,2.0\n'),
    });
    const message = page.locator('[data-field-error="csv_path"]');
    await message.waitFor({ state: 'visible' });
    assert.match(await message.innerText(), /CSV line 4: t_s must be larger than on the line before/);
    assert.equal(await runCount(page), n);
    assert.equal(await summary(page), good);
    await page.locator('[data-testid="lang-switch"]').click();
    assert.match(await message.innerText(), /CSV の 4 行目：t_s は前の行より大きくしてください/);
    await page.locator('[data-testid="lang-switch"]').click();

    // A file over the kernel's 128 MiB limit is refused before it is read.
    await page.evaluate(() => {
      const input = document.querySelector('[data-testid="drills-file"]');
      const files = new DataTransfer();
      files.items.add(new File([new Uint8Array(129 * 1024 * 1024)], 'huge.csv', { type: 'text/csv' }));
      input.files = files.files;
      input.dispatchEvent(new Event('change', { bubbles: true }));
    });
    await page.waitForFunction(() => /huge\.csv/.test(document.querySelector('[data-field-error="csv_path"]').textContent));
    assert.equal(await message.innerText(), '“huge.csv” is 129 MiB: larger than the 128 MiB this drill can read. It was not opened.');
    assert.doesNotMatch(await page.locator('[data-testid="drills-status"]').innerText(), /Reading/);
    assert.equal(await summary(page), good);

    // Back to the sample.
    await page.locator('[data-testid="drills-use-sample"]').click();
    await page.waitForFunction(() => /wrote labeled synthetic sample/.test(document.querySelector('[data-testid="drills-summary"]').textContent));
    assert.equal(await message.isVisible(), false);
    await assertMatchesCli(page, 'traj-resample', ['', '0.05'], 'sample at 0.05');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }

  // A link that names a file: the page asks for it again and does not crash.
  const linked = await openDrills('#/drills?recipe=traj-resample&csv_path=input.csv&dt=0.05');
  try {
    assert.match(await linked.page.locator('[data-testid="drills-url-notice"]').innerText(), /used the file “input\.csv”/);
    assert.match(await linked.page.locator('[data-field-error="csv_path"]').innerText(), /“input\.csv” is not open/);
    assert.equal(await runCount(linked.page), 0);
    await linked.page.locator('[data-testid="drills-file"]').setInputFiles(RESAMPLE_INPUT);
    await waitRuns(linked.page, 0);
    assert.match(await summary(linked.page), /resampled 40 -> 79 rows/);
    assert.deepEqual(linked.errors, []);
  } finally {
    await linked.close();
  }
});

test('traj-resample: a file that is not UTF-8 is refused beside the picker with its byte offset, as bsv refuses it', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=traj-resample');
  try {
    await waitRuns(page, 0);
    const good = await summary(page);
    // `é` in Latin-1 (0xE9): byte 23 of the file, counted from 0.
    const latin1 = Buffer.from([...Buffer.from('t_s,q1,note\n0.0,0.0,caf'), 0xe9, ...Buffer.from('\n0.1,1.0,x\n')]);
    await page.locator('[data-testid="drills-file"]').setInputFiles({ name: 'latin1.csv', mimeType: 'text/csv', buffer: latin1 });
    const message = page.locator('[data-field-error="csv_path"]');
    await message.waitFor({ state: 'visible' });
    assert.equal(await message.innerText(), '“latin1.csv” is not UTF-8 text: the byte at offset 23 (counted from 0) is not valid UTF-8. Save the file as UTF-8 (in a spreadsheet: “CSV UTF-8”) and open it again.');
    assert.equal(await summary(page), good, 'the last result stays');
    // The CLI refuses the same bytes, naming the same offset.
    const dir = mkdtempSync(join(tmpdir(), 'drills-latin1-'));
    writeFileSync(join(dir, 'latin1.csv'), latin1);
    const cliRun = spawnSync(BSV, ['traj-resample', 'latin1.csv', '--out', dir], { cwd: dir, encoding: 'utf8' });
    assert.equal(cliRun.status, 2);
    assert.match(cliRun.stderr, /'latin1\.csv' is not UTF-8 text: byte 23 /);
    rmSync(dir, { recursive: true, force: true });
    await page.locator('[data-testid="lang-switch"]').click();
    assert.match(await message.innerText(), /「latin1\.csv」は UTF-8 のテキストではありません：オフセット 23/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Invalid input ----------

test('invalid values are flagged beside their field in English and Japanese; the last result stays', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=pid-step');
  try {
    await waitRuns(page, 0);
    const good = await summary(page);
    const steps = page.locator('[data-field="steps"]');
    const message = page.locator('[data-field-error="steps"]');
    await steps.fill('abc');
    assert.equal(await message.isVisible(), true);
    assert.equal(await message.innerText(), 'Number of steps (0.05 s each): “abc” must be a whole number, such as 3 or 800.');
    assert.equal(await steps.getAttribute('aria-invalid'), 'true');
    // Two bad fields at once: both are named.
    await page.locator('[data-field="tau"]').fill('-1');
    assert.match(await page.locator('[data-field-error="tau"]').innerText(), /Plant time constant τ \(s\) must be between 0 and 1,000,000 \(it is -1\)/);
    assert.equal(await message.isVisible(), true);
    // Run refuses and says why; the previous result is still there, marked stale.
    await page.locator('[data-testid="drills-run"]').click();
    assert.match(await page.locator('[data-testid="drills-status"]').innerText(), /Fix the value marked in red/);
    assert.equal(await page.evaluate(() => document.activeElement?.dataset.field), 'tau');
    assert.equal(await summary(page), good);
    assert.equal(await page.locator('[data-testid="drills-stale"]').isVisible(), true);
    await page.locator('[data-testid="lang-switch"]').click();
    assert.equal(await message.innerText(), 'ステップ数（1 ステップ 0.05 秒）：「abc」ではなく、3 や 800 のような整数を指定してください。');
    assert.match(await page.locator('[data-field-error="tau"]').innerText(), /プラントの時定数 τ（秒） は 0 以上 1,000,000 以下にしてください/);
    assert.match(await page.locator('[data-testid="drills-status"]').innerText(), /赤で示した値を直して/);
    // Fixing both runs again.
    await page.locator('[data-testid="lang-switch"]').click();
    await page.locator('[data-field="tau"]').fill('0.8');
    const n = await runCount(page);
    await steps.fill('90');
    await waitRuns(page, n);
    assert.equal(await message.isVisible(), false);
    assert.match(await summary(page), /^wrote 90 PID samples/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }

  const grid = await openDrills('#/drills?recipe=manip-grid&lang=ja');
  try {
    await waitRuns(grid.page, 0);
    await grid.page.locator('[data-field="n"]').fill('5000');
    const message = grid.page.locator('[data-field-error="n"]');
    assert.equal(await message.innerText(), '格子の大きさ n（n × n 通りの関節角） は 1 以上 1,024 以下にしてください（現在の値: 5,000）。');
    await grid.page.locator('[data-testid="lang-switch"]').click();
    await grid.page.waitForFunction(() => document.documentElement.lang === 'en');
    assert.equal(await message.innerText(), 'Grid size n (n × n joint configurations) must be between 1 and 1,024 (it is 5,000).');
    assert.match(await grid.page.locator('[data-field-wrap="n"] .drills-hint').innerText(), /from 1 to 1,024: n × n rows, so at most 1,048,576/);
    assert.deepEqual(grid.errors, []);
  } finally {
    await grid.close();
  }
});

test('a link with bad values, unknown keys or an unknown drill opens with a notice, not a crash', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=pid-step&steps=abc&Kp=x&foo=1');
  try {
    const notice = page.locator('[data-testid="drills-url-notice"]');
    assert.equal(await notice.isVisible(), true);
    const text = await notice.innerText();
    assert.match(text, /ignored: foo/);
    assert.match(text, /not valid \(Kp, steps\)/);
    assert.equal(await page.locator('[data-field="steps"]').inputValue(), 'abc');
    assert.match(await page.locator('[data-field-error="steps"]').innerText(), /whole number/);
    assert.match(await page.locator('[data-field-error="Kp"]').innerText(), /not a number/);
    assert.equal(await runCount(page), 0);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  const unknown = await openDrills('#/drills?recipe=warp-drive&lang=ja');
  try {
    await waitRuns(unknown.page, 0);
    assert.match(await unknown.page.locator('[data-testid="drills-url-notice"]').innerText(), /「warp-drive」は存在しない/);
    assert.equal(await unknown.page.locator('[data-testid="drills-recipe"]').inputValue(), RECIPES[0][0]);
    assert.deepEqual(unknown.errors, []);
  } finally {
    await unknown.close();
  }
});

// ---------- Keys, copy, switching, home links ----------

test('keys run, download and switch drills; copy puts the command on the clipboard; home cards link here', async () => {
  const { page, context, errors, close } = await openDrills('#/drills?recipe=cubic-path');
  try {
    await waitRuns(page, 0);
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    let n = await runCount(page);
    await page.keyboard.press('r');
    await waitRuns(page, n);
    const [dl] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('d')]);
    assert.equal(dl.suggestedFilename(), 'cubic_path.csv');
    n = await runCount(page);
    await page.keyboard.press(']');
    await waitRuns(page, n);
    assert.equal(await page.locator('[data-testid="drills-recipe"]').inputValue(), 'se3-relative');
    await page.waitForFunction(() => location.hash === '#/drills?recipe=se3-relative');
    assert.match(await page.locator('[data-testid="drills-quirks"]').innerText(), /degrees/);
    await page.keyboard.press('[');
    await page.waitForFunction(() => location.hash === '#/drills?recipe=cubic-path');
    // Values typed in a drill come back when the user returns to it.
    await page.locator('[data-field="T"]').fill('2');
    await page.locator('[data-testid="drills-recipe"]').selectOption('dh-fk');
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-output"]').dataset.recipe === 'dh-fk');
    await page.locator('[data-testid="drills-recipe"]').selectOption('cubic-path');
    assert.equal(await page.locator('[data-field="T"]').inputValue(), '2');
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-cmd-bsv"]').textContent === 'bsv cubic-path 0.0 1.2 2 0.02');

    await context.grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.locator('[data-copy="bsv"]').click();
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-copy-status"]').textContent !== '');
    assert.equal(await page.evaluate(() => navigator.clipboard.readText()), 'bsv cubic-path 0.0 1.2 2 0.02');

    await page.keyboard.press('?');
    const overlay = page.locator('[data-testid="shortcut-overlay"]');
    await overlay.waitFor();
    assert.match(await overlay.innerText(), /Run the drill/);
    assert.match(await overlay.innerText(), /Previous \/ next drill/);
    await page.keyboard.press('Escape');

    // Every home card links to its drill; the 2R cards keep their IK page link.
    await page.goto(`${server.url}/#/`);
    await page.locator('[data-testid="home-headline"]').waitFor();
    for (const [id] of RECIPES) {
      assert.equal(await page.locator(`[data-testid="recipe-drill-${id}"]`).getAttribute('href'), `#/drills?recipe=${id}`);
    }
    assert.equal(await page.locator('[data-testid="recipe-link-manip-grid"]').getAttribute('href'), '#/ik-2r');
    await page.locator('[data-testid="recipe-drill-umeyama-2d"]').click();
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-output"]')?.dataset.recipe === 'umeyama-2d');
    assert.match(await summary(page), /^Umeyama s=1\.3012 ang=34\.90deg rmse=0\.0282/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Japanese ----------

test('with Japanese selected no English UI string remains on the page', async () => {
  const english = englishStrings();
  assert.ok(english.includes('Nothing computed yet. Press Run, or Enter in any field.'), 'drills.ftl is read');
  const seen = [];
  // The page's words, without what the recipes print (summary, CSV previews, command lines).
  const collect = async (page) => seen.push(await page.evaluate(() => {
    const output = [...document.querySelectorAll('[data-testid="drills-summary"], .drills-table-box, code')];
    const shown = output.map((el) => el.style.display);
    output.forEach((el) => { el.style.display = 'none'; });
    const text = document.body.innerText;
    output.forEach((el, i) => { el.style.display = shown[i]; });
    return text;
  }));
  for (const [id] of RECIPES) {
    const { page, errors, close } = await openDrills(`#/drills?recipe=${id}&lang=ja`);
    try {
      await waitRuns(page, 0);
      await collect(page);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  // The texts the page formats itself: invalid fields, a large run, a stale result, a copy,
  // the python note, a URL notice, a file, a refused file.
  const { page, context, errors, close } = await openDrills('#/drills?recipe=pendulum-energy&integrator=rk4&bogus=1&lang=ja');
  try {
    await waitRuns(page, 0);
    await context.grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.locator('[data-copy="python"]').click();
    await page.waitForFunction(() => document.querySelector('[data-testid="drills-copy-status"]').textContent !== '');
    await collect(page);
    await page.locator('[data-field="duration_s"]').fill('1000');
    await page.waitForFunction(() => /計算量/.test(document.querySelector('[data-testid="drills-status"]').textContent));
    await collect(page);
    await page.locator('[data-field="mass"]').fill('0');
    await collect(page);
    await page.locator('[data-testid="drills-run"]').click();
    await collect(page);
    await page.locator('[data-testid="drills-recipe"]').selectOption('traj-resample');
    await waitRuns(page, 0);
    await collect(page);
    await page.locator('[data-testid="drills-file"]').setInputFiles(RESAMPLE_INPUT);
    await page.waitForFunction(() => /resampled 40/.test(document.querySelector('[data-testid="drills-summary"]').textContent));
    await collect(page);
    const text = seen.join('\n');
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /すべてのドリル/);
    assert.match(text, /計算量の多い実行です/);
    assert.match(text, /コマンドをクリップボードにコピーしました/);
    assert.match(text, /カプセルの質量 m（kg） は 0 より大きい値にしてください/);
    assert.match(text, /この実行を再現できるのは bsv の行だけです/);
    assert.match(text, /無視しました：bogus/);
    assert.match(text, /入力：input\.csv/);
    assert.match(text, /何を計算するのか/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Phone, screenshots ----------

test('at phone width the page has no horizontal scroll; wide tables scroll in their own box', async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await openDrills(`#/drills?recipe=jacobian-2r&lang=${lang}`, { viewport: { width: 390, height: 844 } });
    try {
      await waitRuns(page, 0);
      const widths = await page.evaluate(() => {
        const box = document.querySelector('[data-preview="jacobian_2r.csv"]');
        return {
          page: document.documentElement.scrollWidth - document.documentElement.clientWidth,
          box: box.scrollWidth - box.clientWidth,
          boxRight: box.getBoundingClientRect().right,
        };
      });
      assert.ok(widths.page <= 0, `${lang}: page overflows by ${widths.page}px`);
      assert.ok(widths.box > 0, `${lang}: the 8-column table scrolls inside its box`);
      assert.ok(widths.boxRight <= 390, `${lang}: the table box ends at ${widths.boxRight}px`);
      const run = await page.locator('[data-testid="drills-run"]').boundingBox();
      assert.ok(run.height >= 40, `Run is a comfortable touch target (${run.height}px)`);
      await page.screenshot({ path: join(OUT, `drills-390-${lang}.png`) });
      await page.locator('[data-testid="drills-output"]').scrollIntoViewIfNeeded();
      await page.screenshot({ path: join(OUT, `drills-390-${lang}-result.png`) });
      // Every drill fits the width (forms differ a lot: se3 has twelve fields, pendulum options).
      for (const [id] of RECIPES) {
        await page.locator('[data-testid="drills-recipe"]').selectOption(id);
        await page.waitForFunction((r) => document.querySelector('[data-testid="drills-page"]').dataset.recipe === r, id);
        const over = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
        assert.ok(over <= 0, `${lang} ${id}: page overflows by ${over}px`);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('screenshots: English and Japanese at 1280×800', async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await openDrills(`#/drills?recipe=pendulum-energy&duration_s=2&lang=${lang}`);
    try {
      await waitRuns(page, 0);
      await page.screenshot({ path: join(OUT, `drills-${lang}-1280.png`) });
      await page.screenshot({ path: join(OUT, `drills-${lang}-1280-full.png`), fullPage: true });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  const { page, errors, close } = await openDrills('#/drills?recipe=traj-resample&dt=0.05', { storage: { 'bsv.projector': '1' } });
  try {
    await waitRuns(page, 0);
    await page.screenshot({ path: join(OUT, 'drills-projector-1280.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- What a user sees: labels, warnings, rounded tables, the result in view ----------

test('messages name the field by its label; a cross-field limit marks every field and speaks on the changed one', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=trapezoid-profile');
  try {
    await waitRuns(page, 0);
    await page.locator('[data-field="distance"]').fill('1e9');
    const message = page.locator('[data-field-error="distance"]');
    await message.waitFor({ state: 'visible' });
    const text = await message.innerText();
    assert.match(text, /^Move distance: /, 'the label, not the internal name');
    assert.doesNotMatch(text, /\de[+-]?\d|\.0\b/, `numbers as a person writes them: ${text}`);
    assert.equal(await page.locator('[data-field-error="dt"]').isVisible(), false, 'one message, on the changed field');
    assert.equal(await page.locator('[data-field="distance"]').getAttribute('aria-invalid'), 'true');
    assert.equal(await page.locator('[data-field="dt"]').getAttribute('aria-invalid'), 'true', 'dt is involved too');
    assert.equal(await page.locator('[data-field-error]:visible').count(), 1, 'one message for one limit');
    // Integers take any whole-number notation.
    await page.locator('[data-testid="drills-recipe"]').selectOption('pid-step');
    await page.locator('[data-field="steps"]').fill('1e2');
    await page.waitForFunction(() => /^wrote 100 PID samples/.test(document.querySelector('[data-testid="drills-summary"]').textContent));
    assert.equal(await page.locator('[data-field-error="steps"]').isVisible(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('pid-step Kp=1e9: the warning shows beside the result (EN/JA) and the CSV stays the CLI bytes', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=pid-step&Kp=1e9');
  try {
    await waitRuns(page, 0);
    const warnings = page.locator('[data-testid="drills-warnings"]');
    assert.equal(await warnings.isVisible(), true);
    assert.match(await warnings.innerText(), /Check this result/);
    assert.match(await warnings.innerText(), /blew up|unstable/);
    await assertMatchesCli(page, 'pid-step', ['1e9', '0.4', '0.05', '0.8', '80'], 'pid Kp=1e9');
    await page.locator('[data-testid="lang-switch"]').click();
    assert.match(await warnings.innerText(), /この結果を確認してください/);
    await page.locator('[data-testid="lang-switch"]').click();
    // A stable loop has no warning.
    const n = await runCount(page);
    await page.locator('[data-field="Kp"]').fill('1.2');
    await waitRuns(page, n);
    assert.equal(await warnings.isVisible(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('tables show rounded numbers, the switch shows the exact CSV text, downloads stay exact', async () => {
  const { page, errors, close } = await openDrills('#/drills?recipe=jacobian-2r');
  try {
    await waitRuns(page, 0);
    const want = cli(['jacobian-2r']);
    const csv = want.files.get('jacobian_2r.csv').toString('utf8').split(/\r?\n/).filter((l) => l !== '').slice(1)
      .map((l) => l.split(','));
    const cells = () => page.locator('[data-preview="jacobian_2r.csv"] tbody tr').evaluateAll((rows) =>
      rows.map((r) => [...r.querySelectorAll('td')].slice(1).map((td) => ({ text: td.textContent, title: td.getAttribute('title') }))));
    const significant = (t) => t.split(/e/i)[0].replace(/[-.]/g, '').replace(/^0+/, '').length;
    let rounded = 0;
    for (const [i, row] of (await cells()).entries()) {
      for (const [j, cell] of row.entries()) {
        const exact = csv[i][j];
        assert.ok(significant(cell.text) <= 6 || cell.text === exact, `row ${i} col ${j}: ${cell.text}`);
        if (cell.text !== exact) {
          rounded += 1;
          assert.equal(cell.title, exact, 'the exact text is in the tooltip');
          assert.ok(Math.abs(Number(cell.text) - Number(exact)) <= Math.abs(Number(exact)) * 5e-6, `${cell.text} ≈ ${exact}`);
        }
      }
    }
    assert.ok(rounded > 0, 'some cells are rounded');
    await page.locator('[data-testid="drills-exact"]').check();
    const exact = await cells();
    assert.deepEqual(exact.map((r) => r.map((c) => c.text)), csv.slice(0, exact.length), 'exact = the CSV text');
    assertSameBytes(await download(page, 'jacobian_2r.csv'), want.files.get('jacobian_2r.csv'), 'download stays exact');
    await page.locator('[data-testid="drills-exact"]').uncheck();
    assert.notDeepEqual((await cells()).map((r) => r.map((c) => c.text)), csv.slice(0, exact.length));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('phone: after Run the result comes into view; an invalid field Run focuses is clear of the sticky bar', async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await openDrills(`#/drills?recipe=manip-grid&n=300&lang=${lang}`, { viewport: { width: 390, height: 844 } });
    try {
      await page.waitForFunction(() => document.querySelector('[data-testid="drills-status"]').textContent !== '');
      await run(page);
      await page.waitForFunction(() => document.querySelector('[data-testid="drills-output"]').getBoundingClientRect().top < 844);
      const out = await page.locator('[data-testid="drills-output"]').evaluate((el) => el.getBoundingClientRect().top);
      assert.ok(out >= 0 && out < 844 / 2, `${lang}: the result starts at ${out}px`);
      await page.screenshot({ path: join(OUT, `drills-390-${lang}-after-run.png`) });

      await page.evaluate(() => window.scrollTo(0, 0));
      await page.locator('[data-field="n"]').fill('abc');
      await page.locator('[data-testid="drills-run"]').click();
      assert.equal(await page.evaluate(() => document.activeElement?.dataset.field), 'n');
      const box = await page.evaluate(() => {
        const wrap = document.querySelector('[data-field-wrap="n"]').getBoundingClientRect();
        const bar = document.querySelector('.drills-actions').getBoundingClientRect();
        return { top: wrap.top, bottom: wrap.bottom, bar: bar.top };
      });
      assert.ok(box.top >= 0 && box.bottom <= box.bar, `${lang}: field ${box.top}–${box.bottom}px, sticky bar at ${box.bar}px`);
      assert.match(await page.locator('[data-field-error="n"]').innerText(), lang === 'en' ? /^Grid size n/ : /^格子の大きさ n/);
      // Tap targets of at least 44 px at phone width.
      for (const sel of ['[data-copy="bsv"]', '[data-testid="drills-exact"]', '[data-testid="drills-run"]', '[data-download]', '[data-field="L1"]']) {
        const b = await page.locator(sel).first().evaluate((el) => { const r = (el.closest('label') ?? el).getBoundingClientRect(); return { w: r.width, h: r.height }; });
        assert.ok(b.h >= 44 && b.w >= 44, `${lang} ${sel}: ${b.w}×${b.h}`);
      }
      await page.screenshot({ path: join(OUT, `drills-390-${lang}-invalid.png`) });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
