// The Robot Pilot page (#/teleop) in headless Chromium: holding W moves the tip's x up and Q its
// z up (readouts); an injected gamepad (navigator.getGamepads overridden before the app loads)
// moves the arm and its name is shown; a scripted session (preflight: move, reset checked;
// record: an episode ended, labelled FAILURE / collision with a note) exports its episode CSV,
// which `bsv teleop-replay` reproduces (exit 0), the episodes table and the evidence JSON, whose
// every rule of teleop-session-evidence v0.1 is checked here (and each CSV's SHA-256 against
// the downloaded bytes); a reload keeps the session, and an episode cut off by the reload comes
// back interrupted; a bad saved file is refused with a message naming what is wrong, the
// session kept; Japanese leaves no English UI text. Screenshots go to tests/e2e/out/.
// An idle page requests no animation frames, and a key press still moves the tip on the next
// frame. Four 60 s episodes (stored sessions of 6,000 commands each) export in slices: the
// episode CSV and the evidence with a progress line, and `bsv teleop-replay` reproduces the CSV.
// Ten stored 60 s episodes and one cut off load in slices after a reload (a progress line), the
// session intact. A second session after an exported first: the comparison keeps the first, the
// second's files are its own, and a reload keeps both. The main-thread tasks of the exports and
// of the load are figures of tests/bench/teleop.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { openApp, browser, readouts, screenshots, OUT } from './harness.mjs';
import { serveAppWithCli, BSV, download } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

const open = (hash = '#/teleop', opts = {}) => openApp(server.url, hash, opts);

/** `data-readout` → shown text of the page. */
const shownReadouts = (page) => readouts(page, { text: true });

async function hold(page, key, ms) {
  await page.keyboard.down(key);
  await page.waitForTimeout(ms);
  await page.keyboard.up(key);
}

const canvas = (page) => page.locator('[data-testid="teleop-canvas"]');

test('holding W moves x up, Q moves z up; the arm starts engaged', async () => {
  const { page, errors, close } = await open();
  try {
    const r0 = await shownReadouts(page);
    assert.equal(await page.locator('[data-readout="state"]').getAttribute('data-value'), 'engaged');
    await canvas(page).focus();
    await hold(page, 'w', 300);
    const r1 = await shownReadouts(page);
    assert.ok(Number(r1.x) > Number(r0.x) + 0.01, `x ${r0.x} → ${r1.x}`);
    assert.ok(Math.abs(Number(r1.z) - Number(r0.z)) < 0.01, `z stays: ${r0.z} → ${r1.z}`);
    await hold(page, 'q', 300);
    const r2 = await shownReadouts(page);
    assert.ok(Number(r2.z) > Number(r1.z) + 0.01, `z ${r1.z} → ${r2.z}`);
    // Space pauses: W then moves nothing.
    await page.keyboard.press('Space');
    assert.equal(await page.locator('[data-readout="state"]').getAttribute('data-value'), 'paused');
    await hold(page, 'w', 200);
    const r3 = await shownReadouts(page);
    assert.equal(r3.x, r2.x);
    // Paused, K does nothing; engaged again, K closes the gripper (readout and button).
    await page.keyboard.press('k');
    assert.equal(await page.locator('[data-readout="gripper"]').getAttribute('data-value'), 'open');
    await page.keyboard.press('Space');
    await page.keyboard.press('k');
    assert.equal(await page.locator('[data-readout="gripper"]').getAttribute('data-value'), 'closed');
    assert.equal(await page.locator('[data-action="gripper"]').getAttribute('aria-pressed'), 'true');
    // L on the canvas clears held keys and is not the shell's language switch.
    await page.keyboard.press('l');
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a pointer drag on the arm view pulls the tip only while held (clutch)', async () => {
  const { page, errors, close } = await open();
  try {
    await page.locator('[data-device="pointer"]').click();
    const box = await canvas(page).boundingBox();
    const r0 = await shownReadouts(page);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 40, box.y + box.height / 2 - 30, { steps: 4 });
    await page.waitForTimeout(400);
    const r1 = await shownReadouts(page);
    assert.ok(Number(r1.x) > Number(r0.x) + 0.01, `x ${r0.x} → ${r1.x}`);
    assert.ok(Number(r1.z) > Number(r0.z) + 0.01, `z ${r0.z} → ${r1.z}`);
    await page.mouse.up();
    await page.waitForTimeout(150);
    const r2 = await shownReadouts(page);
    await page.waitForTimeout(200);
    assert.equal((await shownReadouts(page)).x, r2.x, 'released: the tip stays');
    assert.equal(await page.locator('[data-check="moved"]').getAttribute('data-state'), 'done');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Injects a standard gamepad at rest (window.__testPad) into every page of `context`. */
function injectPad(context) {
  return context.addInitScript(() => {
    const buttons = Array.from({ length: 17 }, () => ({ pressed: false, touched: false, value: 0 }));
    const pad = { id: 'Test Pad (STANDARD GAMEPAD)', index: 0, connected: true, mapping: 'standard', timestamp: 0, axes: [0, 0, 0, 0], buttons };
    window.__testPad = pad;
    Object.defineProperty(Navigator.prototype, 'getGamepads', { configurable: true, value: () => [pad, null, null, null] });
  });
}

test('an injected gamepad moves the arm and is named', async () => {
  const context = await (await browser()).newContext({ viewport: { width: 1280, height: 800 }, locale: 'en-US' });
  await injectPad(context);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  try {
    await page.goto(`${server.url}/#/teleop`);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.locator('[data-device="gamepad"]').click();
    await page.waitForFunction(() => document.querySelector('[data-tele="device-status"]').textContent.includes('Test Pad'));
    // The gamepad's sensitivities (Isaac Lab's 1.0 / 1.6) replace the keyboard's.
    assert.equal(await page.locator('[data-field="pos_sensitivity"]').inputValue(), '1');
    assert.equal(await page.locator('[data-field="rot_sensitivity"]').inputValue(), '1.6');
    const r0 = await shownReadouts(page);
    // Left stick up (negative in the standard mapping): +x.
    // Each stick is held until the readout moves (a loaded machine may give the page few
    // frames in a fixed time), then let go.
    const moved = (key, from) => page.waitForFunction(([k, v]) => {
      const el = document.querySelector(`[data-readout="${k}"]`);
      return el && Number(el.textContent) > Number(v) + 0.01;
    }, [key, from], { timeout: 10000 });
    await page.evaluate(() => { window.__testPad.axes[1] = -1; });
    await page.waitForTimeout(250);
    await moved('x', r0.x);
    await page.evaluate(() => { window.__testPad.axes[1] = 0; });
    const r1 = await shownReadouts(page);
    assert.ok(Number(r1.x) > Number(r0.x) + 0.01, `x ${r0.x} → ${r1.x}`);
    // Right stick up: +z.
    await page.evaluate(() => { window.__testPad.axes[3] = -1; });
    await page.waitForTimeout(250);
    await moved('z', r1.z);
    await page.evaluate(() => { window.__testPad.axes[3] = 0; });
    const r2 = await shownReadouts(page);
    assert.ok(Number(r2.z) > Number(r1.z) + 0.01, `z ${r1.z} → ${r2.z}`);
    // X (button 2) toggles the gripper on its press.
    await page.evaluate(() => { window.__testPad.buttons[2] = { pressed: true, touched: true, value: 1 }; });
    await page.waitForFunction(() => document.querySelector('[data-readout="gripper"]').dataset.value === 'closed');
    await page.evaluate(() => { window.__testPad.buttons[2] = { pressed: false, touched: false, value: 0 }; });
    // The preflight saw the chosen device move the arm.
    assert.equal(await page.locator('[data-check="moved"]').getAttribute('data-state'), 'done');
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

function sha256(buf) {
  return createHash('sha256').update(buf).digest('hex');
}

/** The rules of teleop-session-evidence v0.1. */
function checkEvidence(doc) {
  const keys = ['schemaVersion', 'evidenceId', 'pilotId', 'taskId', 'environment', 'runtime', 'runtimeVersion', 'embodiment',
    'inputDevice', 'startedAt', 'endedAt', 'episodes', 'safetyEvents', 'dataArtifacts', 'metrics', 'review'];
  assert.deepEqual(Object.keys(doc).sort(), [...keys].sort(), 'exactly the schema\'s top-level keys');
  assert.equal(doc.schemaVersion, '0.1');
  assert.match(doc.evidenceId, /^teleop_[a-z0-9_-]+$/);
  for (const k of ['pilotId', 'taskId', 'runtime', 'runtimeVersion', 'embodiment', 'inputDevice']) {
    assert.equal(typeof doc[k], 'string', k);
    assert.ok(doc[k].length > 0, k);
  }
  assert.equal(doc.environment, 'SIMULATION');
  const iso = /^\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}(\.\d+)?(Z|[+-]\d{2}:\d{2})$/;
  assert.match(doc.startedAt, iso);
  assert.match(doc.endedAt, iso);
  assert.ok(!Number.isNaN(Date.parse(doc.startedAt)) && Date.parse(doc.endedAt) >= Date.parse(doc.startedAt));
  const e = doc.episodes;
  assert.deepEqual(Object.keys(e).sort(), ['attempted', 'failed', 'recoveryEpisodes', 'successful']);
  for (const v of Object.values(e)) assert.ok(Number.isInteger(v) && v >= 0);
  assert.equal(e.successful + e.failed, e.attempted);
  assert.ok(Array.isArray(doc.safetyEvents));
  for (const ev of doc.safetyEvents) assert.equal(typeof ev, 'string');
  assert.ok(Array.isArray(doc.dataArtifacts));
  for (const a of doc.dataArtifacts) {
    assert.equal(typeof a.type, 'string');
    assert.equal(typeof a.uriOrRef, 'string');
    assert.match(a.sha256, /^[0-9a-f]{64}$/);
  }
  for (const [k, v] of Object.entries(doc.metrics)) {
    assert.ok(v === null || ['number', 'string', 'boolean'].includes(typeof v), `metrics.${k}`);
  }
  assert.deepEqual(doc.review, { status: 'UNREVIEWED' });
}

test('a scripted session: preflight, an episode recorded, labelled, exported; bsv teleop-replay reproduces it; reload keeps it', async () => {
  const { page, errors, close } = await open();
  const dir = mkdtempSync(join(tmpdir(), 'bsv-teleop-'));
  try {
    // Preflight: the keyboard moves the arm, a reset returns it to the start state.
    await canvas(page).focus();
    await hold(page, 'w', 250);
    assert.equal(await page.locator('[data-check="moved"]').getAttribute('data-state'), 'done');
    await page.keyboard.press('r');
    assert.equal(await page.locator('[data-check="reset"]').getAttribute('data-state'), 'done');
    // The readouts show the reset pose on the next frame.
    await page
      .waitForFunction(() => [...document.querySelectorAll('[data-readout="x"]')].every((el) => el.textContent.trim() === '0.1000'), null, { timeout: 3000 })
      .catch(() => {});
    assert.equal((await shownReadouts(page)).x, '0.1000');
    // Record ten.
    await page.locator('[data-module="record-ten"]').click();
    assert.equal((await shownReadouts(page)).episode, '1 / 10');
    await canvas(page).focus();
    await hold(page, 'w', 400);
    await hold(page, 'e', 300);
    await page.keyboard.press('k');
    await page.waitForTimeout(100);
    await page.locator('[data-action="end-episode"]').click();
    const panel = page.locator('[data-tele="label-panel"]');
    await panel.waitFor({ state: 'visible' });
    await page.locator('[data-label="FAILURE"]').click();
    await page.locator('[data-category="collision"]').click();
    assert.equal(await page.locator('[data-category="collision"]').getAttribute('aria-pressed'), 'true');
    await page.locator('[data-field="note"]').fill('wrist hit, "table"');
    await page.locator('[data-action="confirm-label"]').click();
    await panel.waitFor({ state: 'hidden' });
    assert.equal((await shownReadouts(page)).episode, '2 / 10');

    // The episode's time series replays exactly with the CLI.
    const episodeCsv = await download(page, 'teleop_episode_1.csv');
    const last1x = episodeCsv.toString('utf8').trim().split('\n').pop().split(',')[12];
    const file = join(dir, 'teleop_episode_1.csv');
    writeFileSync(file, episodeCsv);
    const out = execFileSync(BSV, ['teleop-replay', file], { encoding: 'utf8' });
    assert.ok(out.length > 0);

    // The episodes table.
    const table = (await download(page, 'teleop_episodes.csv')).toString('utf8').trim().split('\n');
    assert.match(table[0], /^id,task,label,category,note,interrupted,outcome,duration_s,path_m,efficiency,collisions,/);
    assert.equal(table.length, 2);
    assert.match(table[1], /^1,pick-place,FAILURE,collision,"wrist hit, ""table""",0,ended,/);

    // The evidence: every rule, the CSVs' SHA-256.
    const evidenceBytes = await download(page, 'teleop_session_evidence.json');
    const doc = JSON.parse(evidenceBytes.toString('utf8'));
    checkEvidence(doc);
    assert.deepEqual(doc.episodes, { attempted: 1, successful: 0, failed: 1, recoveryEpisodes: 0 });
    assert.equal(doc.inputDevice, 'keyboard');
    assert.equal(doc.metrics['failures.collision'], 1);
    assert.equal(doc.metrics.preflightResetVerified, true);
    const listed = Object.fromEntries(doc.dataArtifacts.map((a) => [a.uriOrRef, a.sha256]));
    assert.equal(listed['teleop_episode_1.csv'], sha256(episodeCsv));
    assert.equal(listed['teleop_episodes.csv'], sha256(Buffer.from(table.join('\n') + '\n')));

    // An explicit reset starts episode 2; under way when the tab reloads, it is kept,
    // interrupted, and offered for labelling.
    await canvas(page).focus();
    await hold(page, 's', 150);
    assert.equal((await shownReadouts(page)).x, Number(last1x).toFixed(4), 'an ended episode takes no input before a reset');
    await page.keyboard.press('r');
    await hold(page, 's', 250);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.locator('[data-tele="restored"]').waitFor({ state: 'visible' });
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 2);
    assert.match(await page.locator('[data-tele="episodes"] tbody tr').first().innerText(), /FAILURE[\s\S]*collision/);
    await panel.waitFor({ state: 'visible' });
    assert.match(await panel.innerText(), /interrupted/);
    assert.equal(await page.locator('[data-label="FAILURE"]').getAttribute('aria-pressed'), 'true');
    assert.equal(await page.locator('[data-category="operator-abort"]').getAttribute('aria-pressed'), 'true');
    await page.locator('[data-action="confirm-label"]').click();
    assert.equal(await page.locator('[data-module="record-ten"]').getAttribute('aria-current'), 'step');

    // Failure review: the stepper replays episode 1 with its first failure marked, if any.
    await page.locator('[data-module="failure-review"]').click();
    await page.locator('[data-testid="teleop-stepper"]').waitFor();
    await page.locator('[data-replay="1"]').click();
    await page.locator('[data-testid="teleop-stepper"] [data-action="end"]').click();
    // At the end, the readouts show the CSV's last row (x, z are columns 13 and 14).
    const last = episodeCsv.toString('utf8').trim().split('\n').pop().split(',');
    const end = await shownReadouts(page);
    assert.equal(end.x, Number(last[12]).toFixed(4));
    assert.equal(end.z, Number(last[13]).toFixed(4));
    // The timeline's marks: Okabe–Ito vermilion (the first failure's triangle, the crosses),
    // none of the old red and green a deuteranope cannot tell apart; a legend names the shapes.
    assert.ok(Number(await page.locator('[data-testid="teleop-timeline"]').getAttribute('data-first-failure')) >= 1);
    const inks = await page.locator('[data-testid="teleop-timeline"]').evaluate((c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const near = (i, [r, g, b]) => Math.abs(d[i] - r) + Math.abs(d[i + 1] - g) + Math.abs(d[i + 2] - b) < 12 && d[i + 3] === 255;
      const count = (rgb) => { let n = 0; for (let i = 0; i < d.length; i += 4) if (near(i, rgb)) n++; return n; };
      return { vermilion: count([213, 94, 0]), red: count([164, 22, 26]), green: count([29, 107, 53]) };
    });
    assert.ok(inks.vermilion > 20, JSON.stringify(inks));
    assert.equal(inks.red + inks.green, 0, JSON.stringify(inks));
    assert.deepEqual(await page.locator('[data-tele="timeline-legend"] li').allTextContents(), [
      '✕failure (collision, drop, missed grasp, time up)', '○grasp, target reached, success',
      '■joint limit, singularity, speed limit', '|release', '▼first failure', '┃step shown',
    ]);

    // A bad saved file: named, the session kept.
    const bad = JSON.parse(evidenceBytes.toString('utf8'));
    bad.operatorMood = 'fine';
    await page.locator('[data-tele="open"]').setInputFiles([
      { name: 'teleop_session_evidence.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(bad)) },
      { name: 'teleop_episodes.csv', mimeType: 'text/csv', buffer: Buffer.from(table.join('\n') + '\n') },
      { name: 'teleop_episode_1.csv', mimeType: 'text/csv', buffer: episodeCsv },
    ]);
    await page.locator('[data-tele="open-error"]').waitFor({ state: 'visible' });
    assert.match(await page.locator('[data-tele="open-error"]').innerText(), /operatorMood/);
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 2);
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  const { page, errors, close } = await open('#/teleop?lang=ja');
  try {
    await page.locator('[data-field="lambda"]').fill('abc');
    await page.locator('[data-field="latency_ms"]').fill('125');
    await canvas(page).focus();
    await hold(page, 'w', 200);
    const text = await page.evaluate(() => {
      let all = document.body.innerText;
      for (const b of document.querySelectorAll('[data-download]')) all = all.replaceAll(b.dataset.download, '');
      for (const k of document.querySelectorAll('kbd')) all = all.replaceAll(k.innerText, '');
      return all;
    });
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /ロボットパイロット練習/);
    assert.ok(await page.locator('[data-field-error="lambda"]').isVisible());
    assert.match(await page.locator('[data-field-error="latency_ms"]').innerText(), /10 ミリ秒/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const shots = [
    ['teleop-en-1920.png', '#/teleop', { viewport: { width: 1920, height: 1080 } }],
    ['teleop-ja-1920.png', '#/teleop?lang=ja', { viewport: { width: 1920, height: 1080 } }],
    ['teleop-projector-1920.png', '#/teleop', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['teleop-phone-390.png', '#/teleop?lang=ja', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots, {
    prepare: async (page) => {
      await canvas(page).focus();
      await hold(page, 'w', 250);
      await hold(page, 'q', 150);
    },
    shot: { fullPage: true },
  });
});

/** Preflight with the keyboard (the arm moved, a reset checked), then Record ten. */
async function preflightThenRecord(page) {
  await canvas(page).focus();
  await hold(page, 'w', 250);
  await page.keyboard.press('r');
  assert.equal(await page.locator('[data-check="reset"]').getAttribute('data-state'), 'done');
  await page.locator('[data-module="record-ten"]').click();
}

/** Records one episode (`key` held `ms`), ended with End episode and labelled as proposed. */
async function recordEpisode(page, key, ms) {
  await canvas(page).focus();
  await hold(page, key, ms);
  await page.locator('[data-action="end-episode"]').click();
  const panel = page.locator('[data-tele="label-panel"]');
  await panel.waitFor({ state: 'visible' });
  await page.locator('[data-action="confirm-label"]').click();
  await panel.waitFor({ state: 'hidden' });
  await page.keyboard.press('r');
}

/** A page whose requestAnimationFrame calls are counted (window.__rafCalls). */
async function openCounted(hash = '#/teleop') {
  const app = await open(hash);
  await app.context.addInitScript(() => {
    window.__rafCalls = 0;
    const raf = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = (cb) => { window.__rafCalls++; return raf(cb); };
  });
  await app.page.reload();
  await app.page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
  return app;
}

/** requestAnimationFrame calls during `ms` of wall time. */
async function framesDuring(page, ms) {
  return page.evaluate(async (ms) => {
    const n0 = window.__rafCalls;
    await new Promise((r) => setTimeout(r, ms));
    return window.__rafCalls - n0;
  }, ms);
}

test('an idle page requests no frames; a key press moves the tip on the next frame', async () => {
  const { page, errors, close } = await openCounted();
  try {
    await page.waitForTimeout(300);
    assert.ok((await framesDuring(page, 1000)) <= 1, 'idle after the mount: no frames');
    await canvas(page).focus();
    // keydown → the first frame after it shows a moved tip (x readout).
    const frames = await page.evaluate(
      () =>
        new Promise((resolve) => {
          const x0 = document.querySelector('[data-readout="x"]').textContent;
          const c = document.querySelector('[data-testid="teleop-canvas"]');
          c.dispatchEvent(new KeyboardEvent('keydown', { code: 'KeyW', key: 'w', bubbles: true }));
          let n = 0;
          const tick = () => {
            n++;
            if (document.querySelector('[data-readout="x"]').textContent !== x0 || n > 30) {
              window.dispatchEvent(new KeyboardEvent('keyup', { code: 'KeyW', key: 'w', bubbles: true }));
              resolve(n);
            } else requestAnimationFrame(tick);
          };
          requestAnimationFrame(tick);
        }),
    );
    assert.equal(frames, 1, 'the tip moved on the next frame');
    // Held keys keep the frames coming and the tip moving.
    const r0 = await shownReadouts(page);
    await page.keyboard.down('q');
    const held = await framesDuring(page, 1000);
    await page.keyboard.up('q');
    // (A busy machine's headless Chromium may give far fewer than 60 frames a second.)
    assert.ok(held >= 5, `${held} frames while Q was held`);
    assert.ok(Number((await shownReadouts(page)).z) > Number(r0.z) + 0.01);
    // The episode's clock runs after the first input (time passes); a reset stops it.
    const t0 = Number((await shownReadouts(page)).time);
    await page.waitForTimeout(300);
    assert.ok(Number((await shownReadouts(page)).time) > t0 + 0.1, 'the episode clock runs');
    await page.keyboard.press('r');
    await page.waitForTimeout(200);
    assert.ok((await framesDuring(page, 1000)) <= 1, 'idle again after the reset');
    assert.equal((await shownReadouts(page)).time, '0.00');
    // The on-screen buttons wake it too: the gripper closes on the next frame.
    await page.locator('[data-action="gripper"]').click();
    await page.waitForFunction(() => document.querySelector('[data-readout="gripper"]').dataset.value === 'closed');
    // A pad connecting asks for a frame (it is then polled every frame).
    await page.keyboard.press('r');
    await page.waitForTimeout(200);
    const woken = await page.evaluate(async () => {
      const n0 = window.__rafCalls;
      window.dispatchEvent(new Event('gamepadconnected'));
      await new Promise((r) => setTimeout(r, 100));
      return window.__rafCalls - n0;
    });
    assert.ok(woken >= 1, 'gamepadconnected asks for a frame');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** The stored session with its episode replaced by `copies` episodes of 6,000 commands (60 s at
 * 100 Hz: the default time box ends each at its last step), in four runs of varied commands. */
/** Puts `text` in the stored session before the app next loads, once (the page saves its own
 *  session on pagehide, and later reloads load that). */
function storeSessionOnNextLoad(context, text) {
  return context.addInitScript((t) => {
    if (sessionStorage.getItem('bsv-test-stored') === null) {
      sessionStorage.setItem('bsv-test-stored', '1');
      localStorage.setItem('bsv.teleop.session', t);
    }
  }, text);
}

function sixtySecondSession(stored, copies) {
  const s = JSON.parse(stored);
  const [entry] = s.episodes;
  const cmd = (dx, dz, dphi, gripper_closed) => ({ dx, dz, dphi, gripper_closed });
  entry.episode.runs = [
    [1500, cmd(1, 0, 0, false)],
    [1500, cmd(0, 1, 0.5, false)],
    [1500, cmd(-1, -0.5, 0, false)],
    [1500, cmd(0.3, -0.2, -1, false)],
  ];
  entry.label = 'FAILURE';
  entry.category = 'timeout';
  s.episodes = Array.from({ length: copies }, () => structuredClone(entry));
  s.in_progress = null;
  return JSON.stringify(s);
}

test('60 s episodes export in slices: progress shown, bsv teleop-replay reproduces the CSV', async () => {
  const { page, context, errors, close } = await open();
  const dir = mkdtempSync(join(tmpdir(), 'bsv-teleop-long-'));
  try {
    await preflightThenRecord(page);
    await recordEpisode(page, 'w', 200);
    const stored = await page.evaluate(() => localStorage.getItem('bsv.teleop.session'));
    await storeSessionOnNextLoad(context, sixtySecondSession(stored, 4));
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.locator('[data-tele="restored"]').waitFor({ state: 'visible' });
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 4);
    assert.match(await page.locator('[data-tele="episodes"] tbody tr').first().innerText(), /60(\.00)? s/);
    // Every text the progress line shows is recorded.
    await page.evaluate(() => {
      window.__progress = [];
      const el = document.querySelector('[data-tele="export-progress"]');
      new MutationObserver(() => { if (!el.hidden) window.__progress.push(el.textContent); })
        .observe(el, { childList: true, characterData: true, subtree: true, attributes: true });
    });
    await page.waitForTimeout(500);
    // One episode's CSV: 6,000 rows, about 1.6 MB.
    const csv = await download(page, 'teleop_episode_1.csv');
    const lines = csv.toString('utf8').trim().split('\n');
    const rows = lines.filter((l) => !l.startsWith('#')).length - 1;
    assert.equal(rows, 6000);
    assert.ok(csv.length > 1_000_000, `${csv.length} bytes`);
    assert.match(lines.at(-1), /,timeout$/);
    const file = join(dir, 'teleop_episode_1.csv');
    writeFileSync(file, csv);
    const out = execFileSync(BSV, ['teleop-replay', file], { encoding: 'utf8' });
    assert.match(out, /^replayed 6000 steps of pick-place \(dls\): every recorded step reproduced exactly\noutcome: timeout\nduration_s: 60\.0\n/);
    const progress = await page.evaluate(() => window.__progress.splice(0));
    assert.ok(progress.some((t) => /^Writing teleop_episode_1\.csv: [\d,]+ of 6,000 rows…$/.test(t)), `progress: ${progress.join(' | ')}`);
    assert.equal(await page.locator('[data-tele="export-progress"]').getAttribute('data-state'), 'idle');
    assert.ok(await page.locator('[data-tele="export-progress"]').isHidden());

    // The evidence: the four CSVs (24,000 rows) hashed in slices.
    const evidence = await download(page, 'teleop_session_evidence.json');
    const doc = JSON.parse(evidence.toString('utf8'));
    checkEvidence(doc);
    assert.equal(doc.episodes.attempted, 4);
    const listed = Object.fromEntries(doc.dataArtifacts.map((a) => [a.uriOrRef, a]));
    assert.equal(listed['teleop_episode_1.csv'].sha256, sha256(csv));
    assert.equal(listed['teleop_episode_1.csv'].bytes, csv.length);
    assert.equal(listed['teleop_episode_4.csv'].sha256, sha256(csv), 'the same commands, the same bytes');
    const progress2 = await page.evaluate(() => window.__progress.splice(0));
    assert.ok(progress2.some((t) => /^Writing teleop_session_evidence\.json: [\d,]+ of 24,000 rows…$/.test(t)), `progress: ${progress2.join(' | ')}`);

    // The file's bytes are what the episodes table and the evidence say (the progress line gone).
    const table = (await download(page, 'teleop_episodes.csv')).toString('utf8').trim().split('\n');
    assert.match(table[1], /^1,pick-place,FAILURE,timeout,,0,timeout,60(\.0)?,/);
    assert.equal(listed['teleop_episodes.csv'].sha256, sha256(Buffer.from(table.join('\n') + '\n')));
    // Two files asked for at once: the second waits for the first; both arrive whole.
    const both = [];
    const arrived = new Promise((resolve) => {
      page.on('download', async (d) => {
        both.push({ name: d.suggestedFilename(), bytes: readFileSync(await d.path()) });
        if (both.length === 2) resolve();
      });
    });
    await page.locator('[data-download="teleop_episode_2.csv"]').click();
    await page.locator('[data-download="teleop_session_evidence.json"]').click();
    await arrived;
    assert.deepEqual(both.map((d) => d.name).sort(), ['teleop_episode_2.csv', 'teleop_session_evidence.json']);
    assert.ok(both.find((d) => d.name === 'teleop_episode_2.csv').bytes.equals(csv));
    const again = JSON.parse(both.find((d) => d.name === 'teleop_session_evidence.json').bytes.toString('utf8'));
    assert.deepEqual({ ...again, endedAt: doc.endedAt }, doc);
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
    await close();
  }
});

test('ten stored 60 s episodes and one cut off load in slices: a progress line, the session intact', async () => {
  const { page, context, errors, close } = await open();
  try {
    await preflightThenRecord(page);
    await recordEpisode(page, 'w', 200);
    const s = JSON.parse(sixtySecondSession(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')), 10));
    // An eleventh episode, 30 s in, under way when the tab reloaded.
    s.in_progress = { ...s.episodes[0].episode, runs: s.episodes[0].episode.runs.slice(0, 2) };
    await storeSessionOnNextLoad(context, JSON.stringify(s));
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    const loading = await page.evaluate(() => document.querySelector('[data-tele="loading"]').textContent);
    await page.locator('[data-tele="restored"]').waitFor({ state: 'visible', timeout: 20000 });
    assert.match(loading, /^Checking the recorded episodes of your stored session… \d+ %$/);
    assert.equal(await page.locator('[data-tele="loading"]').isHidden(), true);
    assert.equal(await page.locator('.tele [inert]').count(), 0, 'the page takes input again');
    // The session intact: ten 60 s episodes labelled FAILURE / timeout, and the one cut off
    // kept, interrupted, offered for labelling.
    const rows = page.locator('[data-tele="episodes"] tbody tr');
    assert.equal(await rows.count(), 11);
    for (let i = 0; i < 10; i++) assert.match(await rows.nth(i).innerText(), /FAILURE[\s\S]*timeout[\s\S]*60(\.00)? s/);
    assert.match(await rows.nth(10).innerText(), /30(\.00)? s/);
    const panel = page.locator('[data-tele="label-panel"]');
    await panel.waitFor({ state: 'visible' });
    assert.match(await panel.innerText(), /interrupted/);
    assert.equal(await page.locator('[data-category="operator-abort"]').getAttribute('aria-pressed'), 'true');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a stored session that no longer replays (loaded in slices): a new session for the same pilot, said so, the stored text kept aside', async () => {
  const { page, context, errors, close } = await openCounted();
  try {
    await preflightThenRecord(page);
    await recordEpisode(page, 'w', 200);
    const s = JSON.parse(sixtySecondSession(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')), 10));
    s.pilot_id = 'ana-7';
    // The last episode's start is not the configuration's any more: it does not replay.
    assert.ok(Array.isArray(s.episodes[9].episode.start.q), JSON.stringify(Object.keys(s.episodes[9].episode.start)));
    s.episodes[9].episode.start.q[0] += 0.25;
    const text = JSON.stringify(s);
    await storeSessionOnNextLoad(context, text);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    const notice = page.locator('[data-tele="restored"]');
    await notice.waitFor({ state: 'visible', timeout: 20000 });
    assert.match(await notice.innerText(), /could not be checked again[\s\S]*bsv\.teleop\.session\.unreadable/);
    assert.equal(await page.locator('.tele [inert]').count(), 0, 'the page takes input again');
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 0);
    // The same pilot in the settings and in the new session; the stored text kept as it was.
    assert.equal(await page.locator('[data-field="pilot"]').inputValue(), 'ana-7');
    assert.equal(await page.evaluate(() => localStorage.getItem('bsv.teleop.session.unreadable')), text);
    await page.evaluate(() => window.dispatchEvent(new Event('pagehide')));
    const saved = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')));
    assert.equal(saved.pilot_id, 'ana-7');
    assert.equal(saved.episodes.length, 0);
    // Japanese says it too.
    await page.click('[data-testid="lang-switch"]');
    assert.match(await notice.innerText(), /再確認できませんでした/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a second session after an exported first: the comparison keeps the first, the files are the second\'s, a reload keeps both', async () => {
  const { page, errors, close } = await open();
  const dir = mkdtempSync(join(tmpdir(), 'bsv-teleop-second-'));
  try {
    await preflightThenRecord(page);
    await recordEpisode(page, 'w', 300);
    const firstCsv = await download(page, 'teleop_episode_1.csv');
    const first = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    assert.equal(first.episodes.attempted, 1);
    // The repeatability table is its module's only.
    assert.ok(!(await page.locator('[data-tele="repeat"]').isVisible()));
    await page.locator('[data-module="repeatability"]').click();
    assert.ok(await page.locator('[data-tele="repeat"]').isVisible());
    // Start the second session: Record ten, no episodes, the first kept for the comparison.
    await page.locator('[data-action="second-session"]').click();
    assert.equal(await page.locator('[data-tele="status"]').innerText(), 'The second session started at Record ten; the first is kept for the comparison.');
    assert.equal(await page.locator('[data-module="record-ten"]').getAttribute('aria-current'), 'step');
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 0);
    assert.equal((await shownReadouts(page)).episode, '1 / 10');
    const cell = (id, col) => page.locator(`[data-tele="compare"] [data-compare="${id}"] td:nth-child(${col})`).innerText();
    assert.equal(await cell('attempted', 2), '1');
    assert.equal(await cell('attempted', 3), '0');
    // Its first episode (Q instead of W): its own files.
    await recordEpisode(page, 'q', 300);
    assert.equal(await cell('attempted', 3), '1');
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 1);
    const secondCsv = await download(page, 'teleop_episode_1.csv');
    assert.notEqual(sha256(secondCsv), sha256(firstCsv), 'episode 1 of the second session is its own');
    const file = join(dir, 'teleop_episode_1.csv');
    writeFileSync(file, secondCsv);
    execFileSync(BSV, ['teleop-replay', file], { encoding: 'utf8' });
    const second = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    checkEvidence(second);
    assert.equal(second.episodes.attempted, 1);
    assert.deepEqual(second.dataArtifacts.map((a) => a.uriOrRef), ['teleop_episodes.csv', 'teleop_episode_1.csv']);
    assert.equal(second.dataArtifacts[1].sha256, sha256(secondCsv));
    assert.equal(second.pilotId, first.pilotId);
    assert.ok(Date.parse(second.startedAt) >= Date.parse(first.endedAt), `${second.startedAt} after ${first.endedAt}`);
    assert.equal(second.metrics.preflightResetVerified, true, 'the preflight carries over');
    // A reload keeps both sessions.
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.locator('[data-tele="restored"]').waitFor({ state: 'visible' });
    assert.equal(await cell('attempted', 2), '1');
    assert.equal(await cell('attempted', 3), '1');
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 1);
    // New session: the second becomes the first; the new one starts at preflight, empty.
    await page.locator('[data-action="new-session"]').click();
    assert.equal(await page.locator('[data-tele="status"]').innerText(), 'A new session started; the previous one is kept as the first session for the comparison.');
    assert.equal(await page.locator('[data-module="preflight"]').getAttribute('aria-current'), 'step');
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 0);
    assert.equal(await cell('attempted', 2), '1');
    assert.equal(await cell('attempted', 3), '0');
    const third = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    assert.equal(third.episodes.attempted, 0);
    assert.deepEqual(third.dataArtifacts.map((a) => a.uriOrRef), ['teleop_episodes.csv']);
    assert.deepEqual(errors, []);
  } finally {
    rmSync(dir, { recursive: true, force: true });
    await close();
  }
});

// ---- A new pilot's first session: the pad offered, closed modules explained, a success
// counted at once and shown over the arm view, storage full ----

/** A fresh page at `hash` with an injected standard gamepad (window.__testPad, at rest). */
async function openWithPad(hash, viewport = { width: 1366, height: 768 }) {
  const context = await (await browser()).newContext({ viewport, locale: 'en-US', acceptDownloads: true, deviceScaleFactor: 1 });
  await injectPad(context);
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${server.url}/${hash}`);
  await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
  return { page, errors, close: () => context.close() };
}

/** The left stick pushed up (`value` of full, +x) for `ms`, then released. */
async function padPush(page, value, ms) {
  await page.evaluate((v) => { window.__testPad.axes[1] = -v; }, value);
  await page.waitForTimeout(ms);
  await page.evaluate(() => { window.__testPad.axes[1] = 0; });
}

/** Preflight with the gamepad (chosen, moved, a checked reset), then Record ten. */
async function padPreflightThenRecord(page) {
  await page.locator('[data-device="gamepad"]').click();
  await padPush(page, 0.5, 250);
  await page.keyboard.press('r');
  assert.equal(await page.locator('[data-check="reset"]').getAttribute('data-state'), 'done');
  await page.locator('[data-module="record-ten"]').click();
}

/** Drives the pad through the reach task's six default targets (a steady pilot: a proportional
 * pull towards each target's centre, the next one after 300 ms inside 2 mm) until the episode's
 * outcome shows; its text. */
async function padReachToSuccess(page) {
  return page.evaluate(() => {
    const targets = [[0.17, 0.04], [0.04, 0.12], [0.12, 0.09], [0.03, 0.02], [0.19, -0.01], [-0.10, 0.08]];
    const pad = window.__testPad;
    const read = (k) => Number(document.querySelector(`[data-readout="${k}"]`).textContent);
    const outcome = document.querySelector('[data-testid="episode-outcome"]');
    const pull = (v) => Math.max(-1, Math.min(1, v / 0.03));
    let i = 0;
    let inside = null;
    const t0 = performance.now();
    return new Promise((resolve, reject) => {
      const tick = (now) => {
        if (!outcome.hidden || now - t0 > 50000) {
          pad.axes[1] = 0;
          pad.axes[3] = 0;
          if (outcome.hidden) reject(new Error(`no outcome after 50 s (target ${i})`));
          else resolve(outcome.textContent);
          return;
        }
        const [tx, tz] = targets[Math.min(i, targets.length - 1)];
        const ex = tx - read('x');
        const ez = tz - read('z');
        pad.axes[1] = -pull(ex);
        pad.axes[3] = -pull(ez);
        if (Math.hypot(ex, ez) < 0.002) {
          inside ??= now;
          if (now - inside > 300) {
            i++;
            inside = null;
          }
        } else inside = null;
        requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    });
  });
}

/** The bounding box of `sel`, rounded: { x, y, width, height }. */
async function boxOf(page, sel) {
  const b = await page.locator(sel).boundingBox();
  return Object.fromEntries(Object.entries(b).map(([k, v]) => [k, Math.round(v)]));
}

test('a gamepad that sends input is offered at once, never switched to by itself (EN/JA)', async () => {
  const { page, errors, close } = await openWithPad('#/teleop');
  try {
    const offer = page.locator('[data-testid="gamepad-offer"]');
    assert.ok(await offer.isHidden(), 'a pad at rest is not offered');
    // The pad sends input while the keyboard is chosen: offered, not switched to.
    await page.evaluate(() => { window.__testPad.axes[1] = -0.5; });
    await offer.waitFor({ state: 'visible' });
    assert.equal(await offer.getAttribute('role'), 'status');
    assert.match(await offer.innerText(), /The gamepad “Test Pad \(STANDARD GAMEPAD\)” is sending input\. Use it for this session\?/);
    await page.waitForTimeout(300);
    await page.evaluate(() => { window.__testPad.axes[1] = 0; });
    assert.equal(await page.locator('[data-device="keyboard"]').getAttribute('aria-checked'), 'true');
    assert.equal(await page.locator('[data-device="gamepad"]').getAttribute('aria-checked'), 'false');
    // Japanese says it too; its button switches the device.
    await page.click('[data-testid="lang-switch"]');
    assert.match(await offer.innerText(), /ゲームパッド「Test Pad \(STANDARD GAMEPAD\)」から入力があります。このセッションでこのゲームパッドを使いますか？/);
    assert.equal(await page.locator('[data-action="use-gamepad"]').innerText(), 'このゲームパッドを使う');
    await page.locator('[data-action="use-gamepad"]').click();
    assert.equal(await page.locator('[data-device="gamepad"]').getAttribute('aria-checked'), 'true');
    assert.ok(await offer.isHidden());
    assert.match(await page.locator('[data-tele="device-status"]').innerText(), /Test Pad/);
    assert.equal(await page.locator('[data-field="pos_sensitivity"]').inputValue(), '1', 'the gamepad\'s sensitivity');
    await padPush(page, 0.5, 250);
    assert.ok(await offer.isHidden(), 'no offer while the gamepad is in use');
    assert.equal(await page.locator('[data-check="moved"]').getAttribute('data-state'), 'done');
    // Back to the keyboard: offered again; "Not now" keeps the keyboard and the offer away.
    await page.click('[data-testid="lang-switch"]');
    await page.locator('[data-device="keyboard"]').click();
    await page.evaluate(() => { window.__testPad.axes[3] = -0.5; });
    await offer.waitFor({ state: 'visible' });
    await page.evaluate(() => { window.__testPad.axes[3] = 0; });
    await page.locator('[data-action="dismiss-gamepad"]').click();
    assert.ok(await offer.isHidden());
    await padPush(page, 0.5, 300);
    assert.ok(await offer.isHidden(), 'declined: not offered again for this pad');
    assert.equal(await page.locator('[data-device="keyboard"]').getAttribute('aria-checked'), 'true');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a closed module says what opens it, visibly and in its accessible description', async () => {
  const { page, errors, close } = await open();
  try {
    /** The closed module's line: shown, and the module's (and Next module's) description. */
    const why = async (module) => {
      const button = page.locator(`[data-module="${module}"]`);
      assert.equal(await button.getAttribute('aria-disabled'), 'true', module);
      const id = await button.getAttribute('aria-describedby');
      assert.ok(id, `${module} has a description`);
      const line = page.locator(`#${id}`);
      assert.ok(await line.isVisible(), `${module}: its line is visible`);
      assert.equal(await line.getAttribute('data-testid'), `module-unlock-${module}`);
      return line.innerText();
    };
    assert.equal(await why('record-ten'), 'Finish the preflight: move the arm, then do a checked reset (R).');
    assert.equal(await why('failure-review'), 'Opens once an episode is recorded in Record ten.');
    assert.equal(await why('repeatability'), 'Opens once an episode is recorded in Record ten.');
    for (const open of ['preflight', 'basic-control']) {
      assert.equal(await page.locator(`[data-module="${open}"]`).getAttribute('aria-describedby'), null);
      assert.ok(await page.locator(`[data-testid="module-unlock-${open}"]`).isHidden());
    }
    // In Basic control, Next module (closed) is described by Record ten's line.
    await page.locator('[data-module="basic-control"]').click();
    assert.equal(await page.locator('[data-action="next-module"]').getAttribute('aria-disabled'), 'true');
    assert.equal(await page.locator('[data-action="next-module"]').getAttribute('aria-describedby'), 'tele-why-record-ten');
    // The line follows the preflight: moved, then only the checked reset is left.
    await page.locator('[data-module="preflight"]').click();
    await canvas(page).focus();
    await hold(page, 'w', 250);
    assert.equal(await why('record-ten'), 'Finish the preflight: do a checked reset (R).');
    // Japanese.
    await page.click('[data-testid="lang-switch"]');
    assert.equal(await why('record-ten'), '先に事前点検を：R で確認付きのリセットをします。');
    assert.equal(await why('failure-review'), '「10 回記録」でエピソードを 1 つ記録すると開きます。');
    await page.click('[data-testid="lang-switch"]');
    // The reset opens Record ten: its line goes.
    await canvas(page).focus();
    await page.keyboard.press('r');
    const record = page.locator('[data-module="record-ten"]');
    assert.equal(await record.getAttribute('aria-disabled'), 'false');
    assert.equal(await record.getAttribute('aria-describedby'), null);
    assert.ok(await page.locator('[data-testid="module-unlock-record-ten"]').isHidden());
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a success counts at once, its outcome over the arm view; the session line reads right in EN and JA', async () => {
  const { page, errors, close } = await openWithPad('#/teleop?task=reach');
  try {
    // The keys work without a click on the arm view, and the hint says so.
    assert.doesNotMatch(await page.locator('[data-tele="device-status"]').innerText(), /click/i);
    const x0 = Number((await shownReadouts(page)).x);
    await hold(page, 'w', 250);
    const x1 = Number((await shownReadouts(page)).x);
    assert.ok(x1 > x0 + 0.01, `W moves the tip with the page focused: ${x0} → ${x1}`);
    await page.locator('[data-device="keyboard"]').click();
    await hold(page, 'w', 250);
    const x2 = Number((await shownReadouts(page)).x);
    assert.ok(x2 > x1 + 0.01, `W moves the tip with a button focused: ${x1} → ${x2}`);
    await padPreflightThenRecord(page);
    const text = await padReachToSuccess(page);
    assert.match(text, /^Success in \d+\.\d\d s\. Recorded as episode 1 and counted as a SUCCESS \(relabel it below if it was not\); R \(Reset\) starts the next one\.$/);
    const outcome = page.locator('[data-testid="episode-outcome"]');
    assert.equal(await outcome.getAttribute('data-outcome'), 'success');
    assert.equal(await outcome.getAttribute('data-tele'), 'ended');
    // Over the arm view, in the first screen at 1366×768.
    const o = await boxOf(page, '[data-testid="episode-outcome"]');
    const c = await boxOf(page, '[data-testid="teleop-canvas"]');
    assert.ok(o.x >= c.x && o.y >= c.y && o.x + o.width <= c.x + c.width && o.y + o.height <= c.y + c.height, `outcome ${JSON.stringify(o)} in the arm view ${JSON.stringify(c)}`);
    assert.ok(o.y + o.height <= 768, `outcome in the first screen: ${JSON.stringify(o)}`);
    await page.screenshot({ path: join(OUT, 'teleop-success-en-1366.png') });
    // Counted at once: the line, the table, the label panel (SUCCESS preselected), the evidence.
    const line = page.locator('[data-tele="session-line"]');
    assert.equal(await line.innerText(), 'Pilot id “pilot”: 1 episode recorded (aim: 10), 1 successful.');
    assert.match(await page.locator('[data-tele="episodes"] tbody tr').first().innerText(), /^1\s+SUCCESS/);
    assert.equal(await page.locator('[data-label="SUCCESS"]').getAttribute('aria-pressed'), 'true');
    const doc = JSON.parse((await download(page, 'teleop_session_evidence.json')).toString('utf8'));
    checkEvidence(doc);
    assert.deepEqual(doc.episodes, { attempted: 1, successful: 1, failed: 0, recoveryEpisodes: 0 });
    assert.equal(doc.inputDevice, 'gamepad');
    const table = (await download(page, 'teleop_episodes.csv')).toString('utf8').trim().split('\n');
    assert.match(table[1], /^1,reach,SUCCESS,,,0,success,/);
    // A second episode, ended by the pilot: not counted as a success; plurals.
    await page.keyboard.press('r');
    assert.ok(await outcome.isHidden(), 'a reset hides the outcome');
    await padPush(page, 0.5, 200);
    await page.locator('[data-action="end-episode"]').click();
    assert.match(await outcome.innerText(), /^Episode ended\. Recorded as episode 2: label it below; R \(Reset\) starts the next one\.$/);
    assert.equal(await line.innerText(), 'Pilot id “pilot”: 2 episodes recorded (aim: 10), 1 successful.');
    await page.click('[data-testid="lang-switch"]');
    assert.equal(await line.innerText(), 'パイロット ID「pilot」：2 エピソードを記録（目標 10）、うち成功 1。');
    assert.match(await outcome.innerText(), /^エピソードを終了しました。エピソード 2 として記録しました。/);
    assert.doesNotMatch(await page.locator('[data-tele="device-status"]').innerText(), /クリック/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('on a phone (390×844, JA) the arm view is on the first screen, the outcome over it', async () => {
  const { page, errors, close } = await openWithPad('#/teleop?task=reach&lang=ja', { width: 390, height: 844 });
  try {
    const c0 = await boxOf(page, '[data-testid="teleop-canvas"]');
    assert.ok(c0.y < 844, `the arm view starts in the first screen: ${JSON.stringify(c0)}`);
    assert.ok(c0.y + c0.height <= 844, `the whole arm view in the first screen: ${JSON.stringify(c0)}`);
    const width = await page.evaluate(() => document.documentElement.scrollWidth);
    assert.ok(width <= 390, `no horizontal scroll (${width})`);
    await padPreflightThenRecord(page);
    assert.ok((await boxOf(page, '[data-testid="teleop-canvas"]')).y < 844, 'still in Record ten');
    const text = await padReachToSuccess(page);
    assert.match(text, /^\d+\.\d\d 秒で成功しました。エピソード 1 として記録し、成功 \(SUCCESS\) に数えました/);
    const o = await boxOf(page, '[data-testid="episode-outcome"]');
    const c = await boxOf(page, '[data-testid="teleop-canvas"]');
    assert.ok(o.y >= c.y && o.y + o.height <= c.y + c.height && o.y + o.height <= 844, `outcome ${JSON.stringify(o)} over the arm view ${JSON.stringify(c)}`);
    assert.equal(await page.locator('[data-tele="session-line"]').innerText(), 'パイロット ID「pilot」：1 エピソードを記録（目標 10）、うち成功 1。');
    await page.screenshot({ path: join(OUT, 'teleop-success-ja-390.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('storage full while recording: the recording goes on, the page says it is not saved and offers the files (EN/JA)', async () => {
  const { page, errors, close } = await open();
  try {
    await preflightThenRecord(page);
    const stored = await page.evaluate(() => localStorage.getItem('bsv.teleop.session'));
    // From now on the browser's storage is full.
    await page.evaluate(() => {
      window.__realSetItem = Storage.prototype.setItem;
      Storage.prototype.setItem = function setItem() {
        throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
      };
    });
    const warning = page.locator('[data-testid="storage-warning"]');
    assert.ok(await warning.isHidden());
    await recordEpisode(page, 'w', 300);
    await warning.waitFor({ state: 'visible' });
    assert.equal(await warning.getAttribute('role'), 'alert');
    assert.match(await warning.innerText(), /^Not saved: this browser refused to store the session \(its storage is full or turned off\)\. The recording goes on in this tab/);
    assert.equal(await page.locator('[data-testid="storage-download-episodes"]').innerText(), 'Download the episode\'s CSV');
    // Recording goes on: a second episode, nothing dropped.
    await recordEpisode(page, 'q', 300);
    assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 2);
    assert.equal(await page.locator('[data-testid="storage-download-episodes"]').innerText(), 'Download the 2 episode CSVs');
    assert.equal(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')), stored, 'the store is as it was');
    // The warning's downloads: the evidence, the table, every episode's CSV.
    const saved = async (testid, count = 1) => {
      const files = [];
      const arrived = new Promise((resolve) => {
        const onDownload = async (d) => {
          files.push({ name: d.suggestedFilename(), bytes: readFileSync(await d.path()) });
          if (files.length === count) {
            page.off('download', onDownload);
            resolve();
          }
        };
        page.on('download', onDownload);
      });
      await page.locator(`[data-testid="${testid}"]`).click();
      await arrived;
      return files;
    };
    const [evidence] = await saved('storage-download-evidence');
    assert.equal(evidence.name, 'teleop_session_evidence.json');
    const doc = JSON.parse(evidence.bytes.toString('utf8'));
    checkEvidence(doc);
    assert.equal(doc.episodes.attempted, 2);
    const [table] = await saved('storage-download-table');
    assert.equal(table.name, 'teleop_episodes.csv');
    assert.equal(table.bytes.toString('utf8').trim().split('\n').length, 3);
    const csvs = await saved('storage-download-episodes', 2);
    assert.deepEqual(csvs.map((f) => f.name).sort(), ['teleop_episode_1.csv', 'teleop_episode_2.csv']);
    const listed = Object.fromEntries(doc.dataArtifacts.map((a) => [a.uriOrRef, a.sha256]));
    for (const f of csvs) assert.equal(listed[f.name], sha256(f.bytes), f.name);
    // Japanese.
    await page.click('[data-testid="lang-switch"]');
    assert.match(await warning.innerText(), /^保存されていません：このブラウザがセッションを保存できませんでした/);
    assert.equal(await page.locator('[data-testid="storage-download-episodes"]').innerText(), 'エピソードの CSV（2 件）をダウンロード');
    await page.click('[data-testid="lang-switch"]');
    // Storage back: the next save stores everything and the warning goes.
    await page.evaluate(() => { Storage.prototype.setItem = window.__realSetItem; });
    await canvas(page).focus();
    await page.keyboard.press('r');
    await warning.waitFor({ state: 'hidden' });
    const back = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')));
    assert.equal(back.episodes.length, 2);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

for (const lang of ['en', 'ja']) {
  test(`a stored session waits for the code that reads it; if it cannot be fetched a line says so with Retry, the session kept (${lang})`, async () => {
    const { page, context, errors, close } = await open(`#/teleop?lang=${lang}`);
    try {
      await preflightThenRecord(page);
      await recordEpisode(page, 'w', 200);
      const stored = await page.evaluate(() => localStorage.getItem('bsv.teleop.session'));
      assert.ok(stored, 'the episode is stored');
      // The code that reads the stored session (the files' chunk) cannot be fetched.
      const pattern = /\/pkg\/(pack_teleop_files(-after-\w+)?\.bin|chunks\/split_teleop_files\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const line = page.locator('[data-testid="late-page"]');
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      assert.equal(await line.getAttribute('role'), 'alert');
      assert.match(await line.innerText(), lang === 'en' ? /reads your stored session could not be loaded/ : /読み込めませんでした/);
      // The page waits, inert, and nothing is lost or overwritten.
      assert.ok(await canvas(page).evaluate((c) => c.closest('[inert]') !== null), 'the page is inert while it waits');
      assert.equal(await page.locator('#app-main').getAttribute('aria-busy'), 'true');
      await page.keyboard.press('w');
      assert.equal(await page.evaluate(() => localStorage.getItem('bsv.teleop.session')), stored);
      await page.setViewportSize({ width: 390, height: 844 });
      await page.screenshot({ path: join(OUT, `teleop-restore-failed-${lang}-390.png`) });
      // Still unreachable: Retry fails again, visibly; then reachable: the session comes back.
      await line.locator('[data-action="retry"]').click();
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      await context.unroute(pattern);
      await line.locator('[data-action="retry"]').click();
      await page.locator('[data-tele="restored"]').waitFor({ state: 'visible', timeout: 15000 });
      assert.equal(await line.count(), 0, 'the line goes with the waiting page');
      assert.equal(await page.locator('#app-main').getAttribute('aria-busy'), null);
      assert.equal(await page.locator('[data-tele="episodes"] tbody tr').count(), 1);
      assert.equal(await canvas(page).evaluate((c) => c.closest('[inert]') === null), true);
      assert.deepEqual(errors.filter((e) => !/Failed to load resource/.test(e)), []);
    } finally {
      await close();
    }
  });
}

test('a stored session is read before the page is live: the restored episodes are shown once it is', async () => {
  const { page, close, errors } = await open();
  try {
    await preflightThenRecord(page);
    await recordEpisode(page, 'w', 200);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    // Settled means built: the stored session is already on screen.
    assert.ok(await page.locator('[data-tele="restored"]').isVisible());
    assert.equal(await page.locator('[data-testid="late-page"]').count(), 0);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
