// Wasm half of `make bench`: the same cases as examples/bench.rs, in Node, from a release
// build with the `bench` feature (target/bench-pkg, built by scripts/bench.sh).
import { createRequire } from 'node:module';
const require = createRequire(import.meta.url);
const wasm = require('../target/bench-pkg/bsv_playground.js');

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
console.log('| case | wasm kernel ms | wasm recipe + CSV ms |');
console.log('|---|---:|---:|');
// An optional argument keeps only the cases whose name contains it.
const filter = process.argv[2] ?? '';
wasm.benchCaseNames().forEach((name, i) => {
  if (!name.includes(filter)) return;
  try {
    const kernel = median(Array.from(wasm.benchCase(i, 5, true)));
    const recipe = median(Array.from(wasm.benchCase(i, 5, false)));
    console.log(`| ${name} | ${kernel.toFixed(1)} | ${recipe.toFixed(1)} |`);
  } catch (e) {
    console.log(`| ${name} | error: ${e.message} | |`);
  }
});
