// Keyboard and screen-reader access beyond what axe-core checks (a11y.test.mjs): Tab reaches
// every visible control of every route with a visible focus ring and no pointer-only element;
// every canvas has a localized name and a text alternative; the live summaries are paced while
// dragging; with `prefers-reduced-motion: reduce` nothing moves by itself.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { closeBrowser, openApp, startServer } from './harness.mjs';

let server;
before(async () => {
  server = await startServer();
});
after(async () => {
  await closeBrowser();
  await server?.close();
});

/** Every route of the navigation (home, the drill pages, drills, lesson). */
async function routes(page) {
  return page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
}

async function open(page, route, lang = 'en') {
  await page.goto(`${server.url}/#/${route}?lang=${lang}`);
  await page.waitForFunction((l) => document.documentElement.lang === l && document.documentElement.dataset.appReady === '1', lang);
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
  return { kbd: e.dataset.kbd ?? null, ring, visible, tag: e.tagName.toLowerCase(), testid: e.dataset.testid ?? '', cls: String(e.className) };
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
