#!/usr/bin/env bash
# Installs what building (and, with --browser, testing) needs, and only what is missing:
# the Rust wasm32 target, wasm-pack, wasm-bindgen-cli and the wasm splitter (wasm-split-cli of
# wasm_split_cli_support) at pinned versions (cargo install),
# wasm-opt, terser, playwright-core and axe-core from npm (package-lock.json pins them), pyarrow
# in the project's .venv (python3 -m venv, for tests/lerobot/check_v3.py), and with --browser
# Debian's chromium, chromium-driver and a Japanese font (apt-get).
set -euo pipefail
cd "$(dirname "$0")/.."

WASM_PACK_VERSION=0.15.1
# The splitter that cuts the app's wasm into a chunk per page (scripts/build-dist.sh).
WASM_SPLIT_VERSION=0.2.4
# The LeRobot dataset checker's only package (tests/lerobot/check_v3.py).
PYARROW_VERSION=26.0.1
# wasm-bindgen-cli must match the wasm-bindgen in Cargo.lock exactly.
WASM_BINDGEN_VERSION=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"

say() { printf '\033[1m[setup]\033[0m %s\n' "$*"; }

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  say "adding Rust target wasm32-unknown-unknown"
  rustup target add wasm32-unknown-unknown
fi
if [[ "$(wasm-pack --version 2>/dev/null)" != "wasm-pack $WASM_PACK_VERSION" ]]; then
  say "installing wasm-pack $WASM_PACK_VERSION (about 3 minutes)"
  cargo install wasm-pack --version "$WASM_PACK_VERSION" --locked
fi
if [[ "$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen $WASM_BINDGEN_VERSION" ]]; then
  say "installing wasm-bindgen-cli $WASM_BINDGEN_VERSION (about 3 minutes)"
  # Not --locked: the registry mirror lags one of the crates its lock file pins.
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --force
fi
if [[ "$(cat "$HOME/.cargo/wasm-split-cli.version" 2>/dev/null)" != "$WASM_SPLIT_VERSION" || ! -x "$HOME/.cargo/bin/wasm-split-cli" ]]; then
  say "installing wasm-split-cli $WASM_SPLIT_VERSION (about 2 minutes)"
  cargo install wasm_split_cli_support --version "$WASM_SPLIT_VERSION" --features build-binary --locked --force
  echo "$WASM_SPLIT_VERSION" > "$HOME/.cargo/wasm-split-cli.version"
fi
if [[ ! -x node_modules/.bin/wasm-opt || ! -d node_modules/playwright-core || ! -d node_modules/axe-core || ! -d node_modules/terser ]] \
  || ! cmp -s package-lock.json node_modules/.package-lock.json.copy 2>/dev/null; then
  say "installing npm tools (binaryen's wasm-opt, terser, playwright-core, axe-core) from package-lock.json"
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.package-lock.json.copy
fi

if [[ "$(.venv/bin/python -c 'import pyarrow; print(pyarrow.__version__)' 2>/dev/null)" != "$PYARROW_VERSION" ]]; then
  if ! python3 -c 'import ensurepip, venv' 2>/dev/null; then
    say "installing Debian's python3-venv"
    sudo_cmd=()
    [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq python3-venv
  fi
  say "installing pyarrow $PYARROW_VERSION into .venv (the LeRobot dataset checker)"
  python3 -m venv .venv
  .venv/bin/pip install -q --disable-pip-version-check "pyarrow==$PYARROW_VERSION"
fi

if [[ "${1:-}" == "--browser" ]]; then
  need=()
  command -v chromium >/dev/null || need+=(chromium)
  command -v chromedriver >/dev/null || need+=(chromium-driver)
  dpkg -s fonts-ipafont-gothic >/dev/null 2>&1 || need+=(fonts-ipafont-gothic)
  if ((${#need[@]})); then
    say "installing Debian packages: ${need[*]}"
    sudo_cmd=()
    [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${need[@]}"
  fi
fi
say "toolchain ready: $(rustc --version), $(wasm-pack --version), $(wasm-bindgen --version), wasm-opt $(wasm-opt --version | awk '{print $3}')"
