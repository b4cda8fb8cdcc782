#!/usr/bin/env bash
# Builds the wasm (release by default, `--dev` for a fast unoptimised build) and assembles
# the static app in dist/: index.html, sw.js (the offline service worker), www/ (css, boot and
# bootstrap js, the worker, favicon, the web app manifest),
# pkg/ (wasm + its JS glue). dist/ runs from any static host or folder served over http.
# dist/www/app.css is one stylesheet: www/app.css, then every stylesheet that sits beside the
# Rust of a page or widget (src/ui/**/*.css, in path order); nothing injects <style> at run time,
# so the app runs under the strict Content-Security-Policy of index.html.
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
{
  cat www/app.css
  find src/ui -name '*.css' -print0 | LC_ALL=C sort -z | while IFS= read -r -d '' css; do
    printf '\n/* ---- %s ---- */\n' "$css"
    cat "$css"
  done
} > dist/www/app.css
cp pkg/bsv_playground.js pkg/bsv_playground_bg.wasm dist/pkg/
# wasm-bindgen `inline_js` / `module` snippets, if any crate uses them.
[[ -d pkg/snippets ]] && cp -r pkg/snippets dist/pkg/
# A release build is minified (the glue and the stylesheet; scripts/minify.mjs).
[[ "$profile" == --release ]] && node scripts/minify.mjs dist
# The offline service worker of exactly these files (dist/sw.js; see www/sw.js).
node scripts/sw-build.mjs dist

size() { gzip -9 -c "$@" | wc -c; }
printf 'dist/ ready (%s): wasm %s B (gzip %s B); wasm+js+css+html gzip %s B\n' \
  "${profile#--}" "$(wc -c < dist/pkg/bsv_playground_bg.wasm)" "$(size dist/pkg/bsv_playground_bg.wasm)" \
  "$(cat dist/pkg/* dist/www/* dist/index.html | gzip -9 -c | wc -c)"
