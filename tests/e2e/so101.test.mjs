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
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { openApp, browser, readouts, screenshots } from './harness.mjs';
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

    // Replay: the view plays the episode back.
    await page.locator('[data-action="replay"][data-episode="1"]').click();
    assert.equal((await values(page)).state, 'replay');

    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    assert.ok(await page.locator('[data-so101="restored"]').isVisible());
    assert.equal(await page.locator('[data-so101="episodes"] tr').count(), 1);
    assert.match(await page.locator('[data-so101="episodes"] tr').innerText(), /FAILURE/);
    assert.equal(await page.locator('[data-module="record-ten"]').getAttribute('aria-pressed'), 'true');
    const again = await download(page, 'so101_episode_1.csv');
    assert.ok(again.equals(csv), 'the reloaded episode is the same bytes');
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
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
