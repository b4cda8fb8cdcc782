#!/usr/bin/env bash
# `make bench`: speed figures (a command, not a timed test). Kernels natively and as wasm in
# Node (release builds), then the IK page (1920x1080) and the RRT page's frames in headless
# Chromium.
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

if [[ -f tests/e2e/ik2r.bench.mjs ]]; then
  echo
  echo "== IK page in headless Chromium (release dist/ with the bench hooks)"
  # The app build has no timing hooks: assemble the release dist/, then a copy of it whose
  # wasm is built with `--features bench` (window.__ik2rBench, __ik2rTimings).
  scripts/build-dist.sh >/dev/null
  wasm-pack build --quiet --target web --release --out-dir target/bench-web --out-name bsv_playground \
    --mode no-install --no-pack -- --features bench
  rm -rf target/bench-dist
  cp -r dist target/bench-dist
  cp target/bench-web/bsv_playground.js target/bench-web/bsv_playground_bg.wasm target/bench-dist/pkg/
  BSV_DIST=target/bench-dist node tests/e2e/ik2r.bench.mjs
fi

if [[ -d target/bench-dist ]]; then
  echo
  echo "== RRT page in headless Chromium: frame work playing as fast as possible to 50,000 nodes"
  # The same bench dist/ (window.__rrtFrameMs, __rrtDrawMs); only the bench test of the file.
  BSV_DIST=target/bench-dist node --test --test-reporter=spec \
    --test-name-pattern='frame work p95' tests/e2e/rrt.test.mjs
fi
