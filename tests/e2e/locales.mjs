// The locale files read as data, for the tests that a Japanese page shows no English UI string.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT } from './harness.mjs';

/** Message values of an .ftl file: id → [literal text outside placeables]. */
function ftlSegments(path) {
  const out = new Map();
  let id = null;
  let value = '';
  const flush = () => {
    if (id === null) return;
    const segments = [];
    let depth = 0, cur = '';
    for (const ch of value) {
      if (ch === '{') {
        if (depth === 0) { segments.push(cur); cur = ''; }
        depth++;
      } else if (ch === '}') {
        depth = Math.max(0, depth - 1);
      } else if (depth === 0) {
        cur += ch;
      }
    }
    segments.push(cur);
    out.set(id, { raw: value, segments: segments.map((s) => s.trim()).filter(Boolean) });
    id = null;
    value = '';
  };
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const m = /^([a-zA-Z][\w-]*)\s*=\s?(.*)$/.exec(line);
    if (m) {
      flush();
      id = m[1];
      value = m[2];
    } else if (id !== null && /^\s+\S/.test(line) && !/^\s*\.\w/.test(line)) {
      value += '\n' + line.trim();
    } else if (!/^\s*$/.test(line)) {
      flush();
    }
  }
  flush();
  return out;
}

/**
 * The English UI strings (literal text of en/*.ftl messages, longer than three characters with a
 * word in them) that no Japanese message contains: none of them may show on a Japanese page.
 */
export function englishStrings() {
  const dir = (l) => join(ROOT, 'locales', l);
  const ja = [];
  for (const f of readdirSync(dir('ja')).filter((f) => f.endsWith('.ftl'))) {
    for (const { raw } of ftlSegments(join(dir('ja'), f)).values()) ja.push(raw);
  }
  const jaText = ja.join('\n');
  const en = new Set();
  for (const f of readdirSync(dir('en')).filter((f) => f.endsWith('.ftl'))) {
    for (const { segments } of ftlSegments(join(dir('en'), f)).values()) {
      for (const s of segments) {
        if (s.length > 3 && /[A-Za-z]{3,}/.test(s) && !jaText.includes(s)) en.add(s);
      }
    }
  }
  return [...en];
}

/**
 * The English UI strings ([`englishStrings`]) the page shows, leaving out file names (the
 * `data-download` buttons) and key caps (`kbd`), which are the same in every language.
 */
export async function englishOnPage(page) {
  const text = await page.evaluate(() => {
    let all = document.body.innerText;
    for (const b of document.querySelectorAll('[data-download]')) all = all.replaceAll(b.dataset.download, '');
    for (const k of document.querySelectorAll('kbd')) all = all.replaceAll(k.innerText, '');
    return all;
  });
  return { text, left: englishStrings().filter((s) => text.includes(s)) };
}
