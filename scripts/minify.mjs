// Minifies a release dist/ in place (scripts/build-dist.sh; a --dev build is left readable):
// - the scripts (SCRIPTS: wasm-bindgen's glue, the splitter's loader, the boot scripts and
//   the worker's) with terser (exports, top-level names of classic scripts and every property
//   name kept, local names shortened, whitespace and comments gone);
// - www/*.css: comments dropped and whitespace collapsed outside quoted strings (no rule,
//   selector or value is rewritten, so what the page looks like cannot change).
// About 9 KB gzipped off the app (scripts/size.mjs), the same behaviour: the e2e suite runs on
// the minified dist/.
//
//   node scripts/minify.mjs [dist]
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { minify } from 'terser';

/** `css` without comments, each whitespace run outside quoted strings as one space, and no
 * space beside `{`, `}` or `;` (nor a `;` before `}`). */
export function minifyCss(css) {
  let out = '';
  let i = 0;
  while (i < css.length) {
    const c = css[i];
    if (c === '"' || c === "'") {
      // A quoted string, escapes included, as it is.
      let j = i + 1;
      while (j < css.length && css[j] !== c) j += css[j] === '\\' ? 2 : 1;
      const string = css.slice(i, j + 1);
      // The last step below would change a string holding these.
      if (/[{};]/.test(string)) throw new Error(`a CSS string holds { } or ;: ${string}`);
      out += string;
      i = j + 1;
    } else if (c === '/' && css[i + 1] === '*') {
      const end = css.indexOf('*/', i + 2);
      i = end < 0 ? css.length : end + 2;
      if (!out.endsWith(' ')) out += ' ';
    } else if (/\s/.test(c)) {
      while (i < css.length && /\s/.test(css[i])) i++;
      if (!out.endsWith(' ')) out += ' ';
    } else {
      out += c;
      i++;
    }
  }
  // Spaces beside braces and semicolons mean nothing in CSS (no string holds them: checked
  // above).
  return out.replace(/ ?([{};]) ?/g, '$1').replace(/;}/g, '}').trim() + '\n';
}

const main = async () => {
  const dist = process.argv[2] ?? 'dist';
  for (const name of readdirSync(join(dist, 'www')).filter((f) => f.endsWith('.css'))) {
    const css = join(dist, 'www', name);
    writeFileSync(css, minifyCss(readFileSync(css, 'utf8')));
  }
  for (const [file, module] of SCRIPTS) {
    const path = join(dist, file);
    const result = await minify(readFileSync(path, 'utf8'), {
      module,
      ecma: 2020,
      compress: { passes: 2 },
      mangle: true,
      format: { comments: false },
    });
    if (!result.code) throw new Error(`${path}: terser returned nothing`);
    writeFileSync(path, result.code);
  }
};

/** The scripts of dist/ and whether each is an ES module (its exports kept) or a classic
 * script (its top-level names kept). */
const SCRIPTS = [
  ['pkg/bsv_playground.js', true],
  ['pkg/__wasm_split.js', true],
  ['www/bootstrap.js', true],
  ['www/worker.js', true],
  ['www/boot.js', false],
];

if (import.meta.url === `file://${process.argv[1]}`) await main();
