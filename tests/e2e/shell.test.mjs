// The app shell in headless Chromium: English and Japanese rendering and switching without a
// reload, ?lang= in the URL, the saved language, the ? shortcut overlay, projector mode, the
// not-found route, the home page's recipe cards, and a phone-width layout without horizontal
// scrolling. Screenshots of the home page go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { serveApp, openApp, browser, OUT, ROOT } from './harness.mjs';

const server = serveApp();

const DISCLAIMER_EN = 'Research, education and simulation only.';
const DISCLAIMER_JA = '研究・教育・シミュレーション専用です。';
const HEADLINE_EN = 'Robotics: simulate, sample, log — then practice teleop';

const text = (page, selector) => page.locator(selector).first().innerText();

/** The app's page table, `[{ id, group }]` in navigation order, from its own glue module. */
const pageTable = (page) =>
  page.evaluate(async () => (await import(new URL('pkg/bsv_playground.js', document.baseURI).href)).pageTable());

/** The navigation the page table asks for: top-level ids, and the menu's groups in order. */
function navFromTable(table) {
  // A teacher's tool page (#/class) has no link in the header.
  const top = table.filter((p) => p.group === null && !p.tool).map((p) => p.id);
  const groups = [...new Set(table.filter((p) => p.group !== null).map((p) => p.group))].map((group) => ({
    heading: `nav-group-${group}-heading`,
    ids: table.filter((p) => p.group === group).map((p) => p.id),
  }));
  return { top, groups };
}

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
    // The navigation is the app's page table in its order: home, then the drills menu (each
    // group under its heading, pages in table order), then the other top-level pages.
    const nav = navFromTable(await pageTable(page));
    assert.equal(nav.top[0], 'home');
    assert.ok(nav.groups.length > 0 && nav.groups.every((g) => g.ids.length > 0));
    const navIds = await page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
    assert.deepEqual(navIds, [nav.top[0], ...nav.groups.flatMap((g) => g.ids), ...nav.top.slice(1)]);
    const topLevel = await page.locator('[data-testid="site-nav"] > ul > li > a').evaluateAll((as) => as.map((a) => a.dataset.page));
    assert.deepEqual(topLevel, nav.top);
    const menuGroups = await page.locator('[data-testid="nav-menu"] .nav-group').evaluateAll((gs) =>
      gs.map((g) => ({ heading: g.querySelector('.nav-group-title').id, ids: [...g.querySelectorAll('a')].map((a) => a.dataset.page) })));
    assert.deepEqual(menuGroups, nav.groups);
    assert.equal(await page.locator('[data-testid="nav-home"]').getAttribute('aria-current'), 'page');
    // Twelve recipe cards, each with both command lines and a link to its drill; the IK ones
    // also link to the IK page.
    assert.equal(await page.locator('.recipe-card').count(), 12);
    // Each card's inputs, files and command lines are behind one disclosure, closed at first.
    const more = page.locator('.recipe-more');
    assert.deepEqual(await more.evaluateAll((ds) => ds.map((d) => d.open)), Array(12).fill(false));
    for (const summary of await page.locator('.recipe-more > summary').all()) await summary.click();
    const ik = page.locator('[data-testid="recipe-card-ik-workspace"]');
    assert.match(await ik.locator('[data-command="cli"] code').innerText(), /^bsv ik-workspace 0\.12 0\.10 200 10$/);
    assert.match(await ik.locator('[data-command="python"] code').innerText(), /^python planar_ik_workspace\.py 0\.12 0\.10 200 10$/);
    assert.equal(await ik.locator('[data-testid="recipe-link-ik-workspace"]').getAttribute('href'), '#/ik-2r');
    assert.equal(await ik.locator('[data-testid="recipe-drill-ik-workspace"]').getAttribute('href'), '#/drills?recipe=ik-workspace');
    // Link texts say where they go: no two links of the home page share an accessible name
    // and a different target.
    const links = await page.locator('#app-main a').evaluateAll((as) => as.map((a) => [a.textContent.replace(/\s+/g, ' ').trim(), a.getAttribute('href')]));
    const byName = new Map();
    for (const [name, href] of links) {
      assert.ok(!byName.has(name) || byName.get(name) === href, `"${name}" goes to ${byName.get(name)} and ${href}`);
      byName.set(name, href);
    }
    assert.match(await ik.locator('[data-testid="recipe-drill-ik-workspace"]').textContent(), /Run this drill: Sample a planar 2-link IK workspace/);
    // Recipes with a page of their own pair with it: the "Pairs with" line and the card's foot link.
    for (const id of ['pendulum-energy', 'rrt-2d', 'se3-relative', 'cubic-path', 'pid-step', 'trapezoid-profile', 'dh-fk', 'umeyama-2d']) {
      const card = page.locator(`[data-testid="recipe-card-${id}"]`);
      assert.doesNotMatch(await card.innerText(), /command line today/);
      assert.deepEqual(await card.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href'))), [`#/${id}`, `#/drills?recipe=${id}`, `#/${id}`]);
      assert.match(await card.locator('.recipe-pairs').innerText(), /^Pairs with the /);
    }
    const pid = page.locator('[data-testid="recipe-card-pid-step"]');
    assert.match(await pid.innerText(), /In the browser:\s*Run this drill\s*(?:: Discrete PID step response \(toy plant\))?\W*PID step response/);
    // Every recipe has a page of its own (the three IK recipes share the IK page).
    for (const id of ['ik-workspace', 'jacobian-2r', 'manip-grid']) {
      assert.ok((await page.locator(`[data-testid="recipe-card-${id}"] a`).evaluateAll((as) => as.map((a) => a.getAttribute('href')))).includes('#/ik-2r'), id);
    }
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
    // The switch is done once the page's strings are in Japanese (fetched first if need be).
    await page.waitForFunction(() => document.querySelector('[data-testid="nav-home"]')?.textContent === 'ホーム');
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
    assert.deepEqual(keys, ['?', 'P', 'L', 'Esc', 'PgDn / PgUp']);
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
    await page.click('[data-testid="nav-menu-button"]');
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
      // The brand, the tools, the two top-level links and the drills menu button all show.
      for (const id of ['brand', 'lang-switch', 'projector-toggle', 'help-button', 'nav-home', 'nav-menu-button', 'nav-drills']) {
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

test('at phone widths the brand shows whole beside the tools, in both languages, and keeps its full name for screen readers', async () => {
  for (const width of [390, 360, 320]) {
    const { page, errors, close } = await openApp(server.url, '#/ik-2r', { viewport: { width, height: 740 } });
    try {
      for (const lang of ['en', 'ja']) {
        const brand = await page.locator('.brand-short').boundingBox();
        const tools = await page.locator('[data-testid="lesson-add"]').boundingBox();
        assert.ok(brand && brand.x >= 0 && brand.x + brand.width <= tools.x, `${width}px ${lang}: the brand ${JSON.stringify(brand)} ends before the tools ${JSON.stringify(tools)}`);
        const tail = await page.locator('[data-testid="help-button"]').boundingBox();
        assert.ok(tail.x + tail.width <= width, `${width}px ${lang}: the tools end on screen`);
        // The accessible names are the full ones.
        const names = await page.evaluate(() => ({
          brand: document.querySelector('[data-testid="brand"] .brand-full').textContent,
          add: document.querySelector('[data-testid="lesson-add"] .tool-full').textContent,
          hidden: [...document.querySelectorAll('.brand-short, .tool-short')].every((e) => e.getAttribute('aria-hidden') === 'true'),
        }));
        assert.equal(names.brand, 'BSV Playground');
        assert.ok(names.add.length > 3 && names.hidden, `${width}px ${lang}: ${JSON.stringify(names)}`);
        if (lang === 'en') await page.click('[data-testid="lang-switch"]');
      }
      await page.screenshot({ path: join(OUT, `ik2r-header-${width}-ja.png`), fullPage: false });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the drills menu groups the drill pages, closes on Escape, outside and navigation, and marks its button on a drill page', async () => {
  for (const viewport of [{ width: 1920, height: 1080 }, { width: 390, height: 844 }]) {
    const { page, errors, close } = await openApp(server.url, '#/', { viewport });
    try {
      const button = page.locator('[data-testid="nav-menu-button"]');
      const menu = page.locator('[data-testid="nav-menu"]');
      assert.equal(await button.getAttribute('aria-expanded'), 'false');
      assert.equal(await menu.isVisible(), false);
      await button.click();
      assert.equal(await button.getAttribute('aria-expanded'), 'true');
      await menu.waitFor({ state: 'visible' });
      assert.deepEqual(await menu.locator('.nav-group-title').allInnerTexts(), ['KINEMATICS', 'DYNAMICS AND CONTROL', 'TRAJECTORIES', 'PLANNING']);
      // Every link of the open menu is on screen, and the header stays one row at 1920 px.
      for (const box of await menu.locator('a').evaluateAll((as) => as.map((a) => a.getBoundingClientRect().toJSON()))) {
        assert.ok(box.left >= 0 && box.right <= viewport.width + 0.5 && box.height >= (viewport.width < 600 ? 44 : 36), JSON.stringify(box));
      }
      if (viewport.width === 1920) {
        const header = await page.locator('[data-testid="site-header"]').boundingBox();
        assert.ok(header.height < 90, `header ${header.height} px`);
        await page.screenshot({ path: join(OUT, 'nav-menu-1920.png') });
      } else {
        await page.screenshot({ path: join(OUT, 'nav-menu-390.png') });
      }
      await page.keyboard.press('Escape');
      assert.equal(await button.getAttribute('aria-expanded'), 'false');
      assert.equal(await page.evaluate(() => document.activeElement?.dataset.testid), 'nav-menu-button');
      await button.click();
      await page.mouse.click(5, viewport.height - 5);
      await menu.waitFor({ state: 'hidden', timeout: 2000 });
      await button.click();
      await page.click('[data-testid="nav-rrt-2d"]');
      await page.waitForFunction(() => location.hash.startsWith('#/rrt-2d'));
      // The menu closes with the navigation (the route change may land a task later).
      await menu.waitFor({ state: 'hidden', timeout: 2000 });
      assert.match(await button.getAttribute('class'), /has-current/);
      assert.equal(await page.locator('[data-testid="nav-rrt-2d"]').getAttribute('aria-current'), 'page');
      await page.click('[data-testid="nav-home"]');
      await page.waitForFunction(() => !document.querySelector('[data-testid="nav-menu-button"]').classList.contains('has-current'));
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('drill pages end with the seed\'s next-step chain; the home page has none', async () => {
  const { page, errors, close } = await openApp(server.url, '#/rrt-2d');
  try {
    const chain = page.locator('[data-testid="drill-chain"]');
    await chain.waitFor({ state: 'visible' });
    assert.equal(await page.locator('[data-testid="chain-next"] span').innerText(), 'Run a discrete PID step response next.');
    assert.equal(await page.locator('[data-testid="chain-next-link"]').innerText(), 'PID step response');
    assert.equal(await page.locator('[data-testid="chain-next-link"]').getAttribute('href'), '#/pid-step');
    assert.deepEqual(await chain.locator('[aria-current="step"]').evaluateAll((as) => as.map((a) => a.dataset.step)), ['rrt-2d']);
    const steps = await chain.locator('.chain-step').evaluateAll((as) => as.map((a) => a.dataset.step));
    assert.equal(steps[0], 'pendulum-energy');
    assert.ok(steps.indexOf('rrt-2d') > steps.indexOf('se3-relative'));
    // Every step links to a page of the app's page table: its own page when the table has
    // one, else its recipe's page or the drills page.
    const ids = new Set((await pageTable(page)).map((p) => p.id));
    for (const [step, href] of await chain.locator('.chain-step').evaluateAll((as) => as.map((a) => [a.dataset.step, a.getAttribute('href')]))) {
      const target = href.replace(/^#\//, '').split('?')[0];
      assert.ok(ids.has(target), `${step}: ${href} is not a page`);
      if (ids.has(step)) assert.equal(href, `#/${step}`);
      else assert.ok(href === `#/drills?recipe=${step}` || href === '#/ik-2r', `${step}: ${href}`);
    }
    // The IK page stands for three steps of the chain.
    await page.goto(`${server.url}#/ik-2r`);
    await page.waitForFunction(() => document.querySelectorAll('#drill-chain [aria-current="step"]').length === 3);
    assert.equal(await page.locator('[data-testid="chain-next-link"]').getAttribute('href'), '#/traj-resample');
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.match(await page.locator('[data-testid="chain-next"]').innerText(), /関節軌道を再サンプリング/);
    assert.equal(await page.locator('[data-testid="drill-chain"] h2').innerText(), '次のステップ');
    await page.click('[data-testid="nav-home"]');
    await page.waitForFunction(() => document.getElementById('drill-chain')?.hidden === true);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a presenter remote\'s PageDown / PageUp go section by section on pages that do not step, then to the next drill', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 1280, height: 800 } });
  try {
    const focused = () => page.evaluate(() => document.activeElement?.dataset.testid || document.activeElement?.tagName);
    await page.keyboard.press('PageDown');
    assert.equal(await focused(), 'featured-ik-2r');
    await page.keyboard.press('PageDown');
    const second = await focused();
    assert.notEqual(second, 'featured-ik-2r');
    const y = await page.evaluate(() => window.scrollY);
    assert.ok(y > 0, 'the page moved');
    await page.keyboard.press('PageUp');
    assert.equal(await focused(), 'featured-ik-2r');
    assert.ok(await page.evaluate(() => window.scrollY) < y);
    // Many presses reach the end of the home page and stay there (home is off the chain).
    for (let i = 0; i < 40; i += 1) await page.keyboard.press('PageDown');
    assert.equal(new URL(page.url()).hash, '#/');
    // On a drill page that does not take PageDown itself, the last section leads to the next
    // drill of the chain: the IK page (IK workspace) is followed by trajectory resampling.
    await page.goto(`${server.url}/#/ik-2r`);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    // Its second stage (the panels below the arm) is there before the walk starts.
    await page.locator('[data-section="explain"]').waitFor();
    await page.locator('#app-main').click({ position: { x: 5, y: 5 } });
    const sections = await page.locator('#app-main h2').count();
    for (let i = 0; i < sections + 10 && !page.url().includes('#/traj-resample'); i += 1) {
      await page.keyboard.press('PageDown');
      await page.waitForTimeout(30);
    }
    await page.waitForFunction(() => location.hash.startsWith('#/traj-resample'));
    // The overlay lists the keys.
    await page.keyboard.press('?');
    assert.match(await page.locator('[role="dialog"]').innerText(), /PgDn \/ PgUp/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('every recipe card shows a picture its kernel drew at the defaults, after the first paint', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    await page.waitForFunction(() => document.querySelectorAll('canvas.card-picture[data-drawn="1"]').length === 12, null, { timeout: 20000 });
    const inked = await page.locator('canvas.card-picture').evaluateAll((cs) => cs.map((c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n += 1;
      return [c.dataset.recipe, n / (c.width * c.height)];
    }));
    for (const [id, share] of inked) assert.ok(share > 0.01, `${id}: ${share}`);
    assert.match(await page.locator('[data-testid="card-picture-rrt-2d"]').getAttribute('aria-label'), /RRT tree/);
    await page.locator('[data-testid="recipe-card-rrt-2d"]').scrollIntoViewIfNeeded();
    await page.screenshot({ path: join(OUT, 'home-pictures.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the Robot Pilot tiles show their scenes at the start, drawn like the other tiles\' pictures', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const ids = ['teleop', 'so101'];
    await page.waitForFunction((ids) => ids.every((id) => document.querySelector(`[data-testid="tile-picture-${id}"]`)?.dataset.drawn === '1'), ids, { timeout: 20000 });
    const size = (id) => page.locator(`[data-testid="tile-picture-${id}"]`).boundingBox();
    const reference = await size('ik-2r');
    for (const id of ids) {
      const canvas = page.locator(`[data-testid="featured-${id}"] canvas.tile-picture`);
      assert.equal(await canvas.getAttribute('data-scene'), id);
      assert.equal(await canvas.getAttribute('aria-hidden'), 'true');
      const box = await size(id);
      assert.ok(Math.abs(box.width - reference.width) < 1 && Math.abs(box.height - reference.height) < 1, `${id}: ${JSON.stringify(box)}`);
      // Inked, in more than one colour: the arm, the block or cube and the goal.
      const { share, colours } = await canvas.evaluate((c) => {
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        const seen = new Set();
        for (let i = 0; i < d.length; i += 4) {
          if (d[i + 3] === 255) {
            n += 1;
            seen.add(`${d[i] >> 4},${d[i + 1] >> 4},${d[i + 2] >> 4}`);
          }
        }
        return { share: n / (c.width * c.height), colours: seen.size };
      });
      assert.ok(share > 0.02, `${id}: ${share} of the canvas inked`);
      assert.ok(colours >= 3, `${id}: ${colours} colours`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the home page ends with the seed\'s "Compare the tools" table, localized, with plain outbound links', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const rows = page.locator('[data-testid="tools"] tbody tr');
    assert.equal(await rows.count(), 7);
    assert.deepEqual(await page.locator('[data-testid="tools"] thead th').allInnerTexts(), ['Tool', 'Job', 'Licence', 'Difficulty', 'Local / cloud']);
    assert.match(await rows.nth(2).locator('th a').textContent(), /^NumPy\s*\(official site, opens outside the app\)$/);
    assert.deepEqual(await rows.nth(2).locator('td').allInnerTexts(), ['Arrays for IK grids and trajectory math', 'BSD-3-Clause', 'Beginner', 'Local']);
    for (const href of await rows.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href')))) {
      assert.match(href, /^https:\/\/[a-z0-9.-]+\//);
    }
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.deepEqual(await rows.nth(2).locator('td').allInnerTexts(), ['IK のグリッドや軌道計算のための配列', 'BSD-3-Clause', '初級', 'ローカル']);
    assert.equal(await page.locator('#tools-heading').innerText(), 'ツールの比較');
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

test('in projector mode the header stays compact: at 1280x800 at most two short rows, at phone widths (390, 320) nothing runs off the screen and every page draws without an error', async () => {
  for (const [width, height, maxHeader] of [[1280, 800, 130], [390, 844, 260], [320, 568, 330]]) {
    const { page, errors, close } = await openApp(server.url, '#/ik-2r', { viewport: { width, height } });
    try {
      await page.keyboard.press('p');
      for (const lang of ['en', 'ja']) {
        const header = await page.locator('[data-testid="site-header"]').boundingBox();
        assert.ok(header.height <= maxHeader, `${width}px ${lang}: the header takes ${header.height} px of ${height}`);
        for (const id of ['brand', 'lesson-add', 'lang-switch', 'projector-toggle', 'help-button']) {
          const box = await page.locator(`[data-testid="${id}"]`).boundingBox();
          assert.ok(box && box.x >= 0 && box.x + box.width <= width + 0.5, `${width}px ${lang}: ${id} on screen (${JSON.stringify(box)})`);
        }
        // The subtitle is still there for screen readers.
        assert.ok((await page.locator('[data-testid="brand-subtitle"]').textContent()).length > 5);
        if (lang === 'en') await page.click('[data-testid="lang-switch"]');
      }
      await page.screenshot({ path: join(OUT, `ik2r-projector-${width}.png`), fullPage: false });
      // Every page lays out and draws with projector type at this size (a short canvas with
      // 24 px labels once made a clamp panic).
      const routes = await page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
      for (const route of routes) {
        await page.evaluate((r) => { location.hash = `#/${r}`; }, route);
        await page.waitForFunction((r) => document.querySelector(`[data-testid="site-nav"] a[data-page="${r}"]`)?.getAttribute('aria-current') === 'page', route);
        await page.waitForTimeout(250);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the focus ring is at least 3:1 against white in the header and inside page content', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r');
  try {
    await page.locator('[data-ik2r="reset"]').waitFor();
    await page.keyboard.press('Tab'); // keyboard modality: programmatic focus shows the ring
    for (const selector of ['[data-testid="nav-home"]', '[data-testid="lang-switch"]', '[data-ik2r="reset"]', '#app-main [data-copy]', '#app-main select', '#app-main input']) {
      // The copy buttons and the form come with the page's second stage.
      await page.locator(selector).first().waitFor({ state: 'attached' });
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

test('home opens on a live arm and tiles that each say what their page shows; the page is short', async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await openApp(server.url, `#/?lang=${lang}`, { viewport: { width: 1366, height: 768 } });
    try {
      await page.waitForSelector('[data-testid="home-arm-canvas"][data-tip-x]');
      // The first screen: the arm, and the first row of tiles with their kernel-drawn pictures.
      const arm = await page.locator('[data-testid="home-arm-canvas"]').boundingBox();
      assert.ok(arm.y + arm.height <= 768 && arm.height > 200, `${lang}: the arm ${JSON.stringify(arm)}`);
      await page.waitForFunction(() => document.querySelector('[data-testid="tile-picture-ik-2r"]')?.dataset.drawn === '1');
      const picture = await page.locator('[data-testid="tile-picture-ik-2r"]').boundingBox();
      assert.ok(picture.y + picture.height <= 768, `${lang}: the first tile picture ${JSON.stringify(picture)}`);
      // Dragging the tip with a mouse turns the joints.
      const q = () => page.locator('.home-arm-value').allTextContents();
      const start = await q();
      const tip = await page.locator('[data-testid="home-arm-canvas"]').evaluate((c) => {
        const r = c.getBoundingClientRect();
        return [r.left + Number(c.dataset.tipX), r.top + Number(c.dataset.tipY)];
      });
      await page.mouse.move(tip[0], tip[1]);
      await page.mouse.down();
      await page.mouse.move(tip[0] - 60, tip[1] + 50, { steps: 5 });
      await page.mouse.up();
      assert.notDeepEqual(await q(), start, `${lang}: the arm moved`);
      // The drag focused the view: an arrow key moves the tip 5 mm.
      const dragged = await q();
      assert.equal(await page.evaluate(() => document.activeElement?.dataset.testid), 'home-arm-canvas');
      await page.keyboard.press('ArrowUp');
      assert.notDeepEqual(await q(), dragged, `${lang}: the key moved the arm`);
      // One tile per page but home, each with its own label; the labels are all different.
      const labels = await page.locator('.tile-grid .featured-label').allTextContents();
      const tiles = await page.locator('.tile-grid .featured-card').count();
      assert.equal(labels.length, tiles);
      assert.equal(new Set(labels).size, labels.length, `${lang}: ${labels.join(' | ')}`);
      assert.ok(labels.every((l) => l.length > 12), labels.join(' | '));
      // The intro names both: this app's Robot Pilot and the Academy.
      const intro = await page.locator('.hero .intro').textContent();
      assert.match(intro, lang === 'en' ? /Robot Pilot page.*Robot Pilot Academy/ : /ロボットパイロット.*Robot Pilot Academy/);
      const height = await page.evaluate(() => document.documentElement.scrollHeight);
      assert.ok(height < 4500, `${lang}: the page is ${height} px tall at 1366×768`);
      await page.screenshot({ path: join(OUT, `home-first-screen-1366-${lang}.png`) });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  const { page, close } = await openApp(server.url, '#/', { viewport: { width: 390, height: 844 } });
  try {
    const arm = await page.locator('[data-testid="home-arm-canvas"]').boundingBox();
    assert.ok(arm.y < 844 - 150, `the arm starts on a phone's first screen: ${JSON.stringify(arm)}`);
    const height = await page.evaluate(() => document.documentElement.scrollHeight);
    assert.ok(height < 9000, `the page is ${height} px tall at 390×844`);
  } finally {
    await close();
  }
});

test('at phone width the nav strip shows that it scrolls, and "+ Lesson" keeps its word', async () => {
  const { page, errors, close } = await openApp(server.url, '#/', { viewport: { width: 390, height: 844 } });
  try {
    for (const lang of ['en', 'ja']) {
      const nav = page.locator('[data-testid="site-nav"]');
      const list = page.locator('[data-testid="site-nav"] > ul');
      await list.evaluate((ul) => { ul.scrollLeft = 0; });
      await page.waitForFunction(() => document.querySelector('[data-testid="site-nav"]').hasAttribute('data-more-after'));
      // The cue: the strip's right edge shows an arrow while links are hidden past it.
      assert.equal(await nav.evaluate((n) => getComputedStyle(n, '::after').content), '"›"');
      assert.equal(await nav.getAttribute('data-more-before'), null);
      const strip = await list.boundingBox();
      const lesson = await page.locator('[data-testid="nav-lesson"]').boundingBox();
      assert.ok(lesson.x + lesson.width > strip.x + strip.width, `${lang}: "Lesson" is past the strip's edge`);
      // Scrolled to the end: the cue moves to the start and "Lesson" is in view.
      await list.evaluate((ul) => { ul.scrollLeft = ul.scrollWidth; });
      await page.waitForFunction(() => {
        const n = document.querySelector('[data-testid="site-nav"]');
        return n.hasAttribute('data-more-before') && !n.hasAttribute('data-more-after');
      });
      const shown = await page.locator('[data-testid="nav-lesson"]').boundingBox();
      assert.ok(shown.x + shown.width <= strip.x + strip.width + 1, `${lang}: "Lesson" scrolled into view`);
      await page.screenshot({ path: join(OUT, `nav-cue-390-${lang}.png`), clip: { x: 0, y: 0, width: 390, height: 120 } });
      await list.evaluate((ul) => { ul.scrollLeft = 0; });
      // The lesson button shows its word, whole, on the first row.
      const add = page.locator('[data-testid="lesson-add"]');
      assert.equal((await add.innerText()).trim(), lang === 'en' ? '+ Lesson' : '+ レッスン');
      const box = await add.boundingBox();
      assert.ok(box.x + box.width <= 390 && box.width > 60, `${lang}: ${JSON.stringify(box)}`);
      if (lang === 'en') await page.click('[data-testid="lang-switch"]');
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
