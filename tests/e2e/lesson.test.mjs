// Lessons: built from three pages with "+ Lesson", edited, exported, imported (a bad file is
// named and the lesson kept), and presented with PageDown: each step shows the state of its
// permalink (same readouts), and a step that asks for it first steps the page's stepper.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { serveApp, OUT, openApp, readouts } from './harness.mjs';

const server = serveApp();

const ROUTES = ['#/pid-step?Kp=2&Ki=0.1', '#/rrt-2d?seed=11&it=0', '#/ik-2r?q1=0.3&q2=1.1'];

/** The page's readouts as it stands (the lesson bar's left out). */
const pageReadouts = (page) => readouts(page, { text: 'fallback', root: '#app-main', except: '.lesson' });

/** Waits until "+ Lesson" says the view was added as step `n` (its chunk may still be loading). */
async function addedStep(page, n) {
  await page.waitForFunction(
    (n) => document.querySelector('[data-testid="lesson-add-status"]').textContent.includes(`step ${n} `),
    n,
  );
}

async function goto(page, hash, { readouts = false } = {}) {
  await page.goto(`${server.url}/${hash}`);
  await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
  // A drill page's first run has written its readouts.
  if (readouts) await page.waitForFunction(() => [...document.querySelectorAll('#app-main [data-readout]')].some((r) => r.textContent.trim()));
  await page.waitForTimeout(400);
}

test('a lesson built from three pages is exported, imported and presented with PageDown', async () => {
  const { page, context, errors, close } = await openApp(server.url, '#/');
  try {
    page.on('dialog', (d) => d.accept());
    // What each permalink shows on its own.
    const expected = [];
    for (const route of ROUTES) {
      await goto(page, route, { readouts: true });
      expected.push(await pageReadouts(page));
      await page.click('[data-testid="lesson-add"]');
    }
    await addedStep(page, 3);

    await goto(page, '#/lesson');
    assert.equal(await page.locator('.lesson-step').count(), 3);
    // Each step is the page's own permalink (pages add their defaults, e.g. the RRT's `it`).
    const shown = await page.locator('.lesson-step-route').allInnerTexts();
    ROUTES.forEach((route, i) => {
      const [path, query] = route.split('?');
      assert.ok(shown[i].startsWith(`${path}?`), shown[i]);
      for (const pair of query.split('&')) assert.ok(shown[i].split('?')[1].split('&').includes(pair), `${shown[i]} has ${pair}`);
    });
    // The RRT step steps the tree three times before the lesson moves on.
    await page.fill('[data-field="step-page-steps-2"]', '3');
    await page.fill('[data-field="step-note-2"]', 'Three iterations, then the IK page.');
    await page.fill('[data-field="step-page-steps-3"]', 'lots');
    assert.match(await page.locator('[data-field-error="step-page-steps-3"]').innerText(), /whole number from 0 to 1000/);
    await page.fill('[data-field="step-page-steps-3"]', '0');
    // The page's URL is the lesson.
    assert.match(decodeURIComponent(page.url()), /#\/lesson\?title=.*&r1=#\/pid-step\?Kp=2&Ki=0\.1&t1=/);

    const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="lesson.json"]')]);
    const file = join(OUT, 'lesson.json');
    await download.saveAs(file);
    const json = JSON.parse(readFileSync(file, 'utf8'));
    assert.equal(json.format, 'bsv-lesson');
    assert.equal(json.steps[1].pageSteps, 3);

    await page.click('[data-action="lesson-clear"]');
    assert.equal(await page.locator('.lesson-step').count(), 0);
    // A bad file is named and changes nothing; the exported one brings the lesson back.
    const bad = join(OUT, 'lesson-bad.json');
    writeFileSync(bad, JSON.stringify({ ...json, format: 'slides' }));
    await page.setInputFiles('input[data-action="lesson-import"]', bad);
    await page.locator('[data-field-error="lesson-file"]:not([hidden])').waitFor();
    assert.match(await page.locator('[data-field-error="lesson-file"]').innerText(), /not a BSV lesson \(format “slides”/);
    assert.equal(await page.locator('.lesson-step').count(), 0);
    await page.setInputFiles('input[data-action="lesson-import"]', file);
    await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 3);
    await page.screenshot({ path: join(OUT, 'lesson-editor-en.png'), fullPage: false });

    // Present: every step shows what its permalink shows.
    await page.click('[data-action="lesson-present"]');
    const bar = page.locator('[data-testid="lesson-bar"]');
    await bar.waitFor({ state: 'visible' });
    await page.waitForFunction(() => location.hash.startsWith('#/pid-step'));
    await page.waitForTimeout(400);
    assert.deepEqual(await pageReadouts(page), expected[0]);
    assert.match(await bar.innerText(), /1 \/ 3/);
    await page.screenshot({ path: join(OUT, 'lesson-present-en.png') });

    await page.keyboard.press('PageDown');
    await page.waitForFunction(() => location.hash.startsWith('#/rrt-2d'));
    await page.waitForTimeout(400);
    assert.deepEqual(await pageReadouts(page), expected[1]);
    assert.match(await page.locator('[data-testid="lesson-note"]').innerText(), /Three iterations/);
    for (let k = 1; k <= 3; k += 1) {
      await page.keyboard.press('PageDown');
      await page.waitForFunction((n) => document.querySelector('[data-readout="iteration"]')?.textContent.trim() === String(n), k);
    }
    assert.ok(page.url().includes('#/rrt-2d'), 'still on the RRT page after its three page steps');
    await page.keyboard.press('PageDown');
    await page.waitForFunction(() => location.hash.startsWith('#/ik-2r'));
    await page.waitForTimeout(400);
    assert.deepEqual(await pageReadouts(page), expected[2]);
    // Back goes to the previous step from its start.
    await page.keyboard.press('PageUp');
    await page.waitForFunction(() => location.hash.startsWith('#/rrt-2d'));
    await page.waitForFunction(() => document.querySelector('[data-readout="iteration"]')?.textContent.trim() === '0');
    // Japanese presenter bar.
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    await page.waitForTimeout(300);
    await page.screenshot({ path: join(OUT, 'lesson-present-ja.png') });
    await page.keyboard.press('Escape');
    await bar.waitFor({ state: 'hidden' });
    assert.deepEqual(errors, []);
    void context;
  } finally {
    await close();
  }
});

test('with no lesson of its own the page opens on a built-in lesson, ready to present; an own lesson is shown after a reload', async () => {
  for (const [lang, viewport, title, note] of [
    ['en', { width: 1366, height: 768 }, 'IK, the Jacobian and singularities', /built-in lesson, ready to present/],
    ['ja', { width: 390, height: 844 }, 'IK、ヤコビアン、特異点', /組み込みのレッスン/],
  ]) {
    const { page, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport });
    try {
      await page.waitForSelector('.lesson-step');
      assert.equal(await page.locator('.lesson-step').count(), 4);
      assert.equal(await page.inputValue('[data-field="lesson-title"]'), title);
      assert.ok(await page.locator('[data-action="lesson-present"]').isEnabled());
      const line = page.locator('[data-testid="lesson-builtin-note"]');
      assert.ok(await line.isVisible());
      assert.match(await line.innerText(), note);
      assert.equal(await page.locator('[data-testid="lesson-empty"]').isVisible(), false);
      // Nothing stored: the user's storage is untouched.
      assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson')), null);
      await page.screenshot({ path: join(OUT, `lesson-open-${lang}-${viewport.width}.png`) });
      if (lang === 'en') {
        // Present works at once.
        await page.click('[data-action="lesson-present"]');
        await page.locator('[data-testid="lesson-bar"]').waitFor({ state: 'visible' });
        await page.waitForFunction(() => location.hash.startsWith('#/ik-2r'));
        await page.keyboard.press('Escape');
        await page.locator('[data-testid="lesson-bar"]').waitFor({ state: 'hidden' });
        // An own lesson: one view added, then the lesson page after a reload shows it alone.
        await goto(page, '#/pid-step?Kp=2');
        await page.click('[data-testid="lesson-add"]');
        await addedStep(page, 1);
        await goto(page, '#/lesson');
        await page.reload();
        await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
        await page.waitForSelector('.lesson-step');
        assert.equal(await page.locator('.lesson-step').count(), 1);
        assert.match(await page.locator('.lesson-step-route').innerText(), /^#\/pid-step\?/);
        assert.equal(await page.locator('[data-testid="lesson-builtin-note"]').isVisible(), false);
        assert.ok(await page.locator('[data-action="lesson-present"]').isEnabled());
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('presenting, the remote works whatever has focus: after a check box, a slider, a button, a canvas; a text field keeps ← →; B and . black out', async () => {
  const lesson = JSON.stringify({
    format: 'bsv-lesson',
    version: 1,
    title: 'Remote',
    steps: [
      { route: '#/ik-2r', title: 'Arm', note: '', pageSteps: 0 },
      { route: '#/pendulum-energy', title: 'Pendulum', note: '', pageSteps: 0 },
      { route: '#/drills?recipe=jacobian-2r', title: 'Sweep', note: '', pageSteps: 0 },
      { route: '#/teleop', title: 'Pilot', note: '', pageSteps: 0 },
    ],
  });
  const { page, errors, close } = await openApp(server.url, '#/lesson', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.lesson': lesson } });
  const bar = page.locator('[data-testid="lesson-bar"]');
  const atStep = async (n, hash) => {
    await page.waitForFunction((n) => document.querySelector('[data-testid="lesson-bar"]')?.dataset.step === String(n), n);
    if (hash) await page.waitForFunction((h) => location.hash.startsWith(h), hash);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
  };
  try {
    await page.click('[data-action="lesson-present"]');
    await atStep(1, '#/ik-2r');
    assert.equal(await bar.getAttribute('data-steps'), '4');
    // A check box ticked: PageDown goes on (it used to scroll the page).
    const grid = page.locator('[data-testid="ik-2r-ws-toggle"]');
    await grid.check();
    await page.keyboard.press('PageDown');
    await atStep(2, '#/pendulum-energy');
    // A slider focused: → goes on (the slider does not take it).
    const slider = page.locator('main input[type="range"]').first();
    await slider.focus();
    await page.keyboard.press('ArrowRight');
    await atStep(3, '#/drills');
    // A text or number field being edited keeps ← and →; PageDown still goes on.
    const field = page.locator('main input[type="number"], main input[type="text"]').first();
    await field.click();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowLeft');
    assert.equal(await bar.getAttribute('data-step'), '3');
    await page.keyboard.press('PageDown');
    await atStep(4, '#/teleop');
    // A click on a button, then on the canvas: ← goes back, → on again.
    await page.locator('[data-action="reset"]').first().click();
    await page.keyboard.press('ArrowLeft');
    await atStep(3, '#/drills');
    await page.keyboard.press('PageDown');
    await atStep(4, '#/teleop');
    await page.locator('[data-testid="teleop-canvas"]').click();
    await page.keyboard.press('PageUp');
    await atStep(3, '#/drills');
    // B blacks the screen, . brings it back; nothing moves meanwhile.
    await page.keyboard.press('b');
    const black = page.locator('[data-testid="blackout"]');
    await black.waitFor({ state: 'visible' });
    const box = await black.boundingBox();
    assert.deepEqual([box.width, box.height], [1920, 1080]);
    await page.keyboard.press('.');
    await black.waitFor({ state: 'hidden' });
    assert.equal(await bar.getAttribute('data-step'), '3');
    // Esc ends.
    await page.keyboard.press('Escape');
    await bar.waitFor({ state: 'hidden' });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
