// Keyboard and screen-reader access beyond what axe-core checks (a11y.test.mjs): Tab reaches
// every visible control of every route with a visible focus ring and no pointer-only element;
// every canvas has a localized name and a text alternative; the live summaries are paced while
// dragging; with `prefers-reduced-motion: reduce` nothing moves by itself.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { serveApp, openApp } from './harness.mjs';

const server = serveApp();

/** Every route of the navigation (home, the drill pages, drills, lesson). */
async function routes(page) {
  return page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
}

async function open(page, route, lang = 'en') {
  await page.goto(`${server.url}/#/${route}?lang=${lang}`);
  await page.waitForFunction((l) => document.documentElement.lang === l && document.documentElement.dataset.appReady === '1', lang);
  // A page's later parts (the IK page's second stage, the home cards) come once it is painted.
  await page.waitForFunction(() => !document.querySelector('[data-state="loading"]'), null, { timeout: 20000 });
  // The IK page's heatmap is drawn (its marker placed) once its second stage is in.
  if (route.startsWith('ik-2r')) await page.waitForSelector('[data-testid="ik-2r-heatmap"][data-marker-q1]', { timeout: 20000 });
  await page.waitForTimeout(200);
}

async function settle(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/**
 * Marks the elements a pointer can act on but Tab cannot reach: elements with a click,
 * pointerdown, mousedown or touchstart listener (read through the DevTools protocol) that
 * are visible, not focusable by Tab and hold no focusable element (a listener on a container
 * that delegates to its buttons is fine). Returns their descriptions.
 */
async function pointerOnly(page, cdp) {
  const { root } = await cdp.send('DOM.getDocument', { depth: 0 });
  const { object } = await cdp.send('DOM.resolveNode', { nodeId: root.nodeId });
  const { listeners } = await cdp.send('DOMDebugger.getEventListeners', { objectId: object.objectId, depth: -1, pierce: false });
  const kinds = new Set(['click', 'pointerdown', 'mousedown', 'touchstart', 'dblclick']);
  const found = [];
  const nodes = new Set(listeners.filter((l) => kinds.has(l.type) && l.backendNodeId).map((l) => l.backendNodeId));
  for (const backendNodeId of nodes) {
    const { object: el } = await cdp.send('DOM.resolveNode', { backendNodeId });
    const { result } = await cdp.send('Runtime.callFunctionOn', {
      objectId: el.objectId,
      returnByValue: true,
      functionDeclaration: `function () {
        if (!(this instanceof Element) || this === document.body || this === document.documentElement || this.disabled) return null;
        if (this.closest('[inert]') || !this.checkVisibility({ visibilityProperty: true })) return null;
        const tabbable = (e) => e.tabIndex >= 0 && !e.disabled && e.checkVisibility({ visibilityProperty: true });
        if (tabbable(this)) return null;
        // A label's control, or a container whose focusable descendants are what it handles.
        if (this.matches('label') && this.control) return null;
        if ([...this.querySelectorAll('*')].some(tabbable)) return null;
        return this.tagName.toLowerCase() + (this.dataset.testid ? '[data-testid=' + this.dataset.testid + ']' : '') + '.' + this.className;
      }`,
    });
    if (result.value) found.push(result.value);
  }
  return found;
}

/** Numbers every visible control Tab must reach (data-kbd) and keeps its unfocused ring style. */
function markControls() {
  const ring = (e) => {
    const s = getComputedStyle(e);
    return `${s.outlineStyle} ${s.outlineWidth} ${s.outlineColor} | ${s.boxShadow} | ${s.borderColor}`;
  };
  const selector = [
    'a[href]', 'button', 'input:not([type="hidden"])', 'select', 'textarea', 'summary',
    '[tabindex]', '[role="button"]', '[role="slider"]',
  ].join(',');
  // tabindex="-1" on a non-control (<main>, a section, a dialog) is a programmatic focus
  // target, not a control.
  const control = 'a[href], button, input, select, textarea, summary, canvas, [role="button"], [role="slider"], [role="radio"], [role="checkbox"], [role="tab"]';
  const controls = [...document.querySelectorAll(selector)].filter(
    (e) => !e.disabled && !e.closest('[inert]') && e.checkVisibility({ visibilityProperty: true }) && (e.tabIndex >= 0 || e.matches(control)),
  );
  const out = [];
  controls.forEach((e, i) => {
    e.dataset.kbd = String(i);
    // A visually hidden input shows its focus on its label.
    const shown = e.getBoundingClientRect().width <= 2 ? e.closest('label') ?? e : e;
    out.push({
      i,
      what: `${e.tagName.toLowerCase()}${e.type ? `[type=${e.type}]` : ''}${e.dataset.testid ? `[data-testid=${e.dataset.testid}]` : ''}${e.getAttribute('name') ? `[name=${e.getAttribute('name')}]` : ''} "${(e.getAttribute('aria-label') ?? e.textContent ?? '').trim().slice(0, 30)}"`,
      radio: e.type === 'radio' ? e.name : null,
      tabIndex: e.tabIndex,
      ring: ring(shown),
    });
  });
  return out;
}

/** The focused element's data-kbd and whether its ring (or its label's) differs from `unfocused`. */
function focusedRing() {
  const e = document.activeElement;
  if (!e || e === document.body) return null;
  const shown = e.getBoundingClientRect().width <= 2 ? e.closest('label') ?? e : e;
  const s = getComputedStyle(shown);
  const ring = `${s.outlineStyle} ${s.outlineWidth} ${s.outlineColor} | ${s.boxShadow} | ${s.borderColor}`;
  const visible = (s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) >= 2) || s.boxShadow !== 'none';
  // A control that appeared during the walk (the pendulum's Replay at the end of a run).
  const late = e.dataset.kbd === undefined && e.matches('a[href], button, input, select, textarea, summary') && e.checkVisibility();
  return { kbd: e.dataset.kbd ?? null, late, ring, visible, tag: e.tagName.toLowerCase(), testid: e.dataset.testid ?? '', cls: String(e.className) };
}

test('Tab alone reaches every visible control of every route, each with a visible focus ring; nothing is pointer-only', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  const cdp = await page.context().newCDPSession(page);
  try {
    const problems = [];
    for (const route of await routes(page)) {
      await open(page, route);
      await page.evaluate(() => document.activeElement?.blur());
      for (const what of await pointerOnly(page, cdp)) problems.push(`${route}: ${what} reacts to the pointer but Tab cannot reach it`);
      const controls = await page.evaluate(markControls);
      for (const c of controls) if (c.tabIndex < 0) problems.push(`${route}: ${c.what} has tabindex ${c.tabIndex}`);
      // From the top of the page, Tab until the focus leaves the document or comes back round.
      // The body focused for a moment: Tab's starting point is then the top of the document.
      await page.evaluate(() => {
        window.scrollTo(0, 0);
        document.body.tabIndex = -1;
        document.body.focus();
        document.body.removeAttribute('tabindex');
      });
      const reached = new Map();
      let first = null;
      for (let n = 0; n < controls.length + 30; n++) {
        await page.keyboard.press('Tab');
        const f = await page.evaluate(focusedRing);
        if (!f) break;
        if (f.late) {
          if (!f.visible) problems.push(`${route}: ${f.tag}.${f.cls} shows no focus ring (${f.ring})`);
          continue;
        }
        if (f.kbd === null) {
          problems.push(`${route}: Tab stops on ${f.tag}[data-testid=${f.testid}].${f.cls}, which is not a visible control`);
          continue;
        }
        if (f.kbd === first) break;
        first ??= f.kbd;
        reached.set(f.kbd, f);
      }
      const radioGroups = new Set(controls.filter((c) => c.radio && reached.has(String(c.i))).map((c) => c.radio));
      for (const c of controls) {
        const f = reached.get(String(c.i));
        if (!f) {
          if (c.radio && radioGroups.has(c.radio)) continue; // one stop per radio group
          if (c.tabIndex >= 0) problems.push(`${route}: Tab never reaches ${c.what}`);
          continue;
        }
        if (!f.visible || f.ring === c.ring) problems.push(`${route}: ${c.what} shows no focus ring (${f.ring})`);
      }
      // A canvas that takes focus takes keys: the ? overlay lists the page's.
      if (controls.some((c) => c.what.startsWith('canvas'))) {
        await page.evaluate(() => document.activeElement?.blur());
        await page.keyboard.press('?');
        await page.locator('[data-testid="shortcut-overlay"]').waitFor();
        const keys = await page.locator('[data-testid="page-keys"] dt').count();
        if (!keys) problems.push(`${route}: a focusable canvas but no page keys in the ? overlay`);
        await page.keyboard.press('Escape');
      }
    }
    assert.deepEqual(problems, []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Every canvas a screen reader meets (not aria-hidden): its name and its description. */
function canvasTexts() {
  const text = (ids) =>
    (ids ?? '')
      .split(/\s+/)
      .filter(Boolean)
      .map((id) => document.getElementById(id))
      .map((e) => (e ? e.textContent.replace(/\s+/g, ' ').trim() : '<missing id>'));
  return [...document.querySelectorAll('canvas:not([aria-hidden="true"])')]
    .filter((c) => c.checkVisibility({ visibilityProperty: true }) && !c.closest('[aria-hidden="true"]'))
    .map((c) => ({
      what: c.dataset.testid ?? c.className,
      role: c.getAttribute('role'),
      name: c.getAttribute('aria-label') ?? text(c.getAttribute('aria-labelledby')).join(' '),
      description: text(c.getAttribute('aria-describedby')),
    }));
}

test('every canvas has a localized name and a text alternative (aria-describedby), in English and Japanese', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const problems = [];
    const japanese = /[\u3040-\u30ff\u4e00-\u9fff]/;
    let canvases = 0;
    for (const lang of ['en', 'ja']) {
      for (const route of await routes(page)) {
        await open(page, route, lang);
        await settle(page);
        for (const c of await page.evaluate(canvasTexts)) {
          canvases++;
          const at = `${lang} ${route} ${c.what}`;
          if (c.role !== 'img') problems.push(`${at}: role ${c.role}, not img`);
          if (!c.name || /^[a-z0-9]+(-[a-z0-9]+)+$/.test(c.name)) problems.push(`${at}: no name (${c.name})`);
          else if (japanese.test(c.name) !== (lang === 'ja')) problems.push(`${at}: name not in ${lang}: ${c.name}`);
          if (!c.description.length) problems.push(`${at}: no aria-describedby`);
          for (const d of c.description) if (!d || d === '<missing id>') problems.push(`${at}: description ${d || 'empty'}`);
        }
      }
    }
    assert.ok(canvases >= 2 * 20, `${canvases} canvases seen`);
    assert.deepEqual(problems, []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the IK heatmap takes the keys a click there stands for: arrows turn q1 and q2; the ? overlay says so', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r?q1=0.3&q2=0.8', { viewport: { width: 1920, height: 1080 } });
  try {
    await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
    await page.waitForSelector('[data-testid="ik-2r-heatmap"][data-marker-q1]');
    const q = () => page.evaluate(() => ['q1', 'q2'].map((k) => Number(document.querySelector(`[data-readout="${k}"]`).textContent)));
    await page.locator('[data-testid="ik-2r-heatmap"]').focus();
    await page.keyboard.press('ArrowUp');
    await page.keyboard.press('Shift+ArrowRight');
    await settle(page);
    const [q1, q2] = await q();
    assert.ok(Math.abs(q1 - 0.4) < 1e-9 && Math.abs(q2 - 0.81) < 1e-9, `q1 ${q1}, q2 ${q2}`);
    // The arm view's arrows still move the tip (q1 and q2 both change).
    await page.locator('[data-testid="ik-2r-canvas"]').focus();
    await page.keyboard.press('ArrowUp');
    await settle(page);
    const [r1, r2] = await q();
    assert.ok(r1 !== q1 && r2 !== q2, 'the tip moved by IK');
    await page.keyboard.press('?');
    assert.match(await page.locator('[data-testid="page-keys"]').innerText(), /On the focused heatmap/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Starts counting the text changes of every live region (aria-live not off, status, alert, log). */
function watchLive() {
  const regions = () => [...document.querySelectorAll('[aria-live]:not([aria-live="off"]), [role="status"], [role="alert"], [role="log"]')];
  const last = new Map(regions().map((e) => [e, e.textContent]));
  window.__liveChanges = [];
  window.__liveObserver?.disconnect();
  window.__liveObserver = new MutationObserver(() => {
    for (const e of regions()) {
      const text = e.textContent;
      if (last.get(e) !== text) {
        last.set(e, text);
        window.__liveChanges.push(`${e.dataset.testid ?? e.className}: ${text.slice(0, 80)}`);
      }
    }
  });
  window.__liveObserver.observe(document.body, { subtree: true, childList: true, characterData: true });
}

/** Moves the mouse for `ms` from (x, y) around a circle of radius `r` px, the button held. */
async function circleDrag(page, [x, y], r, ms = 2000) {
  await page.mouse.move(x, y);
  await page.mouse.down();
  const t0 = Date.now();
  let moves = 0;
  while (Date.now() - t0 < ms) {
    const a = ((Date.now() - t0) / ms) * 2 * Math.PI;
    await page.mouse.move(x + r * Math.sin(a), y - r * (1 - Math.cos(a)) * 0.5 - r * Math.sin(a) * 0.3);
    moves++;
    await page.waitForTimeout(5);
  }
  return moves;
}

/** Numbers in `text` (ASCII or Unicode minus). */
const numbers = (text) => [...text.replaceAll('−', '-').matchAll(/(?<![\w.])-?\d+(?:\.\d+)?(?:e-?\d+)?/g)].map((m) => Number(m[0]));
const readout = (page, key) => page.evaluate((k) => Number(document.querySelector(`[data-readout="${k}"]`).textContent.replaceAll('−', '-')), key);
const near = (a, b, rel) => Math.abs(a - b) <= rel * Math.max(Math.abs(b), 1e-9);

test('live summaries are paced while dragging (≤ 8 changes in 2 s) and end on the final readouts', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 1920, height: 1080 } });
  try {
    const cases = [
      {
        name: 'IK tip drag',
        hash: '#/ik-2r',
        live: 'ik-2r-live',
        async ready() {
          // The page's second stage (its form's error lines are live regions) is in.
          await page.waitForSelector('[data-testid="ik-2r-heatmap"][data-marker-q1]');
        },
        async drag() {
          await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
          const g = await page.locator('[data-testid="ik-2r-canvas"]').evaluate((c) => {
            const r = c.getBoundingClientRect();
            return { x: r.left + Number(c.dataset.tipX), y: r.top + Number(c.dataset.tipY) };
          });
          return circleDrag(page, [g.x, g.y], 60);
        },
        async check(text) {
          const [q1, q2, x, y] = await Promise.all(['q1_deg', 'q2_deg', 'x_mm', 'y_mm'].map((k) => readout(page, k)));
          const said = numbers(text);
          assert.deepEqual(said.slice(0, 4), [q1, q2, x, y].map(Math.round), `${text} vs q1 ${q1}°, q2 ${q2}°, x ${x}, y ${y} mm`);
        },
      },
      {
        name: 'cubic-path q1 slider drag',
        hash: '#/cubic-path',
        live: 'cubic-live',
        async drag() {
          const slider = page.locator('[data-slider="q1"]');
          await slider.scrollIntoViewIfNeeded();
          const box = await slider.boundingBox();
          const f = await slider.evaluate((s) => (s.value - s.min) / (s.max - s.min));
          const x = box.x + 8 + f * (box.width - 16);
          return circleDrag(page, [x, box.y + box.height / 2], Math.min(60, box.width / 3));
        },
        async check(text) {
          const [q1, T, peak] = numbers(text);
          assert.equal(q1, Number(await page.locator('[data-slider="q1"]').inputValue()), text);
          assert.equal(T, 1, text);
          assert.ok(near(peak, await readout(page, 'peak-velocity'), 1e-3), `${text} vs ${await readout(page, 'peak-velocity')}`);
        },
      },
      {
        name: 'Umeyama point drag',
        hash: '#/umeyama-2d',
        live: 'ume-live',
        async drag() {
          const c = page.locator('[data-testid="umeyama-2d-canvas"]');
          await c.scrollIntoViewIfNeeded();
          const box = await c.boundingBox();
          const [px, py] = await c.evaluate((el) => el.dataset.pointsPx.split(';')[0].split(',').map(Number));
          return circleDrag(page, [box.x + px, box.y + py], 40);
        },
        async check(text) {
          const [scale, angle, rmse] = numbers(text);
          assert.ok(near(scale, await readout(page, 'scale'), 1e-3), `${text}: scale ${await readout(page, 'scale')}`);
          assert.ok(near(angle, await readout(page, 'angle'), 1e-3), `${text}: angle ${await readout(page, 'angle')}`);
          assert.ok(near(rmse, await readout(page, 'rmse'), 5e-3), `${text}: rmse ${await readout(page, 'rmse')}`);
        },
      },
    ];
    for (const c of cases) {
      await page.goto(`${server.url}/${c.hash}`);
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      await c.ready?.();
      await page.waitForTimeout(300);
      await page.evaluate(watchLive);
      const moves = await c.drag();
      const during = await page.evaluate(() => window.__liveChanges.slice());
      await page.mouse.up();
      assert.ok(moves >= 20, `${c.name}: ${moves} pointer moves`);
      assert.ok(during.length <= 8, `${c.name}: ${during.length} live changes in 2 s:\n${during.join('\n')}`);
      // Once the drag ends the summary catches up with what the readouts show.
      const live = page.locator(`[data-testid="${c.live}"]`);
      await page.waitForTimeout(1500);
      const text = await live.textContent();
      assert.ok(text.length > 0, `${c.name}: the live region said nothing`);
      await c.check(text);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** Elements (or their ::before / ::after) with a transition or an animation longer than 10 ms. */
function movingStyles() {
  const longest = (list) => Math.max(0, ...list.split(',').map((d) => (d.trim().endsWith('ms') ? parseFloat(d) / 1000 : parseFloat(d))));
  const found = [];
  for (const e of document.querySelectorAll('body *')) {
    for (const pseudo of [null, '::before', '::after']) {
      const s = getComputedStyle(e, pseudo);
      const moving = longest(s.transitionDuration) > 0.01 || (s.animationName !== 'none' && longest(s.animationDuration) > 0.01);
      if (moving) found.push(`${e.tagName.toLowerCase()}.${e.className}${pseudo ?? ''}: transition ${s.transitionDuration}, animation ${s.animationName} ${s.animationDuration}`);
    }
  }
  return found;
}

test('prefers-reduced-motion: nothing plays by itself, the DH walk jumps, no CSS motion; Play still plays', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    await page.emulateMedia({ reducedMotion: 'reduce' });
    // No CSS transition or animation anywhere (the drills page's busy spinner included).
    const problems = [];
    for (const route of await routes(page)) {
      await open(page, route);
      for (const line of await page.evaluate(movingStyles)) problems.push(`${route}: ${line}`);
    }
    await open(page, 'drills');
    await page.evaluate(() => document.querySelector('[data-testid="drills-run"]').setAttribute('aria-busy', 'true'));
    for (const line of await page.evaluate(movingStyles)) problems.push(`drills (busy): ${line}`);
    assert.deepEqual(problems, []);

    // The pendulum waits for Play: t stays 0 for a second, then Play moves it.
    await open(page, 'pendulum-energy');
    const t = () => page.evaluate(() => Number(document.querySelector('[data-readout="t"]').dataset.value));
    await page.waitForTimeout(1000);
    assert.equal(await t(), 0, 'no autoplay');
    await page.locator('[data-action="run"]').click();
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) > 0.05, null, { timeout: 3000 });
    await page.locator('[data-action="run"]').click();

    // The RRT does not grow by itself.
    await open(page, 'rrt-2d');
    const it = await page.locator('[data-readout="iteration"]').textContent();
    await page.waitForTimeout(700);
    assert.equal(await page.locator('[data-readout="iteration"]').textContent(), it);

    // The DH row walk: a step lands at once (no tween) with reduced motion, and tweens without.
    const stepFrames = async () => {
      await page.goto(`${server.url}/#/dh-fk?row=3&step=1`);
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      await page.waitForTimeout(400);
      const canvas = page.locator('[data-testid="dh-fk-canvas"]');
      await page.locator('[data-action="step"]').first().click();
      await settle(page);
      const early = await canvas.evaluate((c) => c.toDataURL());
      await page.waitForTimeout(900);
      const late = await canvas.evaluate((c) => c.toDataURL());
      return early === late;
    };
    assert.equal(await stepFrames(), true, 'reduced motion: the frame is where it ends one frame after the step');
    await page.emulateMedia({ reducedMotion: 'no-preference' });
    assert.equal(await stepFrames(), false, 'without the preference the frame moves there');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the RRT world by keyboard: n chooses start, goal or a box, Shift + arrows move it as a drag would (URL, refusals), Delete removes the box', async () => {
  const { page, errors, close } = await openApp(server.url, '#/rrt-2d');
  try {
    await page.waitForSelector('[data-testid="rrt-2d-canvas"]');
    const target = page.locator('[data-testid="rrt-2d-key-target"]');
    await page.locator('[data-testid="rrt-2d-canvas"]').focus();
    await page.keyboard.press('n');
    assert.equal(await target.textContent(), 'Shift + arrows move the start.');
    for (let k = 0; k < 3; k++) await page.keyboard.press('Shift+ArrowRight');
    await page.keyboard.press('Shift+ArrowUp');
    await page.waitForFunction(() => /start=0\.13(%2C|,)0\.11/.test(location.hash), null, { timeout: 3000 });
    assert.equal(await page.locator('[data-readout="iteration"]').textContent(), '0', 'the run starts again');
    // Out of the square is refused with the drag's message; the start stays at the edge.
    for (let k = 0; k < 12; k++) await page.keyboard.press('Shift+ArrowDown');
    await page.waitForFunction(() => /start=0\.13(%2C|,)0(&|$)/.test(location.hash), null, { timeout: 3000 });
    assert.match(await page.locator('[data-testid="rrt-2d-world-message"]').textContent(), /start/);
    // The goal, then the recipe's box: pushed into the box, the goal is refused with the message.
    await page.keyboard.press('n');
    assert.equal(await target.textContent(), 'Shift + arrows move the goal.');
    await page.keyboard.press('n');
    assert.equal(await target.textContent(), 'Shift + arrows move box 1.');
    await page.keyboard.press('Shift+ArrowDown');
    await page.waitForFunction(() => /obstacle=/.test(location.hash), null, { timeout: 3000 });
    await page.keyboard.press('Delete');
    await page.waitForFunction(() => /obstacle=none/.test(location.hash), null, { timeout: 3000 });
    assert.equal(await target.isVisible(), false);
    // Keys of the ? overlay.
    await page.keyboard.press('?');
    assert.match(await page.locator('[data-testid="page-keys"]').innerText(), /Shift \+ arrows move/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
