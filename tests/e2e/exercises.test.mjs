// Exercises ("predict, then check") in headless Chromium, English and Japanese: every page with
// exercises lists them once its section comes into view; a bad number is refused beside the
// field and a far-off prediction is marked wrong, then the hint shows; the five required goals
// (ik-singular, pendulum-euler-dt, pid-tune, trap-triangle, rrt-300) are met by driving the
// pages and stay done after a reload; a goal the page's link alone meets is not recorded until
// the learner changes the page; bsv_progress.json exported and imported back round-trips; the
// home page shows each page's progress; #/class with three learners' files and a broken one
// shows three rows and names the broken file.
// Pages load in parallel (one context each) to keep the file under about a minute.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { serveApp, OUT, openApp } from './harness.mjs';
import { englishStrings } from './locales.mjs';
import { violations } from './axe.mjs';

const server = serveApp();

/** Each page with exercises and its exercises' ids, in the order it lists them. */
const PAGES = {
  'ik-2r': ['ik-singular', 'ik-w-pose', 'ik-best-elbow', 'ik-singular-where'],
  'dh-fk': ['dh-tip-height', 'dh-raise', 'dh-q3-origin'],
  'se3-relative': ['se3-distance', 'se3-ahead', 'se3-swap'],
  'umeyama-2d': ['umeyama-angle', 'umeyama-exact', 'umeyama-mirror'],
  'pendulum-energy': ['pendulum-euler-dt', 'pendulum-period', 'pendulum-integrator', 'pendulum-over-top'],
  'pid-step': ['pid-tune', 'pid-final-y', 'pid-p-only', 'pid-overshoot'],
  'cubic-path': ['cubic-peak-velocity', 'cubic-speed-limit', 'cubic-peak-accel'],
  'trapezoid-profile': ['trap-triangle', 'trap-accel-end', 'trap-total-time', 'trap-short-peak'],
  'traj-resample': ['traj-rows', 'traj-miss-peak', 'traj-between'],
  'rrt-2d': ['rrt-300', 'rrt-path-length', 'rrt-corner', 'rrt-wall'],
  teleop: ['teleop-near-singular', 'teleop-which-joint', 'teleop-calm-method'],
  so101: ['so101-low-w', 'so101-pan', 'so101-five-joints'],
};

const card = (page, id) => page.locator(`[data-exercise="${id}"]`);
const stateOf = (page, id) => card(page, id).getAttribute('data-exercise-state');

/** Waits until exercise `id` is in state `state`. */
async function waitState(page, id, state, timeout = 10000) {
  await page.waitForFunction(
    ([id, state]) => document.querySelector(`[data-exercise="${id}"]`)?.dataset.exerciseState === state,
    [id, state],
    { timeout },
  );
}

/** Brings the exercises section into view and waits for its cards. */
async function showExercises(page) {
  await page.locator('[data-testid="exercises"]').scrollIntoViewIfNeeded();
  await page.locator('[data-testid="exercises"] [data-exercise]').first().waitFor({ timeout: 20000 });
}

/** Opens `hash` in a fresh context with its exercises shown. */
async function openWithExercises(hash, options = {}) {
  const app = await openApp(server.url, hash, options);
  await showExercises(app.page);
  return app;
}

/** The page's stored progress record. */
const stored = (page) => page.evaluate(() => JSON.parse(localStorage.getItem('bsv.progress') ?? 'null'));

test('every page with exercises lists them, with their state, in its own section (English and Japanese)', async () => {
  const english = englishStrings();
  // One tab per language, going from page to page as a learner would.
  const one = async (lang) => {
    const { page, errors, close } = await openApp(server.url, `#/?lang=${lang}`, { viewport: { width: 1280, height: 720 } });
    try {
      for (const [route, expected] of Object.entries(PAGES)) {
        await page.evaluate((hash) => { location.hash = hash; }, `#/${route}?lang=${lang}`);
        const section = page.locator('[data-testid="exercises"]');
        await section.waitFor({ timeout: 20000 });
        await section.scrollIntoViewIfNeeded();
        await page.locator(`[data-exercise="${expected[0]}"]`).waitFor({ timeout: 20000 });
        assert.equal(await section.getAttribute('data-section'), 'exercises');
        const ids = await section.locator('[data-exercise]').evaluateAll((els) => els.map((e) => e.dataset.exercise));
        assert.deepEqual(ids, expected, route);
        const states = await section.locator('[data-exercise]').evaluateAll((els) => els.map((e) => e.dataset.exerciseState));
        assert.ok(states.every((s) => s === 'open'), `${route}: ${states}`);
        const heading = await section.locator('h2').first().innerText();
        assert.equal(heading, lang === 'en' ? 'Exercises' : '演習', route);
        const text = await section.innerText();
        assert.match(text, lang === 'en' ? /Predict first, then check/ : /まず予想し/);
        if (lang === 'ja') for (const s of english) assert.ok(!text.includes(s), `${route}: English "${s}" on a Japanese page`);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  };
  await Promise.all([one('en'), one('ja')]);
});

for (const [lang, route, id, readout] of [['en', 'pid-step', 'pid-final-y', 'final-y'], ['ja', 'pendulum-energy', 'pendulum-euler-dt', 'drift']]) {
  test(`a bad number is refused beside its field; a far-off prediction is wrong, then the hint shows (${lang})`, async () => {
    const { page, errors, close } = await openWithExercises(`#/${route}?lang=${lang}`, { viewport: { width: 412, height: 823 } });
    try {
      const field = card(page, id).locator('[data-field="prediction"]');
      const commit = card(page, id).locator('[data-action="commit"]');
      const hint = card(page, id).locator('[data-part="hint"]');
      assert.equal(await hint.isVisible(), false);
      await field.fill('abc');
      assert.equal(await stateOf(page, id), 'predicting');
      await commit.click();
      const error = card(page, id).locator('[data-part="error"]');
      await error.waitFor();
      assert.match(await error.innerText(), lang === 'en' ? /not a number/ : /数値ではありません/);
      assert.equal(await field.getAttribute('aria-invalid'), 'true');
      assert.equal(await stateOf(page, id), 'predicting', 'a refused number is no try');
      await field.fill('1e9');
      await commit.click();
      await waitState(page, id, 'wrong');
      assert.ok(await hint.isVisible(), 'the hint shows after a wrong try');
      // The readout that shows the answer is blurred while the learner predicts.
      const answer = page.locator(`[data-readout="${readout}"]`).first();
      assert.equal(await answer.getAttribute('data-ex-hidden'), '');
      assert.equal(await answer.getAttribute('aria-hidden'), 'true');
      assert.match(await card(page, id).locator('[data-part="verdict"]').innerText(), lang === 'en' ? /too high/ : /大きすぎます/);
      // The second wrong try reveals the answer and its explanation.
      await field.fill('-1e9');
      await commit.click();
      await waitState(page, id, 'revealed');
      assert.ok(await card(page, id).locator('[data-part="explain"]').isVisible());
      assert.equal(await answer.getAttribute('data-ex-hidden'), null, 'shown again with the answer');
      const record = await stored(page);
      assert.deepEqual(record.exercises.find((e) => e.id === id), { id, attempts: 2, firstTryRight: false, done: false });
      await page.screenshot({ path: join(OUT, `exercises-wrong-${lang}-412.png`) });
      assert.deepEqual(await violations(page, route), []);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

/** Where world point (x, y) of the RRT's square is on its canvas (14 px margin). */
async function rrtPoint(page, [x, y]) {
  const box = await page.locator('[data-testid="rrt-2d-canvas"]').boundingBox();
  const side = Math.min(box.width, box.height) - 28;
  return { x: box.x + (box.width - side) / 2 + x * side, y: box.y + (box.height - side) / 2 + (1 - y) * side };
}

/** The five required goals, each driven on its page. */
const DRIVE = {
  // q2 from 0.8 rad to 0.05 rad with the keys (Shift + - turns it 0.1 rad, - 0.01 rad).
  'ik-2r': ['ik-singular', async (page) => {
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    for (let k = 0; k < 7; k++) await page.keyboard.press('Shift+Minus');
    for (let k = 0; k < 5; k++) await page.keyboard.press('Minus');
  }],
  // Euler's drift at the page's step: 0.0015066 % of E(0).
  'pendulum-energy': ['pendulum-euler-dt', async (page) => {
    await card(page, 'pendulum-euler-dt').locator('[data-field="prediction"]').fill('0.0015');
    await card(page, 'pendulum-euler-dt').locator('[data-action="commit"]').click();
  }],
  'pid-step': ['pid-tune', async (page) => {
    await page.locator('[data-action="pid-tuned"]').click();
  }],
  'trapezoid-profile': ['trap-triangle', async (page) => {
    await page.locator('[data-field="distance"]').fill('0.2');
    await page.locator('[data-field="distance"]').press('Enter');
  }],
  // The box moved right and up: seed 7 needs 465 iterations.
  'rrt-2d': ['rrt-300', async (page) => {
    await page.evaluate(() => document.querySelector('[data-testid="rrt-2d-canvas"]').scrollIntoView({ block: 'center' }));
    const a = await rrtPoint(page, [0.5, 0.5]);
    const b = await rrtPoint(page, [0.715, 0.65]);
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(a.x + ((b.x - a.x) * k) / 8, a.y + ((b.y - a.y) * k) / 8);
    await page.mouse.up();
  }],
};

test('the five required goals are met by driving the pages, and stay done after a reload', async () => {
  const one = async ([route, [id, drive]]) => {
    const { page, errors, close } = await openWithExercises(`#/${route}`, { viewport: { width: 1280, height: 900 } });
    try {
      assert.equal(await stateOf(page, id), 'open', route);
      await drive(page);
      await waitState(page, id, id === 'pendulum-euler-dt' ? 'right' : 'done');
      const record = (await stored(page)).exercises.find((e) => e.id === id);
      assert.deepEqual(record, { id, attempts: 1, firstTryRight: true, done: true }, route);
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      await showExercises(page);
      assert.equal(await stateOf(page, id), 'done', `${route} after a reload`);
      assert.deepEqual(errors, [], route);
    } finally {
      await close();
    }
  };
  await Promise.all(Object.entries(DRIVE).slice(0, 3).map(one));
  await Promise.all(Object.entries(DRIVE).slice(3).map(one));
});

test('a goal the link alone meets shows as met and is recorded once the learner changes the page', async () => {
  const { page, errors, close } = await openWithExercises('#/trapezoid-profile?distance=0.2');
  try {
    await page.waitForFunction(() => /link opened it/.test(document.querySelector('[data-exercise="trap-triangle"] [data-part="verdict"]')?.textContent));
    assert.equal(await stateOf(page, 'trap-triangle'), 'open');
    assert.equal(await stored(page), null, 'nothing recorded');
    // Another step keeps the triangle: the learner's change counts it.
    await page.locator('[data-field="dt"]').fill('0.005');
    await page.locator('[data-field="dt"]').press('Enter');
    await waitState(page, 'trap-triangle', 'done');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('bsv_progress.json exported with the learner\'s name and imported back round-trips', async () => {
  const start = {
    format: 'bsv-progress', version: 1, build: 'test',
    exercises: [
      { id: 'pid-overshoot', attempts: 2, firstTryRight: false, done: true },
      { id: 'pid-tune', attempts: 1, firstTryRight: true, done: true },
      { id: 'some-later-exercise', attempts: 1, firstTryRight: true, done: true },
    ],
  };
  const { page, errors, close } = await openApp(server.url, '#/pid-step');
  try {
    await page.evaluate((start) => localStorage.setItem('bsv.progress', JSON.stringify(start)), start);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await showExercises(page);
    assert.equal(await stateOf(page, 'pid-tune'), 'done');
    await page.locator('[data-field="learner-name"]').fill('Aiko');
    await page.locator('[data-field="learner-name"]').press('Tab');
    await page.waitForFunction(() => JSON.parse(localStorage.getItem('bsv.progress')).learner === 'Aiko');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="bsv_progress.json"]')]);
    assert.equal(download.suggestedFilename(), 'bsv_progress.json');
    const file = join(OUT, 'exercises-bsv_progress.json');
    await download.saveAs(file);
    const exported = JSON.parse(readFileSync(file, 'utf8'));
    assert.equal(exported.format, 'bsv-progress');
    assert.equal(exported.learner, 'Aiko');
    assert.match(exported.build, /^bsv-playground /);
    assert.deepEqual(exported.exercises, start.exercises.toSorted((a, b) => a.id.localeCompare(b.id)));
    // A fresh browser: nothing done; the import brings it all back.
    await page.evaluate(() => localStorage.removeItem('bsv.progress'));
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await showExercises(page);
    assert.equal(await stateOf(page, 'pid-tune'), 'open');
    await page.locator('[data-action="progress-import"]').setInputFiles(file);
    await waitState(page, 'pid-tune', 'done');
    assert.equal(await stateOf(page, 'pid-overshoot'), 'done');
    assert.match(await page.locator('[data-testid="progress-status"]').innerText(), /2 exercises merged/);
    assert.equal(await page.locator('[data-field="learner-name"]').inputValue(), 'Aiko');
    const [again] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="bsv_progress.json"]')]);
    const file2 = join(OUT, 'exercises-bsv_progress-2.json');
    await again.saveAs(file2);
    assert.deepEqual(JSON.parse(readFileSync(file2, 'utf8')).exercises, exported.exercises);
    // Another program's file is named with its problem; nothing changes.
    await page.locator('[data-action="progress-import"]').setInputFiles({ name: 'lesson.json', mimeType: 'application/json', buffer: Buffer.from('{"format": "bsv-lesson", "version": 2}') });
    await page.waitForFunction(() => /lesson\.json: .*not a BSV progress file/.test(document.querySelector('[data-testid="progress-status"]').textContent));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the home page shows each page\'s progress, on its tiles and in a list at its foot', async () => {
  const record = {
    format: 'bsv-progress', version: 1, build: 'test',
    exercises: ['trap-triangle', 'trap-accel-end', 'trap-total-time', 'trap-short-peak', 'pid-tune']
      .map((id) => ({ id, attempts: 1, firstTryRight: true, done: true })),
  };
  const { page, errors, close } = await openApp(server.url, '#/?lang=ja', { viewport: { width: 412, height: 823 }, storage: { 'bsv.progress': JSON.stringify(record) } });
  try {
    const list = page.locator('[data-testid="home-progress"]');
    await list.waitFor({ timeout: 20000 });
    const counts = Object.fromEntries(await list.locator('li[data-page]').evaluateAll((items) => items.map((li) => [li.dataset.page, li.querySelector('.count').textContent])));
    assert.equal(Object.keys(counts).length, Object.keys(PAGES).length);
    assert.equal(counts['trapezoid-profile'], '4 / 4');
    assert.equal(counts['pid-step'], '1 / 4');
    assert.equal(counts['ik-2r'], '0 / 4');
    assert.equal(await page.locator('[data-testid="featured-pid-step"] .featured-progress').innerText(), '1 / 4');
    assert.equal(await page.locator('[data-testid="featured-ik-2r"] .featured-progress').isVisible(), false);
    assert.ok(await list.locator('[data-download="bsv_progress.json"]').isVisible());
    assert.ok((await list.innerText()).includes('あなたの演習'));
    await list.scrollIntoViewIfNeeded();
    await page.screenshot({ path: join(OUT, 'exercises-home-ja-412.png') });
    assert.deepEqual(await violations(page, 'home'), []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** A learner's progress file. */
const progressFile = (name, learner, exercises) => ({
  name, mimeType: 'application/json',
  buffer: Buffer.from(JSON.stringify({ format: 'bsv-progress', version: 1, learner, build: 'test', exercises })),
});

for (const lang of ['en', 'ja']) {
  test(`#/class: three learners' files and a broken one give three rows and name the broken file (${lang})`, async () => {
    const { page, errors, close } = await openApp(server.url, `#/class?lang=${lang}`, { viewport: { width: 1280, height: 800 } });
    try {
      await page.locator('[data-field="class-files"]').setInputFiles([
        progressFile('aiko.json', 'Aiko', [{ id: 'pid-tune', attempts: 1, firstTryRight: true, done: true }]),
        progressFile('ken.json', 'Ken', [{ id: 'pid-tune', attempts: 2, firstTryRight: false, done: true }, { id: 'rrt-300', attempts: 1, firstTryRight: true, done: true }]),
        progressFile('sato.json', 'Sato', []),
        { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from('{"format": "bsv-progress",\n  "version": 1,,\n}') },
      ]);
      const table = page.locator('[data-testid="class-table"]');
      await table.waitFor();
      const learners = await table.locator('tbody tr').evaluateAll((rows) => rows.map((r) => r.dataset.learner));
      assert.deepEqual(learners, ['Aiko', 'Ken', 'Sato']);
      const rejected = await page.locator('[data-testid="class-rejected"] li').allInnerTexts();
      assert.equal(rejected.length, 1);
      assert.match(rejected[0], lang === 'en' ? /^broken\.json: .*line 2, column 16/ : /^broken\.json：.*2 行目、16 文字目/);
      // The hardest first: pid-tune (done by two of three) is the last column.
      const columns = await table.locator('thead th[data-exercise]').evaluateAll((ths) => ths.map((t) => t.dataset.exercise));
      assert.equal(columns.at(-1), 'pid-tune');
      assert.equal(await table.locator('tr[data-learner="Ken"] td[data-exercise="pid-tune"]').getAttribute('data-standing'), 'later');
      const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="class_summary.csv"]')]);
      assert.equal(download.suggestedFilename(), 'class_summary.csv');
      const csv = readFileSync(await download.path(), 'utf8').trim().split('\r\n');
      assert.equal(csv.filter((l) => l.startsWith('learner,')).length, 3);
      assert.match(csv.at(-1), /^success_rate,,,.*,66\.7$/);
      await page.screenshot({ path: join(OUT, `exercises-class-${lang}-1280.png`), fullPage: true });
      assert.deepEqual(await violations(page, 'class'), []);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}
