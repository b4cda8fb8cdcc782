#!/usr/bin/env node
// Writes DIR/sw.js (default dist/) from the template www/sw.js: the build id is the sha256 of
// every file of the build (path and bytes, in path order) and the file list is every file in
// DIR but the first-visit packs (`pkg/pack_*.bin`: the same modules as `pkg/chunks/`; the
// strings packs `locales/<lang>/pack_*.json`: the same text as the Fluent files), so the
// service worker caches exactly one build and each module and file once; it makes a pack from
// its modules when one is asked for (each pack's module names are written into sw.js). Prints
// the build id.
// `node scripts/sw-build.mjs [DIR]`; also imported by the offline e2e test.
import { createHash } from 'node:crypto';
import { readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { isStringsPack } from './boot-table.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');

function walk(dir) {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? walk(path) : [path];
  });
}

/** Whether `file` is a first-visit pack (see scripts/split-link.mjs). */
export function isPack(file) {
  return /^pkg\/pack_[^/]*\.bin$/.test(file);
}

/** The module names a pack holds, in order (its format: scripts/split-link.mjs). */
export function packModules(bytes) {
  if (bytes.subarray(0, 4).toString() !== 'BSVP') throw new Error('not a pack');
  const names = [];
  let at = 8;
  for (let i = 0, n = bytes.readUInt32LE(4); i < n; i++) {
    const idLength = bytes.readUInt32LE(at);
    names.push(bytes.subarray(at + 4, at + 4 + idLength).toString());
    at += 4 + idLength;
    at += 4 + bytes.readUInt32LE(at);
  }
  return names;
}

/** Writes `dir`/sw.js and returns { build, files }. */
export function writeServiceWorker(dir) {
  const root = resolve(dir);
  rmSync(join(root, 'sw.js'), { force: true });
  rmSync(join(root, 'www', 'sw.js'), { force: true });
  const files = walk(root)
    .map((path) => relative(root, path).split(sep).join('/'))
    .sort();
  const hash = createHash('sha256');
  for (const file of files) {
    hash.update(file).update('\0').update(readFileSync(join(root, file))).update('\0');
  }
  const build = hash.digest('hex').slice(0, 16);
  const list = ['./', ...files.filter((file) => !isPack(file) && !isStringsPack(file))];
  const packs = Object.fromEntries(
    files.filter(isPack).map((file) => [file.slice(file.lastIndexOf('/') + 1), packModules(readFileSync(join(root, file)))]),
  );
  const template = readFileSync(join(ROOT, 'www', 'sw.js'), 'utf8');
  writeFileSync(
    join(root, 'sw.js'),
    template
      .replace("'__BSV_BUILD__'", JSON.stringify(build))
      .replace('__BSV_FILES__', JSON.stringify(list))
      .replace('__BSV_PACKS__', JSON.stringify(packs)),
  );
  return { build, files: list };
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const { build, files } = writeServiceWorker(process.argv[2] ?? join(ROOT, 'dist'));
  console.log(`sw.js: build ${build}, ${files.length} files`);
}
