// The strict Content-Security-Policy: index.html states it in a <meta http-equiv>, every page
// runs under it without a violation (no inline script, no <style> injection, no style
// attribute, no eval), and the harness really fails a test on a violation or an i18n warning
// (it is made to catch injected ones here).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { basename, join } from 'node:path';
import { serveApp, openApp, takeProblems, seenProblems, assertNoProblems, ROOT } from './harness.mjs';

const POLICY = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self'; object-src 'none'; base-uri 'none'";

const server = serveApp();

/** The chunks' own stylesheets: `<name>.late.css` anywhere under src/ui. */
const LATE_SHEETS = readdirSync(join(ROOT, 'src', 'ui'), { recursive: true })
  .filter((f) => f.endsWith('.late.css'))
  .map((f) => basename(f, '.late.css'));

/** Waits until the harness has seen at least `n` problems (they stay). */
async function problemsAtLeast(n, timeout = 5000) {
  const end = Date.now() + timeout;
  while (seenProblems().length < n && Date.now() < end) {
    await new Promise((r) => setTimeout(r, 50));
  }
  return seenProblems();
}

test('index.html states the strict policy first in <head>, with no inline script, style or handler', () => {
  const html = readFileSync(join(ROOT, 'dist', 'index.html'), 'utf8');
  const metas = [...html.matchAll(/<meta http-equiv="Content-Security-Policy" content="([^"]*)">/g)];
  assert.equal(metas.length, 1);
  assert.equal(metas[0][1], POLICY);
  // Before any script, stylesheet or icon it governs.
  const head = html.slice(0, html.indexOf('</head>'));
  assert.ok(head.indexOf('Content-Security-Policy') < head.search(/<script|<link/), 'the policy comes first');
  // Every <script> has a src; no inline handlers, no <style>, no style= and no data: URL.
  const scripts = [...html.matchAll(/<script\b([^>]*)>([\s\S]*?)<\/script>/g)];
  assert.ok(scripts.length >= 2, 'boot.js and bootstrap.js');
  for (const [, attrs, body] of scripts) {
    assert.match(attrs, /\bsrc="www\/[a-z]+\.js"/, attrs);
    assert.equal(body.trim(), '', `inline script body in <script${attrs}>`);
  }
  assert.doesNotMatch(html, /\son[a-z]+=/, 'an inline event handler');
  assert.doesNotMatch(html, /<style|\sstyle=|data:/);
});

for (const hash of ['#/', '#/drills?recipe=pid-step', '#/ik-2r', '#/drills?recipe=manip-grid&n=40&lang=ja']) {
  test(`${hash} runs under the policy: no violation, styles only from the build's stylesheets`, async () => {
    const { page, errors, close } = await openApp(server.url, hash);
    try {
      const meta = await page.evaluate(
        () => document.querySelector('meta[http-equiv="Content-Security-Policy"]')?.getAttribute('content'),
      );
      assert.equal(meta, POLICY);
      // Styles come from files only: no <style> element; the first stylesheet is www/app.css and
      // holds the page CSS that sits beside the Rust (src/ui/pages/*/style.css); any other is a
      // chunk's or a page's own sheet (`<name>.late.css` in src/ui, www/<name>.css in dist/),
      // linked by the kit with the id late-css-<name> when that part is first drawn.
      const sheets = await page.evaluate(() => ({
        styles: document.querySelectorAll('style').length,
        links: [...document.styleSheets].map((s) => ({
          path: new URL(s.href).pathname,
          id: s.ownerNode?.id ?? '',
        })),
        pageRules: [...document.styleSheets].flatMap((s) => [...s.cssRules])
          .filter((r) => /^\.(drills|ik2r|rrt|sig|pendulum)\b/.test(r.selectorText ?? '')).length,
      }));
      assert.equal(sheets.styles, 0);
      assert.equal(sheets.links[0]?.path, '/www/app.css');
      for (const { path, id } of sheets.links.slice(1)) {
        const name = path.match(/^\/www\/([a-z0-9_]+)\.css$/)?.[1];
        assert.ok(name && LATE_SHEETS.includes(name), `a stylesheet that is no chunk's: ${path}`);
        assert.equal(id, `late-css-${name}`, `${path} linked by the kit`);
      }
      assert.ok(sheets.pageRules > 20, `page rules in app.css: ${sheets.pageRules}`);
      if (hash.startsWith('#/drills')) {
        // The drills stylesheet is in effect (its layout grid), not only present.
        await page.locator('[data-testid="drills-page"]').waitFor();
        const display = await page.locator('.drills-layout').evaluate((el) => getComputedStyle(el).display);
        assert.equal(display, 'grid');
      }
      // Give late work (debounced runs, URL writes) a moment to violate the policy.
      await page.waitForTimeout(400);
      assert.deepEqual(takeProblems(), []);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('the harness catches an inline script, a style attribute, eval and an i18n warning', async () => {
  const { page, close } = await openApp(server.url, '#/');
  try {
    const outcome = await page.evaluate(async () => {
      // Playwright's evaluate itself is exempt from the page's CSP; these are not.
      const script = document.createElement('script');
      script.textContent = 'window.__inlineRan = true;';
      document.body.append(script);
      const box = document.createElement('div');
      document.body.append(box);
      box.setAttribute('style', 'color: rgb(255, 0, 0)');
      // A string timer is eval (compiled later, in the page's own task).
      setTimeout('window.__evalRan = true;', 0);
      await new Promise((r) => setTimeout(r, 100));
      console.warn("i18n: message 'kit-no-such-id' is missing in every language");
      return { inlineRan: window.__inlineRan === true, colour: getComputedStyle(box).color, evalRan: window.__evalRan === true };
    });
    assert.equal(outcome.inlineRan, false, 'the inline script must not run');
    assert.notEqual(outcome.colour, 'rgb(255, 0, 0)', 'the style attribute must not apply');
    assert.equal(outcome.evalRan, false, 'eval must be blocked');
    const seen = await problemsAtLeast(4);
    const csp = seen.filter((p) => p.kind === 'csp').map((p) => p.text);
    const i18n = seen.filter((p) => p.kind === 'i18n').map((p) => p.text);
    assert.equal(csp.length, 3, csp.join('\n'));
    assert.ok(csp.some((t) => /^script-src-elem blocked inline/.test(t)), csp.join('\n'));
    assert.ok(csp.some((t) => /^style-src-attr blocked inline/.test(t)), csp.join('\n'));
    assert.ok(csp.some((t) => /^script-src blocked eval/.test(t)), csp.join('\n'));
    assert.deepEqual(i18n, ["i18n: message 'kit-no-such-id' is missing in every language"]);
    // What the afterEach hook of every e2e file does with them: fail the test, naming each
    // (and clear them, so that this test itself passes).
    assert.throws(() => assertNoProblems(), (e) => {
      assert.match(e.message, /reported 4 problem\(s\)/);
      assert.match(e.message, /csp: script-src-elem blocked inline/);
      assert.match(e.message, /i18n: i18n: message 'kit-no-such-id'/);
      return true;
    });
    assert.deepEqual(seenProblems(), []);
  } finally {
    await close();
  }
});
