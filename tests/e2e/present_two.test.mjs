// Presenting on two screens: "Present on two screens" opens the room's window (the page in
// projector styles, no notes) and turns the lesson page into the presenter view (this step's
// note, the next step's title and picture, the step list, the elapsed time). Keys in either
// window drive both; closing either, or Escape, ends the presentation in both.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { serveApp, OUT, openApp } from './harness.mjs';
import { violations } from './axe.mjs';

const server = serveApp();

const STEPS = [
  ['#/pid-step?Kp=2&Ki=0.1', 'PID', 'Note one: the step response.'],
  ['#/rrt-2d?seed=11&it=0', 'RRT', 'Two presses grow the tree.', 2],
  ['#/ik-2r?q1=0.3&q2=1.1', 'IK', 'The arm.'],
];

/** `#/lesson?...` holding the lesson STEPS, in `lang`. */
function lessonHash(lang) {
  const q = new URLSearchParams({ title: 'Two screens', lang });
  STEPS.forEach(([route, title, note, pageSteps = 0], i) => {
    q.set(`r${i + 1}`, route);
    q.set(`t${i + 1}`, title);
    q.set(`n${i + 1}`, note);
    q.set(`k${i + 1}`, String(pageSteps));
  });
  return `#/lesson?${q}`;
}

/** Starts presenting on two screens from the lesson page: { presenter, audience, errors }. */
async function presentOnTwo(lang) {
  const opened = await openApp(server.url, lessonHash(lang), { viewport: { width: 1366, height: 768 } });
  const { page, context, errors } = opened;
  const [audience] = await Promise.all([context.waitForEvent('page'), page.click('[data-action="lesson-present-two"]')]);
  audience.on('console', (m) => {
    if (m.type() === 'error') errors.push(`audience: ${m.text()}`);
  });
  audience.on('pageerror', (e) => errors.push(`audience: ${e}`));
  await audience.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
  await audience.locator('body[data-testid="audience"]').waitFor();
  await page.locator('[data-testid="presenter-window"]').waitFor();
  return { ...opened, presenter: page, audience };
}

const step = (presenter) => presenter.locator('[data-testid="presenter-window"]').getAttribute('data-step');
/** Waits until the room's window shows `route` (whatever language it names). */
const atRoute = (audience, route) =>
  audience.waitForFunction((route) => decodeURIComponent(location.hash).replace(/[?&]lang=(en|ja)$/, '') === route, route);

/** The room's route (without the language it was opened in). */
const hashOf = (audience) => audience.evaluate(() => decodeURIComponent(location.hash).replace(/[?&]lang=(en|ja)$/, ''));

test('two windows: the presenter view and the room\'s window keep in step, keys in either drive both, Escape ends both', async () => {
  const { presenter, audience, errors, close } = await presentOnTwo('en');
  try {
    // The room's window: the first step's page in projector styles, with no notes.
    assert.equal(await hashOf(audience), STEPS[0][0]);
    assert.equal(await audience.evaluate(() => document.documentElement.classList.contains('projector')), true);
    assert.equal(await audience.locator('[data-testid="lesson-bar"]').isVisible(), false);
    assert.equal(await audience.getByText(STEPS[0][2]).count(), 0, 'no note in the room');
    // The presenter's: this step's note, the next step and its picture, the steps, the time.
    assert.equal(await step(presenter), '1');
    assert.equal(await presenter.locator('[data-testid="presenter-note"]').innerText(), STEPS[0][2]);
    assert.equal(await presenter.locator('[data-testid="presenter-next-title"]').innerText(), '2 · RRT');
    const src = await presenter.locator('#presenter-picture iframe').getAttribute('src');
    assert.match(src, /#\/rrt-2d\?seed=11&it=0&embed=1$/);
    assert.deepEqual(await presenter.locator('[data-testid="presenter-steps"] button').allInnerTexts(), ['PID', 'RRT', 'IK']);
    assert.match(await presenter.locator('[data-testid="presenter-elapsed"]').innerText(), /^\d+:\d\d$/);
    // The picture is the next step's page itself.
    const picture = presenter.frames().find((f) => f.url().includes('embed=1'));
    await picture.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
    await picture.locator('[data-readout="iteration"]').waitFor();
    // The picture tells its host it is ready (the embedding API's events); the presenter's
    // window does not answer an event, so the two stay quiet.
    await presenter.evaluate(() => {
      window.__messages = 0;
      window.addEventListener('message', () => { window.__messages += 1; });
    });
    await picture.evaluate(() => window.parent.postMessage({ namespace: 'bsv', event: 'ready', page: 'rrt-2d' }, '*'));
    await presenter.waitForTimeout(1000);
    assert.ok(await presenter.evaluate(() => window.__messages) <= 2, 'no exchange of messages with the picture');
    await presenter.screenshot({ path: join(OUT, 'present-two-presenter-en.png') });
    assert.deepEqual([...(await violations(presenter, 'presenter')), ...(await violations(audience, 'room'))], []);
    await audience.screenshot({ path: join(OUT, 'present-two-audience-en.png') });

    // PageDown in the presenter's window: the room's window shows step 2.
    await presenter.keyboard.press('PageDown');
    await atRoute(audience, STEPS[1][0]);
    await audience.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    assert.equal(await step(presenter), '2');
    assert.match(await presenter.locator('[data-testid="presenter-window"]').innerText(), /2 page steps before the next lesson step/);
    const iteration = () => audience.locator('[data-readout="iteration"]').innerText();
    assert.equal(await iteration(), '0');
    // PageDown in the room's window steps its page (the step asks for two page steps first).
    await audience.keyboard.press('PageDown');
    await audience.waitForFunction(() => document.querySelector('[data-readout="iteration"]').textContent.trim() === '1');
    await presenter.keyboard.press('ArrowRight');
    await audience.waitForFunction(() => document.querySelector('[data-readout="iteration"]').textContent.trim() === '2');
    assert.equal(await step(presenter), '2');
    await audience.keyboard.press('PageDown');
    await atRoute(audience, STEPS[2][0]);
    await presenter.waitForFunction(() => document.querySelector('[data-testid="presenter-window"]').dataset.step === '3');
    assert.equal(await presenter.locator('[data-testid="presenter-next-title"]').innerText(), 'End of the lesson');

    // B in the room blacks it out (the presenter sees it); . in the presenter's brings it back.
    await audience.keyboard.press('b');
    await audience.locator('[data-testid="blackout"]').waitFor();
    await presenter.getByText('The room’s screen is black').waitFor();
    await presenter.keyboard.press('.');
    await audience.locator('[data-testid="blackout"]').waitFor({ state: 'hidden' });

    // A step chosen in the list; PageUp goes back.
    await presenter.click('[data-testid="presenter-steps"] button >> text=PID');
    await atRoute(audience, STEPS[0][0]);
    await presenter.keyboard.press('PageDown');
    await atRoute(audience, STEPS[1][0]);
    await presenter.keyboard.press('PageUp');
    await atRoute(audience, STEPS[0][0]);

    // Escape in the room's window ends both: it closes, the presenter view goes.
    const closed = audience.waitForEvent('close');
    // (It closes on the key going down: the key's release has no page to go to.)
    await audience.keyboard.down('Escape').catch(() => {});
    await closed;
    await presenter.locator('[data-testid="presenter-window"]').waitFor({ state: 'detached' });
    assert.equal(await presenter.locator('[data-testid="lesson-bar"]').isVisible(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('closing either window ends the presentation in the other (the presenter view in Japanese)', async () => {
  // The room's window closed: the presenter's window is the lesson page again.
  {
    const { presenter, audience, errors, close } = await presentOnTwo('ja');
    try {
      assert.equal(await presenter.locator('[data-testid="presenter-window"] .presenter-label').first().innerText(), '現在');
      assert.equal(await presenter.locator('[data-action="lesson-black"]').innerText(), '画面を黒くする');
      await presenter.screenshot({ path: join(OUT, 'present-two-presenter-ja.png') });
      assert.deepEqual(await violations(presenter, 'presenter ja'), []);
      // The room's window speaks the presenter's language; projector mode stays its own.
      assert.equal(await audience.evaluate(() => document.documentElement.lang), 'ja');
      assert.equal(await presenter.evaluate(() => localStorage.getItem('bsv.projector')), null);
      await audience.close();
      await presenter.locator('[data-testid="presenter-window"]').waitFor({ state: 'detached', timeout: 5000 });
      await presenter.keyboard.press('PageDown');
      assert.match(decodeURIComponent(presenter.url()), /#\/lesson\?/);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  // The presenter's window closed: the room's window closes.
  {
    const { presenter, audience, errors, close } = await presentOnTwo('en');
    try {
      const closed = audience.waitForEvent('close');
      await presenter.close({ runBeforeUnload: true });
      await closed;
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
