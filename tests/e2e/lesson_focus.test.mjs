// Lesson steps that show what their notes say: every page marks its sections (data-section,
// named in English and Japanese); each built-in lesson, presented at 1920×1080 and at 1280×720
// with projector styles, brings every step's focus section fully into view above the presenter
// bar, with the controls its note names set by its link; "+ Lesson" records the section in the
// middle of the screen; the editor offers a step's sections; a version 1 file and a file with a
// focus its page does not have load, the latter named in a notice. Screenshots of presenting
// (EN and JA, both sizes) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { serveApp, OUT, openApp } from './harness.mjs';

const server = serveApp();

const ROUTES = ['home', 'ik-2r', 'dh-fk', 'se3-relative', 'umeyama-2d', 'pendulum-energy', 'pid-step', 'cubic-path',
  'trapezoid-profile', 'traj-resample', 'rrt-2d', 'teleop', 'so101', 'drills', 'lesson'];

const PROJECTOR = { 'bsv.projector': '1' };

/** The editor's steps: each route, and its focus and the focus's choices (value → name). */
function editorSteps(page) {
  return page.evaluate(() => [...document.querySelectorAll('.lesson-step')].map((step) => {
    const select = step.querySelector('[data-field="focus"]');
    return {
      route: step.querySelector('.lesson-step-route').textContent,
      exercise: step.querySelector('[data-field="exercise"]')?.value ?? '',
      title: step.querySelector('[data-field^="step-title-"]').value,
      focus: select.value,
      choices: Object.fromEntries([...select.options].map((o) => [o.value, o.textContent])),
    };
  }));
}

/** The shown step's focus section (its exercise's card, for a step about one) and the bar, as
 * the presenter sees them. */
function focusBoxes(page, focus, exercise) {
  return page.evaluate(([focus, exercise]) => {
    const box = (el) => {
      const r = el.getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height };
    };
    const section = exercise
      ? document.querySelector(`#app-main [data-exercise="${exercise}"]`)
      : document.querySelector(`#app-main [data-section="${focus}"]`);
    const bar = document.querySelector('[data-testid="lesson-bar"]');
    return { section: section && box(section), bar: box(bar), width: innerWidth, height: innerHeight };
  }, [focus, exercise]);
}

/** Waits until the bar shows step `n` with its focus `focus` in view. */
async function shownStep(page, n, focus) {
  await page.waitForFunction(
    ([n, focus]) => {
      const bar = document.querySelector('[data-testid="lesson-bar"]');
      return bar?.dataset.step === String(n) && bar.dataset.focus === focus;
    },
    [n, focus],
    { timeout: 15000 },
  );
}

for (const [key, viewport, lang] of [
  ['ik', { width: 1920, height: 1080 }, 'en'],
  ['ik', { width: 1280, height: 720 }, 'ja'],
  ['energy', { width: 1920, height: 1080 }, 'ja'],
  ['energy', { width: 1280, height: 720 }, 'en'],
  ['planning', { width: 1920, height: 1080 }, 'en'],
  ['planning', { width: 1280, height: 720 }, 'ja'],
]) {
  test(`the built-in lesson "${key}" at ${viewport.width}×${viewport.height} (${lang}, projector): every step's focus is in view above the bar`, async () => {
    const { page, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport, storage: PROJECTOR });
    try {
      await page.click(`[data-builtin="${key}"]`);
      const steps = await editorSteps(page);
      assert.equal(steps.length, 4);
      for (const step of steps) assert.notEqual(step.focus, '', `${step.route} has a focus`);
      const pageSteps = await page.evaluate(() => [...document.querySelectorAll('[data-field^="step-page-steps-"]')].map((i) => Number(i.value)));
      await page.click('[data-action="lesson-present"]');
      for (const [i, step] of steps.entries()) {
        await page.waitForFunction((path) => location.hash.startsWith(path), step.route.split('?')[0]);
        await shownStep(page, i + 1, step.focus);
        if (step.exercise) {
          await page.waitForFunction((id) => {
            const card = document.querySelector(`#app-main [data-exercise="${id}"]`);
            if (!card) return false;
            const r = card.getBoundingClientRect();
            const bar = document.querySelector('[data-testid="lesson-bar"]').getBoundingClientRect();
            return r.top >= 0 && r.bottom <= bar.top;
          }, step.exercise, { timeout: 15000 });
        }
        const { section, bar, width, height } = await focusBoxes(page, step.focus, step.exercise);
        const where = `${key} step ${i + 1} (${step.route}, ${step.focus})`;
        assert.ok(section && section.height > 0, `${where}: shown`);
        assert.ok(section.top >= 0 && section.left >= 0 && section.right <= width && section.bottom <= height, `${where}: inside the viewport ${JSON.stringify(section)}`);
        assert.ok(section.bottom <= bar.top, `${where}: above the bar (section ${section.bottom}, bar ${bar.top})`);
        // The controls the note names are the link's: the page applied every key of the route.
        const query = new URLSearchParams(step.route.split('?')[1] ?? '');
        const shown = new URLSearchParams(await page.evaluate(() => location.hash.split('?')[1] ?? ''));
        for (const [k, v] of query) assert.equal(Number(shown.get(k)) === Number(v) ? v : shown.get(k), v, `${where}: ${k}=${v} applied`);
        if (i === 1) await page.screenshot({ path: join(OUT, `lesson-focus-${key}-${viewport.width}-${lang}.png`) });
        // A prediction's answer first, then the step's page steps, then the next step.
        const reveals = step.exercise && (await page.evaluate((id) => !document.querySelector(`[data-exercise="${id}"] [data-action="reveal"]`).hidden, step.exercise));
        for (let k = reveals ? -1 : 0; k <= pageSteps[i] && i + 1 < steps.length; k += 1) await page.keyboard.press('PageDown');
      }
      await page.keyboard.press('Escape');
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('every route marks its sections, as the lesson editor lists them, named in English and Japanese', async () => {
  // Every route as a step of a lesson link: the editor knows each page's sections unopened.
  const query = ROUTES.filter((r) => r !== 'lesson').map((r, i) => `r${i + 1}=${encodeURIComponent(`#/${r}`)}&t${i + 1}=${r}`).join('&');
  const { page, errors, close } = await openApp(server.url, `#/lesson?title=All&${query}`);
  try {
    const listed = Object.fromEntries((await editorSteps(page)).map((s) => [s.title, Object.keys(s.choices).filter(Boolean)]));
    listed.lesson = ['lessons', 'steps'];
    for (const route of ROUTES) {
      await page.evaluate((r) => { location.hash = `#/${r}`; }, route);
      const expected = [...listed[route]].sort();
      assert.ok(expected.length > 0, route);
      const sections = () => page.evaluate(() => [...document.querySelectorAll('#app-main [data-section]')].map((e) => [e.dataset.section, e.dataset.sectionName]));
      await page.waitForFunction((want) => {
        const ids = [...new Set([...document.querySelectorAll('#app-main [data-section]')].map((e) => e.dataset.section))].sort();
        return JSON.stringify(ids) === want;
      }, JSON.stringify(expected), { timeout: 15000 }).catch(() => {});
      const names = {};
      for (const lang of ['en', 'ja']) {
        if (await page.evaluate(() => document.documentElement.lang) !== lang) {
          await page.click('[data-testid="lang-switch"]');
          await page.waitForFunction((l) => document.documentElement.lang === l, lang);
        }
        names[lang] = Object.fromEntries(await sections());
      }
      assert.deepEqual(Object.keys(names.en).sort(), expected, `${route}: the sections the editor lists`);
      for (const id of expected) {
        assert.ok(names.en[id] && !names.en[id].startsWith('section-'), `${route} ${id}: ${names.en[id]}`);
        assert.ok(names.ja[id] && names.ja[id] !== names.en[id], `${route} ${id}: ${names.ja[id]}`);
      }
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('"+ Lesson" records the section in the middle of the screen; the editor offers the page\'s sections', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r?q1=0.3&q2=0.05', { viewport: { width: 1280, height: 800 } });
  try {
    const heatmap = page.locator('[data-section="heatmap"]');
    await heatmap.waitFor({ state: 'visible' });
    await page.evaluate(() => document.querySelector('[data-section="heatmap"]').scrollIntoView({ block: 'center' }));
    // The header is not sticky: clicked where the page stands (a pointer click would scroll to it).
    await page.evaluate(() => document.querySelector('[data-testid="lesson-add"]').click());
    await page.waitForFunction(() => document.querySelector('[data-testid="lesson-add-status"]').textContent.includes('step 1 '));
    const stored = await page.evaluate(() => JSON.parse(localStorage.getItem('bsv.lesson')));
    assert.equal(stored.version, 3);
    assert.equal(stored.steps[0].focus, 'heatmap');

    await page.evaluate(() => { location.hash = '#/lesson'; });
    await page.waitForSelector('[data-testid="lesson-step-1"] [data-field="focus"]');
    const [step] = await editorSteps(page);
    assert.equal(step.focus, 'heatmap');
    assert.deepEqual(Object.keys(step.choices), ['', 'arm', 'readouts', 'heatmap', 'sweep', 'form', 'exports', 'explain', 'exercises']);
    assert.equal(step.choices.heatmap, 'Manipulability heatmap');
    await page.selectOption('[data-testid="lesson-step-1"] [data-field="focus"]', 'sweep');
    await page.waitForFunction(() => JSON.parse(localStorage.getItem('bsv.lesson')).steps[0].focus === 'sweep');
    assert.match(decodeURIComponent(page.url()), /&f1=sweep/);
    await page.selectOption('[data-testid="lesson-step-1"] [data-field="focus"]', '');
    await page.waitForFunction(() => !('focus' in JSON.parse(localStorage.getItem('bsv.lesson')).steps[0]));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a version 1 file loads as before; a focus the page does not have is named, and its step shows the main view', async () => {
  const { page, errors, close } = await openApp(server.url, '#/lesson', { viewport: { width: 1280, height: 720 }, storage: PROJECTOR });
  try {
    const v1 = join(OUT, 'lesson-v1.json');
    writeFileSync(v1, JSON.stringify({ format: 'bsv-lesson', version: 1, title: 'Old', steps: [{ route: '#/ik-2r?q2=1.1', title: 'One', note: 'n', pageSteps: 0 }] }));
    await page.setInputFiles('input[data-action="lesson-import"]', v1);
    await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 1);
    assert.equal(await page.inputValue('[data-field="lesson-title"]'), 'Old');
    assert.equal((await editorSteps(page))[0].focus, '');
    assert.equal(await page.locator('[data-testid="lesson-focus-notice"]').isVisible(), false);

    const unknown = join(OUT, 'lesson-unknown-focus.json');
    writeFileSync(unknown, JSON.stringify({ format: 'bsv-lesson', version: 2, title: 'New', steps: [
      { route: '#/ik-2r?q2=1.1', title: 'One', focus: 'nowhere' },
      { route: '#/rrt-2d', title: 'Two', focus: 'readouts' },
    ] }));
    await page.setInputFiles('input[data-action="lesson-import"]', unknown);
    await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 2);
    const notice = page.locator('[data-testid="lesson-focus-notice"]');
    assert.match(await notice.innerText(), /Step 1: the page “ik-2r” has no section “nowhere”/);
    assert.deepEqual((await editorSteps(page)).map((s) => s.focus), ['', 'readouts']);
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.match(await notice.innerText(), /ステップ 1：ページ「ik-2r」には区画「nowhere」がない/);

    // Presented, the step without a focus shows the page's main view.
    await page.click('[data-action="lesson-present"]');
    await shownStep(page, 1, 'arm');
    const { section, bar } = await focusBoxes(page, 'arm');
    assert.ok(section.top >= 0 && section.bottom <= bar.top, JSON.stringify({ section, bar }));
    await page.keyboard.press('PageDown');
    await shownStep(page, 2, 'readouts');
    await page.keyboard.press('Escape');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

for (const lang of ['en', 'ja']) {
  test(`a step about an exercise (${lang}): its card in view, its answer hidden from the class until PageDown reveals it`, async () => {
    const viewport = { width: 1280, height: 720 };
    const { page, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport, storage: PROJECTOR });
    try {
      await page.click('[data-builtin="energy"]');
      // The editor names the step's exercise by its prompt, once the prompts are here.
      const select = '.lesson-step:nth-child(3) [data-field="exercise"]';
      await page.waitForFunction((sel) => {
        const s = document.querySelector(sel);
        return s?.value === 'pendulum-euler-dt' && s.selectedOptions[0].textContent !== 'pendulum-euler-dt';
      }, select, { timeout: 15000 });
      await page.click('[data-action="lesson-present"]');
      await shownStep(page, 1, 'pendulum');
      await page.keyboard.press('PageDown');
      await shownStep(page, 2, 'plot');
      await page.keyboard.press('PageDown');
      await page.waitForFunction(() => location.hash.includes('timestep=0.01'));
      const card = '#app-main [data-exercise="pendulum-euler-dt"]';
      await page.waitForSelector(`${card}[data-exercise-state="open"]`, { timeout: 15000 });
      await shownStep(page, 3, 'exercises');
      const hidden = () => page.evaluate(() => [...document.querySelectorAll('#app-main [data-readout][data-ex-hidden]')].map((r) => r.dataset.readout));
      await page.waitForFunction(() => document.querySelector('#app-main [data-readout][data-ex-hidden]'));
      assert.ok((await hidden()).some((k) => k === 'drift' || k === 'drift-euler'), `the drift is hidden: ${await hidden()}`);
      await page.screenshot({ path: join(OUT, `lesson-exercise-predict-${lang}.png`) });
      // PageDown reveals the answer beside nothing predicted, and shows the readouts again.
      await page.keyboard.press('PageDown');
      await page.waitForSelector(`${card}[data-exercise-state="revealed"]`, { timeout: 5000 });
      assert.deepEqual(await hidden(), []);
      assert.match(await page.evaluate(() => location.hash), /timestep=0\.01/, 'still on the step');
      // The card, grown by its answer, is brought into view again above the bar.
      await page.waitForFunction((sel) => {
        const r = document.querySelector(sel).getBoundingClientRect();
        const bar = document.querySelector('[data-testid="lesson-bar"]').getBoundingClientRect();
        return r.top >= 0 && (r.bottom <= bar.top || (r.height > bar.top && r.top <= 10));
      }, card, { timeout: 5000 });
      await page.screenshot({ path: join(OUT, `lesson-exercise-revealed-${lang}.png`) });
      // The next PageDown goes on to the next step; Escape ends and nothing stays hidden.
      await page.keyboard.press('PageDown');
      await page.waitForFunction(() => location.hash.startsWith('#/pid-step'));
      await page.keyboard.press('Escape');
      assert.equal(await page.evaluate(() => document.documentElement.hasAttribute('data-present-exercise')), false);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`a teacher's own goal (${lang}): edited on the step, kept in the link and the file, checked live while presenting`, async () => {
    const viewport = { width: 1280, height: 720 };
    const link = `#/lesson?lang=${lang}&title=PID&r1=${encodeURIComponent('#/pid-step')}&t1=Tune&g1=${encodeURIComponent('final-y~0.8±0.01')}`;
    const { page, errors, close } = await openApp(server.url, link, { viewport, storage: PROJECTOR });
    try {
      const row = (n) => `[data-testid="lesson-step-1"] [data-goal-row="${n}"]`;
      await page.waitForSelector(row(1));
      assert.equal(await page.locator(`${row(1)} [data-field="goal-readout"]`).inputValue(), 'final-y');
      assert.equal(await page.locator(`${row(1)} [data-field="goal-op"]`).inputValue(), 'within');
      assert.equal(await page.locator(`${row(1)} [data-field="goal-value"]`).inputValue(), '0.8');
      assert.equal(await page.locator(`${row(1)} [data-field="goal-tolerance"]`).inputValue(), '0.01');
      // A second condition: added, a bad value named beside it (the last good one kept), then set.
      await page.click('[data-testid="lesson-step-1"] [data-action="goal-add"]');
      await page.waitForSelector(row(2));
      await page.selectOption(`${row(2)} [data-field="goal-readout"]`, 'overshoot');
      await page.fill(`${row(2)} [data-field="goal-value"]`, 'abc');
      assert.equal(await page.locator(`${row(2)} .lesson-step-error`).isVisible(), true);
      const stored = () => page.evaluate(() => JSON.parse(localStorage.getItem('bsv.lesson')).steps[0].goals);
      assert.deepEqual((await stored())[1], { readout: 'overshoot', op: '<', value: 0 });
      await page.fill(`${row(2)} [data-field="goal-value"]`, '5');
      assert.equal(await page.locator(`${row(2)} .lesson-step-error`).isVisible(), false);
      assert.deepEqual(await stored(), [
        { readout: 'final-y', op: 'within', value: 0.8, tolerance: 0.01 },
        { readout: 'overshoot', op: '<', value: 5 },
      ]);
      assert.match(decodeURIComponent(page.url()), /g1=final-y~0\.8±0\.01;overshoot<5/);
      // Three at most: the third hides "Add a goal"; Remove takes one away.
      await page.click('[data-testid="lesson-step-1"] [data-action="goal-add"]');
      await page.waitForSelector(row(3));
      assert.equal(await page.locator('[data-testid="lesson-step-1"] [data-action="goal-add"]').count(), 0);
      await page.click(`${row(3)} [data-action="goal-remove"]`);
      await page.waitForFunction(async () => JSON.parse(localStorage.getItem('bsv.lesson')).steps[0].goals.length === 2);
      // Presented: each condition on the page's numbers, live.
      await page.click('[data-action="lesson-present"]');
      await page.waitForFunction(() => location.hash.startsWith('#/pid-step'));
      const goals = '[data-testid="lesson-goals"]';
      await page.waitForSelector(`${goals}[data-goals-met="true"]`, { timeout: 15000 });
      assert.equal(await page.locator(`${goals} [data-goal="1"]`).getAttribute('data-goal-met'), 'true');
      await page.screenshot({ path: join(OUT, `lesson-goal-met-${lang}.png`) });
      // No integral action: y settles lower, the first condition is no longer met.
      await page.locator('[data-field="Ki"]').fill('0');
      await page.waitForSelector(`${goals} [data-goal="1"][data-goal-met="false"]`, { timeout: 5000 });
      assert.equal(await page.locator(goals).getAttribute('data-goals-met'), 'false');
      await page.locator('[data-field="Ki"]').fill('0.4');
      await page.waitForSelector(`${goals}[data-goals-met="true"]`, { timeout: 5000 });
      await page.keyboard.press('Escape');
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}
