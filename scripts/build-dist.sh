#!/usr/bin/env bash
# Builds the wasm (release by default, `--dev` for a fast unoptimised build) and assembles
# the static app in dist/: index.html, sw.js (the offline service worker), www/ (css, boot and
# bootstrap js, the route table, the worker, favicon, the web app manifest), pkg/ (the main
# wasm + its JS glue, the packs of the split points and their loader). dist/ runs from any
# static host or folder served over http.
#
# The wasm is split by route: cargo builds it with its relocations kept (`--emit-relocs`),
# wasm-split-cli cuts it at the split points (`page!` lines of the page table, each language's
# strings, the worker's kernels) into the main module (the shell) and chunks, wasm-bindgen
# makes the glue of the main module, and scripts/split-link.mjs packs each split point's
# chunks into one file (`pkg/pack_<split>.bin`) and writes `pkg/routes.json`; at the head of
# `www/boot.js` scripts/boot-table.mjs writes the table of which pack each route and language
# needs first, and the main wasm's size.
# dist/www/app.css is one stylesheet: www/app.css, then every stylesheet that sits beside the
# Rust of a page or widget (src/ui/**/*.css, in path order); nothing injects <style> at run time,
# so the app runs under the strict Content-Security-Policy of index.html. A `<name>.late.css`
# styles what only a chunk builds: it is dist/www/<name>.css, linked by that chunk when used.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"

profile=--release
[[ "${1:-}" == "--dev" ]] && profile=--dev
# BSV_FEATURES=bench builds the app with the bench hooks; DIST_DIR says where (default dist);
# BSV_NAMES=1 keeps the wasm functions' names (for a profiler; larger files).
features=split${BSV_FEATURES:+,$BSV_FEATURES}
out=${DIST_DIR:-dist}

if [[ "$profile" == --release ]]; then
  cargo_profile=(--release); built=release
else
  cargo_profile=(); built=debug
fi
# The build a learner's progress file names (`build`, src/ui/kit/progress_store.rs): the
# version and the commit it was built from.
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -n 1)
export BSV_BUILD="bsv-playground $version+$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
# Its own target dir: the relocation flag would otherwise rebuild the checks' artifacts.
CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-Clink-args=--emit-relocs" \
  cargo build --lib --target wasm32-unknown-unknown --no-default-features --locked \
  --target-dir target/app "${cargo_profile[@]}" --features "$features"
rm -rf target/app/split pkg
wasm-split-cli "target/app/wasm32-unknown-unknown/$built/bsv_playground.wasm" target/app/split \
  --out-name bsv_playground
mkdir -p pkg
keep=() opt_keep=()
[[ "${BSV_NAMES:-}" == 1 ]] && keep=(--keep-debug) opt_keep=(-g)
wasm-bindgen --target web --keep-lld-exports --no-demangle "${keep[@]}" --out-dir pkg --out-name bsv_playground \
  target/app/split/bsv_playground.wasm
if [[ "$profile" == --release ]]; then
  wasm-opt -Os "${opt_keep[@]}" --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-reference-types --enable-multivalue \
    pkg/bsv_playground_bg.wasm -o pkg/bsv_playground_bg.wasm
fi

rm -rf "$out"
mkdir -p "$out"/pkg
cp index.html "$out"/
cp -r www "$out"/www
cp -r locales "$out"/locales
{
  cat www/app.css
  find src/ui -name '*.css' ! -name '*.late.css' -print0 | LC_ALL=C sort -z |
    while IFS= read -r -d '' css; do
      printf '\n/* ---- %s ---- */\n' "$css"
      cat "$css"
    done
} > "$out"/www/app.css
find src/ui -name '*.late.css' -print0 | while IFS= read -r -d '' css; do
  cp "$css" "$out/www/$(basename "$css" .late.css).css"
done
cp pkg/bsv_playground.js pkg/bsv_playground_bg.wasm "$out"/pkg/
node scripts/split-link.mjs target/app/split "$out"/pkg
# wasm-bindgen `inline_js` / `module` snippets, if any crate uses them.
[[ -d pkg/snippets ]] && cp -r pkg/snippets "$out"/pkg/
# A release build is minified (the scripts and the stylesheet; scripts/minify.mjs), and the
# main wasm's imports get short names in the wasm and its glue (scripts/short-imports.mjs).
if [[ "$profile" == --release ]]; then
  node scripts/minify.mjs "$out"
  node scripts/short-imports.mjs "$out"/pkg/bsv_playground_bg.wasm "$out"/pkg/bsv_playground.js
fi
# The route table, and the main wasm's final size, at the head of www/boot.js.
node scripts/boot-table.mjs "$out"
# The offline service worker of exactly these files (sw.js; see www/sw.js).
node scripts/sw-build.mjs "$out"

size() { gzip -9 -c "$@" | wc -c; }
printf '%s/ ready (%s): main wasm %s B (gzip %s B); node scripts/size.mjs %s for every file\n' \
  "$out" "${profile#--}" "$(wc -c < "$out"/pkg/bsv_playground_bg.wasm)" \
  "$(size "$out"/pkg/bsv_playground_bg.wasm)" "$out"
