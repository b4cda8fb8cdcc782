// Hostile files and storage: every place a user hands the app a file (lesson import, the
// trajectory CSV of #/traj-resample and #/drills) and every store of work other than teleop's
// (the lesson). Real files written by the test (setInputFiles with buffers); storage full by
// stubbing Storage.prototype.setItem to throw a QuotaExceededError; storage edited by hand by
// writing bad text before the page loads. Each case asserts the message the user sees, no
// console error, and the earlier state intact (the lesson's steps, the last result's readouts).
// Screenshots of the messages (EN, JA, phone) go to tests/e2e/out/hostile-*.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { serveApp, openApp, OUT } from './harness.mjs';

const server = serveApp();

const PHONE = { width: 390, height: 844 };

/** Scrolls `locator` to the middle of the view (clear of a page's sticky bars) for a screenshot. */
const centre = (locator) => locator.evaluate((el) => el.scrollIntoView({ block: 'center' }));
const DESKTOP = { width: 1366, height: 768 };

// ---------- Lessons ----------

const lessonError = (page) => page.locator('[data-field-error="lesson-file"]');
const stepTitles = (page) => page.locator('.lesson-step input[data-field^="step-title-"]').evaluateAll((els) => els.map((e) => e.value));

/** A lesson file's text with `steps` (an array of objects) and optional extra top fields. */
const lessonFile = (steps, extra = {}) => JSON.stringify({ format: 'bsv-lesson', version: 1, title: 'Imported', steps, ...extra });

/** Opens #/lesson and loads the built-in "energy" lesson (stored as the user's own). */
async function openLesson(opts = {}) {
  const app = await openApp(server.url, '#/lesson', opts);
  await app.page.waitForSelector('.lesson-step');
  return app;
}

/**
 * Imports a file of `buffer` named `name` and waits until the error line says `pattern`. A
 * buffer over playwright's 50 MB is written to a file first.
 */
async function importBad(page, name, buffer, pattern) {
  let file = { name, mimeType: 'application/json', buffer };
  if (buffer.length >= 50 * 1024 * 1024) {
    file = join(mkdtempSync(join(tmpdir(), 'hostile-')), name);
    writeFileSync(file, buffer);
  }
  await page.setInputFiles('input[data-action="lesson-import"]', file);
  if (typeof file === 'string') rmSync(dirname(file), { recursive: true, force: true });
  await page.waitForFunction(
    ([source, flags]) => {
      const el = document.querySelector('[data-field-error="lesson-file"]');
      return el && !el.hidden && new RegExp(source, flags).test(el.textContent);
    },
    [pattern.source, pattern.flags],
    { timeout: 20000 },
  );
}

/**
 * Records in `window.__read` the name of every file whose bytes the page reads; with `huge`,
 * the file of that name says it is 200 MiB (its `size`, what a page checks first).
 */
function watchReads(page, huge = null) {
  return page.evaluate((huge) => {
    if (huge) {
      const real = Object.getOwnPropertyDescriptor(Blob.prototype, 'size');
      Object.defineProperty(Blob.prototype, 'size', {
        configurable: true,
        get() { return this.name === huge ? 200 * 1024 * 1024 : real.get.call(this); },
      });
    }
    window.__read = [];
    for (const name of ['arrayBuffer', 'text', 'stream']) {
      const read = Blob.prototype[name];
      Blob.prototype[name] = function watched(...args) {
        window.__read.push(this.name);
        return read.apply(this, args);
      };
    }
  }, huge);
}

const DEEP = '['.repeat(10_000) + ']'.repeat(10_000);
const EVIDENCE = JSON.stringify({ schemaVersion: '0.1', sessionId: 'pilot-1', pilotId: 'pilot', dataArtifacts: [{ type: 'csv', uriOrRef: 'teleop_episodes.csv' }] });

/** [file name, bytes, the English message]: every bad lesson file the page refuses. */
const BAD_LESSONS = [
  ['notes.json', Buffer.from('{ format: bsv-lesson }'), /^This file is not JSON: the text stops making sense at line 1, column 3\. The current lesson is kept\.$/],
  ['teleop_session_evidence.json', Buffer.from(EVIDENCE), /it has no “format” field/],
  ['list.json', Buffer.from('[1, 2, 3]'), /^This JSON file holds a list, not a lesson\./],
  ['number.json', Buffer.from('42'), /^This JSON file holds a number, not a lesson\./],
  ['big.json', Buffer.alloc(50 * 1024 * 1024, 0x20), /^This file is 50 MiB \(52,428,800 bytes\); a lesson file may be at most 512 KiB\. It was not read\./],
  ['deep.json', Buffer.from(DEEP), /nests lists or objects more than 16 deep \(line 1, column 17\)/],
  ['route.json', Buffer.from(lessonFile([{ route: '#/ik-2r', title: 'a' }, { route: '#/warp-drive?x=1', title: 'b' }])), /^Step 2, field “route”: this app has no page “warp-drive”\./],
  ['js.json', Buffer.from(lessonFile([{ route: 'javascript:alert(1)', title: 'a' }])), /^Step 1, field “route”: this app has no page “javascript:alert\(1\)”\./],
  ['field.json', Buffer.from(lessonFile([{ route: '#/ik-2r', title: 'a', onload: 'alert(1)' }])), /^Step 1 has a field this app does not know: “onload”\./],
  ['type.json', Buffer.from(lessonFile([{ route: '#/ik-2r', title: 'a', pageSteps: '3' }])), /^Step 1, field “pageSteps”: must be a whole number\./],
  ['missing.json', Buffer.from(lessonFile([{ route: '#/ik-2r' }])), /^Step 1 has no “title” field\./],
  ['empty-lesson.json', Buffer.from(lessonFile([])), /^This lesson has no steps: there is nothing to present\./],
  ['empty.json', Buffer.alloc(0), /^This file is empty\./],
  ['utf16.json', Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from(lessonFile([{ route: '#/ik-2r', title: 'a' }]), 'utf16le')]), /could not be read as a lesson: “utf16\.json” is UTF-16 text/],
];

test('every bad lesson file is named (what and where) and the current lesson is untouched', async () => {
  const { page, errors, close } = await openLesson({ viewport: DESKTOP });
  try {
    await page.click('[data-builtin="energy"]');
    await page.waitForFunction(() => localStorage.getItem('bsv.lesson') !== null);
    const titles = await stepTitles(page);
    const stored = await page.evaluate(() => localStorage.getItem('bsv.lesson'));
    // Reads of a file's bytes, by name: a file over the limit must not be read at all.
    await watchReads(page);
    assert.equal(titles.length, 4);
    for (const [name, buffer, pattern] of BAD_LESSONS) {
      await importBad(page, name, buffer, pattern);
      assert.deepEqual(await stepTitles(page), titles, `${name}: the lesson is kept`);
      assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson')), stored, `${name}: storage kept`);
      assert.match(await lessonError(page).innerText(), /The current lesson is kept\.$/, name);
      assert.equal((await page.evaluate(() => window.__read)).includes('big.json'), false, 'the big file is not read');
      if (name === 'big.json' || name === 'route.json') {
        await centre(lessonError(page));
        await page.screenshot({ path: join(OUT, `hostile-lesson-${name.replace('.json', '')}-en.png`) });
      }
    }
    assert.ok((await page.evaluate(() => window.__read)).includes('notes.json'), 'the read watch sees the small files');
    // The same message in Japanese (the last one shown, said again on the switch).
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.match(await lessonError(page).innerText(), /「utf16\.json」は UTF-16 のテキストです/);
    await importBad(page, 'route.json', BAD_LESSONS[6][1], /^ステップ 2、フィールド「route」：このアプリに「warp-drive」というページはありません。/);
    await importBad(page, 'big.json', BAD_LESSONS[4][1], /50 MiB（52,428,800 バイト）/);
    await centre(lessonError(page));
    await page.screenshot({ path: join(OUT, 'hostile-lesson-big-ja.png') });
    // A good file still imports after all that.
    await page.setInputFiles('input[data-action="lesson-import"]', { name: 'good.json', mimeType: 'application/json', buffer: Buffer.from(lessonFile([{ route: '#/pid-step?Kp=2&warp=9', title: 'PID' }])) });
    await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 1);
    assert.equal(await lessonError(page).isVisible(), false);
    // A key the page does not know stays in the route; the page names it when it opens.
    assert.equal(await page.locator('.lesson-step-route').innerText(), '#/pid-step?Kp=2&warp=9');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a lesson link with keys that hold no part of the lesson opens the lesson and names them (EN and JA)', async () => {
  const hash = `#/lesson?title=Linked&r1=${encodeURIComponent('#/ik-2r?q1=0.3')}&t1=IK&zz=1&t9=x`;
  const { page, errors, close } = await openApp(server.url, hash, { viewport: DESKTOP });
  try {
    await page.waitForSelector('.lesson-step');
    assert.deepEqual(await stepTitles(page), ['IK']);
    const notice = page.locator('[data-testid="lesson-url-notice"]');
    assert.match(await notice.innerText(), /ignored: zz, t9/);
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.match(await notice.innerText(), /zz, t9/);
    assert.doesNotMatch(await notice.innerText(), /ignored/);
    await page.screenshot({ path: join(OUT, 'hostile-lesson-url-keys-ja.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a bad lesson file at phone width, in Japanese', async () => {
  const { page, errors, close } = await openLesson({ viewport: PHONE, locale: 'ja-JP' });
  try {
    await importBad(page, 'deep.json', Buffer.from(DEEP), /入れ子が 16 段を超えています（1 行目、17 文字目）/);
    assert.equal(await page.locator('.lesson-step').count(), 4, 'the built-in lesson is kept');
    await centre(lessonError(page));
    const width = await page.evaluate(() => document.documentElement.scrollWidth);
    assert.ok(width <= PHONE.width, `page ${width} px wide`);
    await page.screenshot({ path: join(OUT, 'hostile-lesson-deep-ja-390.png') });
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'en');
    assert.match(await lessonError(page).innerText(), /more than 16 deep \(line 1, column 17\)/);
    await page.screenshot({ path: join(OUT, 'hostile-lesson-deep-en-390.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('script-like text in a lesson is shown as text and never runs, in the editor and the presenter bar', async () => {
  const { page, errors, close } = await openLesson({ viewport: DESKTOP });
  try {
    const dialogs = [];
    page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss(); });
    const title = '<img src=x onerror="window.__pwned=1">';
    const stepTitle = '<script>window.__pwned=2</script>';
    const note = 'javascript:window.__pwned=3 <b onmouseover="window.__pwned=4">bold?</b>';
    const buffer = Buffer.from(lessonFile([{ route: '#/ik-2r?q1=0.3', title: stepTitle, note }], { title }));
    await page.setInputFiles('input[data-action="lesson-import"]', { name: 'script.json', mimeType: 'application/json', buffer });
    await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 1);
    assert.equal(await page.inputValue('[data-field="lesson-title"]'), title);
    assert.equal(await page.inputValue('[data-field="step-title-1"]'), stepTitle);
    assert.equal(await page.inputValue('[data-field="step-note-1"]'), note);
    assert.equal(await page.locator('.lesson img, .lesson script, .lesson b').count(), 0, 'no element made from the text');
    assert.equal(await page.locator('.lesson-step-route').getAttribute('href'), '#/ik-2r?q1=0.3');
    await page.screenshot({ path: join(OUT, 'hostile-lesson-script-en.png') });
    await page.click('[data-action="lesson-present"]');
    await page.locator('[data-testid="lesson-bar"]').waitFor({ state: 'visible' });
    await page.waitForFunction(() => location.hash.startsWith('#/ik-2r'));
    assert.match(await page.locator('[data-testid="lesson-note"]').innerText(), /javascript:window\.__pwned=3 <b onmouseover/);
    await page.locator('[data-testid="lesson-bar"]').hover();
    await page.waitForTimeout(300);
    assert.equal(await page.evaluate(() => window.__pwned), undefined);
    assert.deepEqual(dialogs, []);
    await page.keyboard.press('Escape');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a stored lesson edited by hand: the page starts clean, keeps the text aside and says so', async () => {
  for (const [label, text] of [
    ['truncated', '{"format":"bsv-lesson","version":1,"title":"My physics class","steps":[{"route":"#/pid-step","ti'],
    ['wrong types', '{"format":"bsv-lesson","version":1,"title":5,"steps":{"route":"#/pid-step"}}'],
  ]) {
    for (const [lang, viewport] of [['en', DESKTOP], ['ja', PHONE]]) {
      const { page, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport, storage: { 'bsv.lesson': text } });
      try {
        await page.waitForSelector('.lesson-step');
        const note = page.locator('[data-testid="lesson-unreadable"]');
        assert.ok(await note.isVisible(), `${label} ${lang}: the note is shown`);
        assert.match(
          await note.innerText(),
          lang === 'en'
            ? /The lesson stored in this browser could not be read .* started clean\. Its text is kept in this browser's storage under bsv\.lesson\.unreadable\./
            : /保存されていたレッスンが読めなかった.*bsv\.lesson\.unreadable/,
        );
        // Started clean: the built-in lesson, ready to present; the text kept aside, byte for byte.
        assert.equal(await page.locator('[data-testid="lesson-builtin-note"]').isVisible(), true);
        assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson.unreadable')), text);
        assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson')), null);
        await page.screenshot({ path: join(OUT, `hostile-lesson-unreadable-${label.replace(' ', '-')}-${lang}-${viewport.width}.png`) });
        if (lang === 'en') {
          // Its text comes back as a download; editing the page's lesson leaves it aside.
          const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="lesson-unreadable.json"]')]);
          const saved = join(OUT, 'hostile-lesson-unreadable.json');
          await download.saveAs(saved);
          assert.equal(readFileSync(saved, 'utf8'), text);
          await page.fill('[data-field="step-note-1"]', 'edited');
          assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson.unreadable')), text);
          assert.match(await page.evaluate(() => localStorage.getItem('bsv.lesson')), /"note": "edited"/);
          await page.click('[data-action="lesson-forget-unreadable"]');
          assert.equal(await note.isVisible(), false);
          assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson.unreadable')), null);
        }
        assert.deepEqual(errors, []);
      } finally {
        await close();
      }
    }
  }
});

/** Makes every localStorage.setItem of the page throw a QuotaExceededError (undone by `full(page, false)`). */
async function full(page, on = true) {
  await page.evaluate((on) => {
    if (on) {
      window.__realSetItem ??= Storage.prototype.setItem;
      Storage.prototype.setItem = function setItem() {
        throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
      };
    } else if (window.__realSetItem) {
      Storage.prototype.setItem = window.__realSetItem;
    }
  }, on);
}

test('storage full while saving a lesson: the page says it is not saved and nothing in memory is dropped', async () => {
  const own = lessonFile([{ route: '#/pid-step?Kp=2', title: 'PID' }, { route: '#/ik-2r', title: 'IK' }], { title: 'Mine' });
  for (const [lang, viewport] of [['en', DESKTOP], ['ja', PHONE]]) {
    const { page, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport });
    try {
      await page.evaluate((t) => localStorage.setItem('bsv.lesson', t), own);
      await page.reload();
      await page.waitForSelector('.lesson-step');
      assert.deepEqual(await stepTitles(page), ['PID', 'IK']);
      await full(page);
      await page.fill('[data-field="step-title-1"]', 'PID, tuned');
      const unsaved = page.locator('[data-testid="lesson-unsaved"]');
      await unsaved.waitFor({ state: 'visible' });
      assert.match(await unsaved.innerText(), lang === 'en' ? /^This lesson is not saved: this browser's storage is full/ : /^このレッスンは保存されていません：このブラウザーの保存領域がいっぱいです/);
      await page.screenshot({ path: join(OUT, `hostile-lesson-full-${lang}-${viewport.width}.png`) });
      // Still in memory: the field, and the lesson the export writes.
      assert.deepEqual(await stepTitles(page), ['PID, tuned', 'IK']);
      const old = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.lesson')));
      assert.equal(old.steps[0].title, 'PID', 'storage holds the old copy');
      if (lang === 'en') {
        const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-download="lesson.json"]')]);
        const file = join(OUT, 'hostile-lesson-full.json');
        await download.saveAs(file);
        assert.equal(JSON.parse(readFileSync(file, 'utf8')).steps[0].title, 'PID, tuned');
        // Another page's "+ Lesson" adds to the lesson in memory and says it is not saved.
        await page.evaluate(() => { location.hash = '#/rrt-2d'; });
        await page.waitForSelector('[data-testid="rrt-page"], canvas');
        await page.click('[data-testid="lesson-add"]');
        await page.waitForFunction(() => /step 3/.test(document.querySelector('[data-testid="lesson-add-status"]').textContent));
        assert.match(await page.locator('[data-testid="lesson-add-status"]').textContent(), /Added as step 3 of the lesson, but this browser's storage is full/);
        await page.evaluate(() => { location.hash = '#/lesson'; });
        await page.waitForFunction(() => document.querySelectorAll('.lesson-step').length === 3);
        assert.deepEqual((await stepTitles(page)).slice(0, 2), ['PID, tuned', 'IK']);
        assert.ok(await unsaved.isVisible());
        // Room again: the next edit is saved and the line goes.
        await full(page, false);
        await page.fill('[data-field="step-title-2"]', 'IK again');
        await unsaved.waitFor({ state: 'hidden' });
        const stored = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.lesson')));
        assert.deepEqual(stored.steps.map((s) => s.title).slice(0, 2), ['PID, tuned', 'IK again']);
        assert.equal(stored.steps.length, 3);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('screenshots: every lesson message at phone width, EN and JA (the message and its card)', { timeout: 120_000 }, async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await openLesson({ viewport: PHONE, locale: lang === 'ja' ? 'ja-JP' : 'en-US' });
    try {
      for (const [name, buffer] of BAD_LESSONS) {
        await page.evaluate(() => { document.querySelector('[data-field-error="lesson-file"]').hidden = true; });
        await importBad(page, name, buffer, /./);
        await centre(lessonError(page));
        const box = await lessonError(page).boundingBox();
        assert.ok(box.x >= 0 && box.x + box.width <= PHONE.width, `${name}: inside the page`);
        await lessonError(page).screenshot({ path: join(OUT, `hostile-msg-${name.replace('.json', '')}-${lang}-390.png`) });
      }
      assert.equal(await page.locator('.lesson-step').count(), 4);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

// ---------- Trajectory CSVs ----------

const PNG = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52]);
const utf16 = (text) => Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from(text, 'utf16le')]);
const WIDE = Buffer.from(['t_s', ...Array.from({ length: 999_999 }, (_, j) => `q${j + 1}`)].join(',') + '\n0' + ',0'.repeat(999_999) + '\n1' + ',1'.repeat(999_999) + '\n');

/** [file name, bytes, the English message, the Japanese one]: every bad CSV, refused beside the picker. */
const BAD_CSVS = [
  ['photo.png', PNG, '“photo.png” holds a NUL byte (line 3, byte 1 of the line): it is a binary file, not CSV text.', /「photo\.png」に NUL バイトがあります（3 行目、その行の 1 バイト目）/],
  ['nul.csv', Buffer.from('t_s,q1\n0,1\n0.1,2\u0000\n'), '“nul.csv” holds a NUL byte (line 3, byte 6 of the line): it is a binary file, not CSV text.', /3 行目、その行の 6 バイト目/],
  ['excel.csv', utf16('t_s,q1\r\n0,1\r\n1,2\r\n'), '“excel.csv” is UTF-16 text (it starts with a UTF-16 byte-order mark); this app reads UTF-8. Save the file as UTF-8 (in a spreadsheet: “CSV UTF-8”) and open it again.', /「excel\.csv」は UTF-16 のテキストです/],
  ['wide.csv', WIDE, 'The CSV header has 1,000,000 columns; at most 1,000 are read.', /CSV のヘッダーに列が 1,000,000 個あります。読める列は 1,000 個までです。/],
  ['header.csv', Buffer.from('t_s,q1,q2\n'), /^The CSV has 0 data rows?; .*at least 2/, /データ行が 0 行しかありません/],
];

/** The page's file input, readouts and error line: #/traj-resample's or #/drills'. */
const PAGES = {
  traj: { hash: '#/traj-resample', file: '[data-testid="traj-file"]', ready: async (page) => page.waitForFunction(() => document.querySelector('[data-readout="rows_in"]')?.textContent === '5', null, { timeout: 20000 }) },
  drills: { hash: '#/drills?recipe=traj-resample', file: '[data-testid="drills-file"]', ready: async (page) => page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]')?.dataset.run) > 0, null, { timeout: 20000 }) },
};

/** What the last result shows: the traj page's counts, the drills page's summary (the CLI's words). */
const lastResult = (page, which) => (which === 'traj'
  ? page.evaluate(() => Object.fromEntries(['rows_in', 'rows_out', 'joints'].map((k) => [k, document.querySelector(`[data-readout="${k}"]`).textContent])))
  : page.locator('[data-testid="drills-summary"]').innerText());

for (const which of ['traj', 'drills']) {
  test(`${which}: a binary file, NUL bytes, UTF-16, a million columns, a header only: named, the last result kept`, { timeout: 120_000 }, async () => {
    const { hash, file, ready } = PAGES[which];
    const { page, errors, close } = await openApp(server.url, hash, { viewport: DESKTOP });
    try {
      await ready(page);
      const shown = await lastResult(page, which);
      const message = page.locator('[data-field-error="csv_path"]');
      for (const [name, buffer, en] of BAD_CSVS) {
        await page.locator(file).setInputFiles({ name, mimeType: 'text/csv', buffer });
        await page.waitForFunction(
          ([n, text]) => {
            const el = document.querySelector('[data-field-error="csv_path"]');
            return el && el.offsetParent !== null && (text ? el.textContent === text : el.textContent.includes(n) || /CSV/.test(el.textContent));
          },
          [name, typeof en === 'string' ? en : null],
          { timeout: 60000 },
        );
        if (typeof en === 'string') assert.equal(await message.innerText(), en, name);
        else assert.match(await message.innerText(), en, name);
        assert.deepEqual(await lastResult(page, which), shown, `${which} ${name}: the last result stays`);
        await message.screenshot({ path: join(OUT, `hostile-csv-${which}-${name.replace('.', '_')}-en-1366.png`) });
        if (name === 'excel.csv' || name === 'wide.csv') {
          await centre(message);
          await page.screenshot({ path: join(OUT, `hostile-${which}-${name.replace('.csv', '')}-en.png`) });
        }
      }
      // Said again in Japanese on a switch (the last one: the header only).
      await page.click('[data-testid="lang-switch"]');
      await page.waitForFunction(() => document.documentElement.lang === 'ja');
      assert.match(await message.innerText(), BAD_CSVS[4][3]);
      await message.screenshot({ path: join(OUT, `hostile-csv-${which}-header_csv-ja-1366.png`) });
      for (const [name, buffer, , ja] of BAD_CSVS.slice(0, 3)) {
        await page.locator(file).setInputFiles({ name, mimeType: 'text/csv', buffer });
        await page.waitForFunction((source) => new RegExp(source).test(document.querySelector('[data-field-error="csv_path"]')?.textContent ?? ''), ja.source, { timeout: 20000 });
        await message.screenshot({ path: join(OUT, `hostile-csv-${which}-${name.replace('.', '_')}-ja-1366.png`) });
      }
      await centre(message);
      await page.screenshot({ path: join(OUT, `hostile-${which}-utf16-ja.png`) });
      assert.deepEqual(await lastResult(page, which), shown);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });

  test(`${which}: CR-only line ends read as line ends; a UTF-8 byte-order mark is accepted; at phone width`, async () => {
    const { hash, file, ready } = PAGES[which];
    const { page, errors, close } = await openApp(server.url, hash, { viewport: PHONE, locale: 'ja-JP' });
    try {
      await ready(page);
      const text = 't_s,q1,q2\r0,0,0\r0.1,0.2,0.1\r0.25,0.5,0.4\r0.4,0.7,0.6\r';
      await page.locator(file).setInputFiles({ name: 'mac.csv', mimeType: 'text/csv', buffer: Buffer.from(`\ufeff${text}`) });
      if (which === 'traj') {
        await page.waitForFunction(() => document.querySelector('[data-readout="rows_in"]')?.textContent === '4', null, { timeout: 20000 });
        assert.equal((await page.locator('[data-readout="joints"]').innerText()).trim(), '2');
        assert.equal((await page.locator('[data-readout="rows_out"]').innerText()).trim(), '21');
      } else {
        await page.waitForFunction(() => /4 -> 21 rows/.test(document.querySelector('[data-testid="drills-summary"]')?.textContent ?? ''), null, { timeout: 20000 });
      }
      // A NUL byte at phone width: the message wraps inside the page.
      await page.locator(file).setInputFiles({ name: 'nul.csv', mimeType: 'text/csv', buffer: BAD_CSVS[1][1] });
      const message = page.locator('[data-field-error="csv_path"]');
      await message.waitFor({ state: 'visible' });
      assert.match(await message.innerText(), /NUL バイト/);
      await centre(message);
      const width = await page.evaluate(() => document.documentElement.scrollWidth);
      assert.ok(width <= PHONE.width, `page ${width} px wide`);
      await page.screenshot({ path: join(OUT, `hostile-${which}-nul-ja-390.png`) });
      await page.click('[data-testid="lang-switch"]');
      await page.waitForFunction(() => document.documentElement.lang === 'en');
      await centre(message);
      await page.screenshot({ path: join(OUT, `hostile-${which}-nul-en-390.png`) });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('drills: a file over 128 MiB is refused from its size, unread, with the size (EN and JA); the last result stays', async () => {
  const { hash, file, ready } = PAGES.drills;
  const { page, errors, close } = await openApp(server.url, hash, { viewport: PHONE });
  try {
    await ready(page);
    const shown = await lastResult(page, 'drills');
    // A small file the page sees as 200 MiB (its `size` is what the page reads first).
    await watchReads(page, 'huge.csv');
    await page.locator(file).setInputFiles({ name: 'huge.csv', mimeType: 'text/csv', buffer: Buffer.from('t_s,q1\n0,0\n1,1\n') });
    const message = page.locator('[data-field-error="csv_path"]');
    await message.waitFor({ state: 'visible' });
    assert.equal(await message.innerText(), '“huge.csv” is 200 MiB: larger than the 128 MiB this drill can read. It was not opened.');
    assert.deepEqual(await page.evaluate(() => window.__read), [], 'nothing read');
    assert.equal(await lastResult(page, 'drills'), shown);
    await centre(message);
    await page.screenshot({ path: join(OUT, 'hostile-drills-huge-en-390.png') });
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    assert.match(await message.innerText(), /「huge\.csv」.*200 MiB/);
    await centre(message);
    await page.screenshot({ path: join(OUT, 'hostile-drills-huge-ja-390.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
