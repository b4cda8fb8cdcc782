#!/usr/bin/env bash
# Every check and test, in the order a failure is cheapest to find: formatting, clippy (native
# and wasm32), rustdoc, native tests (unit, golden parity, CLI, properties, doctests), the
# LeRobot dataset check (and that it catches a corrupted copy), the same golden tests as wasm
# under Node, then the release app in headless Chromium. Fails on the first error.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PWD/node_modules/.bin:$PATH"
export CARGO_TERM_COLOR=never

step() { printf '\n\033[1m== %s\033[0m\n' "$*"; }
t0=$SECONDS

step "rustfmt"
cargo fmt --all -- --check

step "clippy (native, all targets)"
cargo clippy --all-targets --locked -- -D warnings

step "clippy (wasm32, lib and tests)"
cargo clippy --target wasm32-unknown-unknown --lib --tests --features bench --locked -- -D warnings

step "rustdoc (wasm32, warnings are errors)"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --target wasm32-unknown-unknown --lib --locked

step "native tests"
cargo test --locked

step "LeRobot v3.0 dataset of the scripted session (tests/lerobot/check_v3.py)"
dataset=$(mktemp -d)
cargo run --locked --quiet --bin bsv -- so101-dataset tests/so101/session/so101_episode_*.csv \
  --out "$dataset/ok"
.venv/bin/python tests/lerobot/check_v3.py "$dataset/ok"
# The checker must be able to fail: one frame too many in info.json, a stats.json mean off.
cp -r "$dataset/ok" "$dataset/bad-total" && cp -r "$dataset/ok" "$dataset/bad-stats"
sed -i 's/"total_frames": \([0-9]*\)/"total_frames": 1\1/' "$dataset/bad-total/meta/info.json"
.venv/bin/python - "$dataset/bad-stats/meta/stats.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
stats["observation.state"]["mean"][0] += 0.5
json.dump(stats, open(sys.argv[1], "w"), indent=4)
PY
for bad in bad-total bad-stats; do
  if .venv/bin/python tests/lerobot/check_v3.py "$dataset/$bad" 2>"$dataset/$bad.err"; then
    echo "check_v3.py passed a corrupted dataset ($bad)" >&2
    exit 1
  fi
  echo "check_v3.py refuses the corrupted copy ($bad): $(sed -n 2p "$dataset/$bad.err")"
done
rm -rf "$dataset"

step "wasm tests under Node (wasm-pack test --node)"
log=$(mktemp)
wasm-pack test --node --mode no-install 2>&1 | tee "$log"
passed=$(grep -Eo '[0-9]+ passed' "$log" | awk '{s += $1} END {print s + 0}')
if [[ "$passed" -eq 0 ]]; then
  echo "wasm-pack test --node ran no test: that is a failure" >&2
  exit 1
fi
echo "wasm tests under Node: $passed passed"

step "release build of the app (dist/)"
scripts/build-dist.sh

step "size of the app (scripts/size.mjs: fails above its ceiling)"
node scripts/size.mjs dist --check

step "browser end-to-end tests (headless Chromium)"
node --test tests/e2e/*.test.mjs

printf '\nall checks passed in %ss\n' "$((SECONDS - t0))"
