#!/usr/bin/env bash
# `make bench`: speed figures (a command, not a timed test). Kernels natively and as wasm in
# Node (release builds), then the IK page in headless Chromium at 1920x1080.
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
  echo "== IK page in headless Chromium (release dist/)"
  scripts/build-dist.sh >/dev/null
  node tests/e2e/ik2r.bench.mjs
fi
