#!/usr/bin/env bash
# Builds the wasm (release by default, `--dev` for a fast unoptimised build) and assembles
# the static app in dist/: index.html, www/ (css, bootstrap js), pkg/ (wasm + its JS glue).
# dist/ runs from any static host or folder served over http.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"

profile=--release
[[ "${1:-}" == "--dev" ]] && profile=--dev

wasm-pack build --target web "$profile" --out-dir pkg --out-name bsv_playground --mode no-install --no-pack

rm -rf dist
mkdir -p dist/pkg
cp index.html dist/
cp -r www dist/www
cp pkg/bsv_playground.js pkg/bsv_playground_bg.wasm dist/pkg/

size() { gzip -9 -c "$@" | wc -c; }
printf 'dist/ ready (%s): wasm %s B (gzip %s B); wasm+js+css+html gzip %s B\n' \
  "${profile#--}" "$(wc -c < dist/pkg/bsv_playground_bg.wasm)" "$(size dist/pkg/bsv_playground_bg.wasm)" \
  "$(cat dist/pkg/* dist/www/* dist/index.html | gzip -9 -c | wc -c)"
