// The SO-101 page (#/so101) in headless Chromium: each Se3Keyboard key moves its axis the
// right way (W/S x, A/D y, Q/E z, C/V yaw; readouts' exact values); an injected gamepad moves
// the arm and is offered at once; a scripted episode is recorded, labelled, exported (its CSV
// reproduced by `bsv teleop-replay`, the evidence's artifacts hashed to the downloaded bytes,
// `embodiment` the SO-101's), and a reload keeps the session; the home card and #/teleop's next
// step lead here; Japanese leaves no English UI text; screenshots EN/JA, projector and phone go
// to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { ROOT, openApp, browser, readouts, screenshots, query } from './harness.mjs';
import { serveAppWithCli, BSV, download } from './cli.mjs';
import { englishOnPage } from './locales.mjs';

const server = serveAppWithCli();
const open = (hash = '#/so101', opts = {}) => openApp(server.url, hash, opts);
const canvas = (page) => page.locator('[data-testid="so101-canvas"]');
const values = (page) => readouts(page, { numbers: true });

async function hold(page, key, ms) {
  await page.keyboard.down(key);
  await page.waitForTimeout(ms);
  await page.keyboard.up(key);
  await page.waitForTimeout(50);
}

test('each key moves its axis the right way (W/S x, A/D y, Q/E z, C/V yaw)', async () => {
  const { page, errors, close } = await open();
  try {
    assert.equal((await values(page)).state, 'engaged');
    await canvas(page).focus();
    for (const [key, axis, sign] of [
      ['w', 'x', 1], ['s', 'x', -1], ['a', 'y', 1], ['d', 'y', -1],
      ['q', 'z', 1], ['e', 'z', -1], ['c', 'yaw', 1], ['v', 'yaw', -1],
    ]) {
      const before = (await values(page))[axis];
      await hold(page, key, 300);
      const after = (await values(page))[axis];
      const moved = (after - before) * sign;
      assert.ok(moved > (axis === 'yaw' ? 0.01 : 0.002), `${key}: ${axis} ${before} → ${after}`);
    }
    // Space pauses: a held key then moves nothing.
    await page.keyboard.press('Space');
    assert.equal((await values(page)).state, 'paused');
    const before = await values(page);
    await hold(page, 'w', 200);
    assert.equal((await values(page)).x, before.x);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('an injected gamepad moves the arm and is offered at once', async () => {
  const context = await (await browser()).newContext({ viewport: { width: 1280, height: 800 }, locale: 'en-US' });
  await context.addInitScript(() => {
    const buttons = Array.from({ length: 17 }, () => ({ pressed: false, touched: false, value: 0 }));
    const pad = { id: 'Test Pad (STANDARD GAMEPAD)', index: 0, connected: true, mapping: 'standard', timestamp: 0, axes: [0, 0, 0, 0], buttons };
    window.__testPad = pad;
    Object.defineProperty(Navigator.prototype, 'getGamepads', { configurable: true, value: () => [pad, null, null, null] });
  });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  try {
    await page.goto(`${server.url}/#/so101`);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    const r0 = await values(page);
    // Left stick right: +y (Se3Gamepad's LEFT_STICK_RIGHT).
    await page.evaluate(() => { window.__testPad.axes[0] = 1; });
    await page.waitForFunction((y0) => {
      const el = document.querySelector('[data-readout="y"]');
      return el && Number(el.dataset.value) > y0 + 0.005;
    }, r0.y, { timeout: 10000 });
    await page.evaluate(() => { window.__testPad.axes[0] = 0; });
    const offer = page.locator('[data-testid="gamepad-offer"]');
    assert.ok(await offer.isVisible());
    assert.match(await offer.innerText(), /Test Pad/);
    await page.locator('[data-action="use-gamepad"]').click();
    assert.equal(await page.locator('[data-device="gamepad"]').getAttribute('aria-pressed'), 'true');
    assert.ok(!(await offer.isVisible()));
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

test('a scripted episode: recorded, labelled, exported, replayed by bsv; reload keeps the session', async () => {
  const { page, errors, close } = await open();
  const dir = mkdtempSync(join(tmpdir(), 'bsv-so101-'));
  try {
    await page.locator('[data-module="record-ten"]').click();
    assert.equal((await values(page)).episode, 1);
    await canvas(page).focus();
    await hold(page, 'w', 300);
    await hold(page, 'e', 200);
    await page.keyboard.press('k');
    await page.waitForTimeout(100);
    await page.locator('[data-action="end-episode"]').click();
    const panel = page.locator('[data-so101="label-panel"]');
    await panel.waitFor({ state: 'visible' });
    // The proposal: the gripper closed on nothing, a FAILURE of category grasp-miss.
    assert.equal(await page.locator('[data-label="FAILURE"]').getAttribute('aria-pressed'), 'true');
    assert.equal(await page.locator('[data-category="grasp-miss"]').getAttribute('aria-pressed'), 'true');
    await page.locator('[data-category="operator-abort"]').click();
    await page.locator('[data-field="note"]').fill('scripted, "quoted", note');
    await page.locator('[data-action="confirm-label"]').click();
    assert.ok(!(await panel.isVisible()));
    const row = page.locator('[data-so101="episodes"] tr');
    assert.equal(await row.count(), 1);
    assert.match(await row.innerText(), /FAILURE/);

    const csv = await download(page, 'so101_episode_1.csv');
    const table = await download(page, 'so101_episodes.csv');
    const evidence = await download(page, 'teleop_session_evidence.json');
    const path = join(dir, 'so101_episode_1.csv');
    writeFileSync(path, csv);
    const out = execFileSync(BSV, ['teleop-replay', path], { encoding: 'utf8' });
    assert.match(out, /^replayed \d+ steps of pick-place \(dls\): every recorded step reproduced exactly\n/);
    assert.match(out, /\ngrasp_misses: 1\n/);
    assert.match(table.toString('utf8'), /^id,task,label,category,note,/);
    assert.match(table.toString('utf8'), /\n1,pick-place,FAILURE,operator-abort,"scripted, ""quoted"", note",0,ended,/);
    const doc = JSON.parse(evidence.toString('utf8'));
    assert.equal(doc.schemaVersion, '0.1');
    assert.equal(doc.embodiment, 'so101-sim');
    assert.equal(doc.taskId, 'pick-place');
    assert.deepEqual(doc.episodes, { attempted: 1, successful: 0, failed: 1, recoveryEpisodes: 0 });
    const sha = (b) => createHash('sha256').update(b).digest('hex');
    const listed = Object.fromEntries(doc.dataArtifacts.map((a) => [a.uriOrRef, a.sha256]));
    assert.deepEqual(listed, { 'so101_episodes.csv': sha(table), 'so101_episode_1.csv': sha(csv) });
    assert.equal(doc.metrics['failures.operator-abort'], 1);

    // Replay: the failure review plays the episode back.
    await page.locator('[data-action="replay"][data-episode="1"]').click();
    assert.equal((await values(page)).state, 'replay');

    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    assert.ok(await page.locator('[data-so101="restored"]').isVisible());
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 1);
    assert.match(await page.locator('[data-so101="episodes"] tr').innerText(), /FAILURE/);
    assert.equal(await page.locator('[data-module="failure-review"]').getAttribute('aria-pressed'), 'true');
    await page.locator('[data-testid="so101-stepper"]').waitFor({ state: 'visible' });
    const again = await download(page, 'so101_episode_1.csv');
    assert.ok(again.equals(csv), 'the reloaded episode is the same bytes');
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
    await close();
  }
});

test('the gizmo: dragging a ring turns the tool about its axis while held (mouse and touch)', async () => {
  for (const touch of [false, true]) {
    const { page, errors, close } = await open('#/so101', touch ? { touch: true, viewport: { width: 1024, height: 768 } } : {});
    try {
      const grips = async () => (await canvas(page).getAttribute('data-ring-grips')).split('|')
        .map((g) => (g === '-' ? null : g.split(',').map(Number)));
      await canvas(page).evaluate((c) => c.scrollIntoView({ block: 'center' }));
      const box = await canvas(page).boundingBox();
      // Yaw ring (about z): a drag along it the positive way turns the tool's yaw up; pitch
      // and roll rings: the tool's orientation changes (or, where five joints cannot follow,
      // the orientation error shows it).
      for (const [k, key] of [[2, 'yaw'], [1, 'pitch'], [0, 'roll']]) {
        const grip = (await grips())[k];
        assert.ok(grip, `ring ${k} in view`);
        const [x, y, dx, dy] = grip;
        const at = { x: box.x + x, y: box.y + y };
        const before = await values(page);
        if (touch) {
          const cdp = await page.context().newCDPSession(page);
          const touchAt = (p) => [{ x: p.x, y: p.y, id: 1 }];
          await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: touchAt(at) });
          for (let i = 1; i <= 6; i++) {
            await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: touchAt({ x: at.x + dx * 5 * i, y: at.y + dy * 5 * i }) });
          }
          await page.waitForTimeout(300);
          await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        } else {
          await page.mouse.move(at.x, at.y);
          await page.mouse.down();
          await page.mouse.move(at.x + dx * 30, at.y + dy * 30, { steps: 6 });
          await page.waitForTimeout(300);
          await page.mouse.up();
        }
        await page.waitForTimeout(100);
        const after = await values(page);
        const turned = ['roll', 'pitch', 'yaw'].some((a) => Math.abs(after[a] - before[a]) > 0.01)
          || after['orientation-error'] > 0.01;
        assert.ok(turned, `ring ${k} (${touch ? 'touch' : 'mouse'}): ${JSON.stringify({ before, after })}`);
        if (key === 'yaw') assert.ok(after.yaw > before.yaw + 0.01, `yaw ${before.yaw} → ${after.yaw}`);
        // Let go: it stops.
        const held = await values(page);
        await page.waitForTimeout(200);
        assert.equal((await values(page))[key], held[key], 'the tool stops when the ring is let go');
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the wrist camera turns with the wrist: its image rolls as wrist_roll does', async () => {
  const { page, errors, close } = await open();
  try {
    const wrist = page.locator('[data-testid="so101-wrist"]');
    const turned = async () => Number(await wrist.getAttribute('data-roll'));
    const q5 = async () => (await values(page)).q5;
    const [roll0, q50] = [await turned(), await q5()];
    // C turns the tool about z; pointing down, the wrist roll does most of it.
    await canvas(page).focus();
    await hold(page, 'c', 400);
    const [roll1, q51] = [await turned(), await q5()];
    assert.ok(Math.abs(q51 - q50) > 0.1, `q5 ${q50} → ${q51}`);
    const wrapped = (a) => Math.atan2(Math.sin(a), Math.cos(a));
    assert.ok(Math.abs(Math.abs(wrapped(roll1 - roll0)) - Math.abs(q51 - q50)) < 0.1,
      `image ${roll0} → ${roll1}, q5 ${q50} → ${q51}`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Records one episode in Record ten (keys held on the canvas, the gripper closed on
 * nothing: a missed grasp) and confirms its proposed label. */
async function recordEpisode(page, key = 'w', ms = 300) {
  await canvas(page).focus();
  await hold(page, key, ms);
  await page.keyboard.press('k');
  await page.waitForTimeout(100);
  await page.locator('[data-action="end-episode"]').click();
  const panel = page.locator('[data-so101="label-panel"]');
  await panel.waitFor({ state: 'visible' });
  await page.locator('[data-action="confirm-label"]').click();
  await panel.waitFor({ state: 'hidden' });
  // R starts the next episode.
  await canvas(page).focus();
  await page.keyboard.press('r');
}

const stepper = (page) => page.locator('[data-testid="so101-stepper"]');

/** The entries of the zip at `path`, name → bytes (Python's zipfile: no npm package). */
function unzip(path) {
  const out = execFileSync('python3', ['-c', `
import base64, json, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
print(json.dumps({i.filename: base64.b64encode(z.read(i)).decode() for i in z.infolist()}))
`, path], { encoding: 'utf8', maxBuffer: 64 << 20 });
  return new Map(Object.entries(JSON.parse(out)).map(([k, v]) => [k, Buffer.from(v, 'base64')]));
}

/** Every file under `dir`, its path from `dir` → bytes. */
function tree(dir, prefix = '') {
  const out = new Map();
  for (const e of readdirSync(join(dir, prefix), { withFileTypes: true })) {
    const rel = prefix ? `${prefix}/${e.name}` : e.name;
    if (e.isDirectory()) for (const [k, v] of tree(dir, rel)) out.set(k, v);
    else out.set(rel, readFileSync(join(dir, rel)));
  }
  return out;
}

test('the LeRobot dataset: the zip of the page is the files of bsv so101-dataset, listed in the evidence, and passes the v3.0 checker', async () => {
  const { page, errors, close } = await open();
  const dir = mkdtempSync(join(tmpdir(), 'bsv-lerobot-'));
  try {
    const progress = page.locator('[data-so101="dataset-progress"]');
    // No labelled episode yet: the page says what to do, nothing is downloaded.
    await page.locator('[data-download="so101_lerobot_v3.zip"]').click();
    await page.locator('[data-so101="dataset-progress"][data-state="none"]').waitFor();
    assert.match(await progress.innerText(), /Label an episode first/);
    await page.locator('[data-module="record-ten"]').click();
    await recordEpisode(page, 'w', 300);
    await recordEpisode(page, 'q', 250);
    // A third episode left unlabelled stays out of the dataset.
    await canvas(page).focus();
    await hold(page, 'a', 200);
    await page.locator('[data-action="end-episode"]').click();
    await page.locator('[data-so101="label-panel"]').waitFor({ state: 'visible' });

    const zip = await download(page, 'so101_lerobot_v3.zip');
    assert.equal(await progress.getAttribute('data-state'), 'done');
    assert.match(await progress.innerText(), /2 labelled episodes/);
    writeFileSync(join(dir, 'so101_lerobot_v3.zip'), zip);
    const entries = unzip(join(dir, 'so101_lerobot_v3.zip'));
    assert.deepEqual([...entries.keys()].sort(), [
      'data/chunk-000/file-000.parquet', 'meta/bsv_labels.json', 'meta/episodes/chunk-000/file-000.parquet',
      'meta/info.json', 'meta/stats.json', 'meta/tasks.parquet',
    ]);
    const info = JSON.parse(entries.get('meta/info.json').toString('utf8'));
    assert.equal(info.codebase_version, 'v3.0');
    assert.equal(info.robot_type, 'so_follower');
    assert.equal(info.fps, 25);
    assert.equal(info.total_episodes, 2);

    // The CLI writes the same bytes from the page's episode CSVs and table.
    const session = join(dir, 'session');
    mkdirSync(session);
    for (const f of ['so101_episode_1.csv', 'so101_episode_2.csv', 'so101_episode_3.csv', 'so101_episodes.csv']) {
      writeFileSync(join(session, f), await download(page, f));
    }
    const out = join(dir, 'cli');
    execFileSync(BSV, ['so101-dataset', ...[1, 2, 3].map((n) => join(session, `so101_episode_${n}.csv`)), '--out', out], { stdio: 'pipe' });
    const written = tree(out);
    assert.deepEqual([...written.keys()].sort(), [...entries.keys()].sort());
    for (const [name, bytes] of entries) assert.ok(bytes.equals(written.get(name)), `${name} differs from bsv so101-dataset's`);
    // The project's v3.0 checker (pyarrow), where make test's setup installed it.
    const python = join(ROOT, '.venv', 'bin', 'python');
    assert.ok(existsSync(python), 'no .venv with pyarrow: run scripts/setup.sh (make test does)');
    execFileSync(python, [join(ROOT, 'tests', 'lerobot', 'check_v3.py'), out], { stdio: 'pipe' });

    // The evidence lists the zip with the SHA-256 of the bytes downloaded.
    const evidence = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    const listed = evidence.dataArtifacts.find((a) => a.uriOrRef === 'so101_lerobot_v3.zip');
    assert.equal(listed.type, 'lerobot-dataset');
    assert.equal(listed.mediaType, 'application/zip');
    assert.equal(listed.sha256, createHash('sha256').update(zip).digest('hex'));
    // Relabelled, the session is no longer the zip's: the evidence stops listing it.
    await page.locator('[data-label="PARTIAL"]').click();
    await page.locator('[data-action="confirm-label"]').click();
    const after = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    assert.ok(!after.dataArtifacts.some((a) => a.uriOrRef === 'so101_lerobot_v3.zip'));
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
    await close();
  }
});
const position = (page) => stepper(page).locator('[data-stepper="position"]').innerText();

test('failure review: a stepper walks the replayed episode, its first failure marked', async () => {
  const { page, errors, close } = await open();
  try {
    // With no episode the review says what it waits for.
    await page.locator('[data-module="failure-review"]').click();
    assert.match(await page.locator('[data-so101="review-event"]').innerText(), /No episode to replay yet/);
    assert.ok(!(await page.locator('[data-action="engage"]').isVisible()), 'the live buttons hide in the review');
    await page.locator('[data-module="record-ten"]').click();
    await recordEpisode(page, 'w', 300);
    const csv = (await download(page, 'so101_episode_1.csv')).toString('utf8').trim().split('\n');
    const rows = csv.slice(4);
    const header = csv[3].split(',');
    const col = (row, name) => Number(row.split(',')[header.indexOf(name)]);

    await page.locator('[data-module="failure-review"]').click();
    await stepper(page).waitFor({ state: 'visible' });
    assert.equal((await values(page)).state, 'replay');
    assert.equal(await position(page), `Step 0 of ${rows.length}`);
    // The first failure (the missed grasp) is marked on the timeline, at its step.
    const timeline = page.locator('[data-testid="so101-timeline"]');
    const first = Number(await timeline.getAttribute('data-first-failure'));
    const missed = rows.findIndex((r) => r.split(',')[header.indexOf('event')].includes('grasp-miss')) + 1;
    assert.equal(first, missed);
    assert.match(await page.locator('[data-so101="review-event"]').innerText(), new RegExp(`step ${missed}`));
    // End: the readouts are the CSV's last row.
    await stepper(page).locator('[data-action="end"]').click();
    const end = await values(page);
    assert.equal(end.x, col(rows.at(-1), 'x'));
    assert.equal(end.q1, col(rows.at(-1), 'q1'));
    // Step back one, then scrub to step 10: the readouts follow the CSV's rows.
    await stepper(page).locator('[data-action="back"]').click();
    assert.equal((await values(page)).x, col(rows.at(-2), 'x'));
    await stepper(page).locator('[data-stepper="scrub"]').fill('10');
    assert.equal(await position(page), `Step 10 of ${rows.length}`);
    assert.equal((await values(page)).z, col(rows[9], 'z'));
    // Keys step it too (the page's stepper keys): Home goes back to the start.
    await page.locator('h1').click();
    await page.keyboard.press('Home');
    assert.equal(await position(page), `Step 0 of ${rows.length}`);
    await page.keyboard.press('ArrowRight');
    assert.equal(await position(page), `Step 1 of ${rows.length}`);
    // Play runs it (then pause).
    await stepper(page).locator('[data-action="run"]').click();
    await page.waitForFunction(() => {
      const el = document.querySelector('[data-testid="so101-stepper"] [data-stepper="position"]');
      return el && !el.textContent.startsWith('Step 1 of');
    });
    await stepper(page).locator('[data-action="run"]').click();
    // The table's Replay button opens the review of that episode.
    await page.locator('[data-module="record-ten"]').click();
    assert.ok(!(await stepper(page).isVisible()));
    await page.locator('[data-action="replay"][data-episode="1"]').click();
    assert.equal(await page.locator('[data-module="failure-review"]').getAttribute('aria-pressed'), 'true');
    assert.match(await page.locator('[data-so101="review-title"]').innerText(), /episode 1/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('repeatability: a second session beside the first; a reload keeps both', async () => {
  const { page, errors, close } = await open();
  try {
    await page.locator('[data-module="record-ten"]').click();
    await recordEpisode(page, 'w', 250);
    await recordEpisode(page, 'q', 250);
    const cells = async (id) => page.locator(`[data-so101="compare"] tr[data-compare="${id}"] td`).allInnerTexts();
    // The second session is the repeatability module's.
    await page.locator('[data-module="repeatability"]').click();
    assert.deepEqual((await cells('attempted')).slice(1), ['2', '—']);
    await page.locator('[data-action="second-session"]').click();
    assert.match(await page.locator('[data-so101="status"]').innerText(), /second session started/i);
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 0);
    assert.equal(await page.locator('[data-module="record-ten"]').getAttribute('aria-pressed'), 'true');
    await recordEpisode(page, 'e', 250);
    assert.deepEqual((await cells('attempted')).slice(1), ['2', '1']);
    assert.deepEqual((await cells('grasp-miss')).slice(1), ['2', '1']);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.waitForFunction(() => {
      const row = document.querySelector('[data-so101="compare"] tr[data-compare="attempted"]');
      return row && row.children[1].textContent === '2';
    });
    assert.deepEqual((await cells('attempted')).slice(1), ['2', '1']);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('saved files open again as a session in the review; a bad set is named and changes nothing', async () => {
  const first = await open();
  let files;
  try {
    await first.page.locator('[data-module="record-ten"]').click();
    await recordEpisode(first.page, 'w', 250);
    files = [
      { name: 'teleop_session_evidence.json', mimeType: 'application/json', buffer: await download(first.page, 'teleop_session_evidence.json') },
      { name: 'so101_episodes.csv', mimeType: 'text/csv', buffer: await download(first.page, 'so101_episodes.csv') },
      { name: 'so101_episode_1.csv', mimeType: 'text/csv', buffer: await download(first.page, 'so101_episode_1.csv') },
    ];
  } finally {
    await first.close();
  }
  const { page, errors, close } = await open();
  try {
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 0);
    // A bad set: the evidence with a key the format does not allow.
    const bad = JSON.parse(files[0].buffer.toString('utf8'));
    bad.operatorMood = 'fine';
    await page.locator('[data-so101="open"]').setInputFiles([{ ...files[0], buffer: Buffer.from(JSON.stringify(bad)) }, files[1], files[2]]);
    await page.locator('[data-so101="open-error"]').waitFor({ state: 'visible' });
    assert.match(await page.locator('[data-so101="open-error"]').innerText(), /operatorMood/);
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 0);
    // A missing episode file is named.
    await page.locator('[data-so101="open"]').setInputFiles(files.slice(0, 2));
    await page.waitForFunction(() => /so101_episode_1\.csv is missing/.test(document.querySelector('[data-so101="open-error"]').textContent));
    // The good set: the session, in the failure review.
    await page.locator('[data-so101="open"]').setInputFiles(files);
    await page.locator('[data-so101="open-error"]').waitFor({ state: 'hidden' });
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 1);
    assert.match(await page.locator('[data-so101="status"]').innerText(), /saved session is open/);
    assert.equal(await page.locator('[data-module="failure-review"]').getAttribute('aria-pressed'), 'true');
    await stepper(page).waitFor({ state: 'visible' });
    const again = await download(page, 'so101_episode_1.csv');
    assert.ok(again.equals(files[2].buffer), 'the opened episode is the same bytes');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('storage full while recording: the recording goes on, a warning offers the files (EN/JA)', async () => {
  const { page, errors, close } = await open();
  try {
    await page.locator('[data-module="record-ten"]').click();
    await page.evaluate(() => {
      window.__realSetItem = Storage.prototype.setItem;
      Storage.prototype.setItem = function setItem() {
        throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
      };
    });
    const warning = page.locator('[data-testid="storage-warning"]');
    await recordEpisode(page, 'w', 250);
    await warning.waitFor({ state: 'visible' });
    assert.equal(await warning.getAttribute('role'), 'alert');
    assert.match(await warning.innerText(), /^Not saved: this browser refused to store the session/);
    await recordEpisode(page, 'q', 250);
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 2);
    assert.equal(await page.locator('[data-testid="storage-download-table"]').innerText(), 'Download so101_episodes.csv');
    const saved = async (testid, count) => {
      const names = [];
      const arrived = new Promise((resolve) => {
        const on = (d) => {
          names.push(d.suggestedFilename());
          if (names.length === count) {
            page.off('download', on);
            resolve();
          }
        };
        page.on('download', on);
      });
      await page.locator(`[data-testid="${testid}"]`).click();
      await arrived;
      return names.sort();
    };
    assert.deepEqual(await saved('storage-download-evidence', 1), ['teleop_session_evidence.json']);
    assert.deepEqual(await saved('storage-download-table', 1), ['so101_episodes.csv']);
    assert.deepEqual(await saved('storage-download-episodes', 2), ['so101_episode_1.csv', 'so101_episode_2.csv']);
    await page.click('[data-testid="lang-switch"]');
    assert.match(await warning.innerText(), /^保存されていません/);
    assert.equal(await page.locator('[data-testid="storage-download-episodes"]').innerText(), 'エピソードの CSV（2 件）をダウンロード');
    await page.click('[data-testid="lang-switch"]');
    // Storage back: the next save stores everything and the warning goes.
    await page.evaluate(() => { Storage.prototype.setItem = window.__realSetItem; });
    await canvas(page).focus();
    await page.keyboard.press('r');
    await warning.waitFor({ state: 'hidden' });
    const back = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.so101.session')));
    assert.equal(back.episodes.length, 2);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the settings are the URL: a link opens them, an edit writes them, bad values are left out', async () => {
  const { page, errors, close } = await open('#/so101?ik=pinv&latency_ms=50&noise=0.1&pos_sensitivity=1&rot_sensitivity=1.6&obstacle=true');
  try {
    const field = (name) => page.locator(`[data-field="${name}"]`);
    assert.equal(await field('ik').inputValue(), 'pinv');
    assert.equal(await field('latency_ms').inputValue(), '50');
    assert.equal(await field('noise').inputValue(), '0.1');
    assert.equal(await field('pos_sensitivity').inputValue(), '1');
    assert.equal(await field('rot_sensitivity').inputValue(), '1.6');
    assert.ok(await field('obstacle').isChecked());
    await page.locator('.so101-settings summary').click();
    await field('latency_ms').fill('120');
    await field('latency_ms').dispatchEvent('change');
    await page.waitForFunction(() => location.hash.includes('latency_ms=120'));
    assert.deepEqual(await query(page), {
      ik: 'pinv', latency_ms: '120', noise: '0.1', pos_sensitivity: '1', rot_sensitivity: '1.6', obstacle: 'true',
    });
    // A value the simulation refuses is not taken: the field shows the one in force.
    await field('noise').fill('7');
    await field('noise').dispatchEvent('change');
    assert.equal(await field('noise').inputValue(), '0.1');
    await page.goto(`${server.url}/#/so101?ik=magic&latency_ms=-5&noise=x`);
    await page.waitForFunction(() => document.querySelector('[data-field="ik"]')?.value === 'dls');
    assert.equal(await field('latency_ms').inputValue(), '0');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the home card and #/teleop\'s next step lead here', async () => {
  const { page, errors, close } = await open('#/');
  try {
    const card = page.locator('[data-testid="featured-so101"]');
    assert.equal(await card.getAttribute('href'), '#/so101');
    assert.match(await card.innerText(), /SO-101/);
    await page.goto(`${server.url}/#/teleop`);
    await page.locator('[data-testid="chain-next-link"]').waitFor({ state: 'visible' });
    assert.equal(await page.locator('[data-testid="chain-next-link"]').getAttribute('href'), '#/so101');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const { page, errors, close } = await open('#/so101?lang=ja');
  try {
    await canvas(page).focus();
    await hold(page, 'w', 200);
    const { text, left } = await englishOnPage(page);
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /ロボットパイロット：SO-101/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the page opens on the arm: the 3D view and its buttons in the first screen, phone to projector', async () => {
  const sizes = [
    [{ width: 390, height: 844 }, 'ja'],
    [{ width: 390, height: 844 }, 'en'],
    [{ width: 1366, height: 768 }, 'en'],
    [{ width: 1366, height: 800 }, 'ja'],
  ];
  for (const [viewport, lang] of sizes) {
    const { page, errors, close } = await open(`#/so101?lang=${lang}`, { viewport });
    try {
      await canvas(page).waitFor();
      const scrolled = await page.evaluate(() => window.scrollY);
      assert.equal(scrolled, 0, `${lang} ${viewport.width}: opened scrolled`);
      const view = await canvas(page).boundingBox();
      // Most of the world view shows without scrolling.
      const seen = Math.min(view.y + view.height, viewport.height) - Math.max(view.y, 0);
      assert.ok(seen >= 0.75 * Math.min(view.height, viewport.height * 0.5), `${lang} ${viewport.width}: ${seen} px of the view seen`);
      if (viewport.width < 720) {
        // On a phone the engage button follows the view at once.
        const engage = await page.locator('[data-action="engage"]').boundingBox();
        assert.ok(engage.y > view.y + view.height && engage.y < viewport.height + 60, `${lang}: engage at ${engage.y}`);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('screenshots: EN and JA 1366×768, projector, phone 390 px', async () => {
  const shots = [
    ['so101-en-1366.png', '#/so101', { viewport: { width: 1366, height: 768 } }],
    ['so101-ja-1366.png', '#/so101?lang=ja', { viewport: { width: 1366, height: 768 } }],
    ['so101-projector-1920.png', '#/so101', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['so101-phone-390.png', '#/so101?lang=ja', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots, {
    prepare: async (page) => {
      await canvas(page).focus();
      await hold(page, 'a', 250);
      await hold(page, 'e', 250);
    },
  });
});
