#!/usr/bin/env bash
# `make bench`: speed figures (a command, not a timed test). Kernels natively and as wasm in
# Node (release builds), the app's size and first interactive frame, then every page bench of
# tests/bench/ in headless Chromium, each figure printed against its budget. What the benches
# print is also written to docs/figures.md, with the date, the commit and the machine's cores,
# so that no figure is copied into the docs by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"

benches() {
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
  # The app build has no timing hooks: the release dist/, then the same build with
  # `--features bench` (window.__ik2rBench, __pendulumBench, ...) in target/bench-dist.
  scripts/build-dist.sh >/dev/null
  BSV_FEATURES=bench DIST_DIR=target/bench-dist scripts/build-dist.sh >/dev/null

  echo
  echo "== size of the app (dist/, every file gzipped at level 9; the budget is 350 KB)"
  node scripts/size.mjs dist

  echo
  echo "== first interactive frame: cold loads of the release dist/ from localhost in headless Chromium"
  node tests/bench/firstframe.bench.mjs

  echo
  echo "== a phone's first visit: each route under Lighthouse's mobile profile (throttled), gzipped"
  node tests/bench/firstload.bench.mjs

  echo
  echo "== Lighthouse 12.2.3, mobile preset: every route in English and Japanese (median of 3 runs)"
  # Not a dependency of the app or of `make test`: pinned, in a folder of its own (13.x needs
  # Node 22), run against Debian's chromium.
  if [[ "$(node -p "require('./target/lighthouse/node_modules/lighthouse/package.json').version" 2>/dev/null)" != 12.2.3 ]]; then
    mkdir -p target/lighthouse
    [[ -f target/lighthouse/package.json ]] || echo '{ "private": true }' > target/lighthouse/package.json
    (cd target/lighthouse && npm i -E --no-audit --no-fund --loglevel=error lighthouse@12.2.3)
  fi
  CHROME_PATH=${CHROME_PATH:-/usr/bin/chromium} node tests/bench/lighthouse.bench.mjs

  # Every page bench (tests/bench/<page>.bench.mjs) on the dist with the bench hooks; each prints
  # its figures against their budgets.
  for bench in tests/bench/*.bench.mjs; do
    page=$(basename "$bench" .bench.mjs)
    [[ $page == firstframe || $page == firstload || $page == lighthouse ]] && continue
    echo
    echo "== $page page in headless Chromium"
    BSV_DIST=target/bench-dist node "$bench"
  done
}

printed=$(mktemp)
trap 'rm -f "$printed"' EXIT
benches | tee "$printed"

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- 2>/dev/null || commit="$commit with uncommitted changes"
{
  echo "# Figures"
  echo
  echo "Written by \`make bench\` (scripts/bench.sh) on $(date -u +%Y-%m-%d), commit $commit, on a"
  echo "machine with $(nproc) cores: every figure beside its budget. Timings move from run to run;"
  echo "run \`make bench\` again rather than editing this file."
  echo
  echo '```text'
  sed 's/\x1b\[[0-9;]*m//g' "$printed"
  echo '```'
} > docs/figures.md
echo
echo "figures written to docs/figures.md"
