#!/usr/bin/env bash
# `make bench`: speed figures (a command, not a timed test). Kernels natively and as wasm in
# Node (release builds), the app's size and first interactive frame, then every page bench of
# tests/bench/ in headless Chromium, each figure printed against its budget.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"

echo "== kernels, native (release)"
cargo run --quiet --release --example bench

echo
echo "== kernels, wasm in Node (release)"
wasm-pack build --quiet --target nodejs --release --out-dir target/bench-pkg --mode no-install --no-pack -- --features bench
# The nodejs target is CommonJS; the repo's package.json says "module".
echo '{ "type": "commonjs" }' > target/bench-pkg/package.json
node scripts/bench-wasm.mjs

echo
echo "== release dist/ with the bench hooks (target/bench-dist)"
# The app build has no timing hooks: assemble the release dist/, then a copy of it whose
# wasm is built with `--features bench` (window.__ik2rBench, __pendulumBench, ...).
scripts/build-dist.sh >/dev/null
wasm-pack build --quiet --target web --release --out-dir target/bench-web --out-name bsv_playground \
  --mode no-install --no-pack -- --features bench
rm -rf target/bench-dist
cp -r dist target/bench-dist
cp target/bench-web/bsv_playground.js target/bench-web/bsv_playground_bg.wasm target/bench-dist/pkg/

echo
echo "== size of the app (dist/, every file gzipped at level 9; the budget is 350 KB)"
node scripts/size.mjs dist

echo
echo "== first interactive frame: cold loads of the release dist/ from localhost in headless Chromium"
node tests/bench/firstframe.bench.mjs

# Every page bench (tests/bench/<page>.bench.mjs) on the dist with the bench hooks; each prints
# its figures against their budgets.
for bench in tests/bench/*.bench.mjs; do
  page=$(basename "$bench" .bench.mjs)
  [[ $page == firstframe ]] && continue
  echo
  echo "== $page page in headless Chromium"
  BSV_DIST=target/bench-dist node "$bench"
done
