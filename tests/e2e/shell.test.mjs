// The app shell in headless Chromium: English and Japanese rendering and switching without a
// reload, ?lang= in the URL, the saved language, the ? shortcut overlay, projector mode, the
// not-found route, the home page's recipe cards, and a phone-width layout without horizontal
// scrolling. Screenshots of the home page go to tests/e2e/out/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { startServer, openApp, closeBrowser, browser, OUT, ROOT } from './harness.mjs';

let server;
before(async () => {
  server = await startServer();
});
after(async () => {
  await closeBrowser();
  await server?.close();
});

const DISCLAIMER_EN = 'Research, education and simulation only.';
const DISCLAIMER_JA = '研究・教育・シミュレーション専用です。';
const HEADLINE_EN = 'Robotics: simulate, sample, log — then practice teleop';

const text = (page, selector) => page.locator(selector).first().innerText();

/** The visible strings the language switch must change. */
async function shellTexts(page) {
  return {
    subtitle: await text(page, '[data-testid="brand-subtitle"]'),
    navHome: await text(page, '[data-testid="nav-home"]'),
    disclaimer: await text(page, '[data-testid="disclaimer"]'),
    headline: await text(page, '[data-testid="home-headline"]'),
    langButton: await text(page, '[data-testid="lang-switch"]'),
    htmlLang: await page.evaluate(() => document.documentElement.lang),
    title: await page.title(),
  };
}

test('the shell renders in English with the home page, navigation and disclaimer', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const t = await shellTexts(page);
    assert.equal(t.htmlLang, 'en');
    assert.equal(t.headline, HEADLINE_EN);
    assert.equal(t.navHome, 'Home');
    assert.equal(t.langButton, '日本語');
    assert.ok(t.disclaimer.startsWith(DISCLAIMER_EN), t.disclaimer);
    assert.match(await text(page, '[data-testid="site-footer"]'), /Works offline; no data leaves this page\./);
    assert.match(await text(page, '[data-testid="brand"]'), /BSV Playground/);
    assert.match(t.title, /^BSV Playground/);
    // Only pages that exist are in the navigation: home, the IK page, the pendulum, trajectory
    // resampling, the RRT stepper, the three signal pages and all drills.
    const navIds = await page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
    assert.deepEqual(navIds, ['home', 'ik-2r', 'pendulum-energy', 'traj-resample', 'rrt-2d', 'cubic-path', 'pid-step', 'trapezoid-profile', 'teleop', 'drills']);
    assert.equal(await page.locator('[data-testid="nav-home"]').getAttribute('aria-current'), 'page');
    // Twelve recipe cards, each with both command lines and a link to its drill; the IK ones
    // also link to the IK page.
    assert.equal(await page.locator('.recipe-card').count(), 12);
    const ik = page.locator('[data-testid="recipe-card-ik-workspace"]');
    assert.match(await ik.locator('[data-command="cli"] code').innerText(), /^bsv ik-workspace 0\.12 0\.10 200 10$/);
    assert.match(await ik.locator('[data-command="python"] code').innerText(), /^python planar_ik_workspace\.py 0\.12 0\.10 200 10$/);
    assert.equal(await ik.locator('[data-testid="recipe-link-ik-workspace"]').getAttribute('href'), '#/ik-2r');
    assert.equal(await ik.locator('[data-testid="recipe-drill-ik-workspace"]').getAttribute('href'), '#/drills?recipe=ik-workspace');
    // Recipes with a page of their own pair with it: the "Pairs with" line and the card's foot link.
    for (const id of ['pendulum-energy', 'rrt-2d', 'cubic-path', 'pid-step', 'trapezoid-profile']) {
      const card = page.locator(`[data-testid="recipe-card-${id}"]`);
      assert.doesNotMatch(await card.innerText(), /command line today/);
      assert.deepEqual(await card.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href'))), [`#/${id}`, `#/drills?recipe=${id}`, `#/${id}`]);
      assert.match(await card.locator('.recipe-pairs').innerText(), /^Pairs with the /);
    }
    const pid = page.locator('[data-testid="recipe-card-pid-step"]');
    assert.match(await pid.innerText(), /In the browser:\s*Run this drill\W*PID step response/);
    // A recipe without a page of its own links to its drill only.
    const se3 = page.locator('[data-testid="recipe-card-se3-relative"]');
    assert.deepEqual(await se3.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href'))), ['#/drills?recipe=se3-relative']);
    // The featured card is the IK playground.
    assert.equal(await page.locator('[data-testid="featured-ik-2r"]').getAttribute('href'), '#/ik-2r');
    // No message id leaked through untranslated (a missing message shows its id).
    const body = await page.locator('body').innerText();
    assert.doesNotMatch(body, /\b(recipe|home|nav|footer|app|key|overlay)-[a-z0-9-]+\b(?![.\w])/, 'a raw message id is visible');
    await page.screenshot({ path: join(OUT, 'home-en.png'), fullPage: true });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the language switch re-renders everything in Japanese and back, without a reload', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    await page.evaluate(() => { window.__noReload = true; });
    await page.click('[data-testid="lang-switch"]');
    const ja = await shellTexts(page);
    assert.equal(ja.htmlLang, 'ja');
    assert.equal(ja.langButton, 'English');
    assert.equal(ja.navHome, 'ホーム');
    assert.equal(ja.subtitle, 'ブラウザで動くロボット工学ドリル');
    assert.ok(ja.disclaimer.startsWith(DISCLAIMER_JA), ja.disclaimer);
    assert.match(ja.headline, /ロボティクス/);
    assert.match(ja.title, /BSV Playground — ブラウザで動くロボット工学ドリル/);
    assert.match(await text(page, '[data-testid="recipe-card-pid-step"] h3'), /PID/);
    assert.match(await text(page, '[data-testid="recipe-card-pid-step"]'), /コマンドライン/);
    assert.equal(await page.locator('[data-testid="lang-switch"]').getAttribute('lang'), 'en');
    // The choice is in the URL (a copied link opens in Japanese) and saved.
    assert.match(page.url(), /[?&]lang=ja\b/);
    assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lang')), 'ja');
    assert.equal(await page.evaluate(() => window.__noReload), true, 'the page reloaded');
    await page.screenshot({ path: join(OUT, 'home-ja.png'), fullPage: true });

    await page.click('[data-testid="lang-switch"]');
    const en = await shellTexts(page);
    assert.equal(en.htmlLang, 'en');
    assert.equal(en.headline, HEADLINE_EN);
    assert.equal(en.navHome, 'Home');
    assert.ok(en.disclaimer.startsWith(DISCLAIMER_EN));
    assert.match(page.url(), /[?&]lang=en\b/);
    assert.equal(await page.evaluate(() => window.__noReload), true, 'the page reloaded');

    // `l` switches too.
    await page.keyboard.press('l');
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'ja');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('?lang=ja in the URL opens Japanese; a saved choice and the browser language apply otherwise', async () => {
  {
    const { page, errors, close } = await openApp(server.url, '#/?lang=ja');
    try {
      const t = await shellTexts(page);
      assert.equal(t.htmlLang, 'ja');
      assert.equal(t.navHome, 'ホーム');
      assert.ok(t.disclaimer.startsWith(DISCLAIMER_JA));
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  {
    // Browser in Japanese, nothing saved: Japanese, and the URL stays free of lang=.
    const { page, errors, close } = await openApp(server.url, '#/', { locale: 'ja-JP' });
    try {
      assert.equal(await page.evaluate(() => document.documentElement.lang), 'ja');
      assert.doesNotMatch(page.url(), /lang=/);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  {
    // Saved English beats a Japanese browser; ?lang= beats both.
    const { page, close } = await openApp(server.url, '#/', { locale: 'ja-JP', storage: { 'bsv.lang': 'en' } });
    try {
      assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
    } finally {
      await close();
    }
    const second = await openApp(server.url, '#/?lang=ja', { storage: { 'bsv.lang': 'en' } });
    try {
      assert.equal(await second.page.evaluate(() => document.documentElement.lang), 'ja');
    } finally {
      await second.close();
    }
  }
});

test('? opens the shortcut overlay, focus stays inside it, Escape closes it', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    await page.keyboard.press('?');
    const dialog = page.locator('[data-testid="shortcut-overlay"]');
    await dialog.waitFor({ state: 'visible' });
    assert.equal(await dialog.getAttribute('role'), 'dialog');
    assert.equal(await dialog.getAttribute('aria-modal'), 'true');
    const keys = await dialog.locator('[data-testid="shell-keys"] kbd').allInnerTexts();
    assert.deepEqual(keys, ['?', 'P', 'L', 'Esc']);
    assert.match(await dialog.innerText(), /Projector mode on or off/);
    // Focus starts on the close button and Tab cannot leave the dialog.
    assert.equal(await page.evaluate(() => document.activeElement?.dataset.testid), 'overlay-close');
    for (let i = 0; i < 3; i += 1) {
      await page.keyboard.press('Tab');
      assert.ok(await page.evaluate(() => !!document.activeElement?.closest('[data-testid="shortcut-overlay"]')));
    }
    // Shell keys do nothing while it is open.
    await page.keyboard.press('p');
    assert.equal(await page.evaluate(() => document.documentElement.classList.contains('projector')), false);
    await page.keyboard.press('Escape');
    await dialog.waitFor({ state: 'detached' });
    assert.equal(await page.evaluate(() => document.getElementById('app').hasAttribute('inert')), false);

    // The ? button opens it too, in the current language; the close button closes it.
    await page.click('[data-testid="lang-switch"]');
    await page.click('[data-testid="help-button"]');
    await dialog.waitFor({ state: 'visible' });
    assert.match(await dialog.innerText(), /キーボードショートカット/);
    await page.click('[data-testid="overlay-close"]');
    await dialog.waitFor({ state: 'detached' });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('p toggles projector mode, which is saved; keys are ignored while typing', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const on = () => page.evaluate(() => document.documentElement.classList.contains('projector'));
    const fontSize = () => page.evaluate(() => parseFloat(getComputedStyle(document.documentElement).fontSize));
    const base = await fontSize();
    assert.equal(await on(), false);
    await page.keyboard.press('p');
    assert.equal(await on(), true);
    assert.ok((await fontSize()) >= base * 1.3, 'projector type is larger');
    assert.equal(await page.locator('[data-testid="projector-toggle"]').getAttribute('aria-pressed'), 'true');
    assert.equal(await page.evaluate(() => localStorage.getItem('bsv.projector')), '1');
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    assert.equal(await on(), true, 'projector mode survives a reload');
    await page.click('[data-testid="projector-toggle"]');
    assert.equal(await on(), false);

    // Typing "p", "l" and "?" into a text field changes nothing.
    await page.evaluate(() => {
      const input = document.createElement('input');
      input.id = 'probe';
      document.getElementById('app-main').prepend(input);
    });
    await page.focus('#probe');
    await page.keyboard.type('pl?');
    assert.equal(await on(), false);
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
    assert.equal(await page.locator('[data-testid="shortcut-overlay"]').count(), 0);
    assert.equal(await page.inputValue('#probe'), 'pl?');
    // Ctrl+P (print) and presenter-remote keys are not taken by the shell.
    await page.locator('#probe').blur();
    await page.keyboard.press('PageDown');
    await page.keyboard.press('b');
    assert.equal(await on(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('an unknown route shows a localized not-found page with a link home', async () => {
  const { page, errors, close } = await openApp(server.url, '#/no-such-page?x=1');
  try {
    const notFound = page.locator('[data-testid="not-found"]');
    await notFound.waitFor();
    assert.match(await notFound.innerText(), /Page not found/);
    assert.match(await page.title(), /Page not found — BSV Playground/);
    await page.click('[data-testid="lang-switch"]');
    assert.match(await notFound.innerText(), /ページが見つかりません/);
    await page.click('[data-testid="not-found-home"]');
    await page.locator('[data-testid="home-headline"]').waitFor();
    assert.match(await text(page, '[data-testid="home-headline"]'), /ロボティクス/);
    // Still Japanese after navigating, and the URL keeps lang=ja.
    assert.match(page.url(), /#\/\?lang=ja$/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('navigating to the IK page and back re-mounts pages through the hash', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    await page.click('[data-testid="nav-ik-2r"]');
    await page.waitForFunction(() => location.hash.startsWith('#/ik-2r'));
    await page.waitForFunction(() => document.querySelector('[data-testid="nav-ik-2r"]')?.getAttribute('aria-current') === 'page');
    assert.equal(await page.locator('[data-testid="home-headline"]').count(), 0);
    assert.match(await page.title(), /— BSV Playground$/);
    await page.goBack();
    await page.locator('[data-testid="home-headline"]').waitFor();
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('at phone width (390x844) the home page has no horizontal scroll and the nav wraps', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 390, height: 844 } });
  try {
    const widths = await page.evaluate(() => ({
      scroll: document.documentElement.scrollWidth,
      client: document.documentElement.clientWidth,
    }));
    assert.ok(widths.scroll <= widths.client, `page is ${widths.scroll}px wide in a ${widths.client}px viewport`);
    await page.screenshot({ path: join(OUT, 'home-390.png'), fullPage: false });
    await page.click('[data-testid="lang-switch"]');
    const ja = await page.evaluate(() => document.documentElement.scrollWidth <= document.documentElement.clientWidth);
    assert.ok(ja, 'Japanese page scrolls horizontally at 390px');
    await page.screenshot({ path: join(OUT, 'home-390-ja.png'), fullPage: false });
    // Buttons are comfortable touch targets.
    const box = await page.locator('[data-testid="lang-switch"]').boundingBox();
    assert.ok(box.height >= 40 && box.width >= 40, JSON.stringify(box));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('when the app cannot start, a bilingual message says why (wasm missing, file://)', async () => {
  const context = await (await browser()).newContext();
  try {
    const page = await context.newPage();
    await page.route('**/*.wasm', (route) => route.fulfill({ status: 404, body: 'not found' }));
    await page.goto(`${server.url}/#/`);
    const box = page.locator('[data-testid="boot-error"]');
    await box.waitFor({ timeout: 20000 });
    const shown = await box.innerText();
    assert.match(shown, /BSV Playground could not start\./);
    assert.match(shown, /BSV Playground を起動できませんでした。/);
    assert.match(shown, /Reload the page/);

    const local = await context.newPage();
    await local.goto(`${pathToFileURL(join(ROOT, 'dist', 'index.html')).href}#/`);
    const fileBox = local.locator('[data-testid="boot-error"]');
    await fileBox.waitFor({ timeout: 20000 });
    const fileText = await fileBox.innerText();
    assert.match(fileText, /make serve/);
    assert.match(fileText, /file:\/\//);
    assert.match(fileText, /ファイルとして開かれています/);
  } finally {
    await context.close();
  }
});

// ---------- Phone, projector, focus and keys, measured as a user sees them ----------

/** Visible controls under `root` smaller than `min` px in height (or width, for buttons). */
function smallTargets([root, min]) {
  const out = [];
  const sel = 'a[href], button, summary, select, input:not([type="hidden"]):not([type="checkbox"]):not([type="radio"]):not([type="range"]), label:has(> input[type="checkbox"]), label:has(> input[type="radio"])';
  for (const el of document.querySelector(root).querySelectorAll(sel)) {
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.height === 0 || el.closest('p')) continue; // hidden; inline text links are exempt
    const tooNarrow = el.matches('button') && r.width < min;
    if (r.height < min - 0.01 || tooNarrow) out.push(`${el.tagName.toLowerCase()}.${el.className || el.dataset.testid || ''} ${r.width.toFixed(0)}×${r.height.toFixed(1)}`);
  }
  return out;
}

/** The smallest computed font size of any visible text on the page, and where. */
function smallestText() {
  let min = { px: Infinity, where: '' };
  const walker = document.createTreeWalker(document.getElementById('app'), NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (!node.textContent.trim()) continue;
    const el = node.parentElement;
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.height === 0 || el.closest('[hidden]')) continue;
    const cs = getComputedStyle(el);
    if (cs.visibility === 'hidden' || cs.clipPath === 'inset(50%)') continue; // screen-reader only
    const px = parseFloat(cs.fontSize);
    if (px < min.px) min = { px, where: `${el.tagName.toLowerCase()}.${el.className}: ${node.textContent.trim().slice(0, 30)}` };
  }
  return min;
}

/** WCAG contrast ratio of a computed rgb() colour against white. */
function contrastOnWhite(rgb) {
  const [r, g, b] = rgb.match(/[\d.]+/g).slice(0, 3).map(Number).map((c) => {
    const s = c / 255;
    return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  });
  const l = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return 1.05 / (l + 0.05);
}

test('at phone width every tap target is at least 44 px and the header is compact', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 390, height: 844 } });
  try {
    for (const lang of ['en', 'ja']) {
      assert.deepEqual(await page.evaluate(smallTargets, ['.site-header', 44]), [], `${lang} header`);
      assert.deepEqual(await page.evaluate(smallTargets, ['#app-main', 44]), [], `${lang} home page`);
      const header = await page.locator('[data-testid="site-header"]').boundingBox();
      assert.ok(header.height <= 110, `${lang}: the header takes ${header.height} px of 844`);
      // The brand, the tools and the three navigation links all show.
      for (const id of ['brand', 'lang-switch', 'projector-toggle', 'help-button', 'nav-home', 'nav-ik-2r', 'nav-drills']) {
        const box = await page.locator(`[data-testid="${id}"]`).boundingBox();
        assert.ok(box && box.y >= 0 && box.y + box.height <= header.y + header.height + 0.5, `${lang}: ${id} inside the header`);
      }
      // The subtitle is still there for screen readers.
      assert.ok((await page.locator('[data-testid="brand-subtitle"]').textContent()).length > 5);
      if (lang === 'en') await page.click('[data-testid="lang-switch"]');
    }
    await page.screenshot({ path: join(OUT, 'home-390-compact.png'), fullPage: false });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a localized skip link is the first focusable element and moves focus to the content', async () => {
  const { page, errors, close } = await openApp(server.url, '#/?lang=ja');
  try {
    const skip = page.locator('[data-testid="skip-link"]');
    assert.equal(await skip.innerText(), '本文へ移動');
    // Off screen until focused.
    assert.ok((await skip.boundingBox()).y + (await skip.boundingBox()).height <= 0);
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement?.dataset.testid), 'skip-link');
    const box = await skip.boundingBox();
    assert.ok(box.y >= 0 && box.height >= 44, `focused skip link at ${JSON.stringify(box)}`);
    const hash = await page.evaluate(() => location.hash);
    await page.keyboard.press('Enter');
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'app-main');
    assert.equal(await page.evaluate(() => location.hash), hash, 'the route stays');
    assert.equal(await page.locator('[data-testid="home-headline"]').count(), 1);
    await page.click('[data-testid="lang-switch"]');
    assert.equal(await skip.innerText(), 'Skip to content');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('in projector mode at 1920x1080 no text on the home page is under 24 px', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 1920, height: 1080 } });
  try {
    const before = await page.evaluate(smallestText);
    assert.ok(before.px < 24, `without projector mode the smallest text is ${before.px} px`);
    await page.keyboard.press('p');
    const min = await page.evaluate(smallestText);
    assert.ok(min.px >= 24, `smallest text ${min.px} px (${min.where})`);
    assert.ok(await page.evaluate(() => parseFloat(getComputedStyle(document.documentElement).fontSize)) >= 24);
    await page.screenshot({ path: join(OUT, 'home-projector-1920.png'), fullPage: false });
    await page.click('[data-testid="lang-switch"]');
    const ja = await page.evaluate(smallestText);
    assert.ok(ja.px >= 24, `Japanese: smallest text ${ja.px} px (${ja.where})`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the focus ring is at least 3:1 against white in the header and inside page content', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r');
  try {
    await page.locator('[data-ik2r="reset"]').waitFor();
    await page.keyboard.press('Tab'); // keyboard modality: programmatic focus shows the ring
    for (const selector of ['[data-testid="nav-home"]', '[data-testid="lang-switch"]', '[data-ik2r="reset"]', '#app-main [data-copy]', '#app-main select', '#app-main input']) {
      const ring = await page.evaluate((s) => {
        const el = document.querySelector(s);
        el.focus();
        const cs = getComputedStyle(el);
        return { style: cs.outlineStyle, width: parseFloat(cs.outlineWidth), color: cs.outlineColor, visible: el.matches(':focus-visible') };
      }, selector);
      assert.ok(ring.visible && ring.style === 'solid' && ring.width >= 3, `${selector}: ${JSON.stringify(ring)}`);
      const ratio = await page.evaluate(contrastOnWhite, ring.color);
      assert.ok(ratio >= 3, `${selector}: ring ${ring.color} is ${ratio.toFixed(2)}:1 on white`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('page keys do nothing while a button has focus and act on the page body', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r');
  try {
    const x = () => page.evaluate(() => Number(document.querySelector('[data-readout="x_mm"]').textContent));
    const frames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await page.locator('[data-readout="x_mm"]').waitFor();
    const x0 = await x();
    await page.locator('[data-ik2r="reset"]').focus();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('w');
    await frames();
    assert.equal(await x(), x0, 'ArrowRight on the focused Reset button moved the tip');
    assert.equal(await page.locator('[data-testid="ik-2r-ws-toggle"]').isChecked(), false);
    // Shell keys still work there (they are not typing).
    await page.keyboard.press('?');
    await page.locator('[data-testid="shortcut-overlay"]').waitFor();
    await page.keyboard.press('Escape');
    // On the page body the same key moves the tip by 1 mm.
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('ArrowRight');
    await frames();
    assert.ok(Math.abs((await x()) - (x0 + 1)) < 1e-3, `x ${x0} -> ${await x()}`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
